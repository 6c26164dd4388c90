#!/usr/bin/env python3
"""The measurements behind the Jolt adapter's choices (docs/peers/jolt.md): the prisms' half
height factor, one query or two, the slack of mMaxSeparationDistance, the scale of the shapes.
Not a test: a tool, run by hand.

  jolt_sweep.py [--cases N] [--seed S] [--scale X] [--factors 0.5,1,2] [--slack 1.125] [--one-query]

Cases: pairs of random convex polygons, each the hull of 3 to 8 points on a circle of radius
uniform in [0.5, 2] about a centre uniform in [-3, 3]^2, all times --scale, rounded to float (the
variant is float). Each is answered by a copy of validation/plugins/jolt/adapter.js with
HEIGHT_FACTOR (and MAX_SEPARATION_SLACK, and with --one-query only its second query, at
mMaxSeparationDistance, for every case) replaced, and compared with a brute-force signed distance
in double: the origin against hull{a_i - b_j}, its distance outside, minus its distance to the
nearest edge line inside (the 2D depth). Printed per factor: the overlapping cases, how many have
their depth within 1e-6 relative, how many got a depth <= 0, the median and largest relative depth
error; the separated ones' median and largest relative error; answers more than 1e-4 off (the
contract's tolerance); refusals (Jolt could not build a prism) and errors (no contact found).
"""
import argparse
import math
import os
import random
import statistics
import struct
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..", "..", "..")
sys.dont_write_bytecode = True  # importing adapter_driver leaves no __pycache__ in the source tree
sys.path.insert(0, os.path.join(ROOT, "tests", "plugins"))
from adapter_driver import Adapter, fmt_case, shape  # noqa: E402


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def hull(pts):
    pts = sorted(set(pts))
    if len(pts) <= 2:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lo, up = [], []
    for p in pts:
        while len(lo) >= 2 and cross(lo[-2], lo[-1], p) <= 0:
            lo.pop()
        lo.append(p)
    for p in reversed(pts):
        while len(up) >= 2 and cross(up[-2], up[-1], p) <= 0:
            up.pop()
        up.append(p)
    return lo[:-1] + up[:-1]


def segment_distance(a, b):
    """The origin's distance to the segment a-b."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = 0 if length2 == 0 else max(0.0, min(1.0, -(a[0] * dx + a[1] * dy) / length2))
    return math.hypot(a[0] + t * dx, a[1] + t * dy)


def signed_distance(a, b):
    m = hull([(p[0] - q[0], p[1] - q[1]) for p in a for q in b])
    edges = [(m[i], m[(i + 1) % len(m)]) for i in range(len(m))]
    inside = all((q[0] - p[0]) * (-p[1]) - (q[1] - p[1]) * (-p[0]) > 0 for p, q in edges)
    if inside:
        return -min(
            abs(p[0] * (q[1] - p[1]) - p[1] * (q[0] - p[0])) / math.hypot(q[0] - p[0], q[1] - p[1])
            for p, q in edges
        )
    return min(segment_distance(p, q) for p, q in edges)


def polygon(rng, scale):
    cx, cy = rng.uniform(-3, 3) * scale, rng.uniform(-3, 3) * scale
    r = rng.uniform(0.5, 2) * scale
    angles = [rng.uniform(0, 2 * math.pi) for _ in range(rng.randint(3, 8))]
    return hull([(f32(cx + r * math.cos(t)), f32(cy + r * math.sin(t))) for t in angles])


def adapter_copy(work, factor, slack, one_query):
    src = open(os.path.join(ROOT, "validation", "plugins", "jolt", "adapter.js")).read()
    for old, new in [
        ("const HEIGHT_FACTOR = 2;", f"const HEIGHT_FACTOR = {factor};"),
        ("const MAX_SEPARATION_SLACK = 1 + 1 / 8;", f"const MAX_SEPARATION_SLACK = {slack};"),
    ]:
        if old not in src:
            sys.exit(f"jolt_sweep: adapter.js has no line {old!r}")
        src = src.replace(old, new)
    if one_query:
        first = (
            "  p.b.ts.CollideShape(p.a.shape, unitScale, p.comA, overlapSettings, origin, collector, filter);\n"
            "  if (collector.HadHit()) return collector.mHit;\n  collector.Reset();\n"
        )
        if first not in src:
            sys.exit("jolt_sweep: adapter.js has no first query to remove")
        src = src.replace(first, "")
    js = os.path.join(work, f"adapter-{factor}.js")
    open(js, "w").write(src)
    wrapper = os.path.join(work, f"adapter-{factor}.sh")
    modules = os.path.join(ROOT, "build", "npm", "jolt", "node_modules")
    open(wrapper, "w").write(f'#!/bin/sh\nNODE_PATH="{modules}" exec node "{js}"\n')
    os.chmod(wrapper, 0o755)
    return wrapper


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cases", type=int, default=4000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--factors", default="2")
    ap.add_argument("--slack", default="1 + 1 / 8")
    ap.add_argument("--one-query", action="store_true")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    cases = []
    while len(cases) < a.cases:
        p, q = polygon(rng, a.scale), polygon(rng, a.scale)
        if len(p) >= 3 and len(q) >= 3:
            cases.append((p, q, signed_distance(p, q)))
    with tempfile.TemporaryDirectory() as work:
        for factor in a.factors.split(","):
            ad = Adapter(adapter_copy(work, factor, a.slack, a.one_query))
            over, sep, off, refused, errors, nonpositive = [], [], 0, 0, 0, 0
            for i, (p, q, s) in enumerate(cases):
                t = ad.ask(f"distance {i} jolt-1.1.0 {fmt_case(shape(p), shape(q))}").split()
                if t[0] == "refused":
                    refused += 1
                    continue
                if t[0] != "ok":
                    errors += 1
                    continue
                d = float(t[2])
                off += abs(d - s) > 1e-4
                if s < 0:
                    nonpositive += d >= 0
                    over.append((d - s) / -s)  # > 0: the depth short
                else:
                    sep.append(abs(d - s) / s if s > 0 else abs(d))
            ad.close()
            within = sum(abs(r) <= 1e-6 for r in over)
            print(
                f'factor {factor} (scale {a.scale}, slack {a.slack}{", one query" if a.one_query else ""}): '
                f"overlapping {len(over)}: depth within 1e-6 rel {within}, depth <= 0 {nonpositive}, "
                f"median rel {statistics.median(over) if over else math.nan:.2g}, "
                f"largest |rel| {max(map(abs, over)) if over else math.nan:.2g}; "
                f"separated {len(sep)}: median rel {statistics.median(sep) if sep else math.nan:.2g}, "
                f"largest {max(sep) if sep else math.nan:.2g}; off by > 1e-4 {off}; refused {refused}; "
                f"errors {errors}"
            )


if __name__ == "__main__":
    main()
