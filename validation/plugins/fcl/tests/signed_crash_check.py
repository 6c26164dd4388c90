#!/usr/bin/env python3
"""FCL's signed distance aborts on an assertion: one case counted as a crash, the campaign goes on
(validation/plugins/fcl/tests/tests.cmake; docs/peers/fcl.md).

  signed_crash_check.py --exe E --plugin gjk2d-fcl.so --cases signed-assert-cases.json --work W

The case file holds two hard/scale-sweep cases with their provenance: /57 is answered, /58 makes
libccd's EPA abort in ComputeVisiblePatch (gjk_libccd-inl.h:1327, an assertion compiled into
Debian's libfcl). Checked: the run exits 0; fcl-0.7-libccd-signed's family row counts crashed 1;
/57 has an answer and /58 none; `double` answers both; the terminal names the case and the signal,
and the plugin's log holds FCL's assertion.
Exit 0 when every check holds; else a message and exit 1.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

VARIANT = "fcl-0.7-libccd-signed"
ANSWERED = "hard/scale-sweep/57-vertex-edge-gap-x1e-05"
ABORTS = "hard/scale-sweep/58-touching-edge-x1e-05"


def check(cond, msg):
    if not cond:
        print("signed_crash_check: FAIL: " + msg, file=sys.stderr)
        sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    for k in ("--exe", "--plugin", "--cases", "--work"):
        ap.add_argument(k, required=True)
    a = ap.parse_args()
    out = os.path.join(a.work, "report")
    shutil.rmtree(out, ignore_errors=True)
    cmd = [
        a.exe,
        "run",
        "--cases",
        a.cases,
        "--variants",
        "double," + VARIANT,
        "--no-default-plugins",
        "--plugin",
        a.plugin,
        "--no-timing",
        "--no-progress",
        "--per-case",
        "--out",
        out,
    ]
    p = subprocess.run(cmd, capture_output=True, text=True)
    check(
        p.returncode == 0,
        "{} exited {}:\n{}".format(" ".join(cmd), p.returncode, (p.stdout + p.stderr)[-3000:]),
    )
    with open(os.path.join(out, "report.json")) as f:
        r = json.load(f)
    row = r["families"][0]["variants"][VARIANT]
    check(row["crashed"] == 1, "crashed {} != 1".format(row["crashed"]))
    check(row["cases"] == 2, "cases {} != 2".format(row["cases"]))
    answers = {}
    with open(os.path.join(out, "cases.jsonl")) as f:
        for line in f:
            c = json.loads(line)
            answers[c["name"]] = c["variants"]
    check(answers[ANSWERED][VARIANT].get("distance") is not None, ANSWERED + " has no answer")
    check(answers[ABORTS][VARIANT].get("distance") is None, ABORTS + " has an answer")
    for name in (ANSWERED, ABORTS):
        check(answers[name]["double"].get("distance") is not None, "double: no answer on " + name)
    said = "crashed on case '{}': signal 6 (Aborted); the other cases go on".format(ABORTS)
    check(said in p.stderr + p.stdout, "the terminal does not say " + repr(said))
    with open(os.path.join(out, "plugin-gjk2d-fcl.log")) as f:
        log = f.read()
    check(
        "ComputeVisiblePatch" in log and "isOutsidePolytopeFace" in log,
        "the plugin's log does not hold FCL's assertion:\n" + log[-2000:],
    )
    print("signed_crash_check: ok")


if __name__ == "__main__":
    main()
