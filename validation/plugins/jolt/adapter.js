// The Jolt Physics adapter: an executable adapter (protocol version 2, docs/peers/jolt.md)
// around Jolt's shape-vs-shape collision query (TransformedShape::CollideShape), through the
// WebAssembly build of the npm package jolt-physics 1.1.0 (JoltPhysics.js, which builds Jolt
// Physics v5.6.0: its CMakeLists.txt, FetchContent GIT_TAG "v5.6.0"), run by Node.
//
// Jolt is a 3D library in single precision. Each 2D shape P goes in as the prism P x [-h, h], a
// ConvexHullShape of its 2n points (x, y, -h), (x, y, h) ("The prism reduction (FCL, Bullet)" in
// docs/peers.md: the prisms' 3D distance is the 2D one, and their penetration depth is the 2D one
// while 2h exceeds it):
// - ConvexHullShapeSettings.mMaxConvexRadius = 0: no convex radius, the hull is the points' hull
//   (a convex radius would shrink the hull and round it back: ConvexHullShape.h:25-26, 34; 0 is
//   the member's default, the constructors that take points default to 0.05, h:27-28);
// - mHullTolerance = 0: its default 1e-3 lets points up to 1e-3 outside the hull be dropped
//   (ConvexHullShape.h:36); Jolt still raises it to its coplanar distance
//   3 FLT_EPSILON (max|x| + max|y| + max|z|) (ConvexHullBuilder.cpp:240-247, 313-317).
// - h = HEIGHT_FACTOR (eA + eB), e the shape's bounding box width plus its height (at least its
//   diameter, so at least any 2D depth d, and independent of where the shape is), in double, then
//   rounded up to float (prismHalfHeight below). With HEIGHT_FACTOR 2 (FCL's), 2h >= 4 (eA + eB)
//   >= 8 d: the cap-to-cap translation 2h never competes with the in-plane one. Factors 0.5 to 4
//   measured alike, 2 a little the best (docs/peers/jolt.md); taller is worse in float:
//   GJK calls shapes touching when |v|^2 <= FLT_EPSILON max|y|^2 over its simplex
//   (GJKClosestPoint.h:442), and the hull builder's coplanar distance grows with max|z|
//   (ConvexHullBuilder.cpp:240-247): measured in docs/peers/jolt.md.
//
// What it takes (the handshake's lines):
// - `input jolt-1.1.0 world`: the host sends each case as world points rounded to float with the
//   identity transform. Jolt takes a rotation as a float quaternion (Math/Quat.h:264) and, more to
//   the point, places a ConvexHullShape by its centre of mass: the constructor computes it and
//   stores the points relative to it, in float (ConvexHullShape.cpp:82-83, 153), so even an exact
//   input is recentred by Jolt's own arithmetic. The adapter hands Jolt the world points as they
//   come (body position 0, rotation the identity): what Jolt then does with them (the recentring)
//   is Jolt's. A case whose transform is not the identity is refused (the host never sends one).
// - `no-radius`: Jolt has no rounded polygon: a ConvexHullShape's convex radius lies inside the
//   given hull (it shrinks the hull by the radius and rounds it back), not a Minkowski sum with a
//   disc; the runner refuses rounded cases without asking.
// - max_vertices 128: a ConvexHullShape holds at most cMaxPointsInHull = 256 points
//   (ConvexHullShape.h:45-47); a prism of n points has 2n, and a hull with more vertices than the
//   limit is built as an approximation (ConvexHullShape.cpp:60-61: MaxVerticesReached accepted).
// - Shapes Jolt cannot build are refused with Jolt's own message (ShapeSettings::Create's error):
//   a single point (its prism, a vertical segment of 2 points: "Need at least 3 points to make a
//   hull", ConvexHullBuilder.cpp:306-311); a segment's prism is a flat quad, which Jolt builds
//   (the coplanar case, ConvexHullBuilder.cpp:404-418) and answers.
//
// The query: shape A is the query shape with its centre-of-mass transform, shape B a
// TransformedShape, TransformedShape::CollideShape (base offset 0, a closest-hit collector), in two
// steps, both in query() and so both timed:
// 1. Jolt's defaults (CollideShapeSettings as constructed: mMaxSeparationDistance 0,
//    CollideShape.h:100): a hit is an overlap (or a contact within mCollisionTolerance), its depth
//    from GJK, else EPA, on the prisms themselves;
// 2. no hit: again with mMaxSeparationDistance = U, at least the case's distance (else a separated
//    pair answers nothing: CollideShape.h:98-100), U the least distance from a point of one shape
//    to an edge of the other (reachBound, in prepare(), outside the timed loop), times 1 + 1/8,
//    rounded up to float, and at least h / 2^20 (for shapes that touch U is 0).
// Why two: sCollideConvexVsConvex inflates shape 1 by mMaxSeparationDistance as a convex radius
// (at most 1 in EPA) and subtracts it again from |point2 - point1| in float (ConvexShape.cpp:93,
// 113-121, 134, 141), so with one query at U for every case EPA's overlap depths were taken on a
// rounded shape: measured (docs/peers/jolt.md) a median relative depth error of 6.1e-7 and
// at most 0.44, against 4.9e-9 and 1.8e-4 in two steps; and the cancellation costs about an ulp
// of U on a separated distance, and Jolt's contact points move off their shapes as
// mMaxSeparationDistance grows (measured on a case 0.0009999 apart: a point on its vertex at 0.0011,
// 9.5e-4 off at 0.89), hence U as small as a bound allows.
// The answer: CollideShapeResult's mPenetrationDepth ("If
// CollideShapeSettings::mMaxSeparationDistance > 0 this number can be negative to indicate that
// the objects are separated by -mPenetrationDepth. The contact points are the closest points in
// that case", CollideShape.h:62), so the distance is -mPenetrationDepth, and the x, y of
// mContactPointOn1 and mContactPointOn2 (world space with base offset 0, CollideShape.h:59-60);
// iterations -1 (Jolt does not report them).
//
// Prepared shapes (`prepared jolt-1.1.0 case`): each shape's ConvexHullShape is built once from the
// case's (world) points with the case's h, with its TransformedShape; a query is the one or two
// CollideShape calls on them (query() below). A `time` request prepares its 2m shapes once, timed
// apart, before its timed loop; a `distance` request goes through the same prepare() and query().
//
// The contract (the `contract` lines, CONTRACT below), read in Jolt's sources (JoltPhysics at the
// snapshot of 2026-06-30, 3b47ec39, where the files cited last changed on 2026-06-13 at the
// latest, c799c896; the release v5.6.0 that jolt-physics 1.1.0 builds followed):
// - overlap `penetration`: mPenetrationDepth, "move shape 2 by this distance to resolve the
//   collision" (CollideShape.h:62), with the two contact points on their shapes
//   (CollideShape.h:59-60);
// - tolerance abs 1e-4: "If objects are closer than this distance, they are considered to be
//   colliding (used for GJK)" (CollideSettingsBase::mCollisionTolerance, CollideShape.h:82-83;
//   cDefaultCollisionTolerance = 1.0e-4f, PhysicsSettings.h:9-10);
// - margin 0: the adapter sets mMaxConvexRadius = 0 (ConvexHullShape.h:34);
// - depth: none stated. mPenetrationTolerance (CollideShape.h:85-86, default 1e-4,
//   PhysicsSettings.h:12-13) stops EPA when the squared depth changes by less than it times the
//   squared depth: a stopping rule, not a bound on the depth's error.
//
// jolt-physics is found through NODE_PATH, which the generated wrapper
// build/<preset>/validation/plugins/gjk2d-jolt sets (CMakeLists.txt here). The package is an ES
// module: it is loaded with import() of the file require.resolve finds.
'use strict';

