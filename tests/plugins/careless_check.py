#!/usr/bin/env python3
"""Careless plugins under --judge (issue 30; tests/plugins/CMakeLists.txt, careless_plugin.cpp).

  careless_check.py --exe E --plugin P --kind KIND --work W

Runs `E run --plugin P --judge careless-KIND --per-case` on random cases and hard families with
separated, touching and overlapping shapes, and checks every case's verdict in cases.jsonl against
what KIND must get, worked out from the exact side's values (exact distance) and the bounds the
case was held to, never from the verdict under test:

  negative       every case fails, invalid "negative_distance"; a false overlap where the exact
                 distance is > 0, none where it is 0
  nan_witness    every case fails as non-finite (invalid stays null)
  shift_witness  fails, invalid "witness_off_shape", wherever a point moved by (10, 0) leaves its
                 shape (by more than 4 x the witness bound; the distance computed here from the
                 shapes of `E generate`); passes where both stay on their shapes (a long shared
                 edge: hard/touching-edge/13-shared-edge-rot270); cases in between not asserted
  swap_witness   fails exactly where the exact distance exceeds twice the witness bound (A's point
                 then lies at about d from A), invalid "witness_off_shape"; passes where the exact
                 distance is 0 (the points are one point); the cases in between are not asserted
  rel_error      fails exactly where |d - d_exact| > bound or | ||pB - pA|| - d | > witness bound
                 (the 1e-3 error, 1e-3 d, beyond either); passes where the exact distance is 0

Each branch asserted must hold on at least one case; `double` (judged beside it) passes every case
and every case is kept (cases = the families' counts). Exit 0 when every check holds, else 1.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys

FAMILIES = [
    ("random", 300),
    ("hard/touching-vertex", 24),
    ("hard/touching-edge", 24),
    ("hard/identical-nested", 24),
    ("hard/rounded", 40),
    ("hard/near-zero-separation", 60),
    ("hard/ulp-gap", 32),
]


def fail(msg):
    print("careless_check: FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def number(v):
    """A report number: a JSON number, or "inf" / "-inf" / "nan"."""
    return float(v)


def world_points(shape):
    t = shape.get("transform", {})
    c, s = t.get("q", [1.0, 0.0])
    px, py = t.get("p", [0.0, 0.0])
    return [(c * x - s * y + px, s * x + c * y + py) for x, y in shape["points"]]


def hull(pts):
    """Convex hull, counter-clockwise (monotone chain); 1 or 2 points for degenerate sets."""
    pts = sorted(set(pts))
    if len(pts) <= 2:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def segment_distance(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    l2 = dx * dx + dy * dy
    t = 0.0 if l2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def shape_distance(shape, p):
    """Distance from world point p to the shape with its radius (0 inside), in double."""
    h = hull(world_points(shape))
    if len(h) >= 3 and all(
        (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0
        for a, b in zip(h, h[1:] + h[:1])
    ):
        return 0.0
    d = (
        min(segment_distance(p, a, b) for a, b in zip(h, h[1:] + h[:1]))
        if len(h) > 1
        else math.hypot(p[0] - h[0][0], p[1] - h[0][1])
    )
    return max(0.0, d - shape.get("radius", 0.0))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--plugin", required=True)
    ap.add_argument(
        "--kind",
        required=True,
        choices=["negative", "nan_witness", "shift_witness", "swap_witness", "rel_error"],
    )
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    name = "careless-" + a.kind.replace("_", "-")
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    out = os.path.join(a.work, "report")
    cmd = [
        a.exe,
        "run",
        "--variants",
        "double",
        "--no-default-plugins",
        "--plugin",
        a.plugin,
        "--judge",
        name,
        "--per-case",
        "--no-timing",
        "--threads",
        "2",
        "--out",
        out,
        "--no-progress",
    ]
    for fam, n in FAMILIES:
        cmd += ["--family", "{}:{}".format(fam, n)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 1:
        fail(
            "{} exited {} (expected 1: the judged careless plugin fails)\nstdout:\n{}\nstderr:\n{}".format(
                " ".join(cmd), p.returncode, p.stdout[-3000:], p.stderr[-3000:]
            )
        )

    report = json.load(open(os.path.join(out, "report.json")))
    for fam, n in FAMILIES:
        f = next((f for f in report["families"] if f["name"] == fam), None)
        if f is None:
            fail("no family {} in report.json".format(fam))
        for v in ("double", name):
            st = f["variants"][v]
            if st["cases"] != n:
                fail(
                    "{} x {}: {} cases, expected {} (every case kept)".format(
                        fam, v, st["cases"], n
                    )
                )
        if f["variants"]["double"]["failures"] != 0:
            fail("{} x double: {} failures".format(fam, f["variants"]["double"]["failures"]))

    shapes = {}  # case name -> the case (shift_witness: the shapes, from `generate`)
    if a.kind == "shift_witness":
        gen = os.path.join(a.work, "cases.json")
        g = [a.exe, "generate", "-o", gen]
        for fam, n in FAMILIES:
            g += ["--family", "{}:{}".format(fam, n)]
        q = subprocess.run(g, capture_output=True, text=True)
        if q.returncode != 0:
            fail("{} exited {}: {}".format(" ".join(g), q.returncode, q.stderr[-2000:]))
        shapes = {c["name"]: c for c in json.load(open(gen))["cases"]}
    branches = {}  # branch -> cases checked
    failures = read = 0
    with open(os.path.join(out, "cases.jsonl")) as lines:
        for line in lines:
            c = json.loads(line)
            read += 1
            if "rejected" in c:
                fail("case {} rejected: {}".format(c["name"], c["rejected"]))
            v = c["variants"][name]
            if "skipped" in v or "plugin_status" in v:
                fail("case {}: not answered: {}".format(c["name"], v))
            exact = number(c["exact"]["distance"])
            failed, invalid, mis = v["failed"], v["invalid"], v["misclassified"]
            bound, wbound = number(v["bound"]), number(v["witness_bound"])
            failures += failed

            def expect(branch, want_failed, want_invalid=None, check_invalid=True):
                branches[branch] = branches.get(branch, 0) + 1
                if failed != want_failed or (check_invalid and invalid != want_invalid):
                    fail(
                        "{}: case {} (exact distance {!r}, bound {!r}, witness bound {!r}): "
                        "failed {}, invalid {}; expected failed {}, invalid {} ({})".format(
                            a.kind,
                            c["name"],
                            exact,
                            bound,
                            wbound,
                            failed,
                            invalid,
                            want_failed,
                            want_invalid,
                            branch,
                        )
                    )

            if a.kind == "negative":
                want_mis = "false-overlap" if exact > 0 else None
                expect(
                    "separated: false overlap" if exact > 0 else "overlapping: no misclass",
                    True,
                    "negative_distance",
                )
                if mis != want_mis:
                    fail(
                        "case {} (exact {!r}): misclassified {}, expected {}".format(
                            c["name"], exact, mis, want_mis
                        )
                    )
            elif a.kind == "nan_witness":
                if not (isinstance(v["pointA"][0], str) and math.isnan(number(v["pointA"][0]))):
                    fail("case {}: pointA {} is not NaN".format(c["name"], v["pointA"]))
                expect("every case (non-finite)", True, None)
            elif a.kind == "shift_witness":
                case = shapes[c["name"]]
                off = max(
                    shape_distance(case["a"], [number(x) for x in v["pointA"]]),
                    shape_distance(case["b"], [number(x) for x in v["pointB"]]),
                )
                if off > 4 * wbound:
                    expect("moved off a shape: fails", True, "witness_off_shape")
                elif off < wbound / 4:
                    expect("both still on their shapes: passes", False, None)
                else:
                    branches["between (not asserted)"] = (
                        branches.get("between (not asserted)", 0) + 1
                    )
            elif a.kind == "swap_witness":
                # Swapped, A's point is B's: at the exact distance d from A, to within the witness
                # bound (both points are within it of their shapes). It fails where d > 2 x bound
                # and passes where d = 0; between, the test does not say.
                if exact > 2 * wbound:
                    expect("d > 2 x witness bound: fails", True, "witness_off_shape")
                elif exact == 0:
                    expect("d = 0: passes", False, None)
                else:
                    branches["between (not asserted)"] = (
                        branches.get("between (not asserted)", 0) + 1
                    )
            elif a.kind == "rel_error":
                d = number(v["distance"])
                gap = math.hypot(
                    number(v["pointB"][0]) - number(v["pointA"][0]),
                    number(v["pointB"][1]) - number(v["pointA"][1]),
                )
                if exact == 0:
                    expect("d = 0: passes", False, None)
                elif abs(d - exact) > bound:
                    expect("error beyond the bound: fails", True, None, check_invalid=False)
                elif abs(gap - d) > wbound:
                    expect(
                        "error within the bound, gap beyond the witness bound: fails",
                        True,
                        "witness_gap",
                    )
                else:
                    expect("error within both bounds: passes", False, None)
    need = {
        "negative": ["separated: false overlap", "overlapping: no misclass"],
        "shift_witness": ["moved off a shape: fails"],
        "swap_witness": ["d > 2 x witness bound: fails", "d = 0: passes"],
        "rel_error": ["d = 0: passes", "error beyond the bound: fails"],
    }.get(a.kind, [])
    for b in need:
        if branches.get(b, 0) == 0:
            fail("{}: no case in branch '{}' (branches: {})".format(a.kind, b, branches))
    total = sum(n for _, n in FAMILIES)
    if read != total:
        fail("cases.jsonl has {} cases, expected {}".format(read, total))
    print(
        "careless_check: {}: {} cases, {} failed; per branch {}".format(
            a.kind, total, failures, branches
        )
    )


if __name__ == "__main__":
    main()
