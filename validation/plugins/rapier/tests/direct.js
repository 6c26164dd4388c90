// Rapier's own API on a file of cases, with nothing of gjk2d in it: the program the report's Rapier
// answers are checked against, bit for bit (direct_check.py). It reads JSON from the file named
// by its argument, {"cases": [{"name", "a": {"points": [[x, y], ...], "radius"}, "b": ...}]}, each
// shape's WORLD points and radius as f32 values, and prints one line per case:
//   <name> <distance> <p1.x> <p1.y> <p2.x> <p2.y>     each as the double's 16 hexadecimal digits
//   <name> none <why>                                 when Rapier builds no shape (or the bindings
//                                                     have none: a rounded segment), answers null
//                                                     or throws
// The calls are a Rapier user's: 3 or more points a ConvexPolygon(points, false) (Rapier's convex
// hull), or a RoundConvexPolygon(points, radius, false); 1 point a Ball(radius) at that point; 2
// points a Segment; each at angle 0; shapeA.contactShape(posA, 0, shapeB, posB, 0, prediction)
// with the f32 maximum as prediction.
//   NODE_PATH=build/npm/rapier/node_modules node direct.js cases.json
'use strict';

const fs = require('fs');
const RAPIER = require('@dimforge/rapier2d-compat');

const PREDICTION = 3.4028234663852886e38; // f32::MAX

function bits(x) {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  return view.getBigUint64(0).toString(16).padStart(16, '0');
}

function build(s) {
  const n = s.points.length;
  if (n === 1)
    return { shape: new RAPIER.Ball(s.radius), at: { x: s.points[0][0], y: s.points[0][1] } };
  const at = { x: 0, y: 0 };
  if (n === 2) {
    if (s.radius > 0) return null; // the bindings have no rounded segment with free end points
    const [p, q] = s.points;
    return { shape: new RAPIER.Segment({ x: p[0], y: p[1] }, { x: q[0], y: q[1] }), at };
  }
  const v = new Float32Array(s.points.flat());
  const shape =
    s.radius > 0
      ? new RAPIER.RoundConvexPolygon(v, s.radius, false)
      : new RAPIER.ConvexPolygon(v, false);
  const raw = shape.intoRaw(); // what contactShape builds from it; undefined: Rapier builds none
  if (!raw) return null;
  raw.free();
  return { shape, at };
}

RAPIER.init().then(() => {
  const { cases } = JSON.parse(fs.readFileSync(process.argv[2], 'utf8'));
  const out = [];
  for (const c of cases) {
    let a, b, r;
    try {
      a = build(c.a);
      b = build(c.b);
      if (a && b) r = a.shape.contactShape(a.at, 0, b.shape, b.at, 0, PREDICTION);
    } catch (e) {
      // Rapier threw: a WebAssembly trap (a Rust panic), e.g. in its convex hull.
      out.push(`${c.name} none threw ${e.name}: ${e.message}`.replace(/\s+/g, ' '));
      continue;
    }
    if (!a || !b) {
      out.push(`${c.name} none no shape`);
      continue;
    }
    if (!r) {
      out.push(`${c.name} none null`);
      continue;
    }
    out.push(
      [c.name, r.distance, r.point1.x, r.point1.y, r.point2.x, r.point2.y]
        .map((v, i) => (i ? bits(v) : v))
        .join(' '),
    );
  }
  process.stdout.write(out.join('\n') + '\n');
});
