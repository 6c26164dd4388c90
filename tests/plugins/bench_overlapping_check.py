#!/usr/bin/env python3
"""`gjk-validate bench --overlapping` times exactly the overlapping cases (tests/plugins/CMakeLists.txt;
docs/speed.md, "Signed distance against Bullet's EPA").

  bench_overlapping_check.py --exe E --work W [--plugin gjk2d-bullet-double.so]

The exact side's count first: `run --family random:300 --seed 1 --per-case`, the cases whose exact
distance is 0 (exact.upper == 0: overlapping or touching, radii included). Then `bench --family
random:300 --seed 1 --overlapping --variants double-signed[,bullet-3.24-double] --passes 1
--json`: each variant's cases must be that count, cases_total too, and every figure positive;
without --overlapping, all 300 cases.
Exit 0 when every check holds; else a message and exit 1.
"""
import argparse
import json
import os
import subprocess
import sys


def check(cond, msg):
    if not cond:
        print("bench_overlapping_check: FAIL: " + msg, file=sys.stderr)
        sys.exit(1)


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    check(
        p.returncode == 0,
        "{} exited {}:\n{}".format(" ".join(cmd), p.returncode, (p.stdout + p.stderr)[-3000:]),
    )


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--plugin")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    family = ["--family", "random:300", "--seed", "1"]
    out = os.path.join(a.work, "run")
    run(
        [a.exe, "run"]
        + family
        + [
            "--variants",
            "double",
            "--no-default-plugins",
            "--no-timing",
            "--no-progress",
            "--per-case",
            "--out",
            out,
        ]
    )
    with open(os.path.join(out, "cases.jsonl")) as f:
        overlapping = sum(1 for line in f if json.loads(line)["exact"]["upper"] == 0)
    check(0 < overlapping < 300, "random:300 has {} overlapping cases".format(overlapping))
    variants = ["double-signed"]
    plugin = ["--no-default-plugins"]
    if a.plugin:
        variants.append("bullet-3.24-double")
        plugin += ["--plugin", a.plugin]
    for flag, want in ((["--overlapping"], overlapping), ([], 300)):
        path = os.path.join(a.work, "bench{}.json".format("-overlapping" if flag else ""))
        run(
            [a.exe, "bench"]
            + family
            + flag
            + ["--variants", ",".join(variants)]
            + plugin
            + ["--passes", "1", "--json", path]
        )
        with open(path) as f:
            j = json.load(f)
        check(
            j["context"]["cases_total"] == want,
            "{}: cases_total {} != {}".format(flag, j["context"]["cases_total"], want),
        )
        for v in variants:
            got = j["variants"][v]
            check(got["cases"] == want, "{} {}: cases {} != {}".format(flag, v, got["cases"], want))
            check(
                got["ns_per_query"] is not None and got["ns_per_query"] > 0,
                "{} {}: ns_per_query {}".format(flag, v, got["ns_per_query"]),
            )
    print("bench_overlapping_check: ok ({} of 300 overlapping)".format(overlapping))


if __name__ == "__main__":
    main()
