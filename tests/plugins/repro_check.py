#!/usr/bin/env python3
"""CTest "plugins: repro: <variant> ..." (docs/peers.md, "Repro programs"): `gjk-validate repro`
writes a peer's standalone program for each given case; the program is built with the command its
own comment gives (C and C++) or run by its language's interpreter (node with the project's npm
package of the peer, Debian's python3 for GEOS), and its printed answer ("answer
distance|pointA|pointB ... HEX...")
must equal the answer `gjk-validate explain --json` gives for the case, bit for bit. The cases must
hold an overlapping and a separated one (by the exact truth), so that the check cannot drift to
one kind.

  repro_check.py --exe GJK_VALIDATE --variant NAME|PREFIX* --family SPEC --seed S --cases a,b
                 --work DIR [--node-path DIR] [--env NAME=VALUE]... [--expect-on-overlap EXT]...

Exit status: 0 pass, 1 fail, 77 the variant is not built here (gjk-validate list --peers does
not list it): CTest SKIP_RETURN_CODE; with GJK2D_REQUIRE_ALL=1 (CI) a skip is a failure.
"""
import argparse
import json
import math
import os
import pathlib
import re
import shutil
import struct
import subprocess
import sys


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def skip(why):
    if os.environ.get("GJK2D_REQUIRE_ALL") == "1":  # CI: a skip is a failure
        fail(f"{why}, and GJK2D_REQUIRE_ALL=1 makes a skip a failure")
    print(f"skipped: {why}")
    sys.exit(77)


def bits(x):
    """A double's bits; every NaN the same (the report writes "nan")."""
    return "nan" if math.isnan(x) else struct.pack("<d", x).hex()


def number(v):
    """A report's JSON number: a number, or "nan"/"inf"/"-inf"."""
    return float(v) if not isinstance(v, str) else float(v)


def stem(variant, case):
    return re.sub(r"[^A-Za-z0-9._-]", "-", f"{variant}-{case}")


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600, **kw)
    if r.returncode != 0:
        fail(
            f'{cmd if isinstance(cmd, str) else " ".join(cmd)} exited {r.returncode}:\n'
            f"{r.stdout[-2000:]}{r.stderr[-2000:]}"
        )
    return r.stdout


def program_output(path, node_path, env):
    """Builds and runs the program as its comment says; its standard output."""
    text = path.read_text()
    if path.suffix in (".c", ".cpp"):
        m = re.search(r"^//   ((?:g\+\+|gcc|cc|c\+\+) .*)$", text, re.M)
        if not m:
            fail(f"{path.name}: no one-line compile command in its comment")
        return run(["bash", "-c", m.group(1)], cwd=path.parent, env=dict(os.environ, **env))
    if path.suffix == ".js":
        if not re.search(r"NODE_PATH=build/npm/[a-z0-9-]+/node_modules node ", text):
            fail(f"{path.name}: its comment does not say how it finds its package")
        env = dict(os.environ, NODE_PATH=node_path)
        return run(["node", path.name], cwd=path.parent, env=env)
    if path.suffix == ".py":
        return run(["/usr/bin/python3", path.name], cwd=path.parent)
    fail(f"{path.name}: no way to run a {path.suffix} program")


