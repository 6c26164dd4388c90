#!/usr/bin/python3
"""The GEOS adapter: an executable adapter (protocol version 2, docs/peers/geos.md)
for GEOS's distance through shapely, run by Debian's /usr/bin/python3 (python3-shapely 1.8.5,
GEOS 3.11.1 on Debian 12).

What a Python user would write, and what it takes:
- each shape is built in its local frame as shapely would be used: 1 point -> Point, 2 points ->
  LineString, 3 or more -> MultiPoint(points).convex_hull (the case's points are a convex set but
  may be out of order or degenerate; the hull is a Polygon, or a LineString / Point when they are
  collinear / equal), then placed with shapely.affinity.affine_transform(g, [c, -s, s, c, px, py])
  (world = R local + p, (c, s) as given, not renormalised);
- the core distance is g_a.distance(g_b) (GEOS, double; 0 when a point of one is inside the other
  polygon), the witness points shapely.ops.nearest_points(g_a, g_b);
- radii: GEOS has no rounded shapes. With core distance d and radii rA, rB:
  d > rA + rB: distance d - (rA + rB), each witness moved along the segment between them, by rA
    (A's, toward B's) and rB (B's, toward A's): exact up to the rounding of that subtraction;
  d <= rA + rB: the rounded shapes overlap or touch, distance 0, and both witness points are the
    one point q = pA + rA / (rA + rB) (pB - pA) (q = pA when rA + rB = 0): |q - pA| = d rA/(rA + rB)
    <= rA and |pB - q| = d rB/(rA + rB) <= rB, so q lies in both rounded shapes (the overlap answer
    docs/validate-your-gjk.md asks for).
- iterations: GEOS does not say (-1). No vertex limit (0): GEOS takes any number of points.
It refuses only a shape without points (shapely cannot build one).

Prepared shapes (the handshake's `prepared ... case` line): GEOS works in world coordinates, so a
shape is prepared per case, its world geometry built once (geometry() above: the hull and the
affine transform), as a user who queries the same pair again keeps it; the query (query()) is
distance, nearest_points and the radii. A `time` request builds its 2m geometries once, timed
apart, before its timed loop of queries, and answers both figures; a `distance` request goes
through the same geometry() and query(), so what is judged is what is timed. No shapely
preparation: shapely.prepared.prep (1.8) and shapely.prepare (2.x) speed up predicates only
(shapely 2.0's reference, shapely.prepare: "contains, contains_properly, covered_by, covers,
crosses, disjoint, intersects, overlaps, touches, and within"), not distance or nearest_points.

The contract (the handshake's `contract` lines, CONTRACT below), read in GEOS 3.11.1 (libgeos/geos
tag 3.11.1) and shapely 1.8.5:
- overlap `common-point`: nearest_points (shapely/ops.py:328-332) is GEOS's DistanceOp, whose
  nearest points are "a pair of points in the input geometries which have the minimum distance
  between them" (include/geos/operation/distance/DistanceOp.h:53-61): on intersecting geometries
  they are 0 apart, one point of both (a vertex inside the other polygon: that vertex twice,
  src/operation/distance/DistanceOp.cpp:253-269). With radii, the point q above is in both
  rounded shapes;
- tolerance: none stated (DistanceOp.h:62-64 says only that a point inside a segment is "a close
  approximation to the exact point"); margin 0.
"""
import sys
import time

import shapely
from shapely.affinity import affine_transform
from shapely.geometry import LineString, MultiPoint, Point
from shapely.ops import nearest_points

try:  # shapely 1.8 (Debian 12)
    from shapely.geos import geos_version
except ImportError:  # shapely 2
    geos_version = shapely.geos_version

GEOS_VERSION = ".".join(str(v) for v in geos_version)
IMPL = f"geos-{GEOS_VERSION}"
# What GEOS promises (the module docstring): the handshake's `contract` lines, protocol version 2.
CONTRACT = [
    f"contract {IMPL} overlap common-point include/geos/operation/distance/DistanceOp.h:53-61 (the "
    'nearest points: "a pair of points in the input geometries which have the minimum distance between '
    'them"), src/operation/distance/DistanceOp.cpp:253-269 (a vertex inside the other polygon: both '
    "points at it), GEOS 3.11.1, via shapely 1.8.5 ops.nearest_points (shapely/ops.py:328-332)",
    f"contract {IMPL} tolerance none none",
    f"contract {IMPL} margin 0",
]


def say(line):
    sys.stdout.write(line + "\n")
    sys.stdout.flush()


class RequestError(Exception):
    pass


def read_shape(t, i, letter):
    """One shape "<r> <px> <py> <c> <s> <n> <x0> <y0> ..." after its letter at t[i]:
    ((r, px, py, c, s, points), next index)."""
    if i >= len(t) or t[i] != letter:
        raise RequestError(f'expected "{letter}" at token {i}')

    def num(k, what):
        if k >= len(t):
            raise RequestError(f"shape {letter}: missing {what}")
        try:
            return float(t[k])
        except ValueError:
            raise RequestError(f'shape {letter}: {what} "{t[k]}" is not a number') from None

    r, px, py, c, s = (num(i + 1 + k, w) for k, w in enumerate(("radius", "px", "py", "c", "s")))
    n = num(i + 6, "n")
    if n != int(n) or n < 0:
        raise RequestError(f'shape {letter}: n "{t[i + 6]}" is not a count')
    n = int(n)
    points = [(num(i + 7 + 2 * k, f"x{k}"), num(i + 8 + 2 * k, f"y{k}")) for k in range(n)]
    return (r, px, py, c, s, points), i + 7 + 2 * n


