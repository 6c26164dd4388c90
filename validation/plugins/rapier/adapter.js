// The Rapier adapter: an executable adapter (protocol version 2, docs/peers/rapier.md)
// around Rapier's Shape.contactShape, the official JavaScript bindings (@dimforge/rapier2d-compat,
// WebAssembly built from rapier.js over parry2d, in f32), run by Node.
//
// Sources read (each file:line below names one of them):
// - rapier.js: the TypeScript sources of @dimforge/rapier2d-compat 0.21.0 itself, as its
//   dist/rapier.mjs.map carries them (sourcesContent, paths gen2d/...); its Rust side, src/..., read
//   at dimforge/rapier.js 6c7e720 (the newest snapshot at hand, after v0.19.3).
// - parry: src/..., read at dimforge/parry 3a41ac2 (0.25.3, the newest snapshot at hand); the
//   package's WebAssembly names parry2d-0.31.1 in its panic paths (`strings rapier_wasm2d_bg.wasm`),
//   so the lines cited are those of an earlier parry than the one that runs.
//
// What it takes. Rapier places a shape by a position and a rotation ANGLE in f32:
// contactShape(shapePos1, shapeRot1: number, ...) turns the angle into a unit complex number
// (gen2d/math.ts:80-82 RotationOps.intoRaw -> RawRotation.fromAngle; src/math.rs:36-38
// `Self(Rotation::new(angle))`, cos and sin of an f32 angle). The case's (c, s) is not an angle:
// atan2(s, c) rounded to f32, then cos and sin again, is another rotation. So the adapter declares
// `input NAME world`: the host sends every case as its world points rounded to f32 with the identity
// transform, and the adapter refuses a case whose transform is not the identity. Each shape is then
// placed at position (0, 0) (a Ball at its point) with angle 0, whose cos and sin are exactly 1 and
// 0: Rapier gets the world points exactly.
//
// Shapes (prepare() below), built from the f32 world points:
// - 3 or more points: ConvexPolygon(points, false), or RoundConvexPolygon(points, radius, false)
//   when the radius is positive. skipConvexHullComputation = false: the case's points are a convex
//   set but may come in any order, repeated or collinear, while the other path, convexPolyline,
//   assumes a counter-clockwise convex polyline and does not check it (parry
//   src/shape/convex_polygon.rs:144-152); the hull (gen2d/geometry/shape.ts:1332-1337 ->
//   SharedShape::convex_hull -> ConvexPolygon::from_convex_hull, convex_polygon.rs:139-142) is what
//   a user with such points calls. Both paths end in from_convex_polyline, which drops every vertex
//   whose two edges' unit normals have a dot product above 1 - sqrt(f32::EPSILON), a turn below
//   about 1.5 degrees (convex_polygon.rs:216-241), and builds nothing below 3 vertices (247-251):
//   then the bindings return no shape, and the adapter refuses the case, saying so.
// - 1 point: Ball(radius) at that point (Ball(0) is the point itself).
// - 2 points: Segment(p0, p1) when the radius is 0. A rounded segment with free end points is not
//   in the bindings (Capsule(halfHeight, radius) lies along the y axis: it would need a rotation,
//   an f32 angle again), so a 2-point shape with a radius is refused.
// The radius is f32 (the host rounds it), RoundShape's border radius: support point of the core
// plus the radius along the direction (parry src/shape/round_shape.rs:177-193, 280-282): no other
// margin.
//
// The query (query() below): shapeA.contactShape(posA, 0, shapeB, posB, 0, PREDICTION, target).
// contactShape answers null when the shapes are further apart than `prediction` (gen2d/geometry/
// shape.ts:415-416; parry's GJK stops when its lower bound exceeds it, src/query/gjk/gjk.rs:409-410;
// ball-ball compares with the radii plus it, contact_ball_ball.rs:20). PREDICTION is f32's largest
// value, 3.4028234663852886e38: every finite distance is within it, and the prediction only decides
// whether to answer, never the answer (gjk.rs:409-410 is its one use in GJK; the test "a far-apart
// case is answered" checks squares 999999 apart). A distance bound from the case's points would do
// as well but costs a computation per case and must stay above every f32 rounding of the distance;
// infinity would do as well, but a finite f32 keeps every comparison and sum with it plain
// (contact_ball_ball.rs:20 adds the radii to it).
// The answer is in world coordinates: "The result is given in world-space" (gen2d/geometry/
// shape.ts:416; parry src/query/contact/contact_shape_shape.rs:130-137, transform_by_mut(pos1,
// pos2)), checked by the tests with shapes placed away from the origin. distance = contact.distance
// (negative on penetration), the witness points point1 and point2, iterations -1 (not reported).
// contactShape builds each shape's WebAssembly form again on every call (gen2d/geometry/
// shape.ts:432-433, this.intoRaw(), and frees it after): the hull is computed per query, inside the
// timed loop, because that is what every contactShape call costs its user.
// null within the prediction (parry's GJK stops after 100 iterations with NoIntersection, gjk.rs:
// 449-450, or EPA finds nothing, contact_support_map_support_map.rs:69-76) is answered `error`, as
// is a throw: 3 or more coincident points make parry's hull panic (COINCIDENT below, answered
// without running the trap), and any other trap is answered and followed by a fresh instance of
// the bindings (freshRapier()).
//
// Prepared shapes: `prepared NAME case` (the world points baked in). A `time` request builds its 2m
// shapes once, timed apart, before its timed loop of queries, and answers both figures; a
// `distance` request goes through the same prepare() and query(), so what is judged is what is
// timed.
//
// The contract (CONTRACT below), in parry's own words:
// - overlap `penetration`: Contact::dist "Negative: Shapes are penetrating (absolute value =
//   penetration depth)" (src/query/contact/contact.rs:97-104), point1 and point2 on each shape's
//   surface (contact.rs:72-82); the bindings: "If this is negative, this contact represents a
//   penetration." (gen2d/geometry/contact.ts:8-12). EPA gives the pair
//   (contact_support_map_support_map.rs:69-73).
// - tolerance: GJK's absolute tolerance eps_tol = 10 f32::EPSILON = 1.1920928955078125e-6
//   (gjk.rs:126-144): a simplex within it of the origin is an intersection (gjk.rs:387-393); and its
//   relative one sqrt(eps_tol), stop when the upper and lower bounds of the distance are within it
//   times the upper bound (gjk.rs:366-367, 413-416): "The minimum distance is found within the
//   tolerance" (gjk.rs:232). sqrt(eps_tol) in f32 is 0.0010918 (REL_TOL below).
// - margin 0 (round_shape.rs above: the border radius is the case's radius).
// - depth: EPA stops when its upper and lower depth bounds are within 100 f32::EPSILON =
//   1.1920928955078125e-5 (src/query/epa/epa2.rs:355-356, 501-509); relative: none stated.
//
// @dimforge/rapier2d-compat is found by require() through NODE_PATH, which the generated wrapper
// build/<preset>/validation/plugins/gjk2d-rapier sets (CMakeLists.txt here).
'use strict';