def printed_answer(out, name):
    """{"distance": [x], "pointA": [x, y], "pointB": [x, y]} from the program's "answer" lines:
    the hexadecimal numbers at the end of each (C's %a, JS's and Python's equivalents)."""
    got = {}
    for line in out.splitlines():
        t = line.split()
        if len(t) >= 3 and t[0] == "answer" and t[1] in ("distance", "pointA", "pointB"):
            n = 1 if t[1] == "distance" else 2
            got[t[1]] = [float.fromhex(h) for h in t[-n:]]
    if set(got) != {"distance", "pointA", "pointB"}:
        fail(f"{name}: the program did not print its answer lines:\n{out}")
    return got


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--variant", required=True)
    ap.add_argument("--family", required=True)
    ap.add_argument("--seed", default="1")
    ap.add_argument("--cases", required=True, help="case names, separated by commas")
    ap.add_argument("--work", required=True)
    ap.add_argument(
        "--node-path",
        default="",
        help="the project's npm packages of the peer: build/npm/<peer>/node_modules",
    )
    ap.add_argument(
        "--env",
        action="append",
        default=[],
        help="NAME=VALUE for the compile command (BOX2D3: the Box2D v3 sources)",
    )
    ap.add_argument(
        "--expect-on-overlap",
        action="append",
        default=[],
        help="an extension repro must also write on an overlapping case, and only there "
        "(planck's .md bug report)",
    )
    a = ap.parse_args()

    listed = subprocess.run([a.exe, "list", "--peers"], capture_output=True, text=True).stdout
    names = re.findall(r"^  (\S+) +(?:float|double) +comparison plugin ", listed, re.M)
    if a.variant.endswith("*"):  # the first variant of that prefix (GEOS's carries its version)
        a.variant = next((n for n in names if n.startswith(a.variant[:-1])), a.variant)
    if a.variant not in names:
        skip(
            f"{a.variant} is not built here (gjk-validate list --peers does not list it"
            f'{"; the Box2D v3 variant needs the Box2D v3 sources" if a.variant.startswith("box2d-3") else ""})'
        )
    work = pathlib.Path(a.work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    kinds = set()
    for case in a.cases.split(","):
        where = ["--peers", "--family", a.family, "--seed", a.seed, case, "--variants", a.variant]
        run([a.exe, "explain", *where, "--json", str(work / "detail.json")])
        detail = json.loads((work / "detail.json").read_text())
        v = detail["variants"][a.variant]
        if "distance" not in v:
            fail(f"{case}: {a.variant} gave no answer to compare: {v}")
        truth = detail[
            "exact_float_input"
            if v["type"] == "float" and "exact_float_input" in detail
            else "exact"
        ]
        kinds.add("overlap" if truth["overlap"] else "separated")
        run([a.exe, "repro", *where, "--out", str(work)])
        s = stem(a.variant, case)
        programs = [
            p for p in work.iterdir() if p.stem == s and p.suffix in (".c", ".cpp", ".js", ".py")
        ]
        if len(programs) != 1:
            fail(f"{case}: expected one program {s}.*, found {[p.name for p in programs]}")
        for ext in a.expect_on_overlap:
            if (work / (s + ext)).is_file() != truth["overlap"]:
                fail(
                    f'{case}: repro {"wrote no" if truth["overlap"] else "wrote a"} {s}{ext} on '
                    f'{"an overlapping" if truth["overlap"] else "a separated"} case'
                )
        code = re.sub(r'/\*.*?\*/|""".*?"""', "", programs[0].read_text(), flags=re.S)
        if "gjk2d" in re.sub(r"(//|#).*", "", code).replace("gjk-validate", ""):
            fail(f"{programs[0].name}: gjk2d appears in its code (only its comments may name it)")
        out = program_output(programs[0], a.node_path, dict(e.split("=", 1) for e in a.env))
        got = printed_answer(out, programs[0].name)
        want = {
            "distance": [number(v["distance"])],
            "pointA": [number(x) for x in v["pointA"]],
            "pointB": [number(x) for x in v["pointB"]],
        }
        for key in want:
            if [bits(x) for x in got[key]] != [bits(x) for x in want[key]]:
                fail(
                    f"{case}: the program prints {key} {got[key]}, gjk-validate reports {want[key]}"
                    f"\n{out}"
                )
        print(
            f'{case} ({"overlap" if truth["overlap"] else "separated"}): {programs[0].name} '
            f'prints the report\'s answer bit for bit: distance {want["distance"][0]!r}'
        )
    if kinds != {"overlap", "separated"}:
        fail(f"the cases {a.cases} are all {kinds.pop()}: give an overlapping and a separated one")
    return 0


if __name__ == "__main__":
    sys.exit(main())
