"""What the Python call costs beyond the C++ loop (docs/python.md, "A batch of queries").

Times, on the same packed pairs (8-point random polygons, positions spread so that about half
overlap), the median of 7 runs of:
  - gjk2d.distance_batch: the whole Python call (argument checks, packing, the C++ gjk::distanceBatchLanes,
    the output arrays);
  - the C++ gjk::distanceBatchLanes call alone, timed inside the module (gjk2d._gjk2d._batch_loop_seconds);
  - one gjk2d.distance call per pair from a Python loop.
and prints each per query and the batch's overhead per query (the first minus the second).

  PYTHONPATH=build/release/python /usr/bin/python3 python/bench/batch_overhead.py [pairs]
"""

import statistics
import sys
import time

import numpy as np

import gjk2d
from gjk2d import _gjk2d


def median_seconds(fn, runs=7):
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main():
    pairs = int(sys.argv[1]) if len(sys.argv) > 1 else 10000
    rng = np.random.default_rng(1)
    angles = np.sort(rng.uniform(0, 2 * np.pi, size=(2 * pairs, 8)), axis=1)
    shapes = np.stack([np.cos(angles), np.sin(angles)], axis=2).reshape(-1, 2)
    offsets = np.arange(0, 2 * pairs * 8 + 1, 8)
    oa, ob = offsets[: pairs + 1], offsets[pairs:]
    position_b = rng.uniform(-3, 3, size=(pairs, 2))
    for dtype in (np.float64, np.float32):
        points = shapes.astype(dtype)
        batch = median_seconds(lambda: gjk2d.distance_batch(points, oa, ob, position_b=position_b))
        loop = _gjk2d._batch_loop_seconds(points, oa, ob, position_b=position_b, repeats=7)
        single = median_seconds(
            lambda: [
                gjk2d.distance(
                    points[oa[i] : oa[i + 1]], points[ob[i] : ob[i + 1]], position_b=position_b[i]
                )
                for i in range(pairs)
            ],
            runs=3,
        )
        ns = 1e9 / pairs
        print(
            f"{np.dtype(dtype).name}: {pairs} pairs; ns per query: distance_batch {batch * ns:.0f}, "
            f"C++ loop {loop * ns:.0f}, overhead {(batch - loop) * ns:.0f}; "
            f"one gjk2d.distance per pair {single * ns:.0f}"
        )


if __name__ == "__main__":
    main()