const readline = require('readline');

// The bindings' module. A Rust panic inside it is a WebAssembly trap (RuntimeError: unreachable)
// that leaves its shadow stack pointer where the panic left it: measured, some tens of thousands
// of traps later a query fails with "memory access out of bounds", so earlier answers after a trap
// cannot be trusted either. After a trap the adapter evaluates the package again (a fresh
// instance, its own memory: about 80 ms) before it answers the next request.
const PACKAGE = '@dimforge/rapier2d-compat';
let RAPIER = require(PACKAGE);
function freshRapier() {
  // Forgotten by the cache and by this module's children, the old instance and its memory can be
  // collected (measured: 100 fresh instances, 142 MB resident; 1.4 GB for 300 while the children
  // kept them).
  for (const key of Object.keys(require.cache))
    if (key.includes('rapier2d-compat')) delete require.cache[key];
  module.children = module.children.filter((child) => !child.id.includes('rapier2d-compat'));
  RAPIER = require(PACKAGE);
  return RAPIER.init();
}

const F32_EPSILON = 1.1920928955078125e-7; // 2^-23
const EPS_TOL = Math.fround(10 * F32_EPSILON); // gjk.rs:141-144, exact in f32
const REL_TOL = Math.fround(Math.sqrt(EPS_TOL)); // gjk.rs:367, sqrt in f32 (one rounding of the double's)
const EPA_TOL = Math.fround(100 * F32_EPSILON); // epa2.rs:355-356
const PREDICTION = 3.4028234663852886e38; // f32::MAX

