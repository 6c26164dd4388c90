// Jolt Physics's CollideShape on one case: a standalone reproduction, with nothing of gjk2d in it.
// Written by gjk2d's `gjk-validate repro` (docs/peers.md, "Repro programs"):
//   gjk-validate repro --family random:200000 --seed 1 random/51418 --variants jolt-1.1.0 --no-default-plugins --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-float.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-double.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-fcl.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-geos --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-jolt --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-planck --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-rapier --out /work/wt-issue55-runner/docs/peers/repro
// Run it with jolt-physics 1.1.0 (npm; Jolt Physics v5.6.0 in WebAssembly) where Node's
// require.resolve("jolt-physics/wasm-compat") finds it; from a gjk2d checkout, whose
// scripts/setup_npm.sh installs it into build/npm/jolt/node_modules:
//   NODE_PATH=build/npm/jolt/node_modules node jolt-1.1.0-random-51418.js
// from an installed gjk2d, NODE_PATH=<prefix>/lib/gjk2d/plugins/jolt/node_modules; or after
// `npm install jolt-physics@1.1.0` beside this file, node jolt-1.1.0-random-51418.js.
//
// The case: random/51418 (family random), as the variant jolt-1.1.0 is given it: each shape's world
// points, rounded to float (each number below is the shortest decimal that reads back as the same
// float: JavaScript reads it as the nearest double, and world() rounds that to float, Math.fround,
// which gives the float back). When a shape's transform below is not the identity, its world points
// are made here as gjk-validate makes them: x' = (c x - s y) + px, y' = (s x + c y) + py, each
// operation rounded to double, then to float.
// The call, as gjk2d's adapter (validation/plugins/jolt/adapter.js) makes it: each 2D shape as the
// prism P x [-h, h], a ConvexHullShape of its 2n points with mMaxConvexRadius = 0 and
// mHullTolerance = 0, at body position 0 with the identity rotation (Jolt places it by its centre
// of mass); h = HEIGHT_FACTOR (eA + eB), e a shape's bounding-box width plus height, rounded up to
// float. Shape A is the query shape, B a TransformedShape; TransformedShape::CollideShape, base
// offset 0, a closest-hit collector, first with Jolt's default CollideShapeSettings
// (mMaxSeparationDistance 0: overlaps), and when that finds nothing again with
// mMaxSeparationDistance = U (1 + 1/8), at least h / 2^20, rounded up to float, U the least
// distance from a point of one shape to an edge of the other (at least the distance). The
// distance is -mPenetrationDepth, the witness points the x, y of mContactPointOn1 and
// mContactPointOn2.
"use strict";

const path = require("path");
const url = require("url");
const VERSION = require("jolt-physics/package.json").version;
const HEIGHT_FACTOR = 2;
const MAX_SEPARATION_SLACK = 1 + 1 / 8;
const MIN_SEPARATION = 2 ** -20;

const A = {
  p: [0.0, 0.0],
  q: [1.0, 0.0],
  points: [-4.2382464, -3.4984365, -4.2312856, -3.5291846, -2.1084945, -4.4862595],
};
const B = {
  p: [0.0, 0.0],
  q: [1.0, 0.0],
  points: [-4.92387, -5.2684593, -4.3255467, -4.3995814, -4.232035, -3.5135028, -8.127391, -4.1489596, -6.6521688, -5.6752534],
};

// The exact answer for these inputs (gjk2d's CGAL/GMP ground truth), correctly rounded to double:
// the distance, and for overlapping shapes the signed distance (minus the penetration depth) with
// a penetration pair, each point on its own shape.
const exact = {
  distance: 0,
  overlap: true,
  pointA: [-4.234364612336674, -3.515583586960036],
  pointB: [-4.234364612336674, -3.515583586960036],
  signed: true,
  signedDistance: -0.002731383376879681,
  penetrationA: [-4.2346991327265995, -3.5141059156650787],
  penetrationB: [-4.232035160064697, -3.513502836227417],
};

// World points, rounded to float, as gjk-validate hands them to the variant.
function world(s) {
  const [c, sn] = s.q;
  const out = [];
  for (let i = 0; i < s.points.length; i += 2) {
    const x = s.points[i];
    const y = s.points[i + 1];
    out.push([Math.fround(c * x - sn * y + s.p[0]), Math.fround(sn * x + c * y + s.p[1])]);
  }
  return out;
}

// The smallest float >= x.
function floatUp(x) {
  const f = Math.fround(x);
  if (f >= x) return f;
  const view = new DataView(new ArrayBuffer(4));
  view.setFloat32(0, f);
  view.setUint32(0, view.getUint32(0) + 1);
  return view.getFloat32(0);
}

function extent(points) {
  const xs = points.map((p) => p[0]);
  const ys = points.map((p) => p[1]);
  return Math.max(...xs) - Math.min(...xs) + (Math.max(...ys) - Math.min(...ys));
}