const readline = require('readline');
const path = require('path');
const fs = require('fs');
const url = require('url');

const PACKAGE = path.join(path.dirname(require.resolve('jolt-physics/package.json')));
const PACKAGE_VERSION = JSON.parse(
  fs.readFileSync(path.join(PACKAGE, 'package.json'), 'utf8'),
).version;
// The Jolt Physics release the package builds (JoltPhysics.js CMakeLists.txt, GIT_TAG "v5.6.0").
const JOLT_VERSION = '5.6.0';
const IMPL = 'jolt-' + PACKAGE_VERSION;
// The prisms' half height over eA + eB (docs/peers/jolt.md: measured).
const HEIGHT_FACTOR = 2;
// mMaxSeparationDistance over U, the upper bound of the distance: room for Jolt's own error, so
// that an answer a little above U is still given (docs/peers/jolt.md: with 1 + 1/1024, 3 of
// 3153 separated random cases got no contact, e.g. 2.62042 answered with more room where U and the
// exact distance are 2.61549; with 1 + 1/8 all are answered, the median error the same; with 2
// it grows from 7.3e-8 to 9.5e-8).
const MAX_SEPARATION_SLACK = 1 + 1 / 8;
// The least mMaxSeparationDistance over h, 8 float ulps of h: shapes that share a point (U = 0)
// touch, and Jolt answers them no contact at distance 0 (nor does the first query: EPA finds no
// penetration); a little more reaches them (docs/peers/jolt.md: of 208 such cases of the hard
// families, without it all no contact, 180 are then answered within gjk2d's bound; h / 4096 got
// 183 but made two near-touching answers with a small U worse, h / 2^20 none).
const MIN_SEPARATION = 2 ** -20;