const PARRY = "parry (dimforge/parry 3a41ac2, 0.25.3; the package's WebAssembly is parry2d 0.31.1)";
const BINDINGS = '@dimforge/rapier2d-compat 0.21.0 (npm; gen2d/... from its dist/rapier.mjs.map)';
let VERSION = null; // RAPIER.version() after init
let IMPL = null;

function contract() {
  return [
    `contract ${IMPL} overlap penetration src/query/contact/contact.rs:97-104 (Contact::dist: "Negative: Shapes ` +
      `are penetrating (absolute value = penetration depth)"), 72-82 (point1, point2 on each shape's surface), ` +
      `src/query/contact/contact_support_map_support_map.rs:64-73 (GJK, then EPA inside the CSO), ${PARRY}; ` +
      `gen2d/geometry/contact.ts:8-12 ("If this is negative, this contact represents a penetration."), ${BINDINGS}`,
    `contract ${IMPL} tolerance ${EPS_TOL} ${REL_TOL} src/query/gjk/gjk.rs:126-144 (eps_tol = 10 f32::EPSILON: ` +
      `the simplex within it of the origin is an intersection, 387-393), 366-367, 413-416 (stop when the distance's ` +
      `upper and lower bounds are within sqrt(eps_tol) times the upper bound), 232 ("The minimum distance is found ` +
      `within the tolerance"), ${PARRY}`,
    `contract ${IMPL} margin 0 src/shape/round_shape.rs:177-193, 280-282 (RoundShape: the core's support point ` +
      `plus border_radius, the case's radius; ConvexPolygon, Ball and Segment have no margin), ${PARRY}`,
    `contract ${IMPL} depth ${EPA_TOL} none src/query/epa/epa2.rs:355-356, 501-509 (EPA stops when its depth's ` +
      `upper and lower bounds are within 100 f32::EPSILON), ${PARRY}`,
  ];
}

// A request the adapter cannot read (its answer: "error <id> <message>").
class RequestError extends Error {}

function say(line) {
  process.stdout.write(line + '\n');
}

// A number as the host writes it (fmt "{}": "0.1", "-3", "1e-300", "inf", "-inf", "nan");
// undefined when it is none.
function parseNumber(tok) {
  if (/^[+-]?(inf|infinity)$/i.test(tok)) return tok[0] === '-' ? -Infinity : Infinity;
  if (/^[+-]?nan$/i.test(tok)) return NaN;
  if (!/^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$/.test(tok)) return undefined;
  return Number(tok);
}

