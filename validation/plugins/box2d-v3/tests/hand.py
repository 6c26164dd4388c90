#!/usr/bin/env python3
"""Hand-derived cases for the shipped Box2D v3 adapter, run through gjk-validate as a campaign
runs it (the description, the child process, world coordinates):

  hand.py --exe GJK_VALIDATE --plugin gjk2d-box2d3.so --variant NAME --work DIR

Expected answers, derived by hand (world = R local + p, R = [[c, -s], [s, c]]):
- squares-3-apart: unit squares (half size 0.5) at (0, 0) and (4, 0): the gap between x = 0.5 and
  x = 3.5 is 3; the witnesses lie on those edges at one height y in [-0.5, 0.5]. Every coordinate
  is a small dyadic number and 3 = sqrt(9): exact in float.
- squares-overlap: the same squares at (0, 0) and (0.5, 0.25) overlap: distance 0.
- point-segment: the point (0, 2) against the segment (-1, 0)-(1, 0): the closest point of the
  segment has barycentric weights 1/2, 1/2 (exact), so pA = (0, 2), pB = (0, 0), distance 2.
- rotated-rectangle: a 4 x 1 rectangle (local x in [-2, 2]) turned by 90 degrees (c = 0, s = 1)
  at the origin, against the point (0, 5). In A's frame the point is R^T (0, 5) = (5, 0), closest
  to the edge x = 2 at (2, 0), which R maps to (0, 2): pA = (0, 2), pB = (0, 5), distance 3, all
  exact. (A transform applied the wrong way round would give pA = (0, -2).)
- circles: radius 0.5 at (0, 0) and radius 0.25 at (3, 4): centres 5 apart (3-4-5), distance
  5 - 0.75 = 4.25 (exact); pA = 0.5 (0.6, 0.8) = (0.3, 0.4), pB = (3, 4) - 0.25 (0.6, 0.8) =
  (2.85, 3.8). 0.3, 0.4, 2.85 and 3.8 are not floats: the witnesses are checked to 2e-6, four
  float ulps at 4 (ulp 4.8e-7), for the few float roundings of the direction and the scaling.
- circles-overlap (the contract's `perimeter` clause): radius 1 at (0, 0) and at (1.5, 0): the cores
  (the centres) 1.5 apart, the discs overlap by 2 - 1.5 = 0.5. b2ShapeDistance answers distance 0
  and keeps each point on its own perimeter along the cores' normal (1, 0): pA = (1, 0),
  pB = (1.5, 0) - (1, 0) = (0.5, 0), 0.5 apart, the overlap's depth; all exact in float.
- nine-points: a 9-point shape: more than B2_MAX_POLYGON_VERTICES = 8, refused by the runner
  without calling (the description's max_vertices), not answered.
With --bridge (gjk2d-adapter-bridge), the plugin's declared contract is read through the bridge's
handshake (protocol 2): overlap `perimeter` with its source (src/distance.c, erincatto/box2d
617d32ab), no tolerance stated, margin 0; and its prepared shapes, scope `shape` (a b2ShapeProxy
in the shape's own frame).
Exit 0 when every case gives its expected answer, else 1 naming the case.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys

REFUSED = (
    "refused by the implementation (plugin)"  # kSkipRefused, validation/src/evaluate/evaluate.hpp
)
SQUARE = [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]


def shape(points, p=(0.0, 0.0), q=(1.0, 0.0), radius=0.0):
    return {"points": points, "radius": radius, "transform": {"p": list(p), "q": list(q)}}


NINE = [[math.cos(2 * math.pi * k / 9), math.sin(2 * math.pi * k / 9)] for k in range(9)]
CASES = [
    ("squares-3-apart", shape(SQUARE), shape(SQUARE, p=(4, 0))),
    ("squares-overlap", shape(SQUARE), shape(SQUARE, p=(0.5, 0.25))),
    ("point-segment", shape([[0, 0]], p=(0, 2)), shape([[-1, 0], [1, 0]])),
    (
        "rotated-rectangle",
        shape([[-2, -0.5], [2, -0.5], [2, 0.5], [-2, 0.5]], q=(0, 1)),
        shape([[0, 0]], p=(0, 5)),
    ),
    ("circles", shape([[0, 0]], radius=0.5), shape([[0, 0]], p=(3, 4), radius=0.25)),
    ("circles-overlap", shape([[0, 0]], radius=1.0), shape([[0, 0]], p=(1.5, 0), radius=1.0)),
    ("nine-points", shape(NINE), shape([[0, 0]], p=(5, 0))),
]


def check(name, v):
    """None when the variant's answer `v` is the hand-derived one, else what differs."""
    if name == "nine-points":
        return None if v.get("skipped") == REFUSED else "expected refused, got {}".format(v)
    if "distance" not in v:
        return "no answer: {}".format(v)
    d, (ax, ay), (bx, by) = v["distance"], v["pointA"], v["pointB"]
    if name == "squares-3-apart":
        ok = d == 3 and ax == 0.5 and bx == 3.5 and ay == by and -0.5 <= ay <= 0.5
    elif name == "squares-overlap":
        ok = d == 0
    elif name == "point-segment":
        ok = d == 2 and [ax, ay, bx, by] == [0, 2, 0, 0]
    elif name == "circles-overlap":
        ok = d == 0 and [ax, ay, bx, by] == [1, 0, 0.5, 0]
    elif name == "rotated-rectangle":
        ok = d == 3 and [ax, ay, bx, by] == [0, 2, 0, 5]
    else:  # circles
        ok = d == 4.25 and all(
            abs(x - e) <= 2e-6 for x, e in zip([ax, ay, bx, by], [0.3, 0.4, 2.85, 3.8])
        )
    return None if ok else "distance {} pointA {} pointB {}".format(d, v["pointA"], v["pointB"])


