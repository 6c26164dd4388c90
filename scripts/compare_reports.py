#!/usr/bin/env python3
"""Are two report directories the same campaign result?

    scripts/compare_reports.py OLD_DIR NEW_DIR

Compares report.json with what legitimately changes between runs removed (the same fields as
stripVolatile() in validation/src/campaign/verdict.cpp: date, host, threads, timings, command,
revision; and how the truth was decided: the context's and the Stats' "truth"), and the cases of worst-cases.json (names and inputs; its comments quote the command).
Prints the first differences and exits 1 when there are any, 0 when the two are the same.
"""
import json
import sys

CONTEXT_VOLATILE = ["date", "host", "threads", "elapsed_s", "throughput", "command", "git_revision"]
STATS_VOLATILE = [
    "ns_per_query",
    "ns_spread",
    "ratio_to_baseline",
    "timing_passes",
    "prepare_ns_per_shape",
    "prepared_ns_per_query",
]
# How the truth was decided, not what it is (--truth filtered and exact give the same truths, bit
# for bit; docs/exact.md, "The filter"): the context's "truth" and the Stats' "truth" counts.
TRUTH_PATH = "truth"


def stripped(report):
    for k in CONTEXT_VOLATILE + [TRUTH_PATH]:
        report["context"].pop(k, None)
    for entry in report["context"]["inputs"]:  # the same files in another checkout
        if "file" in entry:
            entry["file"] = entry["file"].rsplit("/", 1)[-1]
    for family in report["families"]:
        for stats in family["variants"].values():
            for k in STATS_VOLATILE + [TRUTH_PATH]:
                stats.pop(k, None)
    return report


def differences(a, b, path="", out=None):
    out = [] if out is None else out
    if type(a) != type(b):
        out.append(f"{path}: {json.dumps(a)[:80]} != {json.dumps(b)[:80]}")
    elif isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                out.append(f"{path}/{k}: only in {'new' if k in b else 'old'}")
            else:
                differences(a[k], b[k], f"{path}/{k}", out)
    elif isinstance(a, list):
        if len(a) != len(b):
            out.append(f"{path}: {len(a)} entries != {len(b)}")
        for i, (x, y) in enumerate(zip(a, b)):
            differences(x, y, f"{path}[{i}]", out)
    elif a != b:
        out.append(f"{path}: {json.dumps(a)[:80]} != {json.dumps(b)[:80]}")
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    old, new = sys.argv[1], sys.argv[2]
    load = lambda d, f: json.load(open(f"{d}/{f}"))
    diffs = differences(
        stripped(load(old, "report.json")), stripped(load(new, "report.json")), "report.json"
    )
    diffs += differences(
        load(old, "worst-cases.json")["cases"],
        load(new, "worst-cases.json")["cases"],
        "worst-cases.json/cases",
    )
    for d in diffs[:40]:
        print(d)
    if diffs:
        print(f"{len(diffs)} difference(s)")
        return 1
    print("same campaign result (timing, date, host, threads and command aside)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
