// The planck.js adapter: an executable adapter (protocol version 2, docs/peers/planck.md)
// around planck.js's Distance, the JavaScript port of Box2D 2.x's b2Distance, run by Node.
//
// What it takes, checked in planck 1.5.0's sources (src/collision/Distance.ts):
// - DistanceProxy.setVertices(vertices, count, radius) stores the array and the count, with no
//   limit: getSupport loops over all `count` points, and SimplexCache keeps its indices in plain JS
//   arrays of numbers (no 8-bit index as in Box2D 2.4.1's b2SimplexCache). Settings.maxPolygonVertices
//   (12) bounds PolygonShape only, not this path. So max_vertices is 0 (no limit).
// - It computes in JS numbers (double). Transform.set({p, q: {c, s}}) copies (c, s) as given
//   (Rot.set with an object, dist/planck.js: no angle, no sin or cos), so it takes the case's
//   transform exactly.
// - useRadii = true: distance minus both radii, witness points moved onto the rounded surfaces.
// - A fresh SimplexCache (count 0) per query: a cold start (the protocol has no warm start).
// It refuses only what it cannot hand planck: a shape without points.
// Prepared shapes (the handshake's `prepared ... shape` line): a shape is built once in its own
// frame, as an engine keeps it (its vertices as planck Vec2s in a DistanceProxy with its radius,
// prepare() below), and each query sets the two transforms and runs Distance on the two proxies
// (query() below). A `time` request prepares its 2m shapes once, timed apart, before its timed
// loop of queries, and answers both figures; a `distance` request goes through the same prepare()
// and query(), so what is judged is what is timed.
// The contract (the `contract` lines of the handshake, CONTRACT below), read in planck 1.5.0's
// src/collision/Distance.ts (the npm package's sources; its dist/planck.js does the same):
// - overlap `midpoint`: with useRadii, when the core distance is at most rA + rB (or at most
//   EPSILON), "Move the witness points to the middle" (Distance.ts:211-217), as Box2D 2.x does;
// - tolerance: none stated; margin 0 (a DistanceProxy has the case's radius only).
// Finding (a bug, which breaks that contract): in that branch planck 1.5.0 sets both witness
// points to pointA - pointB (Distance.ts:214-216, a difference vector, not a point: Box2D's C++
// takes the midpoint 0.5 (pointA + pointB)). The adapter reports what planck returns, unchanged.
// Finding: that branch is taken too when the core distance is at most planck's EPSILON, 1e-9
// (src/common/Math.ts): shapes 5e-10 apart get distance 0 (a false overlap).
// Finding: on NaN input getSupport returns -1 and planck throws a TypeError: answered "error".
//
// planck is found by require("planck") through NODE_PATH, which the generated wrapper
// build/<preset>/validation/plugins/gjk2d-planck sets (CMakeLists.txt here).
'use strict';

const planck = require('planck');
const readline = require('readline');

// planck's exports map hides "planck/package.json": read it beside dist/planck.js.
const VERSION = JSON.parse(
  require('fs').readFileSync(
    require('path').join(require.resolve('planck'), '..', '..', 'package.json'),
    'utf8',
  ),
).version;
const IMPL = 'planck-' + VERSION;
// What planck promises (the header comment): the handshake's `contract` lines, protocol version 2.
const CONTRACT = [
  `contract ${IMPL} overlap midpoint src/collision/Distance.ts:211-217 (useRadii: "Shapes are overlapped when ` +
    `radii are considered. Move the witness points to the middle."), planck.js 1.5.0 (npm)`,
  `contract ${IMPL} tolerance none none`,
  `contract ${IMPL} margin 0`,
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
  const vertices = new Array(n);
  for (let k = 0; k < n; ++k) {
    vertices[k] = { x: num(i + 7 + 2 * k, `x${k}`), y: num(i + 8 + 2 * k, `y${k}`) };
  }
  return { shape: { r, xf: { p: { x: px, y: py }, q: { c, s } }, vertices }, next: i + 7 + 2 * n };
}

// "A ... B ..." from index i: {a, b, next}.
function readCase(t, i) {
  const A = readShape(t, i, 'A');
  const B = readShape(t, A.next, 'B');
  return { a: A.shape, b: B.shape, next: B.next };
}

