#!/usr/bin/env python3
"""The Rapier executable adapter gjk2d-rapier (docs/peers/rapier.md) driven without
gjk-validate, through tests/plugins/adapter_driver.py's Adapter (a small host side of the protocol):
its handshake (the `input ... world` line, the contract, `prepared ... case`), hand-derived cases
given as world points with the identity transform, as the host gives them to an adapter that
declares `input NAME world`, what it refuses and why, bad requests, a time request.

  rapier_driver.py --adapter FILE --check NAME     one check (a CTest entry)
  rapier_driver.py --adapter FILE --measure        the time loop's ns/query and the round trip

Exit status: 0 pass, 1 fail, 77 the adapter was not built (node or build/npm/rapier missing: CTest
SKIP_RETURN_CODE); with GJK2D_REQUIRE_ALL=1 (CI) a missing adapter is a failure.
"""
import argparse
import math
import os
import pathlib
import re
import struct
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[4] / "tests" / "plugins"))
from adapter_driver import Adapter, fail, fmt_case, near  # noqa: E402


def f32(x):
    """x rounded to the nearest float, as a double (what the host sends a float implementation)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def shape(points, r=0.0, p=(0.0, 0.0), cs=(1.0, 0.0)):
    return (r, p, cs, points)


def square(cx, cy, h=0.5):
    """The square of half side h centred at (cx, cy), as world points."""
    return [(cx - h, cy - h), (cx + h, cy - h), (cx + h, cy + h), (cx - h, cy + h)]


VARIANT = "rapier2d-0.21.0"
F32_EPS = 2.0**-23
EPS_TOL = 10 * F32_EPS  # parry's gjk::eps_tol(): 10 f32::EPSILON, exact in f32
REL_TOL = f32(math.sqrt(EPS_TOL))  # its relative tolerance, sqrt(eps_tol) in f32
EPA_TOL = 100 * F32_EPS  # EPA's, 100 f32::EPSILON
F32_MAX = 3.4028234663852886e38


# The contract's distance tolerance T = abs + rel x exact (the judge's, evaluate/contract_judge.cpp).
def T(exact):
    return EPS_TOL + REL_TOL * abs(exact)


def check_handshake(ad):
    """Version 2; library; one float variant with radii and no vertex limit; its `input ... world`
    line naming where Rapier builds the rotation from an angle; the four contract lines with
    parry's constants; `prepared ... case`; ready."""
    h = ad.handshake
    want = [
        r"gjk2d-adapter 2",
        r"library Rapier @dimforge/rapier2d-compat 0\.21\.0",
        re.escape(f"implementation {VARIANT} float radius 0 ") + r".+",
        re.escape(f"input {VARIANT} world ") + r".*gen2d/math\.ts:80-82.*src/math\.rs:36-38.*",
        re.escape(f"contract {VARIANT} overlap penetration ")
        + r"src/query/contact/contact\.rs:97-104 .+",
        re.escape(f"contract {VARIANT} tolerance ")
        + r"(\S+) (\S+) src/query/gjk/gjk\.rs:126-144 .+",
        re.escape(f"contract {VARIANT} margin 0 ") + r"src/shape/round_shape\.rs.+",
        re.escape(f"contract {VARIANT} depth ")
        + r"(\S+) none src/query/epa/epa2\.rs:355-356, 501-509 .+",
        re.escape(f"prepared {VARIANT} case"),
        r"ready",
    ]
    if len(h) != len(want):
        fail(f"expected {len(want)} handshake lines, got {len(h)}: {h}")
    for line, pattern in zip(h, want):
        m = re.fullmatch(pattern, line)
        if not m:
            fail(f"handshake line {line!r} does not match {pattern!r}")
        if line.startswith(f"contract {VARIANT} tolerance "):
            if (float(m.group(1)), float(m.group(2))) != (EPS_TOL, REL_TOL):
                fail(f"tolerance {m.group(1)} {m.group(2)}, expected {EPS_TOL!r} {REL_TOL!r}")
        if line.startswith(f"contract {VARIANT} depth ") and float(m.group(1)) != EPA_TOL:
            fail(f"depth tolerance {m.group(1)}, expected {EPA_TOL!r}")
    print(f"handshake: {h[1]!r}, variant {VARIANT}, input world, overlap penetration")


def parse_ok(answer, rid):
    t = answer.split(" ")
    if len(t) != 8 or t[0] != "ok" or t[1] != str(rid) or t[7] != "-1":
        fail(f'expected "ok {rid} <d> <ax> <ay> <bx> <by> -1", got {answer!r}')
    d, ax, ay, bx, by = (float(v) for v in t[2:7])
    return d, (ax, ay), (bx, by)


