#!/usr/bin/env python3
"""Tests of the Jolt Physics executable adapter gjk2d-jolt (docs/peers/jolt.md) without
gjk-validate: the protocol's host side of tests/plugins/adapter_driver.py (its Adapter class)
sends hand-made requests, as the host sends an `input NAME world` variant its cases (world points,
floats, the identity transform), and each answer is checked against values derived by hand.

  jolt_driver.py --adapter FILE --check NAME     one check (a CTest entry)
  jolt_driver.py --adapter FILE --measure        round-trip and time-loop cost

Every case's numbers are floats (the variant is float), so Jolt gets them exactly. Jolt computes
in float: a tolerance below names what it allows for, and each printed answer shows the rest.
Exit status: 0 pass, 1 fail, 77 the adapter was not built (node or build/npm/jolt missing: CTest
SKIP_RETURN_CODE); with GJK2D_REQUIRE_ALL=1 (CI) a missing adapter is a failure.
"""
import argparse
import math
import os
import re
import sys
import time

sys.dont_write_bytecode = True  # importing adapter_driver leaves no __pycache__ in the source tree
sys.path.insert(
    0,
    os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "tests", "plugins"
    ),
)
from adapter_driver import Adapter, fail, fmt_case, shape  # noqa: E402

VARIANT = "jolt-1.1.0"
FLT_EPS = 2.0**-23


def square(cx, cy, side=1.0):
    h = side / 2
    return [(cx - h, cy - h), (cx + h, cy - h), (cx + h, cy + h), (cx - h, cy + h)]


def check_handshake(ad):
    """Version 2; the library line; one float no-radius implementation of at most 128 points; its
    input line (world, with its source); the four contract lines (penetration, tolerance 1e-4,
    margin 0, no depth tolerance), each with its source; prepared case; ready."""
    h = ad.handshake
    want = [
        r"gjk2d-adapter 2",
        r"library Jolt Physics 5\.6\.0 \(jolt-physics 1\.1\.0, WebAssembly\)",
        r"implementation jolt-1\.1\.0 float no-radius 128 .+",
        r"input jolt-1\.1\.0 world .*ConvexHullShape\.cpp:\d+.*",
        r"contract jolt-1\.1\.0 overlap penetration .*CollideShape\.h:59-62.*",
        r"contract jolt-1\.1\.0 tolerance 0\.0001 none .*CollideShape\.h:82-83.*PhysicsSettings\.h:9-10.*",
        r"contract jolt-1\.1\.0 margin 0 .*mMaxConvexRadius = 0.*",
        r"contract jolt-1\.1\.0 depth none none .*mPenetrationTolerance.*",
        r"prepared jolt-1\.1\.0 case",
        r"ready",
    ]
    if len(h) != len(want):
        fail(f"expected {len(want)} handshake lines, got {len(h)}: {h}")
    for line, pattern in zip(h, want):
        if not re.fullmatch(pattern, line):
            fail(f"handshake line {line!r} does not match {pattern!r}")
    print("handshake:", *h, sep="\n  ")


def ask_ok(ad, a, b, rid=1):
    answer = ad.ask(f"distance {rid} {VARIANT} {fmt_case(shape(a), shape(b))}")
    t = answer.split(" ")
    if len(t) != 8 or t[:2] != ["ok", str(rid)] or t[7] != "-1":
        fail(f'expected "ok {rid} <d> <ax> <ay> <bx> <by> -1", got {answer!r}')
    d, ax, ay, bx, by = (float(v) for v in t[2:7])
    print(f"answer: {answer}")
    return d, (ax, ay), (bx, by)


def expect(what, got, want, tol):
    if not abs(got - want) <= tol:
        fail(f"{what}: {got!r}, expected {want!r} within {tol!r} (off by {abs(got - want)!r})")


def check_squares_3_apart(ad):
    # Unit squares centred at (0, 0) and (4, 0): the facing edges x = 0.5 and x = 3.5, 3 apart; the
    # nearest pairs (0.5, y), (3.5, y), y in [-0.5, 0.5]. Every number is a small binary fraction and
    # each square's centre of mass is its centre (exact): Jolt's float arithmetic is exact here
    # (measured), tolerance a few ulps of 4 all the same (4 * 2^-21).
    tol = 4 * 2.0**-21
    d, pa, pb = ask_ok(ad, square(0, 0), square(4, 0))
    expect("distance", d, 3.0, tol)
    expect("pA.x", pa[0], 0.5, tol)
    expect("pB.x", pb[0], 3.5, tol)
    if not (-0.5 - tol <= pa[1] <= 0.5 + tol and abs(pa[1] - pb[1]) <= tol):
        fail(f"witness points {pa}, {pb}: expected (0.5, y), (3.5, y), y in [-0.5, 0.5]")