const JOLT_SRC = `JoltPhysics read at 3b47ec39 (2026-06-30; jolt-physics ${PACKAGE_VERSION}, npm, builds v${JOLT_VERSION})`;
const INPUT = `input ${IMPL} world Jolt takes a rotation as a float quaternion (Jolt/Math/Quat.h:264, a Vec4) and places a shape by its centre of mass (Jolt/Physics/Collision/TransformedShape.h:99-101), a ConvexHullShape storing its points relative to it in float (Jolt/Physics/Collision/Shape/ConvexHullShape.cpp:82-83, 153), ${JOLT_SRC}`;
const CONTRACT = [
  `contract ${IMPL} overlap penetration Jolt/Physics/Collision/CollideShape.h:59-62 (mPenetrationDepth: "move shape 2 by this distance to resolve the collision"; with mMaxSeparationDistance > 0 "negative to indicate that the objects are separated by -mPenetrationDepth. The contact points are the closest points in that case"), ${JOLT_SRC}`,
  `contract ${IMPL} tolerance 0.0001 none Jolt/Physics/Collision/CollideShape.h:82-83 (mCollisionTolerance: "If objects are closer than this distance, they are considered to be colliding (used for GJK)"), Jolt/Physics/PhysicsSettings.h:9-10 (cDefaultCollisionTolerance = 1.0e-4f), ${JOLT_SRC}`,
  `contract ${IMPL} margin 0 the adapter sets ConvexHullShapeSettings::mMaxConvexRadius = 0 (Jolt/Physics/Collision/Shape/ConvexHullShape.h:34, the member's default too; the constructors that take points default to cDefaultConvexRadius 0.05, ConvexHullShape.h:27-28, PhysicsSettings.h:15-16), ${JOLT_SRC}`,
  `contract ${IMPL} depth none none no depth tolerance stated: mPenetrationTolerance (Jolt/Physics/Collision/CollideShape.h:85-86, default 1e-4, PhysicsSettings.h:12-13) stops EPA when the squared depth changes by less than it times the squared depth (Jolt/Geometry/EPAPenetrationDepth.h:140): a stopping rule, not a bound on the depth, ${JOLT_SRC}`,
];

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
  const points = new Array(n);
  for (let k = 0; k < n; ++k)
    points[k] = [num(i + 7 + 2 * k, `x${k}`), num(i + 8 + 2 * k, `y${k}`)];
  return { shape: { letter, r, px, py, c, s, points }, next: i + 7 + 2 * n };
}

function readCase(t, i) {
  const A = readShape(t, i, 'A');
  const B = readShape(t, A.next, 'B');
  return { a: A.shape, b: B.shape, next: B.next };
}

// Why a case cannot be given to Jolt as it is, or null. Jolt gets the points as they are, so a
// transform other than the identity (which the host never sends to an `input world` variant) is
// refused rather than applied here; a radius is refused (no-radius: the host never sends one).
function refusal(c) {
  for (const s of [c.a, c.b]) {
    if (s.points.length < 1) return `shape ${s.letter} without points`;
    if (!(s.px === 0 && s.py === 0 && s.c === 1 && s.s === 0))
      return `shape ${s.letter}'s transform is not the identity: Jolt takes the world points (input world)`;
    if (s.r !== 0) return `shape ${s.letter} has a radius: Jolt has no rounded polygon (no-radius)`;
    if (s.points.length > 128)
      return `shape ${s.letter} has ${s.points.length} points: Jolt's hull holds at most 256 (cMaxPointsInHull), 128 a prism`;
    for (const [x, y] of s.points)
      if ((Math.fround(x) !== x && !Number.isNaN(x)) || (Math.fround(y) !== y && !Number.isNaN(y)))
        return `shape ${s.letter}'s point (${x}, ${y}) is not a float`;
  }
  return null;
}

