"""gjk2d.exact_distance is the C++ exact side: the same distance, exact squared distance and
witnesses as gjk-validate's truth (`exact`, and `exact_float_input` for float-rounded inputs) on
the default campaign's families (conftest.py); and a case by hand."""

from fractions import Fraction

import numpy as np
import pytest

import gjk2d


def as_fraction(text):
    num, _, den = text.partition("/")
    return Fraction(int(num), int(den or 1))


def test_two_unit_squares_three_apart():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]])
    r = gjk2d.exact_distance(square, square, position_b=(4, 0))
    assert r["distance"] == 3.0 and r["squared"] == Fraction(9)
    assert not r["overlap"]
    assert r["interval"] == (3.0, 3.0)
    # The closest features are the parallel edges x = 1 and x = 4: the exact side's witnesses lie
    # on them, at one common height in [0, 1].
    (ax, ay), (bx, by) = r["exact_point_a"], r["exact_point_b"]
    assert (ax, bx) == (1, 4) and ay == by and 0 <= ay <= 1
    assert isinstance(ay, Fraction)


def test_two_unit_squares_one_apart_and_radii():
    # Squares of half-width 1 with centres 3 apart: edges x = 1 and x = 2, 1 apart.
    square = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]])
    r = gjk2d.exact_distance(square, square, position_b=(3, 0))
    assert r["distance"] == 1.0 and r["squared"] == Fraction(1)
    # Radii: 1 - 0.25 - 0.5, exact in binary; the squared distance stays the hulls'.
    r = gjk2d.exact_distance(square, square, position_b=(3, 0), radius_a=0.25, radius_b=0.5)
    assert r["distance"] == 0.25 and r["squared"] == Fraction(1)
    # Overlap: squared distance 0.
    r = gjk2d.exact_distance(square, square, position_b=(1.5, 1.5))
    assert r["overlap"] and r["squared"] == 0 and r["distance"] == 0


def test_same_as_gjk_validates_truth_on_the_default_campaign(campaign):
    cases, answers = campaign
    compared = 0
    for name, case in cases.items():
        want = answers[name]["exact"]
        got = gjk2d.exact_distance(**gjk2d.case_args(case))
        assert got["distance"] == want["distance"], name
        assert got["squared"] == as_fraction(want["squared"]), name
        assert got["overlap"] == want["overlap"], name
        assert list(got["point_a"]) == want["witnessA"] and list(got["point_b"]) == want["witnessB"]
        assert got["interval"] == (want["lower"], want["upper"]), name
        compared += 1
    assert compared > 7500


def test_bad_input_raises_a_value_error_naming_the_argument():
    with pytest.raises(ValueError, match="^points_b: "):
        gjk2d.exact_distance([[0.0, 0.0]], np.zeros((0, 2)))
    with pytest.raises(ValueError, match="^radius_a: "):
        gjk2d.exact_distance([[0.0, 0.0]], [[1.0, 1.0]], radius_a=-0.5)


# ---------------------------------------------------------------- signed=True: the penetration
#
# An independent reference in exact rationals (fractions), written without the C++ side's hull or
# edge merge: the world points exactly (a double is a Fraction exactly), overlap by the
# separating-axis test over every candidate direction (normals of point pairs within a shape,
# differences of a point of each), the squared distance when apart as the least point-to-segment
# distance over every point and point pair, and on overlap the squared depth as the least over
# candidate edge normals n (perpendicular to a pair of distinct points of A, or of B, both signs) of
# max(0, h(n))^2 / |n|^2, h(n) = max n.a - min n.b the support function of hull(A) - hull(B): for
# the origin inside a convex polygon its distance to the boundary is the least support over unit
# normals, taken at an edge normal (docs/exact.md, "Penetration depth").

import math
import os
import random


def world(points, position=(0, 0), rotation=(1, 0)):
    c, s = Fraction(rotation[0]), Fraction(rotation[1])
    px, py = Fraction(position[0]), Fraction(position[1])
    return [
        (c * Fraction(x) - s * Fraction(y) + px, s * Fraction(x) + c * Fraction(y) + py)
        for x, y in points
    ]


def pair_normals(pts):
    for i in range(len(pts)):
        for j in range(i + 1, len(pts)):
            (x0, y0), (x1, y1) = pts[i], pts[j]
            if (x0, y0) != (x1, y1):
                yield (y0 - y1, x1 - x0)
                yield (y1 - y0, x0 - x1)


def support_gap(n, a, b):
    """max n.a - min n.b"""
    return max(n[0] * x + n[1] * y for x, y in a) - min(n[0] * x + n[1] * y for x, y in b)


def separated(a, b):
    dirs = list(pair_normals(a)) + list(pair_normals(b))
    dirs += [(bx - ax, by - ay) for ax, ay in a for bx, by in b]
    for n in dirs:
        if n == (0, 0):
            continue
        if support_gap(n, a, b) < 0 or support_gap((-n[0], -n[1]), a, b) < 0:
            return True
    return False