def check_penetration(ad, a, b, depth, axis, tol):
    """An overlap answered as the contract says: distance -depth, each point on its own shape's
    boundary (checked by the caller's axis: the points differ by depth along it, in the plane)."""
    d, pa, pb = ask_ok(ad, a, b)
    expect("distance", d, -depth, tol)
    gap = (pb[0] - pa[0], pb[1] - pa[1])
    # "move shape 2 by this distance to resolve the collision" (CollideShape.h:61-62): pB - pA is
    # the depth along -axis (B moves by pA - pB): compare with the hand-derived axis.
    expect("|pB - pA|", math.hypot(*gap), depth, tol)
    expect(
        "pA - pB along the axis", (pa[0] - pb[0]) * axis[0] + (pa[1] - pb[1]) * axis[1], depth, tol
    )
    return pa, pb


def check_overlap(ad):
    # Unit squares centred at (0, 0) and (0.5, 0.25) overlap by 0.5 in x and 0.75 in y: the minimal
    # translation moves B by 0.5 along +x (depth 0.5), the pair on the edges x = 0.5 (of A) and
    # x = 0 (B's left edge), with the same y in the overlap [-0.25, 0.5]. Jolt's EPA stops on a
    # relative change of the squared depth (mPenetrationTolerance 1e-4): measured exact here;
    # tolerance 1e-6.
    pa, pb = check_penetration(ad, square(0, 0), square(0.5, 0.25), 0.5, (1.0, 0.0), 1e-6)
    expect("pA.x", pa[0], 0.5, 1e-6)
    expect("pB.x", pb[0], 0.0, 1e-6)
    if not -0.25 - 1e-6 <= pa[1] <= 0.5 + 1e-6:
        fail(f"pA {pa}: its y is outside the overlap [-0.25, 0.5]")


def check_deep_in_plane(ad):
    # The prism reduction for penetration: two 10 x 10 squares, B shifted by (5, 0), overlap by 5:
    # the 2D depth is 5 (B moves by 5 along +x; along y it would take 10). The prisms'
    # half height is 2 (eA + eB) = 80, so the cap-to-cap translation 2h = 160 is far above 5: the
    # answer must be 5 in the plane, not along z. (Bullet's EPA answers 5 / sqrt 2 here along a
    # diagonal: docs/peers/bullet.md.) Tolerance 1e-5: a float EPA on numbers of size 10.
    check_penetration(ad, square(0, 0, 10), square(5, 0, 10), 5.0, (1.0, 0.0), 1e-5)
    # Concentric 10 x 10 squares: depth 10 (the side) along x or y. A half height of 1 would
    # have answered the cap-to-cap 2h = 2.
    d, pa, pb = ask_ok(ad, square(0, 0, 10), square(0, 0, 10), rid=2)
    expect("distance", d, -10.0, 1e-5)
    expect("|pB - pA|", math.hypot(pb[0] - pa[0], pb[1] - pa[1]), 10.0, 1e-5)


def check_far_apart(ad):
    # Unit squares 999 apart (centres (0, 0) and (1000, 0)): answered only because
    # mMaxSeparationDistance covers the distance (the second query); Jolt inflates shape A by it and
    # subtracts it again in float (ConvexShape.cpp:134, 141): the answer is within a few ulps of
    # 1000 (ulp 6.1e-5), inside the contract's 1e-4.
    d, pa, pb = ask_ok(ad, square(0, 0), square(1000, 0))
    expect("distance", d, 999.0, 1e-4)
    expect("pA.x", pa[0], 0.5, 1e-4)
    expect("pB.x", pb[0], 999.5, 1e-4)


