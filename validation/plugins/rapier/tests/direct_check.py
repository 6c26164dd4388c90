#!/usr/bin/env python3
"""CTest "plugins: rapier: the report's answers are Rapier's own, bit for bit": on cases made at
test time (a family generated with a seed drawn now, printed so that a failure can be replayed),
`gjk-validate run` with the Rapier adapter writes its answers (cases.jsonl); direct.js, a program
of Rapier's own API alone, computes each case from its world points, which this script derives
from the case file by the protocol's rule (`input NAME world`: x' = (c x - s y) + px,
y' = (s x + c y) + py, each operation rounded to double, then rounded to f32; the radius rounded to
f32); every answer the report holds must be direct.js's, bit for bit, every error one where Rapier
answers null or throws, and every case the adapter refused for want of a Rapier shape one
direct.js cannot build either.

  direct_check.py --exe GJK_VALIDATE --adapter FILE --node-path DIR --work DIR
                  [--family SPEC] [--seed S]

Exit status: 0 pass, 1 fail, 77 the adapter was not built (CTest SKIP_RETURN_CODE); with
GJK2D_REQUIRE_ALL=1 (CI) a skip is a failure.
"""
import argparse
import json
import math
import os
import pathlib
import random
import shutil
import struct
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
VARIANT = "rapier2d-0.21.0"


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=1200, **kw)
    if r.returncode != 0:
        fail(
            f'{" ".join(map(str, cmd))} exited {r.returncode}:\n{r.stdout[-3000:]}{r.stderr[-3000:]}'
        )
    return r.stdout


def f32(x):
    """x rounded to the nearest float, as a double; None when it overflows float."""
    try:
        return struct.unpack("<f", struct.pack("<f", x))[0]
    except OverflowError:
        return None


def bits(x):
    return struct.pack(">d", x).hex()


def world(shape):
    """The shape as the host gives it to a `world` implementation of scalar float: its points
    mapped by its transform in double (Python's float operations are IEEE double, one rounding
    each, no fused multiply-add), then rounded to f32, and its radius rounded to f32. None when a
    number does not fit in f32 (such a case is not Rapier's to answer)."""
    t = shape.get("transform", {})
    px, py = t.get("p", [0.0, 0.0])
    c, s = t.get("q", [1.0, 0.0])
    points = []
    for x, y in shape["points"]:
        wx = f32((c * x - s * y) + px)
        wy = f32((s * x + c * y) + py)
        if wx is None or wy is None or not (math.isfinite(wx) and math.isfinite(wy)):
            return None
        points.append([wx, wy])
    r = f32(shape.get("radius", 0.0))
    return None if r is None else {"points": points, "radius": r}


def number(v):
    return float(v)  # a JSON number, or "nan"/"inf"/"-inf"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--adapter", required=True)
    ap.add_argument(
        "--node-path", required=True, help="the project's build/npm/rapier/node_modules"
    )
    ap.add_argument("--work", required=True)
    ap.add_argument("--family", default="random:1000")
    ap.add_argument("--seed", type=int, default=None, help="drawn at random when not given")
    a = ap.parse_args()
    if not os.access(a.adapter, os.X_OK):
        why = f"{a.adapter} was not built (node and scripts/setup_npm.sh)"
        if os.environ.get("GJK2D_REQUIRE_ALL") == "1":
            fail(f"{why}, and GJK2D_REQUIRE_ALL=1 makes a skip a failure")
        print(f"SKIP: {why}")
        sys.exit(77)
    seed = a.seed if a.seed is not None else random.SystemRandom().randrange(1, 2**31)
    print(f"cases: --family {a.family} --seed {seed} (replay: --seed {seed})")
    work = pathlib.Path(a.work)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    cases_file = work / "cases.json"
    run([a.exe, "generate", "--family", a.family, "--seed", str(seed), "-o", str(cases_file)])
    cases = json.loads(cases_file.read_text())["cases"]
    run(
        [
            a.exe,
            "run",
            "--cases",
            str(cases_file),
            "--no-default-plugins",
            "--plugin",
            a.adapter,
            "--variants",
            VARIANT,
            "--per-case",
            "--no-timing",
            "--no-progress",
            "--out",
            str(work / "report"),
        ]
    )
    answers = {}
    for line in (work / "report" / "cases.jsonl").read_text().splitlines():
        c = json.loads(line)
        if "variants" in c and VARIANT in c["variants"]:
            answers[c["name"]] = c["variants"][VARIANT]

    worlds = []
    for c in cases:
        wa, wb = world(c["a"]), world(c["b"])
        if wa is not None and wb is not None:
            worlds.append({"name": c["name"], "a": wa, "b": wb})
    (work / "world.json").write_text(json.dumps({"cases": worlds}))
    out = run(
        ["node", str(HERE / "direct.js"), str(work / "world.json")],
        env=dict(os.environ, NODE_PATH=a.node_path),
    )
    direct = {}
    for line in out.splitlines():
        t = line.split(" ")
        direct[t[0]] = t[1:]

    same = refused_alike = errors_alike = 0
    kinds = set()
    for name, v in answers.items():
        d = direct.get(name)
        if "distance" in v and v.get("plugin_status", "ok") == "ok":
            if d is None or d[0] == "none":
                fail(
                    f'{name}: the report has {VARIANT} answer {v["distance"]}, direct.js none ({d})'
                )
            got = [number(v["distance"]), *map(number, v["pointA"]), *map(number, v["pointB"])]
            if [bits(x) for x in got] != d:
                fail(f"{name}: the report has {got} ({[bits(x) for x in got]}), direct.js {d}")
            same += 1
            kinds.add("overlap" if got[0] < 0 else "separated")
        elif v.get("plugin_status") == "error":
            # The adapter's error (contactShape's null, or a throw): Rapier itself gives no answer.
            if d is None or d[0] != "none" or d[1] not in ("null", "threw"):
                fail(
                    f"{name}: the adapter answered an error ({json.dumps(v)[:200]}), direct.js {d}"
                )
            errors_alike += 1
        elif "refused" in v.get("skipped", ""):
            # The adapter refused it (cases.jsonl keeps no reason): for want of a Rapier shape, a
            # polygon Rapier builds none of or a rounded segment, where direct.js has no answer
            # either (it builds no shape, or, trying the other shape first, Rapier throws).
            if d is None or d[0] != "none":
                fail(
                    f"{name}: the adapter refused it ({json.dumps(v)[:160]}), direct.js answers {d}"
                )
            refused_alike += 1
    print(
        f"{same} answers the same bit for bit, {errors_alike} errors where Rapier answers null or throws, "
        f"{refused_alike} refused by both for want of a Rapier shape, "
        f"of {len(answers)} cases ({len(cases)} generated)"
    )
    if same < len(answers) // 2 or kinds != {"overlap", "separated"}:
        fail(
            f"too few answers compared ({same} of {len(answers)}), or not both overlapping and separated ({kinds})"
        )
    print("PASS")


if __name__ == "__main__":
    main()