def at(want_a, want_b, tol=0.0):
    def check(d, pa, pb):
        if not all(near(u, v, tol) for u, v in zip(pa + pb, want_a + want_b)):
            return f"witness points {pa}, {pb}, expected {want_a}, {want_b} (tolerance {tol})"
        return None

    return check


def facing(xa, xb, ylo, yhi):
    """(xa, y) and (xb, y), one y in [ylo, yhi]: the pairs of two facing edges, every one right."""

    def check(d, pa, pb):
        if pa[0] != xa or pb[0] != xb or pa[1] != pb[1] or not ylo <= pa[1] <= yhi:
            return (
                f"witness points {pa}, {pb}: expected ({xa}, y), ({xb}, y) with y in [{ylo}, {yhi}]"
            )
        return None

    return check


def rounded_square(c, r):
    """The distance of p to the boundary of the unit square centred at c rounded by r (r = 0:
    outside points only, which is all the cases below need)."""

    def off(p):
        dx, dy = max(abs(p[0] - c[0]) - 0.5, 0.0), max(abs(p[1] - c[1]) - 0.5, 0.0)
        return abs(math.hypot(dx, dy) - r)

    return off


def disc(c, r):
    return lambda p: abs(math.hypot(p[0] - c[0], p[1] - c[1]) - r)


def on_boundaries(off_a, off_b, tol):
    """Each point within tol of its own shape's boundary, and ||pB - pA|| within tol of |d| (the
    contract's witness clauses, with W = T here)."""

    def check(d, pa, pb):
        for p, off, name in ((pa, off_a, "A"), (pb, off_b, "B")):
            if off(p) > tol:
                return f"point {name} {p} is {off(p)} off its shape's boundary (tolerance {tol})"
        gap = math.hypot(pb[0] - pa[0], pb[1] - pa[1])
        if abs(gap - abs(d)) > tol:
            return f"||pB - pA|| = {gap}, |d| = {abs(d)} (tolerance {tol})"
        return None

    return check


def dropped_vertex(d, pa, pb):
    # The foot of (1, -1) on the line through (0, 0) along u = (2, D): t = (P . u) / (u . u).
    t = (2.0 - D001) / (4.0 + D001 * D001)
    if not (near(pa[0], 2 * t, 1e-6) and near(pa[1], D001 * t, 1e-6) and pb == (1.0, -1.0)):
        return f"witness points {pa}, {pb}: expected the foot {(2 * t, D001 * t)} on (0, 0)-(2, d) and (1, -1)"
    return None


