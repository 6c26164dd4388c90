#!/usr/bin/python3
"""GEOS's distance and nearest points (through shapely) on one case: a standalone reproduction,
with nothing of gjk2d in it. Written by gjk2d's `gjk-validate repro` (docs/peers.md, "Repro
programs"):
  gjk-validate repro --family hard/extreme-scale:244 --seed 1 hard/extreme-scale/168-deep-overlap-1e160 --variants geos-3.11.1 --no-default-plugins --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-float.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-double.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-fcl.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-geos --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-jolt --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-planck --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-rapier --out /work/wt-issue55-runner/docs/peers/repro
Run it with Debian's python3 and python3-shapely (shapely 1.8, GEOS 3.11 on Debian 12):
  /usr/bin/python3 geos-3.11.1-hard-extreme-scale-168-deep-overlap-1e160.py

The case: hard/extreme-scale/168-deep-overlap-1e160 (family hard/extreme-scale), variant geos-3.11.1. Each number is the shortest decimal that
reads back as the same double: Python reads a float literal correctly rounded to the nearest
double, so GEOS gets the very bits gjk-validate gave it.

The call, as gjk2d's adapter (validation/plugins/geos/adapter.py) and a shapely user make it: each
shape in its local frame (1 point: Point, 2: LineString, more: MultiPoint(points).convex_hull),
placed with shapely.affinity.affine_transform(g, [c, -s, s, c, px, py]) (world = R * local + p, the
case's (c, s) as given); the core distance g_a.distance(g_b) and the points
shapely.ops.nearest_points(g_a, g_b). GEOS has no rounded shapes: with core distance d and radii
rA, rB, the adapter answers d - (rA + rB) with each point moved toward the other by its radius when
d > rA + rB, else distance 0 and both points at pA + rA / (rA + rB) (pB - pA).
"""
from shapely.affinity import affine_transform
from shapely.geometry import LineString, MultiPoint, Point
from shapely.ops import nearest_points

try:  # shapely 1.8 (Debian 12)
    from shapely.geos import geos_version
except ImportError:  # shapely 2
    from shapely import geos_version

# (radius, px, py, c, s, [x0, y0, x1, y1, ...])
A = (0.0, -9.703210363565624e+159, -3.528123437796103e+159, -0.6274015986463785, 0.7786958546287303, [1.4811563157222603e+160, 3.863987722154846e+157, 1.4174632401244792e+160, 4.2969398983563954e+159, -3.39467285135651e+159, 1.4417353863756305e+160, -1.3107764505524495e+160, 6.8971302632484686e+159, -1.1937223948903382e+160, -8.768499335361399e+159, -2.234279510522326e+159, -1.4642127279509826e+160])
B = (0.0, -1.2066349859988883e+160, -3.651801777344039e+159, -0.021859261638348754, 0.9997610577936241, [1.0578501939336833e+160, 1.0880155708452244e+160, -6.0113451085226255e+159, 1.3933636334674455e+160, -1.0305618787914415e+160, 1.1138972704828059e+160, -1.3688502659165798e+160, 6.550373002412147e+159, -1.42919863690436e+160, 5.101138808912279e+159, -1.460091093673809e+160, 4.134717806351611e+159])

# The exact answer for these inputs (gjk2d's CGAL/GMP ground truth), correctly rounded to double.
# On overlap the shapes share points: no pair of nearest points is unique, and the exact side's
# witness is one common point.
EXACT_DISTANCE = 0
EXACT_OVERLAP = 'true' == 'true'
EXACT_A = (-1.886958747825194e+160, -8.085696602902303e+159)
EXACT_B = (-1.886958747825194e+160, -8.085696602902303e+159)


def geometry(shape):
    r, px, py, c, s, flat = shape
    points = list(zip(flat[0::2], flat[1::2]))
    if len(points) == 1:
        local = Point(points[0])
    elif len(points) == 2:
        local = LineString(points)
    else:
        local = MultiPoint(points).convex_hull
    return affine_transform(local, [c, -s, s, c, px, py])


def distance(a, b):
    ga, gb = geometry(a), geometry(b)
    d = ga.distance(gb)
    pa, pb = nearest_points(ga, gb)
    ax, ay, bx, by = pa.x, pa.y, pb.x, pb.y
    ra, rb = a[0], b[0]
    if (ra == 0 and rb == 0) or d != d:
        return d, ax, ay, bx, by
    if d > ra + rb:
        ux, uy = (bx - ax) / d, (by - ay) / d
        return d - (ra + rb), ax + ra * ux, ay + ra * uy, bx - rb * ux, by - rb * uy
    w = ra / (ra + rb)
    qx, qy = ax + w * (bx - ax), ay + w * (by - ay)
    return 0.0, qx, qy, qx, qy


d, ax, ay, bx, by = distance(A, B)
print(f'GEOS {".".join(map(str, geos_version))} distance and nearest_points on hard/extreme-scale/168-deep-overlap-1e160:')
print(f'answer distance {d!r} {d.hex()}')
print(f'answer pointA {ax!r} {ay!r} {ax.hex()} {ay.hex()}')
print(f'answer pointB {bx!r} {by!r} {bx.hex()} {by.hex()}')
print(f'exact distance {EXACT_DISTANCE!r}{" (the shapes overlap)" if EXACT_OVERLAP else ""}')
print(f'exact pointA {EXACT_A[0]!r} {EXACT_A[1]!r}{" (a common point)" if EXACT_OVERLAP else ""}')
print(f'exact pointB {EXACT_B[0]!r} {EXACT_B[1]!r}')
