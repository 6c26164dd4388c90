#!/usr/bin/env python3
"""A declared contract in a campaign (issue 49; tests/plugins/CMakeLists.txt).

  contract_check.py --exe E --adapter A --cases C --work W

A is adapters/contract.py: protocol version 2, contract `overlap zero` with an absolute tolerance of
1e-6 (FCL's without signed distance). C is adapters/contract_cases.json: two unit squares with B at
x = 0.5, 1 + 2^-22, 1.25, 2, 4 and 5, so the exact distances are 0 (overlap), 2^-22, 0.25, 1, 3 and
4 (the edges x = 1 and x = x_B are parallel). The adapter answers (toy.py) and what each answer is
by its contract, derived by hand (T = 1e-6, gjk2d's bound on these cases is a few 1e-15):
  overlap          -1, no points: keeps it (zero: only the sign); measured on max(-1, 0) = 0, the
                   exact distance: within gjk2d's bound.
  near             -1 on shapes 2^-22 (2.4e-7) apart: a claim of overlap within T, keeps it; its
                   error 2.4e-7 is outside gjk2d's bound (class 2).
  false-overlap    -1 on shapes 0.25 apart: false_overlap, excess 0.25 / T = 2.5e5 (T = 1e-6 plus
                   gjk2d's bound for double, about 1e-14 here: within 1e-6 relative).
  d1               1, exact: within gjk2d's bound.
  d3               3 + 5e-7: within T, keeps it; outside gjk2d's bound (class 2).
  d4               4 + 1e-3: distance, excess 1e-3 / 1e-6 = 1e3.
So report.json's family x variant has contract_violations {"count": 2, "reasons": {"false_overlap":
1, "distance": 1}}, its worst the false overlap, beyond_bound_keeping_contract 2, no penetration block;
gjk2d's own rules (failures) count 5 (three negative distances, two beyond the bound). variants[]
gives the contract (own false, overlap zero, tolerance abs 1e-6, rel null) and the worst violation
with its family. The run exits 0 (a comparison variant); under --judge toy-contract its two
violations fail it (exit 1). The terminal says "breaks its contract", never "fails", for it;
`explain` gives an answer's class, reason and excess, and what it was held to (d4: distance within
T = 1e-6, points within W = max(gjk2d's witness bound, a few 1e-14 here, T) = 1e-6); `compare`
gives contract_violations a row of its own.
Exit 0 when every check holds; else a message and exit 1.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys


def fail(msg):
    print("contract_check: FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def check(cond, msg):
    if not cond:
        fail(msg)


def campaign(a, out, extra=(), expect=0):
    shutil.rmtree(out, ignore_errors=True)
    cmd = [
        a.exe,
        "run",
        "--cases",
        a.cases,
        "--variants",
        "double,toy-contract",
        "--no-default-plugins",
        "--plugin",
        a.adapter,
        "--no-timing",
        "--no-progress",
        "--per-case",
        "--out",
        out,
    ] + list(extra)
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != expect:
        fail(
            "{} exited {}, expected {}\nstdout:\n{}\nstderr:\n{}".format(
                " ".join(cmd), p.returncode, expect, p.stdout[-3000:], p.stderr[-3000:]
            )
        )
    with open(os.path.join(out, "report.json")) as f:
        return json.load(f), p.stdout


def classes(out):
    """cases.jsonl: case name -> (class, violation) of toy-contract's answer."""
    got = {}
    with open(os.path.join(out, "cases.jsonl")) as f:
        for line in f:
            c = json.loads(line)
            v = c["variants"]["toy-contract"]["contract"]
            got[c["name"]] = (v["class"], v["violation"])
    return got


