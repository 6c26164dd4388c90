"""What gjk2d.validate adds to a callable's time per query (docs/python.md, "Validating your own
GJK from Python"): the ns_per_query of callables that answer at once, without computing, per pair
and per batch, on the random family's first 2,048 cases (the timed sample); and gjk2d.distance's
for comparison.

    PYTHONPATH=build/release/python /usr/bin/python3 python/bench/validate_overhead.py
"""

import tempfile

import numpy as np

import gjk2d


def constant(points_a, points_b, **pose):
    return 0.0, (0.0, 0.0), (0.0, 0.0)


def constant_batch(points, offsets_a, offsets_b, **poses):
    n = len(offsets_a) - 1
    return np.zeros(n), np.zeros((n, 2)), np.zeros((n, 2))


def ns_per_query(fn, batch):
    with tempfile.TemporaryDirectory() as out:
        report = gjk2d.validate(
            fn, families="random:2048", out=out + "/r", name="overhead", batch=batch, progress=False
        )
    return {v: report["families"][0]["variants"][v]["ns_per_query"] for v in ("double", "overhead")}


for label, fn, batch in (
    ("per pair, constant answer", constant, False),
    ("per batch, constant answers", constant_batch, True),
    ("per pair, gjk2d.distance", gjk2d.distance, False),
    ("per batch, gjk2d.distance_batch", gjk2d.distance_batch, True),
):
    t = ns_per_query(fn, batch)
    print(
        f"{label:34} {t['overhead']:9.0f} ns per query "
        f"(gjk2d's double in the same run: {t['double']:.0f} ns)"
    )
