#!/usr/bin/env python3
"""A timing through the executable-adapter protocol agrees with the shared library's.

  scripts/adapter_timing_check.py [--build build/release] [--rounds 6] [--cases 2000]

Times Box2D 2.4.1 (the shipped plugin gjk2d-box2d.so) twice per round with `gjk-validate bench`:
as the shared-library plugin, and through gjk2d-adapter-bridge (an executable adapter hosting the
same .so, its names suffixed -bridge) started by a two-line wrapper script; the two orders
alternate between rounds, so that a drift of the machine's speed falls on both. Prints each
round's ratio bridge / shared library and their median; exit 0 when the median is within 15%,
1 otherwise. A bench check, not a unit test: its figures depend on the machine (run it on a quiet
one; docs/plugin-abi.md, "gjk2d-adapter-bridge").
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile


def bench(exe, plugin, order, cases, out):
    subprocess.run(
        [
            exe,
            "bench",
            "--family",
            "random:{}".format(cases),
            "--variants",
            ",".join(order),
            "--plugin",
            plugin,
            "--passes",
            "15",
            "--json",
            out,
        ],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    v = json.load(open(out))["variants"]
    return v["box2d-2.4.1-bridge"]["ns_per_query"] / v["box2d-2.4.1"]["ns_per_query"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default="build/release")
    ap.add_argument("--rounds", type=int, default=6)
    ap.add_argument("--cases", type=int, default=2000)
    a = ap.parse_args()
    exe = os.path.abspath(os.path.join(a.build, "validation", "gjk-validate"))
    plugins = os.path.abspath(os.path.join(a.build, "validation", "plugins"))
    with tempfile.TemporaryDirectory() as tmp:
        wrapper = os.path.join(tmp, "box2d-bridge")
        with open(wrapper, "w") as f:
            f.write(
                "#!/bin/sh\nexec {0}/gjk2d-adapter-bridge {0}/gjk2d-box2d.so -bridge\n".format(
                    plugins
                )
            )
        os.chmod(wrapper, 0o755)
        orders = [["box2d-2.4.1", "box2d-2.4.1-bridge"], ["box2d-2.4.1-bridge", "box2d-2.4.1"]]
        ratios = [
            bench(exe, wrapper, orders[r % 2], a.cases, os.path.join(tmp, "b.json"))
            for r in range(a.rounds)
        ]
    median = statistics.median(ratios)
    print(
        "bridge / shared library, ns per query, per round: "
        + " ".join("{:.3f}".format(r) for r in ratios)
    )
    print(
        "median {:.3f} ({} rounds of {} random cases, 15 passes each)".format(
            median, a.rounds, a.cases
        )
    )
    return 0 if 1 / 1.15 <= median <= 1.15 else 1


if __name__ == "__main__":
    sys.exit(main())
