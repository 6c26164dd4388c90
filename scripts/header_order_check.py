#!/usr/bin/env python3
"""The header table of docs/code-map.md ("`gjk/`: the talk's sections, one header each") checked
against gjk/include/gjk2d/:

  - every header of gjk/include/gjk2d/ (detail/ included) has a row, and every row a header;
  - each header includes (`#include "gjk2d/..."`) only headers listed above it in the table,
    except an include that UPWARD below names with its reason;
  - every path in backticks in docs/code-map.md that starts with a folder of the repository exists.

Usage: header_order_check.py [ROOT]     check the tree at ROOT (default: this script's repository)
       header_order_check.py --self-test
The self-test copies gjk/include/ and docs/code-map.md to a temporary tree, checks that the copy
passes, then plants an upward include (types.hpp including distance.hpp), a header missing from
the table, and a path that does not exist, one at a time, and checks that each fails, naming it.
Exit 0 when everything holds; 1 with one line per problem (or a failed self-test); 2 bad usage.
"""
import pathlib
import re
import shutil
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOC = "docs/code-map.md"
INCLUDE_DIR = "gjk/include/gjk2d"
SECTION = "## `gjk/`: the talk's sections, one header each"

# Includes of a header listed below the includer: (includer, included) -> the reason.
UPWARD = {
    (
        "distance.hpp",
        "expand.hpp",
    ): "distance.hpp includes expand.hpp at its end, after everything expand.hpp uses, so that "
    '`#include "gjk2d/distance.hpp"` brings the signed distance too',
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"gjk2d/([^"]+)"', re.M)
ROW = re.compile(r"^\|\s*`([^`]+)`\s*\|", re.M)
PATH = re.compile(
    r"`((?:gjk|exact|validation|python|tests|scripts|docs|examples|fuzz|cmake)/[^`\s]*)`"
)


def table_order(doc_text):
    """The headers of the section's table, top down, as paths relative to gjk2d/."""
    start = doc_text.find(SECTION)
    if start < 0:
        raise SystemExit(f'header_order_check: {DOC} has no section "{SECTION[3:]}"')
    end = doc_text.find("\n## ", start + 1)
    section = doc_text[start : end if end >= 0 else len(doc_text)]
    return [name for name in ROW.findall(section) if name.endswith((".hpp", ".h"))]


def check(root):
    root = pathlib.Path(root)
    problems = []
    doc_text = (root / DOC).read_text()
    order = table_order(doc_text)
    rank = {name: i for i, name in enumerate(order)}
    inc = root / INCLUDE_DIR
    headers = sorted(str(p.relative_to(inc)) for p in inc.rglob("*") if p.suffix in (".hpp", ".h"))
    for h in headers:
        if h not in rank:
            problems.append(f"{INCLUDE_DIR}/{h}: not in the header table of {DOC}")
    for name in order:
        if name not in headers:
            problems.append(
                f"{DOC}: the header table lists {name}, which {INCLUDE_DIR}/ does not hold"
            )
    for h in headers:
        if h not in rank:
            continue
        text = (inc / h).read_text()
        for m in INCLUDE.finditer(text):
            other = m.group(1)
            line = text.count("\n", 0, m.start()) + 1
            if other not in rank:
                problems.append(
                    f"{INCLUDE_DIR}/{h}:{line}: includes gjk2d/{other}, "
                    f"which the header table of {DOC} does not list"
                )
            elif rank[other] >= rank[h] and (h, other) not in UPWARD:
                problems.append(
                    f"{INCLUDE_DIR}/{h}:{line}: includes gjk2d/{other}, which the "
                    f"header table of {DOC} lists below it"
                )
    for m in PATH.finditer(doc_text):
        path = m.group(1).rstrip(".,;:")
        if "<" in path or "*" in path or "..." in path:
            continue
        if not (root / path).exists():
            line = doc_text.count("\n", 0, m.start()) + 1
            problems.append(f"{DOC}:{line}: `{path}` does not exist")
    return problems


def self_test():
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        base = pathlib.Path(tmp) / "base"
        (base / "docs").mkdir(parents=True)
        shutil.copytree(ROOT / "gjk" / "include", base / "gjk" / "include")
        shutil.copy(ROOT / DOC, base / DOC)
        # Paths of the doc outside gjk/include: stand-ins, so that only the planted faults fail.
        for m in PATH.finditer((ROOT / DOC).read_text()):
            path = m.group(1).rstrip(".,;:")
            if (ROOT / path).exists() and not (base / path).exists():
                target = base / path
                if (ROOT / path).is_dir():
                    target.mkdir(parents=True, exist_ok=True)
                else:
                    target.parent.mkdir(parents=True, exist_ok=True)
                    target.touch()
        if check(base):
            failures.append("the unchanged copy fails: " + "; ".join(check(base)))

        def planted(name, change, expect):
            tree = pathlib.Path(tmp) / name
            shutil.copytree(base, tree)
            change(tree)
            problems = check(tree)
            if not any(expect in p for p in problems):
                failures.append(f"{name}: expected a problem naming '{expect}', got {problems}")

        def upward(tree):
            p = tree / INCLUDE_DIR / "types.hpp"
            p.write_text(
                p.read_text().replace(
                    '#include "gjk2d/math.hpp"',
                    '#include "gjk2d/math.hpp"\n#include "gjk2d/distance.hpp"',
                    1,
                )
            )

        def unlisted(tree):
            (tree / INCLUDE_DIR / "planted.hpp").write_text("#pragma once\n")

        def missing_path(tree):
            p = tree / DOC
            p.write_text(p.read_text() + "\nSee `gjk/src/planted_missing.cpp`.\n")

        planted("upward", upward, "includes gjk2d/distance.hpp, which the header table")
        planted("unlisted", unlisted, "planted.hpp: not in the header table")
        planted("missing-path", missing_path, "planted_missing.cpp` does not exist")
    for f in failures:
        print(f"header_order_check --self-test: {f}")
    if not failures:
        print(
            "header_order_check --self-test: the unchanged tree passes; the planted upward "
            "include, unlisted header and missing path each fail"
        )
    return 1 if failures else 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) > 2 or (len(argv) == 2 and argv[1].startswith("-")):
        print(__doc__.strip().splitlines()[0])
        print("usage: header_order_check.py [ROOT] | --self-test", file=sys.stderr)
        return 2
    problems = check(argv[1] if len(argv) == 2 else ROOT)
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