def point_segment_squared(p, s0, s1):
    dx, dy = s1[0] - s0[0], s1[1] - s0[1]
    length = dx * dx + dy * dy
    t = Fraction(0) if length == 0 else ((p[0] - s0[0]) * dx + (p[1] - s0[1]) * dy) / length
    t = min(max(t, Fraction(0)), Fraction(1))
    ex, ey = p[0] - s0[0] - t * dx, p[1] - s0[1] - t * dy
    return ex * ex + ey * ey


def hull_squared(p, pts):
    return min(
        point_segment_squared(p, pts[i], pts[j])
        for i in range(len(pts))
        for j in range(i, len(pts))
    )


def reference(a, b):
    """(overlap, q): q the squared core distance when apart, the squared core depth on overlap."""
    if separated(a, b):
        return False, min(min(hull_squared(p, b) for p in a), min(hull_squared(p, a) for p in b))
    depths = [
        max(Fraction(0), support_gap(n, a, b)) ** 2 / (n[0] ** 2 + n[1] ** 2)
        for n in list(pair_normals(a)) + list(pair_normals(b))
    ]
    return True, min(depths, default=Fraction(0))


def cmp_sqrt(q, t):
    """sign(sqrt(q) - t), q >= 0, exactly"""
    if t < 0:
        return 1 if q > 0 else (0 if t == 0 else 1)
    return (q > t * t) - (q < t * t)


def exact_signed_cmp(overlap, q, r):
    """m -> sign(x - m) for x = -(sqrt(q) + r) on overlap, sqrt(q) - r apart"""
    if overlap:
        return lambda m: -cmp_sqrt(q, -(r + m))
    return lambda m: cmp_sqrt(q, r + m)


def even(d):
    m, _ = math.frexp(abs(d))
    return int(m * 2**53) % 2 == 0


def correctly_rounded(d, cmp_to):
    """d is the nearest double (ties to even) to the number x given by cmp_to(m) = sign(x - m):
    x lies between the midpoints from d to its two neighbours, a midpoint only when d is even."""
    below = (Fraction(d) + Fraction(math.nextafter(d, -math.inf))) / 2
    above = (Fraction(d) + Fraction(math.nextafter(d, math.inf))) / 2
    lo, hi = cmp_to(below), cmp_to(above)
    return (lo > 0 or (lo == 0 and even(d))) and (hi < 0 or (hi == 0 and even(d)))


def ulp(v):
    return math.ulp(abs(v))


def point_signed(p, pts):
    """the signed distance of point p to hull(pts), as a float (outside: the least segment distance;
    inside or on: minus the least support gap over the candidate normals)"""
    pq = (Fraction(p[0]), Fraction(p[1]))
    if separated([pq], pts):
        return math.sqrt(hull_squared(pq, pts))
    gaps = [
        (max(n[0] * x + n[1] * y for x, y in pts) - (n[0] * pq[0] + n[1] * pq[1]))
        / math.sqrt(n[0] ** 2 + n[1] ** 2)
        for n in pair_normals(pts)
    ]
    return -float(min(gaps, default=0))


def check_signed(points_a, points_b, **kw):
    """exact_distance(signed=True) against the reference; returns its dict."""
    r = gjk2d.exact_distance(points_a, points_b, signed=True, **kw)
    a = world(points_a, kw.get("position_a", (0, 0)), kw.get("rotation_a", (1, 0)))
    b = world(points_b, kw.get("position_b", (0, 0)), kw.get("rotation_b", (1, 0)))
    ra, rb = kw.get("radius_a", 0.0), kw.get("radius_b", 0.0)
    overlap, q = reference(a, b)
    assert r["overlap"] == overlap
    cmp_to = exact_signed_cmp(overlap, q, Fraction(ra) + Fraction(rb))
    d = r["signed_distance"]
    assert correctly_rounded(d, cmp_to), (d, q)
    lower, upper = r["signed_interval"]
    assert cmp_to(Fraction(lower)) >= 0 and cmp_to(Fraction(upper)) <= 0
    assert upper in (lower, math.nextafter(lower, math.inf))
    if overlap:
        assert r["depth_squared"] == q
        assert d <= 0 and r["distance"] == 0
        # The pair: pA on A's rounded boundary, pB on B's, |pA - pB| = -signed. Each coordinate is
        # correctly rounded (half an ulp of the scale S), so within ulp(S) of the exact points;
        # the float reference's own roundings are a few ulp(S): bound 8 ulp(S) (derivation as in
        # tests/exact/test_penetration.cpp).
        (ax, ay), (bx, by) = r["penetration_a"], r["penetration_b"]
        scale = max(
            [abs(float(v)) for p in a + b for v in p] + [abs(ax), abs(ay), abs(bx), abs(by), ra, rb]
        )
        tol = 8 * ulp(scale)
        assert abs(point_signed((ax, ay), a) - ra) <= tol
        assert abs(point_signed((bx, by), b) - rb) <= tol
        assert abs(math.hypot(ax - bx, ay - by) + d) <= tol
    else:
        assert r["depth_squared"] is None and r["squared"] == q
        assert (r["penetration_a"], r["penetration_b"]) == (r["point_a"], r["point_b"])
    return r