def check_hull_tolerance(ad):
    # mHullTolerance 0 keeps a nearly collinear point: the triangle (-1, 0), (1, 0), (0, eps),
    # eps = 2^-11 = 4.9e-4, below the default hull tolerance 1e-3 (ConvexHullShape.h:36), under the
    # square [-0.5, 0.5] x [0.01, 1.01] (0.01 as a float, F). With the apex kept the distance is
    # F - eps = 0.0095117...; a hull without it (a flat segment) would give F (with the default
    # tolerance Jolt answered 0.0097558). Jolt's own coplanar distance for the triangle's prism is
    # 3 FLT_EPSILON (max|x| + max|y| + max|z|) = 3 FLT_EPSILON (1 + eps + h), h = 2 (eA + eB) =
    # 2 ((2 + eps) + 2) = 8.002: 3.2e-6, far below eps
    # (ConvexHullBuilder.cpp:240-247). Tolerance 1e-6.
    eps = 2.0**-11
    f = 0.009999999776482582  # float(0.01)
    top = 1.0099999904632568  # float(1.01)
    d, pa, pb = ask_ok(
        ad, [(-1.0, 0.0), (1.0, 0.0), (0.0, eps)], [(-0.5, f), (0.5, f), (0.5, top), (-0.5, top)]
    )
    expect("distance", d, f - eps, 1e-6)
    expect("pA", math.hypot(pa[0], pa[1] - eps), 0.0, 1e-6)


def check_centre_of_mass(ad):
    # Jolt recentres a hull on its centre of mass (ConvexHullShape.cpp:83, 153: the points minus it,
    # in float) and places it there: the triangle (0, 0), (1, 0), (0, 1) has its centre of mass at
    # (1/3, 1/3), not a float, so its corner (1, 0) goes in as 1 - float(1/3) rounded and comes
    # back as float(1/3) + that: a few ulps off. Against the square [2, 3] x [0, 1] the nearest pair
    # is (1, 0)-(2, 0)... (any (1 - t, t) is further), distance 1. Allowed: 4 ulps of 1 (4.8e-7)
    # on the distance and the point: what the recentring can move a vertex by here (for the square
    # below, 4 ulps of 2).
    tol = 4 * FLT_EPS
    d, pa, pb = ask_ok(ad, [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)], square(2.5, 0.5))
    expect("distance", d, 1.0, tol)
    expect("pA.x", pa[0], 1.0, tol)
    expect("pA.y", pa[1], 0.0, tol)
    expect("pB.x", pb[0], 2.0, tol)
    print(f"centre of mass: pA is ({pa[0] - 1.0:+.3g}, {pa[1]:+.3g}) from (1, 0)")
    # A square whose centre of mass is not a float either: corners 1 + 2^-23 and 3 on both axes,
    # centre 2 + 2^-24 (floats from 2 to 4 are 2^-22 apart). Against the square [5, 6] x [1.5, 2.5]
    # the nearest pairs are (3, y), (5, y), y in [1.5, 2.5]: distance 2. Same allowance.
    e = FLT_EPS
    d, pa, pb = ask_ok(
        ad, [(1 + e, 1 + e), (3.0, 1 + e), (3.0, 3.0), (1 + e, 3.0)], square(5.5, 2.0), rid=2
    )
    expect("distance", d, 2.0, 2 * tol)
    expect("pA.x", pa[0], 3.0, 2 * tol)
    expect("pB.x", pb[0], 5.0, 2 * tol)
    if not (1.5 - tol <= pa[1] <= 2.5 + tol and abs(pa[1] - pb[1]) <= 2 * tol):
        fail(f"witness points {pa}, {pb}: expected (3, y), (5, y), y in [1.5, 2.5]")


def check_segment(ad):
    # A segment's prism is a flat quad, which Jolt builds (ConvexHullBuilder.cpp:404-418, the
    # coplanar case) and answers: the segment (-1, 0)-(1, 0) and the square [-0.5, 0.5] x [2, 3]
    # are 2 apart, the pairs (x, 0), (x, 2), x in [-0.5, 0.5]. Tolerance 1e-6.
    d, pa, pb = ask_ok(ad, [(-1.0, 0.0), (1.0, 0.0)], square(0, 2.5))
    expect("distance", d, 2.0, 1e-6)
    expect("pA.y", pa[1], 0.0, 1e-6)
    expect("pB.y", pb[1], 2.0, 1e-6)
    expect("pA.x - pB.x", pa[0] - pb[0], 0.0, 1e-6)