D001 = f32(0.01)  # 0.009999999776482582
# The hand-derived cases, each: the two shapes (world points, identity transforms), the expected
# distance, its tolerance, and a check of the witness points. Every input is an f32; tolerance 0
# where every number on the way is a binary fraction Rapier computes exactly.
CASES = {
    # Unit squares centred at (0, 0) and (4, 0): the facing edges x = 0.5 and x = 3.5 are 3 apart.
    "squares-3-apart": (
        shape(square(0, 0)),
        shape(square(4, 0)),
        3.0,
        0.0,
        facing(0.5, 3.5, -0.5, 0.5),
    ),
    # Unit squares centred at (10, 10) and (10.5, 10.25) overlap by 0.5 along x and 0.75 along y:
    # the depth is 0.5 (move B by +0.5 in x), so the distance is -0.5, and the penetration pair is
    # A's right edge point (10.5, y) and B's left edge point (10, y), 0.5 apart, y in the common
    # span [9.75, 10.5].
    "overlap": (
        shape(square(10, 10)),
        shape(square(10.5, 10.25)),
        -0.5,
        0.0,
        facing(10.5, 10.0, 9.75, 10.5),
    ),
    # The point (2, 0) (a Ball of radius 0 placed there) and the segment (0, 0)-(2, 2): the foot is
    # (1, 1), the distance sqrt 2, in f32 1.4142135381698608. The point comes back at (2, 0): the
    # answer is in world coordinates, not in the Ball's frame (which would put it at (0, 0)).
    "point-segment": (
        shape([(2.0, 0.0)]),
        shape([(0.0, 0.0), (2.0, 2.0)]),
        f32(math.sqrt(2.0)),
        0.0,
        at((2.0, 0.0), (1.0, 1.0), 1e-6),
    ),
    # Discs of radius 0.5 at (0, 0) and 0.25 at (3, 0) (two Balls: parry's ball-ball contact): 3 -
    # 0.75 = 2.25, points (0.5, 0) and (2.75, 0).
    "discs": (
        shape([(0.0, 0.0)], r=0.5),
        shape([(3.0, 0.0)], r=0.25),
        2.25,
        0.0,
        at((0.5, 0.0), (2.75, 0.0)),
    ),
    # Discs of radius 1 at (10, 0) and (11, 0) penetrate by 1: distance -1, each point on its own
    # disc along the centres, A's at (11, 0), B's at (10, 0), 1 apart.
    "discs-overlap": (
        shape([(10.0, 0.0)], r=1.0),
        shape([(11.0, 0.0)], r=1.0),
        -1.0,
        0.0,
        at((11.0, 0.0), (10.0, 0.0)),
    ),
    # A disc of radius 0.5 at (0, 0) and the unit square centred at (3, 0) rounded by 0.25
    # (RoundConvexPolygon): cores 2.5 apart, minus 0.75: 1.75. parry's GJK on the rounded square
    # stops within its relative tolerance (measured: 1.751058578491211, the points off the x axis
    # by 1e-3 and 5e-3): the contract's T = eps_tol + sqrt(eps_tol) x 1.75 = 0.00191 holds, each
    # point within T of its boundary.
    "rounded": (
        shape([(0.0, 0.0)], r=0.5),
        shape(square(3, 0), r=0.25),
        1.75,
        T(1.75),
        on_boundaries(disc((0.0, 0.0), 0.5), rounded_square((3.0, 0.0), 0.25), T(1.75)),
    ),
    # Unit squares rounded by 0.25, centred at (0, 0) and (1.25, 0): cores 0.25 apart, the rounded
    # shapes penetrate by 0.5 - 0.25 = 0.25: distance -0.25 within the depth clause (EPA_TOL), the
    # points on their boundaries, 0.25 apart.
    "rounded-overlap": (
        shape(square(0, 0), r=0.25),
        shape(square(1.25, 0), r=0.25),
        -0.25,
        EPA_TOL,
        on_boundaries(rounded_square((0.0, 0.0), 0.25), rounded_square((1.25, 0.0), 0.25), EPA_TOL),
    ),
    # Far apart: unit squares centred at (0, 0) and (1e6, 0) (every coordinate exact in f32):
    # 999999 between the facing edges x = 0.5 and x = 999999.5. contactShape answers nothing beyond
    # its prediction; the adapter's f32 maximum covers every finite distance.
    "far-apart": (
        shape(square(0, 0)),
        shape(square(1e6, 0)),
        999999.0,
        0.0,
        facing(0.5, 999999.5, -0.5, 0.5),
    ),
    # Rapier's finding: beyond sqrt(f32::MAX) = 1.8446743e19 a squared length overflows f32. The
    # unit square at (0, 0) and the point (2^64, 0), 2^64 - 0.5 apart: Rapier answers -0, a false
    # overlap (1.8446742974197924e19, the float below, is answered; bisected). Pinned, so that a
    # parry that scales its norms shows here.
    "beyond-sqrt-f32-max": (
        shape(square(0, 0)),
        shape([(2.0**64, 0.0)]),
        0.0,
        0.0,
        lambda d, pa, pb: None if pb == (2.0**64, 0.0) else f"point B {pb}, expected (2^64, 0)",
    ),
    # Rapier's finding: the convex polygon (0, 0), (1, 0), (2, d), (2, 1), (0, 1) with d = 0.01 (in
    # f32) turns by about d / 1 = 0.57 degrees at (1, 0), below parry's 1.5 degrees, so parry drops
    # that vertex (convex_polygon.rs:216-241). The point (1, -1) is 1 from the polygon (at (1, 0)),
    # but 2.01 / sqrt(4.0001) = 1.0049874... from the edge (0, 0)-(2, d) Rapier keeps: it answers
    # the latter (pinned, so that a parry that keeps the vertex shows here).
    "dropped-vertex": (
        shape([(0.0, 0.0), (1.0, 0.0), (2.0, D001), (2.0, 1.0), (0.0, 1.0)]),
        shape([(1.0, -1.0)]),
        abs(2.0 * -1.0 - D001) / math.hypot(2.0, D001),
        1e-6,
        dropped_vertex,
    ),
}


def check_case(ad, name, rid=1):
    a, b, want, tol, witness = CASES[name]
    answer = ad.ask(f"distance {rid} {VARIANT} {fmt_case(a, b)}")
    d, pa, pb = parse_ok(answer, rid)
    if not near(d, want, tol):
        fail(f"{name}: distance {d!r}, expected {want!r} (tolerance {tol})")
    why = witness(d, pa, pb)
    if why:
        fail(f"{name}: {why}")
    print(f"{name}: {answer}")