def square(x0, y0, x1, y1):
    return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]


def test_signed_is_opt_in():
    r = gjk2d.exact_distance(square(0, 0, 2, 2), square(1, 0.5, 3, 2.5))
    assert "signed_distance" not in r


def test_signed_hand_cases():
    # Squares [0,2]^2 and [1,3] x [1/2,5/2]: Z = [-3,1] x [-5/2,3/2], the side x = 1 nearest:
    # depth 1, pA = (2, 5/4) on A's right edge, pB = (1, 5/4) on B's left (the foot divides Z's
    # edge at 5/8; docs/exact.md). Radii 1/4 and 1/2 move them along (1, 0).
    r = check_signed(square(0, 0, 2, 2), square(1, 0.5, 3, 2.5))
    assert r["signed_distance"] == -1.0 and r["depth_squared"] == 1
    assert r["penetration_a"] == (2.0, 1.25) and r["penetration_b"] == (1.0, 1.25)
    r = check_signed(square(0, 0, 2, 2), square(1, 0.5, 3, 2.5), radius_a=0.25, radius_b=0.5)
    assert r["signed_distance"] == -1.75
    assert r["penetration_a"] == (2.25, 1.25) and r["penetration_b"] == (0.5, 1.25)
    # Rotated by the scaled rotation (3, 4) (3/5, 4/5 are not doubles): depth 5, n = (3/5, 4/5).
    rot = dict(rotation_a=(3, 4), rotation_b=(3, 4), radius_a=0.25, radius_b=0.5)
    r = check_signed(square(0, 0, 2, 2), square(1, 0.5, 3, 2.5), **rot)
    assert r["depth_squared"] == 25 and r["signed_distance"] == -5.75
    assert r["penetration_a"] == (1.15, 11.95) and r["penetration_b"] == (-2.3, 7.35)
    # Touching: depth 0, the signed distance minus the radii.
    r = check_signed(square(0, 0, 1, 1), square(1, 0, 2, 1), radius_a=0.5, radius_b=0.5)
    assert r["depth_squared"] == 0 and r["signed_distance"] == -1.0
    # A point and a segment in [0,4] x [0,2]: the top side 1/2 away.
    r = check_signed(square(0, 0, 4, 2), [[1, 1.5]])
    assert r["signed_distance"] == -0.5 and r["penetration_a"] == (1.0, 2.0)
    r = check_signed(square(0, 0, 4, 2), [[1, 1.5], [3, 1.5]])
    assert r["penetration_a"] == (2.0, 2.0) and r["penetration_b"] == (2.0, 1.5)
    # Deep: B inside a long thin A moves by 3/2 across, not 6 along.
    r = check_signed(square(0, 0, 10, 2), square(4, 0.25, 6, 1.5))
    assert r["signed_distance"] == -1.5 and r["penetration_b"] == (5.0, 1.5)
    # Irrational: the hypotenuse x + y = 4 at 1/sqrt(2) from (3/2, 3/2).
    r = check_signed([[0, 0], [4, 0], [0, 4]], [[1.5, 1.5]], radius_a=1.0)
    assert r["depth_squared"] == Fraction(1, 2)
    # Apart with overlapping radii: 1 - 3/2.
    r = check_signed(square(0, 0, 1, 1), [[2, 0.5]], radius_a=1.0, radius_b=0.5)
    assert r["signed_distance"] == -0.5 and r["distance"] == 0


def random_shape(rng, grid):
    n = rng.randint(1, 6)
    if grid:
        pts = [[float(rng.randint(-3, 3)), float(rng.randint(-3, 3))] for _ in range(n)]
        rotation = rng.choice([(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)])
        position = (rng.randint(-3, 3) / 2, rng.randint(-3, 3) / 2)
    else:
        pts = [[rng.uniform(-2, 2), rng.uniform(-2, 2)] for _ in range(n)]
        t = rng.uniform(0, 2 * math.pi)
        rotation = (math.cos(t), math.sin(t))
        position = (rng.uniform(-1, 1), rng.uniform(-1, 1))
    radius = rng.uniform(0, 0.5) if rng.random() < 0.25 else 0.0
    return pts, radius, position, rotation


def test_signed_random_cases_against_fractions():
    seed = int.from_bytes(os.urandom(8), "little")  # a new draw each run: cases not kept here
    rng = random.Random(seed)
    overlaps = 0
    for k in range(300):
        grid = k % 2 == 1
        pa, ra, qa, ca = random_shape(rng, grid)
        pb, rb, qb, cb = random_shape(rng, grid)
        try:
            r = check_signed(
                np.array(pa),
                np.array(pb),
                radius_a=ra,
                radius_b=rb,
                position_a=qa,
                rotation_a=ca,
                position_b=qb,
                rotation_b=cb,
            )
        except AssertionError as e:
            raise AssertionError(
                f"seed {seed} case {k}: {pa} {ra} {qa} {ca} / {pb} {rb} {qb} {cb}"
            ) from e
        overlaps += r["overlap"]
    assert overlaps > 100, f"seed {seed}: {overlaps} overlapping"
