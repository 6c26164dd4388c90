#!/usr/bin/env python3
"""The speed targets' `random` distribution (gjk/bench/random_shapes.hpp: 3 to 8 points on a circle
of radius 0.5 to 2, sorted by angle, placed in [-4, 4]^2 with a random rotation), written as the
anchors' case text (../shared/anchors/cases.h) for stage_driver, without gjk-validate.

  random_cases.py COUNT SEED > cases.txt

Exit codes: 0 written; 2 bad usage."""
import math
import random
import sys

if len(sys.argv) != 3 or not sys.argv[1].isdigit() or not sys.argv[2].isdigit():
    print(__doc__, file=sys.stderr)
    sys.exit(2)
count, seed = int(sys.argv[1]), int(sys.argv[2])
rng = random.Random(seed)
out = []
for i in range(count):
    out.append(f"case random/{i}")
    for name in "AB":
        n = rng.randint(3, 8)
        r = rng.uniform(0.5, 2.0)
        angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
        q = rng.uniform(0, 2 * math.pi)
        px, py = rng.uniform(-4, 4), rng.uniform(-4, 4)
        out.append(f"{name} {n} 0 {px!r} {py!r} {math.cos(q)!r} {math.sin(q)!r}")
        out.extend(f"{r * math.cos(t)!r} {r * math.sin(t)!r}" for t in angles)
print("\n".join(out))