def check_refusals(ad):
    """What Jolt cannot take, refused with the reason; the stream goes on."""
    good = fmt_case(shape(square(0, 0)), shape(square(4, 0)))
    circle = [
        (math.cos(2 * math.pi * k / 129), math.sin(2 * math.pi * k / 129)) for k in range(129)
    ]
    circle = [(float(f"{x:.6g}"), float(f"{y:.6g}")) for x, y in circle]
    import struct

    circle = [tuple(struct.unpack("f", struct.pack("f", v))[0] for v in p) for p in circle]
    expect_lines = [
        # A transform other than the identity: the host sends world points to an `input world` variant.
        (
            f"distance 11 {VARIANT} {fmt_case(shape(square(0, 0), p=(1.0, 0.0)), shape(square(4, 0)))}",
            r"refused 11 shape A's transform is not the identity.*",
        ),
        (
            f"distance 12 {VARIANT} {fmt_case(shape(square(0, 0)), shape(square(4, 0), cs=(0.6, 0.8)))}",
            r"refused 12 shape B's transform is not the identity.*",
        ),
        # A point: its prism has 2 points, Jolt's hull needs 3 (ConvexHullBuilder.cpp:306-311).
        (
            f"distance 13 {VARIANT} {fmt_case(shape([(0.0, 0.0)]), shape(square(4, 0)))}",
            r"refused 13 Jolt cannot build shape A's prism .*Need at least 3 points to make a hull",
        ),
        # A radius: no-radius.
        (
            f"distance 14 {VARIANT} {fmt_case(shape(square(0, 0), r=0.5), shape(square(4, 0)))}",
            r"refused 14 shape A has a radius.*",
        ),
        # 129 points: a prism of 258, beyond cMaxPointsInHull (256).
        (
            f"distance 15 {VARIANT} {fmt_case(shape(circle), shape(square(4, 0)))}",
            r"refused 15 shape A has 129 points.*",
        ),
        # A number that is not a float: the host rounds a float variant's case to float.
        (
            f"distance 16 {VARIANT} {fmt_case(shape(square(0.1, 0)), shape(square(4, 0)))}",
            r"refused 16 shape A's point .* is not a float",
        ),
    ]
    for request, pattern in expect_lines:
        answer = ad.ask(request)
        if not re.fullmatch(pattern, answer):
            fail(f"request {request[:70]!r}: answer {answer!r} does not match {pattern!r}")
        print(f"{request[:50]}...: {answer}")
    d, _, _ = ask_ok(ad, square(0, 0), square(4, 0), rid=17)  # still answering
    expect("distance", d, 3.0, 1e-6)
    del good


def check_bad_requests(ad):
    """A request the adapter cannot read gets `error` for its id, and the stream goes on."""
    good = fmt_case(shape(square(0, 0)), shape(square(4, 0)))
    expect_lines = [
        (f"distance 5 no-such-variant {good}", r"error 5 .*no-such-variant.*"),
        (
            f"distance 6 {VARIANT} A 0 0 0 1 0 3 zero 0 1 0 0 1 B 0 0 0 1 0 3 5 0 6 0 5 1",
            r"error 6 .*x0.*",
        ),
        (
            f"distance 7 {VARIANT} A 0 0 0 1 0 3 0 0 1 0 0 1 B 0 0 0 1 0 3 5 0 6 0 5",
            r"error 7 .*",
        ),  # y2 missing
        (
            f"distance 8 {VARIANT} A 0 0 0 1 0 0 B 0 0 0 1 0 3 5 0 6 0 5 1",
            r"refused 8 .*without points",
        ),
        (f"time 9 {VARIANT} 0 1 {good}", r"error 9 .*"),  # K = 0
        (f"distance 10 {VARIANT} {good} 1 2", r"error 10 .*tokens after shape B"),
        (f"frobnicate 11 {VARIANT} {good}", r"error 11 unknown request.*"),
    ]
    for request, pattern in expect_lines:
        answer = ad.ask(request)
        if not re.fullmatch(pattern, answer):
            fail(f"request {request[:60]!r}: answer {answer!r} does not match {pattern!r}")
        print(f"{request[:40]}...: {answer}")
    d, _, _ = ask_ok(ad, square(0, 0), square(4, 0), rid=12)
    expect("distance", d, 3.0, 1e-6)