// The smallest float >= x (x finite, >= 0): Math.fround rounds to nearest.
function floatUp(x) {
  let f = Math.fround(x);
  if (f >= x) return f;
  const view = new DataView(new ArrayBuffer(4));
  view.setFloat32(0, f);
  view.setUint32(0, view.getUint32(0) + 1);
  return view.getFloat32(0);
}

// e of a shape: its bounding box's width plus its height, at least its diameter (|dx| + |dy| >=
// the Euclidean length), so at least its width in any direction and any 2D depth it takes part in.
function extent(points) {
  let x0 = Infinity,
    x1 = -Infinity,
    y0 = Infinity,
    y1 = -Infinity;
  for (const [x, y] of points) {
    x0 = Math.min(x0, x);
    x1 = Math.max(x1, x);
    y0 = Math.min(y0, y);
    y1 = Math.max(y1, y);
  }
  return x1 - x0 + (y1 - y0);
}

// The prisms' half height: HEIGHT_FACTOR (eA + eB) in double, up to a float (the points' z), 1
// when that is 0 (two points: refused by Jolt anyway), at most FLT_MAX / 8 (finite prisms).
function prismHalfHeight(a, b) {
  const h = HEIGHT_FACTOR * (extent(a.points) + extent(b.points));
  if (!(h > 0)) return 1;
  return Math.min(floatUp(h), Math.fround(3.4028234663852886e38 / 8));
}

// The least distance from a point of one shape to a segment between consecutive points of the
// other, both ways: each is the distance of a point of A to a point of B (the segments lie in the
// hull), so at least the shapes' distance, and for separated shapes whose points come in convex
// order the distance itself (a vertex and an edge hold a nearest pair). n m operations, in prepare():
// outside the timed loop.
function reachBound(a, b) {
  const toSegments = (p, q) => {
    let best = Infinity;
    for (const [px, py] of p) {
      for (let k = 0; k < q.length; ++k) {
        const [x0, y0] = q[k];
        const [x1, y1] = q[(k + 1) % q.length];
        const dx = x1 - x0;
        const dy = y1 - y0;
        const len2 = dx * dx + dy * dy;
        const t = len2 > 0 ? Math.min(1, Math.max(0, ((px - x0) * dx + (py - y0) * dy) / len2)) : 0;
        best = Math.min(best, Math.hypot(x0 + t * dx - px, y0 + t * dy - py));
      }
    }
    return best;
  };
  return Math.min(toSegments(a, b), toSegments(b, a));
}

let J = null; // the Jolt module, once loaded
let unitScale, origin, identity, filter, collector, overlapSettings;

async function loadJolt() {
  const file = require.resolve('jolt-physics/wasm-compat'); // the wasm inlined: no fetch, no file
  const mod = await import(url.pathToFileURL(file).href);
  J = await mod.default();
  // CollisionDispatch's table of collide functions is filled by RegisterTypes(), which
  // JoltInterface's constructor calls (JoltPhysics.js JoltJS.h, JoltInterface: Factory, then
  // RegisterTypes); without it CollideShape calls a null function. The smallest interface: one
  // object layer, one broad-phase layer, no worker threads; its PhysicsSystem stays unused.
  const objectFilter = new J.ObjectLayerPairFilterTable(1);
  objectFilter.EnableCollision(0, 0);
  const layer = new J.BroadPhaseLayer(0);
  const bpInterface = new J.BroadPhaseLayerInterfaceTable(1, 1);
  bpInterface.MapObjectToBroadPhaseLayer(0, layer);
  J.destroy(layer);
  const settings = new J.JoltSettings();
  settings.mObjectLayerPairFilter = objectFilter;
  settings.mBroadPhaseLayerInterface = bpInterface;
  settings.mObjectVsBroadPhaseLayerFilter = new J.ObjectVsBroadPhaseLayerFilterTable(
    bpInterface,
    1,
    objectFilter,
    1,
  );
  settings.mMaxBodies = 16;
  settings.mMaxBodyPairs = 16;
  settings.mMaxContactConstraints = 16;
  settings.mMaxWorkerThreads = 0;
  new J.JoltInterface(settings); // kept for the process's life
  J.destroy(settings);
  unitScale = new J.Vec3(1, 1, 1);
  origin = new J.RVec3(0, 0, 0);
  identity = new J.Quat(0, 0, 0, 1); // owned: sIdentity() returns the glue's static
  filter = new J.ShapeFilter();
  collector = new J.CollideShapeClosestHitCollisionCollector();
  overlapSettings = new J.CollideShapeSettings(); // Jolt's defaults: mMaxSeparationDistance 0
}

