// planck.js's Distance on one case: a standalone reproduction, with nothing of gjk2d in it.
// Written by gjk2d's `gjk-validate repro` (docs/peers.md, "Repro programs"):
//   gjk-validate repro --family hard/touching-edge:24 --seed 1 hard/touching-edge/15-slanted-partial-rot --variants planck-1.5.0 --no-default-plugins --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-float.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-double.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-fcl.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-geos --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-jolt --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-planck --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-rapier --out /work/wt-issue55-runner/docs/peers/repro
// Run it with planck 1.5.0 where Node's require("planck") finds it; from a gjk2d checkout, whose
// scripts/setup_npm.sh installs planck into build/npm/planck/node_modules:
//   NODE_PATH=build/npm/planck/node_modules node planck-1.5.0-hard-touching-edge-15-slanted-partial-rot.js
// from an installed gjk2d, NODE_PATH=<prefix>/lib/gjk2d/plugins/planck/node_modules; or after
// `npm install planck@1.5.0` beside this file, node planck-1.5.0-hard-touching-edge-15-slanted-partial-rot.js.
//
// The case: hard/touching-edge/15-slanted-partial-rot (family hard/touching-edge). Each number is the shortest decimal that reads back as the
// same double: JavaScript reads a decimal literal correctly rounded to the nearest double, so
// planck gets the very bits gjk-validate gave it.
// The call, as gjk2d's adapter (validation/plugins/planck/adapter.js) and a planck user make it:
// DistanceProxy.setVertices with each shape's points in its local frame and its radius,
// Transform.set({p, q: {c, s}}) with the case's (c, s) as given, useRadii = true, and a fresh
// SimplexCache (a cold start). The world frame: world = R * local + p, R = [[c, -s], [s, c]].
"use strict";

const planck = require("planck");
// planck's exports map hides "planck/package.json": read it beside dist/planck.js.
const path = require("path");
const VERSION = JSON.parse(
  require("fs").readFileSync(path.join(require.resolve("planck"), "..", "..", "package.json"), "utf8"),
).version;

const A = {
  radius: 0.0,
  p: { x: 129575.875, y: 127509.375 },
  q: { c: -0.9263932011772104, s: -0.37655761420085604 },
  points: [0.0, 0.0, 2.0, 0.0, 0.0, 2.0],
};
const B = {
  radius: 0.0,
  p: { x: 129575.875, y: 127509.375 },
  q: { c: -0.9263932011772104, s: -0.37655761420085604 },
  points: [1.5, 0.5, 2.5, -0.5, 2.5, 1.5],
};

// The exact answer for these inputs (gjk2d's CGAL/GMP ground truth), correctly rounded to double.
// On overlap the shapes share points: no pair of nearest points is unique, and the exact side's
// witness is one common point.
const exact = {
  distance: 0,
  overlap: true,
  pointA: [129574.4565305361, 127508.4386062426],
  pointB: [129574.4565305361, 127508.4386062426],
};

function vertices(flat) {
  const v = [];
  for (let i = 0; i < flat.length; i += 2) v.push({ x: flat[i], y: flat[i + 1] });
  return v;
}

function distance(useRadii) {
  const input = new planck.DistanceInput();
  const output = new planck.DistanceOutput();
  const a = vertices(A.points);
  const b = vertices(B.points);
  input.proxyA.setVertices(a, a.length, A.radius);
  input.proxyB.setVertices(b, b.length, B.radius);
  input.transformA.set({ p: A.p, q: A.q });
  input.transformB.set({ p: B.p, q: B.q });
  input.useRadii = useRadii;
  planck.Distance(output, new planck.SimplexCache(), input);
  return output;
}

// A double as C's printf %a writes it, so that the bits can be compared.
function hex(x) {
  if (!Number.isFinite(x)) return String(x).toLowerCase();
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  const hi = view.getUint32(0);
  const lo = view.getUint32(4);
  const sign = hi >>> 31 ? "-" : "";
  const e = (hi >>> 20) & 0x7ff;
  const digits = ((BigInt(hi & 0xfffff) << 32n) | BigInt(lo)).toString(16).padStart(13, "0").replace(/0+$/, "");
  const frac = digits ? "." + digits : "";
  if (e === 0) return digits ? `${sign}0x0${frac}p-1022` : `${sign}0x0p+0`;
  const p = e - 1023;
  return `${sign}0x1${frac}p${p >= 0 ? "+" : ""}${p}`;
}

const pt = (p) => `${p.x} ${p.y} ${hex(p.x)} ${hex(p.y)}`;

const out = distance(true);
console.log(`planck ${VERSION} Distance on hard/touching-edge/15-slanted-partial-rot, useRadii = true (gjk-validate reported 0, (0, 1.4551915228366852e-11), (0, 1.4551915228366852e-11)):`);
console.log(`answer distance ${out.distance} ${hex(out.distance)}`);
console.log(`answer pointA ${pt(out.pointA)}`);
console.log(`answer pointB ${pt(out.pointB)}`);
console.log(`answer iterations ${out.iterations}`);
console.log(`exact distance ${exact.distance}${exact.overlap ? " (the shapes overlap)" : ""}`);
console.log(`exact pointA ${exact.pointA[0]} ${exact.pointA[1]}${exact.overlap ? " (a common point)" : ""}`);
console.log(`exact pointB ${exact.pointB[0]} ${exact.pointB[1]}`);
// The same query without radii: the cores' own nearest points, whose midpoint is where planck's
// comment "Move the witness points to the middle" (src/collision/Distance.ts) puts both points
// when the rounded shapes overlap, as Box2D 2.4.1's b2Distance does.
const core = distance(false);
const rA = A.radius;
const rB = B.radius;
if (core.distance <= rA + rB || core.distance <= 1e-9) {
  const mid = { x: 0.5 * (core.pointA.x + core.pointB.x), y: 0.5 * (core.pointA.y + core.pointB.y) };
  console.log(`cores (useRadii = false): distance ${core.distance}, pointA ${core.pointA.x} ${core.pointA.y}, pointB ${core.pointB.x} ${core.pointB.y}`);
  console.log(`the middle, where both points belong: ${mid.x} ${mid.y}`);
}