def main():
    ap = argparse.ArgumentParser()
    for k in ("--exe", "--adapter", "--cases", "--work"):
        ap.add_argument(k, required=True)
    a = ap.parse_args()
    r, stdout = campaign(a, os.path.join(a.work, "report"))
    st = r["families"][0]["variants"]["toy-contract"]
    cv = st["contract_violations"]
    check(cv["count"] == 2, "contract_violations.count {} != 2".format(cv["count"]))
    check(
        cv["reasons"] == {"false_overlap": 1, "distance": 1},
        "reasons {} != false_overlap 1, distance 1".format(cv["reasons"]),
    )
    check(
        cv["worst"]["case"] == "contract/false-overlap"
        and cv["worst"]["reason"] == "false_overlap"
        and abs(cv["worst"]["excess"] / 2.5e5 - 1) < 1e-6,
        "worst {}".format(cv["worst"]),
    )
    check(
        st["beyond_bound_keeping_contract"] == 2,
        "beyond_bound_keeping_contract {} != 2".format(st["beyond_bound_keeping_contract"]),
    )
    check("penetration" not in st, "a penetration block for a contract of overlap zero")
    check(st["failures"] == 5, "failures (gjk2d's own rules) {} != 5".format(st["failures"]))
    dbl = r["families"][0]["variants"]["double"]
    check(
        dbl["contract_violations"] == {"count": 0, "reasons": {}, "worst": None},
        "double: {}".format(dbl["contract_violations"]),
    )
    v = {x["name"]: x for x in r["variants"]}
    c = v["toy-contract"]["contract"]
    check(
        c["own"] is False
        and c["overlap"] == "zero"
        and c["tolerance"]["abs"] == 1e-6
        and c["tolerance"]["rel"] is None,
        "contract {}".format(c),
    )
    check(v["double"]["contract"]["own"] is True, "double's contract {}".format(v["double"]))
    w = v["toy-contract"]["worst_contract_violation"]
    check(
        w is not None
        and w["case"] == "contract/false-overlap"
        and w["family"] == r["families"][0]["name"],
        "worst_contract_violation {}".format(w),
    )
    check(v["double"]["worst_contract_violation"] is None, "double has a worst violation")
    expect = {
        "contract/overlap": ("within_bound", None),
        "contract/near": ("outside_bound", None),
        "contract/false-overlap": ("breaks_contract", "false_overlap"),
        "contract/d1": ("within_bound", None),
        "contract/d3": ("outside_bound", None),
        "contract/d4": ("breaks_contract", "distance"),
    }
    got = classes(os.path.join(a.work, "report"))
    check(got == expect, "classes {} != {}".format(got, expect))
    check(r["exit_code"] == 0, "exit_code {}".format(r["exit_code"]))
    check("breaks its contract" in stdout, "the terminal does not say 'breaks its contract'")
    for line in stdout.splitlines():
        check(
            not ("toy-contract" in line and "fail" in line.lower()),
            "the terminal says a comparison variant with a contract fails: " + line,
        )
    # explain: the answer's class, reason and excess, and what it was held to (judgedBy).
    p = subprocess.run(
        [
            a.exe,
            "explain",
            a.cases,
            "contract/d4",
            "--variants",
            "double,toy-contract",
            "--no-default-plugins",
            "--plugin",
            a.adapter,
        ],
        capture_output=True,
        text=True,
    )
    check(p.returncode == 0, "explain exited {}: {}".format(p.returncode, p.stderr[-2000:]))
    for want in (
        "** BREAKS ITS CONTRACT **",
        "contract: breaks its contract (distance, 1000 times",
        "held to: distance within 1e-06, points within 1e-06 (its stated tolerance: abs "
        "1e-06, rel none",
        "contract: keeps its contract, within gjk2d's bound",
    ):
        check(want in p.stdout, "explain does not say {!r}:\n{}".format(want, p.stdout))
    check("FAILED" not in p.stdout, "explain says FAILED:\n" + p.stdout)
    # compare: one more violation is a row of its own, with the legend (it gates with --all-variants).
    worse = json.loads(json.dumps(r))
    worse["families"][0]["variants"]["toy-contract"]["contract_violations"]["count"] = 3
    path = os.path.join(a.work, "worse.json")
    with open(path, "w") as f:
        json.dump(worse, f)
    p = subprocess.run(
        [a.exe, "compare", os.path.join(a.work, "report"), path, "--all-variants"],
        capture_output=True,
        text=True,
    )
    check(p.returncode == 1, "compare exited {}: {}".format(p.returncode, p.stdout + p.stderr))
    check(
        "contract_violations" in p.stdout
        and "break their implementation's own contract" in p.stdout,
        "compare does not show the contract row and legend:\n" + p.stdout,
    )
    # Judged: its violations decide the exit code.
    r, _ = campaign(a, os.path.join(a.work, "judged"), ["--judge", "toy-contract"], expect=1)
    check(r["families"][0]["pass"] is False, "judged: the family passes")
    print("contract_check: ok")


if __name__ == "__main__":
    main()
