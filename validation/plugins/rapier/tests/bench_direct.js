// What a Rapier contact query costs its user, measured with Rapier's API alone (docs/peers/rapier.md, "Cost"): Shape.contactShape, which the adapter calls, beside its parts and
// beside Collider.contactCollider, which answers the same query on shapes a World keeps. Two unit
// squares 3 apart (world points, angle 0), as the adapter's time request builds them; each figure
// the median of 5 runs of N calls after 2000 warm-up calls.
//   NODE_PATH=build/npm/rapier/node_modules node validation/plugins/rapier/tests/bench_direct.js
'use strict';

const RAPIER = require('@dimforge/rapier2d-compat');

const PREDICTION = 3.4028234663852886e38;
const N = 20000;

function median(f) {
  for (let i = 0; i < 2000; ++i) f();
  const runs = [];
  for (let r = 0; r < 5; ++r) {
    const t0 = process.hrtime.bigint();
    for (let i = 0; i < N; ++i) f();
    runs.push(Number(process.hrtime.bigint() - t0) / N);
  }
  return runs.sort((x, y) => x - y)[2];
}

RAPIER.init().then(() => {
  const square = (cx) =>
    new Float32Array([cx - 0.5, -0.5, cx + 0.5, -0.5, cx + 0.5, 0.5, cx - 0.5, 0.5]);
  const at = { x: 0, y: 0 };
  const a = new RAPIER.ConvexPolygon(square(0), false);
  const b = new RAPIER.ConvexPolygon(square(4), false);
  const target = new RAPIER.ShapeContact(
    0,
    { x: 0, y: 0 },
    { x: 0, y: 0 },
    { x: 0, y: 0 },
    { x: 0, y: 0 },
  );
  const world = new RAPIER.World({ x: 0, y: 0 });
  const ca = world.createCollider(RAPIER.ColliderDesc.convexHull(square(0)));
  const cb = world.createCollider(RAPIER.ColliderDesc.convexHull(square(4)));
  const one = a.contactShape(at, 0, b, at, 0, PREDICTION);
  const two = ca.contactCollider(cb, PREDICTION);
  console.log(`Rapier ${RAPIER.version()}, node ${process.version}`);
  console.log(`contactShape ${JSON.stringify(one)}`);
  console.log(`contactCollider ${JSON.stringify(two)}`);
  const rows = [
    [
      "Shape.contactShape (the adapter's query)",
      () => a.contactShape(at, 0, b, at, 0, PREDICTION, target),
    ],
    [
      '  of which ConvexPolygon.intoRaw() + free(), twice',
      () => (a.intoRaw().free(), b.intoRaw().free()),
    ],
    [
      '  of which the 4 RawVector / RawRotation + free()',
      () => {
        for (let k = 0; k < 2; ++k) {
          RAPIER.VectorOps.intoRaw(at).free();
          RAPIER.RotationOps.intoRaw(0).free();
        }
      },
    ],
    [
      'Collider.contactCollider (shapes kept in a World)',
      () => ca.contactCollider(cb, PREDICTION, target),
    ],
  ];
  for (const [what, f] of rows) console.log(`${median(f).toFixed(0).padStart(7)} ns  ${what}`);
});
