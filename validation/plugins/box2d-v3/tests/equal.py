#!/usr/bin/env python3
"""The shipped Box2D v3 adapter adds nothing and loses nothing:

  equal.py --exe GJK_VALIDATE --plugin gjk2d-box2d3.so --variant NAME --direct BOX2D3_DIRECT
                  --work DIR --family SPEC [--family SPEC ...]

1. `gjk-validate generate` writes the families' cases to DIR/cases.json;
2. box2d3_direct (validation/plugins/box2d-v3/tests/direct.c, the same Box2D objects and flags as the adapter)
   calls b2ShapeDistance on each case, from DIR/cases.txt, which this script writes: every number
   as Python's repr, so the program reads the file's doubles bit for bit;
3. `gjk-validate run --cases DIR/cases.json --plugin ... --per-case` runs the adapter, child process
   and all, as a campaign does;
4. every case's answer in cases.jsonl (distance, pointA, pointB, iterations) must equal the direct
   call's bit for bit (the report writes each double in its shortest round-trip form; a NaN only as
   "nan", so two NaNs count as equal), and the runner's refusals (more than 8 points, refused
   without calling) must be the direct program's refusals.
Prints the counts; exit 0 when every case agrees, else 1 with the first disagreements. The large
files are removed on success.
"""
import argparse
import json
import math
import os
import shutil
import struct
import subprocess
import sys

# The runner's reasons for not calling a plugin (kSkipRefused, kSkipNotRepresentable in
# validation/src/evaluate/evaluate.hpp): a case of more than max_vertices points; a case whose
# numbers are not all floats, never given to a float implementation.
REFUSED = "refused by the implementation (plugin)"
NOT_FLOAT = "input not representable in float"


def fail(msg):
    print("box2d3_equal: FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def run(cmd, stdout=None):
    p = subprocess.run(cmd, stdout=stdout or subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        fail("{} exited {}\n{}".format(" ".join(cmd), p.returncode, p.stderr[-4000:]))
    return p


def shape_line(tag, s):
    """One shape as box2d3_direct reads it: T n radius px py c s x0 y0 ..."""
    t = s.get("transform", {})
    p, q = t.get("p", [0.0, 0.0]), t.get("q", [1.0, 0.0])
    nums = [len(s["points"]), s.get("radius", 0.0), p[0], p[1], q[0], q[1]]
    nums += [v for pt in s["points"] for v in pt]
    return tag + " " + " ".join(repr(float(v)) if i else str(v) for i, v in enumerate(nums))


def write_text(cases_json, out):
    """Streams the case file (one case per line, docs/case-files.md) into box2d3_direct's format."""
    names = []
    with open(cases_json) as f, open(out, "w") as o:
        for line in f:
            line = line.strip().rstrip(",")
            if not line.startswith('{"name"'):
                continue
            c = json.loads(line)
            names.append(c["name"])
            o.write(
                "case {}\n{}\n{}\n".format(
                    c["name"], shape_line("A", c["a"]), shape_line("B", c["b"])
                )
            )
    return names


def bits(x):
    """A report number (a JSON number or "nan"/"inf"/"-inf") or a %a string, as comparable bits."""
    v = float(x) if not isinstance(x, str) or x in ("nan", "inf", "-inf") else float.fromhex(x)
    return "nan" if math.isnan(v) else struct.pack("<d", v)


def compare(cases_jsonl, direct_csv, variant):
    counts = {"equal": 0, "refused": 0, "not_asked": 0}
    bad = []
    with open(cases_jsonl) as rj, open(direct_csv) as dc:
        for line, row in zip(rj, dc):
            c = json.loads(line)
            name, answer = row.rstrip("\n").split(",", 1)
            if name != c["name"]:
                fail("case order differs: report {} against direct {}".format(c["name"], name))
            v = c.get("variants", {}).get(variant)
            if v is None:
                bad.append(
                    "{}: no answer of {} in cases.jsonl ({})".format(
                        name, variant, c.get("rejected")
                    )
                )
            elif v.get("skipped") == REFUSED or answer == "refused":
                if v.get("skipped") == REFUSED and answer == "refused":
                    counts["refused"] += 1
                else:
                    bad.append(
                        "{}: runner {}, direct {}".format(
                            name, v.get("skipped", "answered"), answer
                        )
                    )
            elif v.get("skipped") == NOT_FLOAT:
                counts["not_asked"] += 1
            elif "skipped" in v:
                bad.append("{}: skipped by the runner: {}".format(name, v["skipped"]))
            elif "plugin_status" in v:
                bad.append(
                    "{}: the adapter's call ended {} ({})".format(
                        name, v["plugin_status"], v["plugin_detail"]
                    )
                )
            else:
                d = answer.split(",")
                got = [v["distance"], *v["pointA"], *v["pointB"]]
                if [bits(x) for x in got] != [bits(x) for x in d[:5]] or v["iterations"] != int(
                    d[5]
                ):
                    bad.append(
                        "{}: adapter {} {}, direct {}".format(
                            name,
                            [float(x) if not isinstance(x, str) else x for x in got],
                            v["iterations"],
                            [float.fromhex(x) for x in d[:5]] + [int(d[5])],
                        )
                    )
                else:
                    counts["equal"] += 1
        if rj.readline() or dc.readline():
            fail("cases.jsonl and the direct program's output have different numbers of cases")
    return counts, bad


def main():
    ap = argparse.ArgumentParser()
    for a in ("--exe", "--plugin", "--variant", "--direct", "--work"):
        ap.add_argument(a, required=True)
    ap.add_argument("--family", action="append", required=True)
    args = ap.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    cases_json = os.path.join(args.work, "cases.json")
    cases_txt = os.path.join(args.work, "cases.txt")
    direct_csv = os.path.join(args.work, "direct.csv")
    report = os.path.join(args.work, "report")
    gen = [args.exe, "generate", "-o", cases_json]
    for f in args.family:
        gen += ["--family", f]
    run(gen)
    names = write_text(cases_json, cases_txt)
    with open(direct_csv, "w") as out:
        run([args.direct, cases_txt], stdout=out)
    run(
        [
            args.exe,
            "run",
            "--cases",
            cases_json,
            "--no-default-plugins",
            "--plugin",
            args.plugin,
            "--variants",
            args.variant,
            "--no-timing",
            "--no-progress",
            "--per-case",
            "--out",
            report,
        ]
    )
    counts, bad = compare(os.path.join(report, "cases.jsonl"), direct_csv, args.variant)
    print(
        "box2d3_equal: {} cases ({}): {} answers equal bit for bit, {} refused by both (more than 8 "
        "points), {} not asked (not representable in float); {} disagreements".format(
            len(names),
            ", ".join(args.family),
            counts["equal"],
            counts["refused"],
            counts["not_asked"],
            len(bad),
        )
    )
    if bad:
        fail("{} cases disagree; the first:\n  ".format(len(bad)) + "\n  ".join(bad[:10]))
    if counts["equal"] + counts["refused"] + counts["not_asked"] != len(names):
        fail("counted {} cases of {}".format(sum(counts.values()), len(names)))
    for p in (cases_json, cases_txt, direct_csv):
        os.remove(p)
    shutil.rmtree(report)


if __name__ == "__main__":
    main()