// One shape "<r> <px> <py> <c> <s> <n> <x0> <y0> ..." from tokens t at index i, after its letter.
// Returns {shape, next} or throws a message naming the field.
function readShape(t, i, letter) {
  if (t[i] !== letter) throw new RequestError(`expected "${letter}" at token ${i}, got "${t[i]}"`);
  const num = (k, what) => {
    if (k >= t.length) throw new RequestError(`shape ${letter}: missing ${what}`);
    const v = parseNumber(t[k]);
    if (v === undefined)
      throw new RequestError(`shape ${letter}: ${what} "${t[k]}" is not a number`);
    return v;
  };
  const r = num(i + 1, 'radius');
  const px = num(i + 2, 'px');
  const py = num(i + 3, 'py');
  const c = num(i + 4, 'c');
  const s = num(i + 5, 's');
  const n = num(i + 6, 'n');
  if (!Number.isInteger(n) || n < 0)
    throw new RequestError(`shape ${letter}: n "${t[i + 6]}" is not a count`);
  const points = new Float64Array(2 * n);
  for (let k = 0; k < n; ++k) {
    points[2 * k] = num(i + 7 + 2 * k, `x${k}`);
    points[2 * k + 1] = num(i + 8 + 2 * k, `y${k}`);
  }
  return { shape: { letter, r, px, py, c, s, points }, next: i + 7 + 2 * n };
}

// "A ... B ..." from index i: {a, b, next}.
function readCase(t, i) {
  const A = readShape(t, i, 'A');
  const B = readShape(t, A.next, 'B');
  return { a: A.shape, b: B.shape, next: B.next };
}

// Why Rapier cannot be given shape `sh` as it is, or null. The checks that need Rapier's own
// answer (does it build a polygon?) build the shape once and free it: outside any timed loop.
function shapeRefusal(sh) {
  const L = sh.letter;
  if (!(sh.c === 1 && sh.s === 0 && sh.px === 0 && sh.py === 0))
    return (
      `shape ${L}'s transform is not the identity: Rapier takes a rotation as an f32 angle (gen2d/math.ts:80-82, ` +
      `src/math.rs:36-38 Rotation::new(angle)), not (c, s); the adapter takes world points (input ${IMPL} world)`
    );
  const n = sh.points.length / 2;
  if (n < 1) return `shape ${L} has no points`;
  const values = [sh.r, ...sh.points];
  if (!values.every(Number.isFinite))
    return `shape ${L} has a coordinate or radius that is not finite`;
  if (!values.every((v) => Math.fround(v) === v))
    return `shape ${L} has a number that is not an f32, which Rapier's Float32Array would round`;
  if (sh.r < 0) return `shape ${L} has a negative radius`;
  if (n === 2 && sh.r > 0)
    return (
      `shape ${L} is a segment with a radius: the bindings have no rounded segment with free end points ` +
      `(Capsule(halfHeight, radius) lies along y and needs an f32 rotation angle)`
    );
  if (n >= 3) {
    if (coincident(sh.points)) return null; // answered `error` by answer(): Rapier panics (COINCIDENT)
    const shape = build(sh);
    const raw = shape.intoRaw();
    if (!raw)
      return (
        `Rapier builds no polygon from shape ${L}'s ${n} points: parry's ConvexPolygon::from_convex_polyline drops ` +
        `each vertex whose edges turn by less than about 1.5 degrees (dot of the unit normals > 1 - sqrt(f32::EPSILON)) ` +
        `and returns None below 3 vertices (src/shape/convex_polygon.rs:216-251, ${PARRY})`
      );
    raw.free();
  }
  return null;
}

function refusal(c) {
  return shapeRefusal(c.a) || shapeRefusal(c.b);
}

// 3 or more points, all the same point (an f32 world point: tiny shapes far from the origin round
// to one): parry's 2D convex hull asserts two distinct support points and panics ("Failed to build
// the 2d convex hull of this point cloud.", src/transformation/convex_hull2.rs:107-110), where
// ConvexPolygon::from_convex_hull promises an Option (convex_polygon.rs:139-142): a user's
// ConvexPolygon of them throws RuntimeError: unreachable on its first use. The adapter answers
// that error without running the trap (tested against the bindings: rapier_driver.py).
const COINCIDENT =
  "Rapier throws RuntimeError: unreachable on a ConvexPolygon of 3 or more coincident points: parry's convex " +
  `hull asserts two distinct points (src/transformation/convex_hull2.rs:107-110, ${PARRY})`;