def main():
    ap = argparse.ArgumentParser()
    for a in ("--exe", "--plugin", "--variant", "--work"):
        ap.add_argument(a, required=True)
    ap.add_argument("--bridge", help="gjk2d-adapter-bridge, to read the plugin's contract")
    args = ap.parse_args()
    if args.bridge:
        h = subprocess.run(
            [args.bridge, args.plugin],
            input="gjk2d-adapter 1\n",
            capture_output=True,
            text=True,
            timeout=30,
        ).stdout.splitlines()
        want = [
            "contract {} overlap perimeter src/distance.c:".format(args.variant),
            "contract {} tolerance none none".format(args.variant),
            "contract {} margin 0".format(args.variant),
        ]
        if (
            h[:1] != ["gjk2d-adapter 2"]
            or len(h) != 8
            or not all(l.startswith(w) for l, w in zip(h[3:6], want))
            or "erincatto/box2d 617d32ab" not in h[3]
            or h[6] != "prepared {} shape".format(args.variant)
        ):
            print(
                "box2d3_hand: FAIL: the contract read through the bridge: {}".format(h),
                file=sys.stderr,
            )
            sys.exit(1)
        print("box2d3_hand: contract: {}".format(h[3]))
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    path = os.path.join(args.work, "hand.json")
    with open(path, "w") as f:
        json.dump(
            {
                "format": "gjk-cases/1",
                "cases": [{"name": "box2d3/" + n, "a": a, "b": b} for n, a, b in CASES],
            },
            f,
        )
    out = os.path.join(args.work, "report")
    p = subprocess.run(
        [
            args.exe,
            "run",
            "--cases",
            path,
            "--no-default-plugins",
            "--plugin",
            args.plugin,
            "--variants",
            args.variant,
            "--no-timing",
            "--no-progress",
            "--per-case",
            "--out",
            out,
        ],
        capture_output=True,
        text=True,
    )
    if p.returncode != 0:
        print(
            "box2d3_hand: FAIL: gjk-validate exited {}\n{}".format(p.returncode, p.stderr),
            file=sys.stderr,
        )
        sys.exit(1)
    failures = []
    with open(os.path.join(out, "cases.jsonl")) as f:
        for line in f:
            c = json.loads(line)
            why = check(c["name"].split("/", 1)[1], c["variants"][args.variant])
            if why:
                failures.append("{}: {}".format(c["name"], why))
            else:
                print("box2d3_hand: {}: as derived".format(c["name"]))
    if failures:
        print("box2d3_hand: FAIL:\n  " + "\n  ".join(failures), file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