# What the adapter refuses, each with the reason it gives (a pattern).
REFUSALS = {
    # (c, s) = (0.6, 0.8): a rotation Rapier would take as an f32 angle; the host sends world
    # points to this adapter, so such a case is refused, never approximated.
    "rotation": (
        shape(square(0, 0), cs=(0.6, 0.8)),
        shape([(5.0, 0.0)]),
        r"shape A's transform is not the identity.*f32 angle",
    ),
    "translation": (
        shape(square(0, 0)),
        shape([(0.0, 0.0)], p=(5.0, 0.0)),
        r"shape B's transform is not the identity",
    ),
    # A regular 1000-gon turns by 0.36 degrees at each vertex: parry drops every one and builds
    # no polygon.
    "1000-gon": (
        shape(
            [
                (f32(math.cos(2 * math.pi * k / 1000)), f32(math.sin(2 * math.pi * k / 1000)))
                for k in range(1000)
            ]
        ),
        shape([(3.0, 0.0)]),
        r"Rapier builds no polygon from shape A's 1000 points.*1\.5 degrees",
    ),
    "collinear": (
        shape([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]),
        shape([(3.0, 0.0)]),
        r"Rapier builds no polygon from shape A's 3 points",
    ),
    "rounded-segment": (
        shape([(0.0, 0.0), (1.0, 0.0)], r=0.5),
        shape([(3.0, 0.0)]),
        r"shape A is a segment with a radius",
    ),
    "not-f32": (
        shape([(0.1, 0.0)]),
        shape([(3.0, 0.0)]),
        r"shape A has a number that is not an f32",
    ),
    "no-points": (shape([]), shape([(3.0, 0.0)]), r"shape A has no points"),
}


def check_refusals(ad):
    for k, (name, (a, b, pattern)) in enumerate(REFUSALS.items()):
        answer = ad.ask(f"distance {20 + k} {VARIANT} {fmt_case(a, b)}")
        if not re.fullmatch(rf"refused {20 + k} .*{pattern}.*", answer):
            fail(
                f'{name}: answer {answer[:200]!r} does not match "refused {20 + k} ...{pattern}..."'
            )
        print(f"{name}: {answer[:160]}")
    check_case(ad, "squares-3-apart", rid=99)  # still answering


def check_coincident(ad):
    """3 points, all (1, 1): parry's convex hull asserts two distinct points and panics
    (convex_hull2.rs:107-110); the adapter answers that error for the id without running the trap
    (direct_check.py checks, on generated cases, that the bindings throw wherever it says so)."""
    answer = ad.ask(
        f"distance 3 {VARIANT} {fmt_case(shape([(1.0, 1.0)] * 3), shape([(3.0, 0.0)]))}"
    )
    if not re.fullmatch(
        r"error 3 Rapier throws RuntimeError: unreachable on a ConvexPolygon of 3 or more "
        r"coincident points.*convex_hull2\.rs:107-110.*",
        answer,
    ):
        fail(f"coincident points: {answer!r}")
    print(f"coincident: {answer[:120]}")
    check_case(ad, "squares-3-apart", rid=4)


def check_trap(ad):
    """A triangle of side 1e-25 (f32): its squared edge lengths underflow f32 to 0, parry's hull
    finds no two distinct points and panics, a WebAssembly trap. The adapter answers the error for
    the id, takes a fresh instance of the bindings, and answers the next request as before."""
    t1, t2 = f32(1e-25), f32(2e-25)
    answer = ad.ask(
        f"distance 3 {VARIANT} {fmt_case(shape([(t1, 0.0), (t2, 0.0), (t1, t1)]), shape([(3.0, 0.0)]))}"
    )
    if answer != "error 3 Rapier threw RuntimeError: unreachable":
        fail(f"a trap: {answer!r}")
    print(f"trap: {answer}")
    for rid in (4, 5):  # the next requests, on the fresh instance
        check_case(ad, "squares-3-apart", rid=rid)
    check_case(ad, "dropped-vertex", rid=6)


