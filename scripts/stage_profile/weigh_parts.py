#!/usr/bin/env python3
"""Weighs parts of the query by taking them out of a copy of the headers (docs/speed.md, "Prepared
shapes and the warm path"): for each part, the instructions a `double` query costs warm and cold
under callgrind without it. The copies are measuring devices, never builds to ship: the range checks
and the world frame are the query's contract.

    scripts/stage_profile/weigh_parts.py OUTDIR CASES.txt

CASES.txt: cases as stage_profile.sh takes them (random_cases.py writes them). Builds
stage_driver.cpp once per part with build_driver.sh on the edited headers (needs the anchors beside
the repository, ANCHORS to point elsewhere), runs `dw` (10 passes) and `d` (3 passes) under callgrind. Each edit
must match the headers exactly: when the code it names has changed, the script stops (exit 1) rather
than weigh something else. Exit codes: 0 printed, 1 an edit no longer matches, 2 bad usage or a
missing tool or file.
"""

import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.path.join(ROOT, "scripts", "stage_profile", "build_driver.sh")

# Each part: (file, text, replacement) edits, applied to a copy of gjk/include/gjk2d.
RANGE_CHECKS = [
    (
        "support.hpp",
        "if constexpr (Checked) // else the sum",
        "if constexpr (false) // else the sum",
    ),
    (
        "support.hpp",
        "bool overflowed() const { return overflow || !(scanCheck == T(0)); }",
        "bool overflowed() const { return false; }",
    ),
    (
        "distance.hpp",
        "if constexpr (Shape::checked) // else decided",
        "if constexpr (false) // else decided",
    ),
    (
        "distance.hpp",
        "    auto zeroIfFinite = [](T x) { return x - x; };",
        "    return false;\n    auto zeroIfFinite = [](T x) { return x - x; };",
    ),
    (
        "distance.hpp",
        "    for (int i = 0; i < simplex.count; ++i)\n"
        "        end.maxAbs = std::max({end.maxAbs, std::abs(simplex.v[i].w.x), "
        "std::abs(simplex.v[i].w.y)});",
        "    end.maxAbs = T(1);",
    ),
]
WORLD_FRAME = [
    (
        "distance.hpp",
        "    const T frameSize2 = squaredSize(world.q);\n    a.pointA",
        "    return false;\n    const T frameSize2 = squaredSize(world.q);\n    a.pointA",
    ),
]
PARTS = [
    ("nothing", []),
    ("the range checks", RANGE_CHECKS),
    ("the world frame", WORLD_FRAME),
    ("both", RANGE_CHECKS + WORLD_FRAME),
]


def copy_headers(where, edits):
    include = os.path.join(where, "include")
    shutil.rmtree(include, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "gjk", "include"), include)
    for name, text, replacement in edits:
        path = os.path.join(include, "gjk2d", name)
        with open(path) as f:
            source = f.read()
        if source.count(text) != 1:
            sys.exit(f"weigh_parts: gjk2d/{name} no longer has this once: {text.splitlines()[0]!r}")
        with open(path, "w") as f:
            f.write(source.replace(text, replacement))
    return include


def instructions(driver, mode, cases, passes, function, where):
    out = os.path.join(where, f"callgrind.{mode}")
    subprocess.run(
        [
            "valgrind",
            "--tool=callgrind",
            f"--callgrind-out-file={out}",
            driver,
            mode,
            cases,
            str(passes),
        ],
        check=True,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    text = subprocess.run(
        ["callgrind_annotate", "--inclusive=yes", out], check=True, capture_output=True, text=True
    ).stdout
    for line in text.splitlines():
        if function in line and "=>" not in line:
            return int(re.match(r"\s*([\d,]+)", line).group(1).replace(",", ""))
    sys.exit(f"weigh_parts: no {function} in {out}")


def main():
    if len(sys.argv) != 3:
        print("usage: weigh_parts.py OUTDIR CASES.txt", file=sys.stderr)
        return 2
    out, cases = sys.argv[1], os.path.abspath(sys.argv[2])
    anchors = os.environ.get("ANCHORS", os.path.join(ROOT, "..", "shared", "anchors"))
    for tool in ("valgrind", "callgrind_annotate"):
        if shutil.which(tool) is None:
            print(f"weigh_parts: {tool} not found", file=sys.stderr)
            return 2
    if not os.path.isfile(os.path.join(anchors, "cases.h")) or not os.path.isfile(cases):
        print(f"weigh_parts: no {anchors}/cases.h or {cases}", file=sys.stderr)
        return 2
    os.makedirs(out, exist_ok=True)
    count = sum(1 for line in open(cases) if line.startswith("case "))
    print("| taken out | warm | cold |")
    print("|---|---|---|")
    for index, (name, edits) in enumerate(PARTS):
        where = os.path.join(out, f"part{index}")
        os.makedirs(where, exist_ok=True)
        include = copy_headers(where, edits)
        env = dict(os.environ, ANCHORS=anchors, GJK_INCLUDE=include)
        subprocess.run([BUILD, where], check=True, env=env)
        driver = os.path.join(where, "stage_driver")
        warm = instructions(driver, "dw", cases, 10, "queryWarm<double>(gjk", where) / (10 * count)
        cold = instructions(driver, "d", cases, 3, "query<double>(gjk", where) / (3 * count)
        print(f"| {name} | {warm:.1f} | {cold:.1f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