// The least distance from a point of one shape to a segment between consecutive points of the
// other, both ways: at least the shapes' distance.
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

(async () => {
  const file = require.resolve("jolt-physics/wasm-compat");
  const J = await (await import(url.pathToFileURL(file).href)).default();
  // JoltInterface's constructor calls RegisterTypes(), which fills the collision dispatch table.
  const objectFilter = new J.ObjectLayerPairFilterTable(1);
  objectFilter.EnableCollision(0, 0);
  const layer = new J.BroadPhaseLayer(0);
  const bpInterface = new J.BroadPhaseLayerInterfaceTable(1, 1);
  bpInterface.MapObjectToBroadPhaseLayer(0, layer);
  const settings = new J.JoltSettings();
  settings.mObjectLayerPairFilter = objectFilter;
  settings.mBroadPhaseLayerInterface = bpInterface;
  settings.mObjectVsBroadPhaseLayerFilter = new J.ObjectVsBroadPhaseLayerFilterTable(bpInterface, 1, objectFilter, 1);
  settings.mMaxWorkerThreads = 0;
  new J.JoltInterface(settings);

  const a = world(A);
  const b = world(B);
  const h = floatUp(HEIGHT_FACTOR * (extent(a) + extent(b)));
  const unit = new J.Vec3(1, 1, 1);
  const origin = new J.RVec3(0, 0, 0);
  function prism(points) {
    const s = new J.ConvexHullShapeSettings();
    s.mMaxConvexRadius = 0;
    s.mHullTolerance = 0;
    for (const [x, y] of points) {
      s.mPoints.push_back(new J.Vec3(x, y, -h));
      s.mPoints.push_back(new J.Vec3(x, y, h));
    }
    const result = s.Create();
    if (result.HasError()) throw new Error(`ConvexHullShapeSettings::Create: ${result.GetError().c_str()}`);
    const shape = result.Get();
    const ts = new J.TransformedShape();
    ts.mShape = shape;
    ts.SetWorldTransform(origin, J.Quat.prototype.sIdentity(), unit);
    const com = shape.GetCenterOfMass();
    return { ts, shape, com: [com.GetX(), com.GetY(), com.GetZ()] };
  }
  const pa = prism(a);
  const pb = prism(b);
  const collector = new J.CollideShapeClosestHitCollisionCollector();
  const comA = pa.ts.GetCenterOfMassTransform();
  let query = new J.CollideShapeSettings(); // Jolt's defaults: mMaxSeparationDistance 0
  pb.ts.CollideShape(pa.shape, unit, comA, query, origin, collector, new J.ShapeFilter());
  if (!collector.HadHit()) {
    query = new J.CollideShapeSettings();
    query.mMaxSeparationDistance = floatUp(Math.max(reachBound(a, b) * MAX_SEPARATION_SLACK, h * MIN_SEPARATION));
    collector.Reset();
    pb.ts.CollideShape(pa.shape, unit, comA, query, origin, collector, new J.ShapeFilter());
  }

  console.log(`jolt-physics ${VERSION} CollideShape on random/51418 (gjk-validate reported -3.3362457752227783, (-4.23444938659668, -3.5152082443237305), (-4.232035160064697, -3.513502836227417)):`);
  console.log(`prisms: half height ${h}, centres of mass A (${pa.com.join(", ")}), B (${pb.com.join(", ")}); mMaxSeparationDistance ${query.mMaxSeparationDistance}`);
  if (!collector.HadHit()) {
    console.log("answer: no hit");
  } else {
    const hit = collector.mHit;
    const d = -hit.mPenetrationDepth;
    const p1 = hit.mContactPointOn1;
    const p2 = hit.mContactPointOn2;
    const axis = hit.mPenetrationAxis;
    console.log(`answer distance ${d} ${hex(d)}`);
    console.log(`answer pointA ${p1.GetX()} ${p1.GetY()} (z ${p1.GetZ()}) ${hex(p1.GetX())} ${hex(p1.GetY())}`);
    console.log(`answer pointB ${p2.GetX()} ${p2.GetY()} (z ${p2.GetZ()}) ${hex(p2.GetX())} ${hex(p2.GetY())}`);
    console.log(`answer penetration axis ${axis.GetX()} ${axis.GetY()} ${axis.GetZ()}`);
  }
  console.log(`exact distance ${exact.distance}${exact.overlap ? " (the shapes overlap)" : ""}`);
  if (exact.signed) {
    console.log(`exact signed distance ${exact.signedDistance}`);
    console.log(`exact penetration pair ${exact.penetrationA.join(" ")}, ${exact.penetrationB.join(" ")}`);
  } else {
    console.log(`exact pointA ${exact.pointA.join(" ")}`);
    console.log(`exact pointB ${exact.pointB.join(" ")}`);
  }
})();