function coincident(points) {
  for (let k = 2; k < points.length; k += 2)
    if (points[k] !== points[0] || points[k + 1] !== points[1]) return false;
  return true;
}
function panics(c) {
  return [c.a, c.b].some((sh) => sh.points.length >= 6 && coincident(sh.points));
}

// Shape `sh` (world points, f32) as Rapier's JavaScript Shape, and where it is placed.
const ORIGIN = { x: 0, y: 0 };
function build(sh) {
  const n = sh.points.length / 2;
  if (n === 1) return new RAPIER.Ball(sh.r);
  if (n === 2)
    return new RAPIER.Segment(
      { x: sh.points[0], y: sh.points[1] },
      { x: sh.points[2], y: sh.points[3] },
    );
  const vertices = new Float32Array(sh.points); // exact: every value is an f32 (shapeRefusal)
  return sh.r > 0
    ? new RAPIER.RoundConvexPolygon(vertices, sh.r, false)
    : new RAPIER.ConvexPolygon(vertices, false);
}

function prepare(sh) {
  const at = sh.points.length === 2 ? { x: sh.points[0], y: sh.points[1] } : ORIGIN;
  return { shape: build(sh), at };
}

// A number as the answer carries it: JavaScript's shortest round-trip decimal, which String()
// gives for every number but -0 (String(-0) is "0"; Rapier answers -0 where a sign is lost).
function num(v) {
  return Object.is(v, -0) ? '-0' : String(v);
}

// One query on two prepared shapes, the same inside and outside the timed loop: angle 0 for both
// (RawRotation.fromAngle(0): cos 0 = 1, sin 0 = 0, the identity), the f32 maximum as prediction.
const target = new RAPIER.ShapeContact(
  0,
  { x: 0, y: 0 },
  { x: 0, y: 0 },
  { x: 0, y: 0 },
  { x: 0, y: 0 },
);
function query(pa, pb) {
  return pa.shape.contactShape(pa.at, 0, pb.shape, pb.at, 0, PREDICTION, target);
}

function answer(t) {
  const id = t[1];
  if (!/^[0-9]+$/.test(id || '')) {
    process.stderr.write(`gjk2d-rapier: request without an id: "${t.join(' ').slice(0, 80)}"\n`);
    return;
  }
  try {
    if (t[2] !== IMPL) return say(`error ${id} unknown implementation "${t[2]}"`);
    if (t[0] === 'distance') {
      const c = readCase(t, 3);
      if (c.next !== t.length) throw new RequestError(`${t.length - c.next} tokens after shape B`);
      const why = refusal(c);
      if (why) return say(`refused ${id} ${why}`);
      if (panics(c)) return say(`error ${id} ${COINCIDENT}`);
      const o = query(prepare(c.a), prepare(c.b));
      if (!o)
        return say(
          `error ${id} contactShape answered null within the prediction ${PREDICTION} (parry's GJK gave up ` +
            `after 100 iterations or its EPA found no face)`,
        );
      const f = num;
      return say(
        `ok ${id} ${f(o.distance)} ${f(o.point1.x)} ${f(o.point1.y)} ${f(o.point2.x)} ${f(o.point2.y)} -1`,
      );
    }
    if (t[0] === 'time') {
      const K = Number(t[3]);
      const m = Number(t[4]);
      if (!Number.isInteger(K) || K < 1 || !Number.isInteger(m) || m < 1)
        throw new RequestError(`time: K "${t[3]}" and m "${t[4]}" must be positive integers`);
      const cases = [];
      let i = 5;
      for (let k = 0; k < m; ++k) {
        const c = readCase(t, i);
        const why = refusal(c) || (panics(c) && COINCIDENT);
        if (why) return say(`refused ${id} case ${k + 1}: ${why}`);
        cases.push(c);
        i = c.next;
      }
      if (i !== t.length) throw new RequestError(`${t.length - i} tokens after case ${m}`);
      const A = new Array(m);
      const B = new Array(m);
      const prepStart = process.hrtime.bigint();
      for (let k = 0; k < m; ++k) {
        A[k] = prepare(cases[k].a);
        B[k] = prepare(cases[k].b);
      }
      const prepared = process.hrtime.bigint() - prepStart;
      let sink = 0;
      const start = process.hrtime.bigint();
      for (let round = 0; round < K; ++round) {
        for (let k = 0; k < m; ++k) {
          const o = query(A[k], B[k]);
          sink += o ? o.distance : 1;
        }
      }
      const total = process.hrtime.bigint() - start;
      if (sink === -1) process.stderr.write('\n'); // keeps the loop's results alive
      return say(`timed ${id} ${total} ${prepared}`);
    }
    return say(`error ${id} unknown request "${t[0]}"`);
  } catch (e) {
    // Rapier threw (a JavaScript error or a WebAssembly trap): the case is an error, the stream
    // goes on, on a fresh instance after a trap.
    const what = e instanceof RequestError ? e.message : `Rapier threw ${e.name}: ${e.message}`;
    say(`error ${id} ${String(what).replace(/\s+/g, ' ')}`);
    if (e instanceof WebAssembly.RuntimeError) {
      ready = false;
      freshRapier()
        .then(resume)
        .catch((err) => {
          process.stderr.write(`gjk2d-rapier: a fresh instance of ${PACKAGE} failed: ${err}\n`);
          process.exit(1);
        });
    }
  }
}