// A shape prepared once, in its own frame: its planck DistanceProxy.
function prepare(shape) {
  const vertices = shape.vertices.map((v) => planck.Vec2(v.x, v.y));
  const proxy = new planck.DistanceProxy();
  proxy.setVertices(vertices, vertices.length, shape.r);
  return proxy;
}

// One query on two prepared shapes and the case's transforms, the same inside and outside the
// timed loop.
const input = new planck.DistanceInput();
const output = new planck.DistanceOutput();
function query(proxyA, xfA, proxyB, xfB) {
  input.proxyA = proxyA;
  input.proxyB = proxyB;
  input.transformA.set(xfA);
  input.transformB.set(xfB);
  input.useRadii = true;
  planck.Distance(output, new planck.SimplexCache(), input);
  return output;
}

function refusal(c) {
  if (c.a.vertices.length < 1 || c.b.vertices.length < 1) return 'a shape without points';
  return null;
}

function answer(t) {
  const id = t[1];
  if (!/^[0-9]+$/.test(id || '')) {
    process.stderr.write(`gjk2d-planck: request without an id: "${t.join(' ').slice(0, 80)}"\n`);
    return;
  }
  try {
    if (t[2] !== IMPL) return say(`error ${id} unknown implementation "${t[2]}"`);
    if (t[0] === 'distance') {
      const c = readCase(t, 3);
      if (c.next !== t.length) throw new RequestError(`${t.length - c.next} tokens after shape B`);
      const why = refusal(c);
      if (why) return say(`refused ${id} ${why}`);
      const o = query(prepare(c.a), c.a.xf, prepare(c.b), c.b.xf);
      return say(
        `ok ${id} ${o.distance} ${o.pointA.x} ${o.pointA.y} ${o.pointB.x} ${o.pointB.y} ${o.iterations}`,
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
        const why = refusal(c);
        if (why) return say(`refused ${id} case ${k + 1}: ${why}`);
        cases.push(c);
        i = c.next;
      }
      if (i !== t.length) throw new RequestError(`${t.length - i} tokens after case ${m}`);
      const proxiesA = new Array(m);
      const proxiesB = new Array(m);
      const prepStart = process.hrtime.bigint();
      for (let k = 0; k < m; ++k) {
        proxiesA[k] = prepare(cases[k].a);
        proxiesB[k] = prepare(cases[k].b);
      }
      const prepared = process.hrtime.bigint() - prepStart;
      let sink = 0;
      const start = process.hrtime.bigint();
      for (let round = 0; round < K; ++round) {
        for (let k = 0; k < m; ++k)
          sink += query(proxiesA[k], cases[k].a.xf, proxiesB[k], cases[k].b.xf).distance;
      }
      const total = process.hrtime.bigint() - start;
      if (sink === -1) process.stderr.write('\n'); // keeps the loop's results alive
      return say(`timed ${id} ${total} ${prepared}`);
    }
    return say(`error ${id} unknown request "${t[0]}"`);
  } catch (e) {
    // planck threw (e.g. a TypeError on NaN input): the case is an error, the stream goes on.
    const what = e instanceof RequestError ? e.message : `planck threw ${e.name}: ${e.message}`;
    return say(`error ${id} ${String(what).replace(/\s+/g, ' ')}`);
  }
}

let handshaken = false;
const rl = readline.createInterface({ input: process.stdin, crlfDelay: Infinity, terminal: false });
rl.on('line', (line) => {
  const t = line.trim().split(/ +/);
  if (t.length === 1 && t[0] === '') return;
  if (!handshaken) {
    // We speak version 2 whatever the host asks: the host judges a mismatch (the protocol's rule).
    if (t[0] !== 'gjk2d-adapter')
      process.stderr.write(`gjk2d-planck: expected the handshake, got "${line.slice(0, 80)}"\n`);
    say('gjk2d-adapter 2');
    say(`library planck.js ${VERSION}`);
    say(
      `implementation ${IMPL} double radius 0 planck.js ${VERSION} Distance (DistanceProxy.setVertices), cold SimplexCache, useRadii`,
    );
    CONTRACT.forEach(say);
    say(`prepared ${IMPL} shape`);
    say('ready');
    handshaken = true;
    return;
  }
  answer(t);
});