def read_case(t, i):
    a, i = read_shape(t, i, "A")
    b, i = read_shape(t, i, "B")
    return (a, b), i


def geometry(shape):
    """The shape as a shapely geometry in world coordinates (the module docstring's rules)."""
    r, px, py, c, s, points = shape
    if len(points) == 1:
        local = Point(points[0])
    elif len(points) == 2:
        local = LineString(points)
    else:
        local = MultiPoint(points).convex_hull
    return affine_transform(local, [c, -s, s, c, px, py])


def prepare(case):
    """The case's two shapes prepared: (world geometry, radius) each."""
    a, b = case
    return (geometry(a), a[0]), (geometry(b), b[0])


def query(prepared):
    """(distance, ax, ay, bx, by) of a prepared case: the work of one query, inside and outside
    the timed loop."""
    (ga, ra), (gb, rb) = prepared
    d = ga.distance(gb)
    pa, pb = nearest_points(ga, gb)
    ax, ay, bx, by = pa.x, pa.y, pb.x, pb.y
    if (ra == 0 and rb == 0) or d != d:  # no radii, or a NaN from NaN input: as GEOS gives it
        return d, ax, ay, bx, by
    if d > ra + rb:
        ux, uy = (bx - ax) / d, (by - ay) / d
        return d - (ra + rb), ax + ra * ux, ay + ra * uy, bx - rb * ux, by - rb * uy
    w = ra / (ra + rb)
    qx, qy = ax + w * (bx - ax), ay + w * (by - ay)
    return 0.0, qx, qy, qx, qy


def refusal(case):
    if not case[0][5] or not case[1][5]:
        return "a shape without points"
    return None


def answer(t):
    if len(t) < 2 or not t[1].isdigit():
        print(f'gjk2d-geos: request without an id: "{" ".join(t)[:80]}"', file=sys.stderr)
        return
    rid = t[1]
    try:
        if len(t) < 3 or t[2] != IMPL:
            return say(f'error {rid} unknown implementation "{t[2] if len(t) > 2 else ""}"')
        if t[0] == "distance":
            case, i = read_case(t, 3)
            if i != len(t):
                raise RequestError(f"{len(t) - i} tokens after shape B")
            why = refusal(case)
            if why:
                return say(f"refused {rid} {why}")
            d, ax, ay, bx, by = query(prepare(case))
            return say(f"ok {rid} {d!r} {ax!r} {ay!r} {bx!r} {by!r} -1")
        if t[0] == "time":
            try:
                k_rounds, m = int(t[3]), int(t[4])
            except (IndexError, ValueError):
                raise RequestError("time: K and m must be positive integers") from None
            if k_rounds < 1 or m < 1:
                raise RequestError("time: K and m must be positive integers")
            cases, i = [], 5
            for k in range(m):
                case, i = read_case(t, i)
                why = refusal(case)
                if why:
                    return say(f"refused {rid} case {k + 1}: {why}")
                cases.append(case)
            if i != len(t):
                raise RequestError(f"{len(t) - i} tokens after case {m}")
            start = time.perf_counter_ns()
            prepared = [prepare(case) for case in cases]
            prepare_ns = time.perf_counter_ns() - start
            start = time.perf_counter_ns()
            for _ in range(k_rounds):
                for p in prepared:
                    query(p)
            total = time.perf_counter_ns() - start
            return say(f"timed {rid} {total} {prepare_ns}")
        return say(f'error {rid} unknown request "{t[0]}"')
    except RequestError as e:
        return say(f"error {rid} {e}")
    except Exception as e:  # shapely/GEOS raised: the case is an error, the stream goes on
        return say(f'error {rid} {type(e).__name__}: {" ".join(str(e).split())}')


def main():
    handshaken = False
    while True:
        line = sys.stdin.readline()  # one line as soon as it arrives (no read-ahead)
        if not line:
            return
        t = line.split()
        if not t:
            continue
        if not handshaken:
            # We speak version 2 whatever the host asks: the host judges a mismatch (the protocol's rule).
            if t[0] != "gjk2d-adapter":
                print(
                    f'gjk2d-geos: expected the handshake, got "{line.strip()[:80]}"',
                    file=sys.stderr,
                )
            say("gjk2d-adapter 2")
            say(f"library GEOS {GEOS_VERSION} via shapely {shapely.__version__}")
            say(
                f"implementation {IMPL} double radius 0 GEOS {GEOS_VERSION} distance and nearest_points "
                f"via shapely {shapely.__version__} (Point, LineString, convex hull), radii subtracted"
            )
            for line in CONTRACT:
                say(line)
            say(f"prepared {IMPL} case")
            say("ready")
            handshaken = True
            continue
        answer(t)


if __name__ == "__main__":
    main()