// A shape prepared for one case: its prism as a ConvexHullShape of its world points and the
// case's h, placed by a TransformedShape at body position 0 with the identity rotation.
// Returns {shape, ts} or {error} (Jolt's message).
function prepareShape(s, h) {
  const settings = new J.ConvexHullShapeSettings();
  settings.mMaxConvexRadius = 0;
  settings.mHullTolerance = 0;
  const v = new J.Vec3(0, 0, 0);
  for (const [x, y] of s.points) {
    v.Set(x, y, -h);
    settings.mPoints.push_back(v);
    v.Set(x, y, h);
    settings.mPoints.push_back(v);
  }
  J.destroy(v);
  const result = settings.Create();
  if (result.HasError()) {
    const error = result.GetError().c_str();
    result.Clear();
    J.destroy(settings);
    return { error };
  }
  const shape = result.Get();
  shape.AddRef(); // ours, beyond the settings' cached result
  result.Clear();
  J.destroy(settings);
  const ts = new J.TransformedShape();
  ts.mShape = shape;
  ts.SetWorldTransform(origin, identity, unitScale); // the centre of mass goes to mShapePositionCOM
  return { shape, ts };
}

// A [Value] result of the bindings is a static of the glue code, overwritten by the next call of
// the same function (and not to be destroyed): a prepared case keeps its own copy.
function ownedCopy(m) {
  const copy = new J.RMat44();
  for (let c = 0; c < 3; ++c) copy.SetColumn4(c, m.GetColumn4(c));
  copy.SetTranslation(m.GetTranslation());
  return copy;
}

// The case prepared: both shapes, shape A's centre-of-mass transform and the query's settings.
// Returns {a, b, comA, settings} or {error}.
function prepare(c) {
  const h = prismHalfHeight(c.a, c.b);
  const a = prepareShape(c.a, h);
  if (a.error)
    return {
      error: `Jolt cannot build shape A's prism (ConvexHullShapeSettings::Create): ${a.error}`,
    };
  const b = prepareShape(c.b, h);
  if (b.error) {
    release({ a });
    return {
      error: `Jolt cannot build shape B's prism (ConvexHullShapeSettings::Create): ${b.error}`,
    };
  }
  const settings = new J.CollideShapeSettings();
  const u = reachBound(c.a.points, c.b.points);
  settings.mMaxSeparationDistance = floatUp(Math.max(u * MAX_SEPARATION_SLACK, h * MIN_SEPARATION));
  return { a, b, comA: ownedCopy(a.ts.GetCenterOfMassTransform()), settings };
}

function release(p) {
  for (const s of [p.a, p.b]) {
    if (!s) continue;
    J.destroy(s.ts);
    s.shape.Release();
  }
  if (p.comA) J.destroy(p.comA);
  if (p.settings) J.destroy(p.settings);
}

// One query on a prepared case, the same inside and outside the timed loop: shape A against the
// TransformedShape of B. Returns the collector's hit, or null.
function query(p) {
  collector.Reset();
  p.b.ts.CollideShape(p.a.shape, unitScale, p.comA, overlapSettings, origin, collector, filter);
  if (collector.HadHit()) return collector.mHit;
  collector.Reset();
  p.b.ts.CollideShape(p.a.shape, unitScale, p.comA, p.settings, origin, collector, filter);
  return collector.HadHit() ? collector.mHit : null;
}

function answerDistance(id, c) {
  const p = prepare(c);
  if (p.error) return say(`refused ${id} ${p.error}`);
  try {
    const hit = query(p);
    if (!hit)
      return say(
        `error ${id} Jolt found no contact within mMaxSeparationDistance ${p.settings.mMaxSeparationDistance}`,
      );
    const d = -hit.mPenetrationDepth;
    const pa = hit.mContactPointOn1;
    const pb = hit.mContactPointOn2;
    return say(`ok ${id} ${d} ${pa.GetX()} ${pa.GetY()} ${pb.GetX()} ${pb.GetY()} -1`);
  } finally {
    release(p);
  }
}

