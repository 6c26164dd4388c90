#!/usr/bin/env python3
"""Two gjk-validate builds' campaign throughput, alternated in one run.

    scripts/throughput_ab.py OLD_EXE NEW_EXE [--family F ...] [--variants V] [--threads N]
                             [--rounds R] [--out DIR]

Runs `EXE run --family F --variants V --no-timing --no-default-plugins --threads N --no-progress`
with OLD_EXE, then NEW_EXE, R times (default 5), and reads each report's context.elapsed_s. Prints,
per phase (generate, exact, gjk, witness, total), both builds' medians in microseconds per case,
then each round's total NEW / OLD and their median: on a shared machine only figures taken in one
session, alternated, compare (docs/speed.md). Defaults: --family random:100000 --variants double
--threads 1, the issue's command. The reports go to DIR (default: a temporary directory, removed).

Exit codes: 0 measured; 1 a run exited with anything but 0 (its last output line is printed);
2 bad usage (an executable missing, a bad option).
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile

PHASES = ["generate", "exact", "gjk", "witness", "total"]


def run_once(exe, args, out):
    cmd = [
        exe,
        "run",
        *sum((["--family", f] for f in args.family), []),
        "--variants",
        args.variants,
        "--no-timing",
        "--no-default-plugins",
        "--threads",
        str(args.threads),
        "--no-progress",
        "--out",
        str(out),
    ]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        last = (r.stdout + r.stderr).strip().splitlines()[-1:] or ["(no output)"]
        raise RuntimeError(f"{exe} exited {r.returncode}: {last[0]}")
    context = json.loads((out / "report.json").read_text())["context"]
    cases = context["cases_total"]
    return {k: 1e6 * context["elapsed_s"][k] / cases for k in PHASES}


def measure(args, work):
    runs = {"old": [], "new": []}
    for r in range(args.rounds):
        for name, exe in (("old", args.old), ("new", args.new)):
            runs[name].append(run_once(exe, args, work / f"{name}-{r}"))
            print(
                f"round {r + 1} {name}: "
                + " ".join(f"{k} {runs[name][-1][k]:.2f}" for k in PHASES),
                flush=True,
            )
    return runs


def report(runs):
    print("us per case, medians: phase old new new/old")
    for k in PHASES:
        o = statistics.median(x[k] for x in runs["old"])
        n = statistics.median(x[k] for x in runs["new"])
        print(f"{k:9s} {o:8.2f} {n:8.2f} {n / o:6.3f}")
    ratios = [n["total"] / o["total"] for o, n in zip(runs["old"], runs["new"])]
    print(
        "total new/old per round: "
        + ", ".join(f"{x:.3f}" for x in ratios)
        + f"; median {statistics.median(ratios):.3f}"
    )


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--family", action="append", default=[])
    ap.add_argument("--variants", default="double")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--out")
    args = ap.parse_args()  # exits 2 on a bad option
    args.family = args.family or ["random:100000"]
    for exe in (args.old, args.new):
        if not (os.path.isfile(exe) and os.access(exe, os.X_OK)):
            print(f"throughput_ab: {exe}: not an executable file", file=sys.stderr)
            return 2
    if args.rounds < 1 or args.threads < 1:
        print("throughput_ab: --rounds and --threads must be at least 1", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory(prefix="gjk2d-ab-") as tmp:
        work = pathlib.Path(args.out) if args.out else pathlib.Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        try:
            runs = measure(args, work)
        except RuntimeError as e:
            print(f"throughput_ab: {e}", file=sys.stderr)
            return 1
    report(runs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
