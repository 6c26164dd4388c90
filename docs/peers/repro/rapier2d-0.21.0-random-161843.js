// Rapier's Shape.contactShape on one case: a standalone reproduction, with nothing of gjk2d in it.
// Written by gjk2d's `gjk-validate repro` (docs/peers.md, "Repro programs"):
//   gjk-validate repro --family random:200000 --seed 1 random/161843 --variants rapier2d-0.21.0 --no-default-plugins --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-float.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-double.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-fcl.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-geos --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-jolt --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-planck --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-rapier --out /work/wt-issue55-runner/docs/peers/repro
// Run it with @dimforge/rapier2d-compat 0.21.0 where Node's require() finds it; from a gjk2d
// checkout, whose scripts/setup_npm.sh installs it into build/npm/rapier/node_modules:
//   NODE_PATH=build/npm/rapier/node_modules node rapier2d-0.21.0-random-161843.js
// from an installed gjk2d, NODE_PATH=<prefix>/lib/gjk2d/plugins/rapier/node_modules; or after
// `npm install @dimforge/rapier2d-compat@0.21.0` beside this file, node rapier2d-0.21.0-random-161843.js.
//
// The case: random/161843 (family random), as Rapier is given it (float): each shape's WORLD points,
// the case's transform applied in double and rounded to f32, with the identity transform, since
// Rapier takes a rotation only as an f32 angle. Each number is the shortest decimal that reads back
// as the same f32: JavaScript reads it as the nearest double, and Math.fround below rounds that to
// the nearest f32, the one gjk-validate gave the adapter (Rapier's Float32Array and its f32
// arguments would round it the same way).
// The call, as gjk2d's adapter (validation/plugins/rapier/adapter.js) makes it: 3 or more points a
// ConvexPolygon(points, false) (Rapier computes the convex hull), or a RoundConvexPolygon(points,
// radius, false) for a radius; 1 point a Ball(radius) placed at the point; 2 points a Segment; each
// placed at angle 0; then shapeA.contactShape(posA, 0, shapeB, posB, 0, prediction) with the f32
// maximum as prediction, so that no finite distance is cut off. The answer is in world
// coordinates; its distance is negative when the shapes penetrate.
"use strict";

const RAPIER = require("@dimforge/rapier2d-compat");

const A = {
  radius: 0.0,
  p: { x: 0.0, y: 0.0 },
  q: { c: 1.0, s: 0.0 },
  points: [-1.9016653, 0.05155654, -1.9125841, -0.731083, -1.0644546, -1.7867297, -0.90342355, -1.8543471, -0.5720181, 1.2112192, -1.7413104, 0.43598896, -1.8466358, 0.21827303, -1.8490443, 0.21210223],
};
const B = {
  radius: 0.0,
  p: { x: 0.0, y: 0.0 },
  q: { c: 1.0, s: 0.0 },
  points: [0.14943437, -0.53773344, 0.15856938, -0.43149143, 0.11218361, -0.16719632, -0.02126089, 0.055609897, -0.06153423, 0.09799528, -0.67101026, 0.29552317],
};

// The exact answer for these inputs (gjk2d's CGAL/GMP ground truth), correctly rounded to double:
// the distance (0 on overlap, where the shapes share points), and for a penetration contract the
// signed distance (minus the depth) and a penetration pair.
const exact = {
  distance: 0,
  overlap: true,
  pointA: [-0.6710101400124012, 0.2955230490469579],
  pointB: [-0.6710101400124012, 0.2955230490469579],
  signed: true,
  signedDistance: -1.2777101666046371e-07,
  penetrationA: [-0.6710101287827219, 0.2955231529237211],
  penetrationB: [-0.6710102558135986, 0.29552316665649414],
};

const PREDICTION = 3.4028234663852886e38; // f32::MAX

function shape(given, name) {
  const s = { ...given, radius: Math.fround(given.radius), points: given.points.map(Math.fround) };
  const identity = s.q.c === 1 && s.q.s === 0 && s.p.x === 0 && s.p.y === 0;
  if (!identity) {
    // Rapier would need the rotation as an f32 angle: another transform than (c, s).
    console.error(`shape ${name}: its transform is not the identity; this program takes world points`);
    process.exit(1);
  }
  const n = s.points.length / 2;
  if (n === 1) return { shape: new RAPIER.Ball(s.radius), at: { x: s.points[0], y: s.points[1] } };
  const at = { x: 0, y: 0 };
  if (n === 2) return { shape: new RAPIER.Segment({ x: s.points[0], y: s.points[1] }, { x: s.points[2], y: s.points[3] }), at };
  const v = new Float32Array(s.points);
  return { shape: s.radius > 0 ? new RAPIER.RoundConvexPolygon(v, s.radius, false) : new RAPIER.ConvexPolygon(v, false), at };
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

RAPIER.init().then(() => {
  const a = shape(A, "A");
  const b = shape(B, "B");
  const c = a.shape.contactShape(a.at, 0, b.shape, b.at, 0, PREDICTION);
  console.log(`Rapier ${RAPIER.version()} Shape.contactShape on random/161843 (gjk-validate reported -1.1920928955078125e-07, (-0.903423547744751, -1.8543471097946167), (-0.6710102558135986, 0.29552316665649414)):`);
  if (!c) {
    console.log("answer none: contactShape returned null");
  } else {
    console.log(`answer distance ${c.distance} ${hex(c.distance)}`);
    console.log(`answer pointA ${pt(c.point1)}`);
    console.log(`answer pointB ${pt(c.point2)}`);
    console.log(`answer normal1 ${c.normal1.x} ${c.normal1.y}`);
  }
  console.log(`exact distance ${exact.distance}${exact.overlap ? " (the shapes overlap)" : ""}`);
  console.log(`exact pointA ${exact.pointA[0]} ${exact.pointA[1]}${exact.overlap ? " (a common point)" : ""}`);
  console.log(`exact pointB ${exact.pointB[0]} ${exact.pointB[1]}`);
  if (exact.signed && exact.overlap) {
    console.log(`exact signed distance ${exact.signedDistance} (minus the penetration depth)`);
    console.log(`exact penetration pair ${exact.penetrationA[0]} ${exact.penetrationA[1]}, ${exact.penetrationB[0]} ${exact.penetrationB[1]}`);
  }
});