def check_bad_requests(ad):
    """What the adapter cannot read gets an error for that id, and the stream goes on."""
    good = fmt_case(*CASES["squares-3-apart"][:2])
    expect = [
        (f"distance 5 no-such-variant {good}", r"error 5 .*no-such-variant.*"),
        (f"distance 6 {VARIANT} A 0 0 0 1 0 1 zero 0 B 0 0 0 1 0 1 0 0", r"error 6 .*x0.*"),
        (f"distance 7 {VARIANT} A 0 0 0 1 0 1 0 0 B 0 0 0 1 0 2 0 0", r"error 7 .*"),  # y1 missing
        (
            f"distance 8 {VARIANT} A 0 0 0 1 0 1 0 0 B 0 0 0 1 0 1 0 0 extra",
            r"error 8 .*after shape B.*",
        ),
        (f"time 9 {VARIANT} 0 1 {good}", r"error 9 .*"),  # K = 0
        (f"nonsense 10 {VARIANT}", r"error 10 .*nonsense.*"),
    ]
    for request, pattern in expect:
        answer = ad.ask(request)
        if not re.fullmatch(pattern, answer):
            fail(f"request {request[:60]!r}: answer {answer!r} does not match {pattern!r}")
        print(f"{request[:40]}...: {answer}")
    check_case(ad, "squares-3-apart", rid=11)  # still answering


def check_nonfinite(ad):
    """nan and inf in a case with the identity transform: refused for that id (Rapier's own
    answers there are no distance: a NaN vertex builds no polygon, a Ball at NaN answers 0 with a
    NaN point), and the stream goes on."""
    for rid, body in (
        (3, "A 0 0 0 1 0 1 nan 0 B 0 0 0 1 0 1 0 0"),
        (4, "A 0 0 0 1 0 1 0 0 B 0 0 0 1 0 1 inf 0"),
        (5, "A nan 0 0 1 0 1 0 0 B 0 0 0 1 0 1 1 0"),
    ):
        answer = ad.ask(f"distance {rid} {VARIANT} {body}")
        if not re.fullmatch(
            rf"refused {rid} shape [AB] has a coordinate or radius that is not finite", answer
        ):
            fail(f"expected a refusal of a case with nan or inf, got {answer!r}")
        print(f"nan/inf: {answer}")
    check_case(ad, "squares-3-apart", rid=6)


def check_time(ad):
    """A time request over two cases, K = 50: "timed <id> <total_ns> <prepare_ns>" (the adapter
    declared `prepared ... case`), both positive; a refused case refuses the request."""
    cases = [CASES["squares-3-apart"], CASES["discs"]]
    body = " ".join(fmt_case(c[0], c[1]) for c in cases)
    answer = ad.ask(f"time 42 {VARIANT} 50 2 {body}")
    m = re.fullmatch(r"timed 42 ([0-9]+) ([0-9]+)", answer)
    if not m or int(m.group(1)) <= 0 or int(m.group(2)) <= 0:
        fail(f'expected "timed 42 <total_ns> <prepare_ns>", both > 0, got {answer!r}')
    print(f"time: {answer} ({int(m.group(1)) / 100:.0f} ns/query)")
    a, b, _ = REFUSALS["rotation"]
    answer = ad.ask(f'time 43 {VARIANT} 5 2 {body.split(" A ")[0]} {fmt_case(a, b)}')
    if not re.fullmatch(r"refused 43 case 2: shape A's transform is not the identity.*", answer):
        fail(f"a time request with a case that is not in world points: {answer[:120]!r}")
    print(f"time with a refused case: {answer[:80]}...")


def measure(ad):
    """The time loop's ns/query (K = 20000 on one case) and the round trip of a distance request."""
    a, b = CASES["squares-3-apart"][:2]
    body = fmt_case(a, b)
    n = 2000
    start = time.perf_counter_ns()
    for i in range(n):
        ad.ask(f"distance {i} {VARIANT} {body}")
    trip = (time.perf_counter_ns() - start) / n
    k = 20000
    answer = ad.ask(f"time 1 {VARIANT} {k} 1 {body}")
    print(
        f"rapier: round trip {trip / 1000:.1f} us/query ({n} requests), time loop "
        f"{int(answer.split()[2]) / k:.0f} ns/query (K = {k}, m = 1), "
        f"{int(answer.split()[3]) / 2:.0f} ns per shape prepared"
    )


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--adapter", required=True)
    ap.add_argument(
        "--check",
        choices=["handshake", "refusals", "coincident", "trap", "bad-requests", "nonfinite", "time"]
        + sorted(CASES),
    )
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
    elif a.check in CASES:
        check_case(ad, a.check)
    elif a.check:
        {
            "refusals": check_refusals,
            "coincident": check_coincident,
            "trap": check_trap,
            "bad-requests": check_bad_requests,
            "nonfinite": check_nonfinite,
            "time": check_time,
        }.get(a.check, lambda ad: None)(ad)
    ad.close()
    print("PASS")


if __name__ == "__main__":
    main()