def check_nonfinite(ad):
    """nan and inf in a case: an answer for its id (ok with whatever Jolt computes, or error), and
    the stream goes on."""
    for rid, request in [
        (3, f"distance 3 {VARIANT} A 0 0 0 1 0 3 0 0 nan 0 1 1 B 0 0 0 1 0 3 5 0 6 0 5 1"),
        (4, f"distance 4 {VARIANT} A 0 0 0 1 0 3 0 0 inf 0 1 1 B 0 0 0 1 0 3 5 0 6 0 5 1"),
    ]:
        answer = ad.ask(request)
        if not re.fullmatch(
            rf"ok {rid} \S+ \S+ \S+ \S+ \S+ -1|error {rid} .+|refused {rid} .+", answer
        ):
            fail(f"expected an answer for id {rid} to a case with nan or inf, got {answer!r}")
        print(f"nan/inf: {answer}")
    d, _, _ = ask_ok(ad, square(0, 0), square(4, 0), rid=5)
    expect("distance", d, 3.0, 1e-6)


def check_time(ad):
    """A time request over two cases (one separated, one overlapping), K = 50: "timed <id>
    <total_ns> <prepare_ns>", both positive integers."""
    body = " ".join(
        [
            fmt_case(shape(square(0, 0)), shape(square(4, 0))),
            fmt_case(shape(square(0, 0)), shape(square(0.5, 0.25))),
        ]
    )
    answer = ad.ask(f"time 42 {VARIANT} 50 2 {body}")
    m = re.fullmatch(r"timed 42 ([0-9]+) ([0-9]+)", answer)
    if not m or int(m.group(1)) <= 0 or int(m.group(2)) <= 0:
        fail(f'expected "timed 42 <total_ns> <prepare_ns>", both > 0, got {answer!r}')
    print(
        f"time: {answer} ({int(m.group(1)) / 100:.0f} ns/query, {int(m.group(2)) / 4:.0f} ns/shape prepared)"
    )
    d, _, _ = ask_ok(ad, square(0, 0), square(4, 0), rid=43)  # the loop released its shapes cleanly
    expect("distance", d, 3.0, 1e-6)


def measure(ad):
    """Per-query round trip and the time loop's ns/query, on a separated case (two queries) and an
    overlapping one (one query)."""
    for what, a, b in [
        ("separated", square(0, 0), square(4, 0.25)),
        ("overlapping", square(0, 0), square(0.5, 0.25)),
    ]:
        body = fmt_case(shape(a), shape(b))
        n = 2000
        start = time.perf_counter_ns()
        for i in range(n):
            ad.ask(f"distance {i} {VARIANT} {body}")
        trip = (time.perf_counter_ns() - start) / n
        k = 20000
        answer = ad.ask(f"time 1 {VARIANT} {k} 1 {body}")
        loop = int(answer.split()[2]) / k
        prepare = int(answer.split()[3]) / 2
        print(
            f"jolt, {what}: round trip {trip / 1000:.1f} us/query ({n} requests), time loop "
            f"{loop:.0f} ns/query (K = {k}, m = 1), {prepare:.0f} ns per shape prepared"
        )


CHECKS = {
    "handshake": None,
    "squares-3-apart": check_squares_3_apart,
    "overlap": check_overlap,
    "deep-in-plane": check_deep_in_plane,
    "far-apart": check_far_apart,
    "hull-tolerance": check_hull_tolerance,
    "centre-of-mass": check_centre_of_mass,
    "segment": check_segment,
    "refusals": check_refusals,
    "bad-requests": check_bad_requests,
    "nonfinite": check_nonfinite,
    "time": check_time,
}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--adapter", required=True)
    ap.add_argument("--check", choices=sorted(CHECKS))
    ap.add_argument("--measure", action="store_true")
    a = ap.parse_args()
    if not os.access(a.adapter, os.X_OK):
        why = f"{a.adapter} was not built (node and scripts/setup_npm.sh)"
        if os.environ.get("GJK2D_REQUIRE_ALL") == "1":  # CI (.ci/run): a skip is a failure
            fail(f"{why}, and GJK2D_REQUIRE_ALL=1 makes a skip a failure")
        print(f"SKIP: {why}")
        sys.exit(77)
    ad = Adapter(a.adapter)
    check_handshake(ad)
    if a.measure:
        measure(ad)
    elif a.check and CHECKS[a.check]:
        CHECKS[a.check](ad)
    ad.close()
    print("PASS")


if __name__ == "__main__":
    main()