function handshake() {
  // We speak version 2 whatever the host asks: the host judges a mismatch (the protocol's rule).
  say('gjk2d-adapter 2');
  say(`library Rapier @dimforge/rapier2d-compat ${VERSION}`);
  say(
    `implementation ${IMPL} float radius 0 Rapier ${VERSION} Shape.contactShape (ConvexPolygon or ` +
      `RoundConvexPolygon from the convex hull, Ball, Segment), f32, prediction f32::MAX, world points`,
  );
  say(
    `input ${IMPL} world Rapier places a shape by an f32 rotation angle, not (c, s): contactShape's ` +
      `RotationOps.intoRaw(angle) -> RawRotation.fromAngle (gen2d/math.ts:80-82, ${BINDINGS}), ` +
      `Self(Rotation::new(angle)) (src/math.rs:36-38, dimforge/rapier.js 6c7e720)`,
  );
  contract().forEach(say);
  say(`prepared ${IMPL} case`);
  say('ready');
}

// The WebAssembly module is instantiated before the handshake is answered: a failure there is a
// failed handshake (one line on stderr, exit 1), and no request waits on it.
const lines = [];
let ready = false;
let handshaken = false;
// Takes the lines that waited for an instance, in order, until one of them needs a fresh one.
function resume() {
  ready = true;
  while (ready && lines.length) take(lines.shift());
}
function take(line) {
  const t = line.trim().split(/ +/);
  if (t.length === 1 && t[0] === '') return;
  if (!handshaken) {
    if (t[0] !== 'gjk2d-adapter')
      process.stderr.write(`gjk2d-rapier: expected the handshake, got "${line.slice(0, 80)}"\n`);
    handshake();
    handshaken = true;
    return;
  }
  answer(t);
}
const rl = readline.createInterface({ input: process.stdin, crlfDelay: Infinity, terminal: false });
rl.on('line', (line) => (ready ? take(line) : lines.push(line)));
RAPIER.init()
  .then(() => {
    VERSION = RAPIER.version();
    IMPL = `rapier2d-${VERSION}`;
    resume();
  })
  .catch((e) => {
    process.stderr.write(`gjk2d-rapier: RAPIER.init() failed: ${e}\n`);
    process.exit(1);
  });