function answerTime(id, t) {
  const K = Number(t[3]);
  const m = Number(t[4]);
  if (!Number.isInteger(K) || K < 1 || !Number.isInteger(m) || m < 1)
    throw new RequestError(`time: K "${t[3]}" and m "${t[4]}" must be positive integers`);
  const cases = [];
  let i = 5;
  for (let k = 0; k < m; ++k) {
    const c = readCase(t, i);
    const why = refusal(c);
    if (why) return say(`refused ${id} case ${k + 1}: ${why}`);
    cases.push(c);
    i = c.next;
  }
  if (i !== t.length) throw new RequestError(`${t.length - i} tokens after case ${m}`);
  const prepared = new Array(m);
  try {
    const prepStart = process.hrtime.bigint();
    for (let k = 0; k < m; ++k) prepared[k] = prepare(cases[k]);
    const prepNs = process.hrtime.bigint() - prepStart;
    for (let k = 0; k < m; ++k)
      if (prepared[k].error) return say(`refused ${id} case ${k + 1}: ${prepared[k].error}`);
    let sink = 0;
    const start = process.hrtime.bigint();
    for (let round = 0; round < K; ++round) {
      for (let k = 0; k < m; ++k) {
        const hit = query(prepared[k]);
        if (hit) sink += hit.mPenetrationDepth;
      }
    }
    const total = process.hrtime.bigint() - start;
    if (sink === 12345.678) process.stderr.write('\n'); // keeps the loop's results alive
    return say(`timed ${id} ${total} ${prepNs}`);
  } finally {
    for (const p of prepared) if (p && !p.error) release(p);
  }
}

function answer(t) {
  const id = t[1];
  if (!/^[0-9]+$/.test(id || '')) {
    process.stderr.write(`gjk2d-jolt: request without an id: "${t.join(' ').slice(0, 80)}"\n`);
    return;
  }
  try {
    if (t[2] !== IMPL) return say(`error ${id} unknown implementation "${t[2]}"`);
    if (t[0] === 'distance') {
      const c = readCase(t, 3);
      if (c.next !== t.length) throw new RequestError(`${t.length - c.next} tokens after shape B`);
      const why = refusal(c);
      if (why) return say(`refused ${id} ${why}`);
      return answerDistance(id, c);
    }
    if (t[0] === 'time') return answerTime(id, t);
    return say(`error ${id} unknown request "${t[0]}"`);
  } catch (e) {
    // Jolt threw (a WebAssembly trap on input it cannot take): the case is an error, the stream
    // goes on.
    const what = e instanceof RequestError ? e.message : `Jolt threw ${e.name}: ${e.message}`;
    return say(`error ${id} ${String(what).replace(/\s+/g, ' ')}`);
  }
}

// The module loads (about 0.2 s) before the handshake is answered, and requests wait for it.
const ready = loadJolt();
let handshaken = false;
let queue = Promise.resolve();
const rl = readline.createInterface({ input: process.stdin, crlfDelay: Infinity, terminal: false });
rl.on('line', (line) => {
  queue = queue
    .then(() => ready)
    .then(() => {
      const t = line.trim().split(/ +/);
      if (t.length === 1 && t[0] === '') return;
      if (!handshaken) {
        // We speak version 2 whatever the host asks: the host judges a mismatch (the protocol's rule).
        if (t[0] !== 'gjk2d-adapter')
          process.stderr.write(`gjk2d-jolt: expected the handshake, got "${line.slice(0, 80)}"\n`);
        say('gjk2d-adapter 2');
        say(`library Jolt Physics ${JOLT_VERSION} (jolt-physics ${PACKAGE_VERSION}, WebAssembly)`);
        say(
          `implementation ${IMPL} float no-radius 128 Jolt Physics ${JOLT_VERSION} TransformedShape::CollideShape of two prisms (ConvexHullShape, mMaxConvexRadius 0, mHullTolerance 0), mMaxSeparationDistance above the distance, closest hit`,
        );
        say(INPUT);
        CONTRACT.forEach(say);
        say(`prepared ${IMPL} case`);
        say('ready');
        handshaken = true;
        return;
      }
      answer(t);
    });
});
ready.catch((e) => {
  process.stderr.write(`gjk2d-jolt: cannot load jolt-physics: ${e && e.stack ? e.stack : e}\n`);
  process.exit(1);
});
