#!/usr/bin/env python3
"""The layer order of validation/src/ (docs/judgement.md, "Layers"), checked: every
`#include "LAYER/..."` in validation/src/<layer>/ names its own layer or one below it; every layer
library of validation/CMakeLists.txt links only layers below it; and the docs draw the same order.

The order's home is GJK2D_VALIDATION_LAYERS in validation/CMakeLists.txt, which also builds one
library per layer, so that a backward include does not compile there. This check says the same
before anything is built, naming the file, the line and both layers.

Usage: layer_check.py [SRC]   (SRC: validation/src, the default found from this file)
Exit 0 when everything runs downwards; 1 with one line per problem. A folder of SRC that is not in
the order fails too (a new folder takes its place in the order before it holds code).
"""
import pathlib
import re
import sys


def cmake_layers(cmake_text):
    """GJK2D_VALIDATION_LAYERS, lowest first: a layer may include itself and the layers before it."""
    m = re.search(r"set\(GJK2D_VALIDATION_LAYERS ([a-z ]+)\)", cmake_text)
    if not m:
        raise SystemExit(
            "layer_check: validation/CMakeLists.txt has no set(GJK2D_VALIDATION_LAYERS ...)"
        )
    return m.group(1).split()


def check_links(cmake_text, layers):
    """Each gjk2d_validation_layer(X ... gjk2d_Y ...) call links only layers Y below X."""
    rank = {name: i for i, name in enumerate(layers)}
    problems = []
    for m in re.finditer(r"gjk2d_validation_layer\((\w+)([^)]*)\)", cmake_text):
        own = m.group(1)
        for other in re.findall(r"gjk2d_(\w+)", m.group(2)):
            if other in rank and rank[other] >= rank[own]:
                problems.append(
                    f"validation/CMakeLists.txt: layer '{own}' links layer '{other}', "
                    f"which is not below it"
                )
    return problems


def check_docs(docs_text, layers):
    """The drawing in docs/judgement.md lists the layers top down, one per line."""
    drawn = [w for w in re.findall(r"^([a-z]+) {2,}", docs_text, re.M) if w in layers]
    if drawn != list(reversed(layers)):
        return [
            f"docs/judgement.md: the layer drawing ({' > '.join(drawn)}) differs from "
            f"GJK2D_VALIDATION_LAYERS ({' < '.join(layers)})"
        ]
    return []


# Backward includes allowed for now: (file relative to SRC, included layer) -> the reason.
# Empty: issue 31's first step moved everything that ran backwards. Add one only with its reason
# and the issue that removes it, so that it shows.
EXCEPTIONS = {}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([A-Za-z0-9_]+)/')


def check(src, layers):
    rank = {name: i for i, name in enumerate(layers)}
    problems = []
    for folder in sorted(p for p in src.iterdir() if p.is_dir()):
        if folder.name not in rank:
            problems.append(
                f"{folder}: a folder of validation/src/ that is not in the layer order "
                f"(GJK2D_VALIDATION_LAYERS in validation/CMakeLists.txt)"
            )
            continue
        own = folder.name
        for path in sorted(folder.rglob("*")):
            if path.suffix not in (".hpp", ".cpp", ".h", ".in") or not path.is_file():
                continue
            rel = path.relative_to(src).as_posix()
            for number, line in enumerate(path.read_text().splitlines(), start=1):
                m = INCLUDE.match(line)
                if not m or m.group(1) not in rank:
                    continue  # <...>, "build_info.hpp", "gjk/...", "gjk_html/...": not a layer
                other = m.group(1)
                if rank[other] <= rank[own] or (rel, other) in EXCEPTIONS:
                    continue
                problems.append(
                    f"validation/src/{rel}:{number}: layer '{own}' includes layer "
                    f"'{other}', which is above it ({' < '.join(layers)})"
                )
    return problems


def main():
    here = pathlib.Path(__file__).resolve().parent
    src = (
        pathlib.Path(sys.argv[1])
        if len(sys.argv) > 1
        else here.parent.parent / "validation" / "src"
    )
    if not src.is_dir():
        print(f"layer_check: {src}: not a directory", file=sys.stderr)
        return 2
    root = src.parent.parent
    cmake_text = (root / "validation" / "CMakeLists.txt").read_text()
    layers = cmake_layers(cmake_text)
    problems = check(src, layers) + check_links(cmake_text, layers)
    problems += check_docs((root / "docs" / "judgement.md").read_text(), layers)
    for p in problems:
        print(p, file=sys.stderr)
    for (rel, other), reason in EXCEPTIONS.items():
        print(f"allowed: validation/src/{rel} includes '{other}': {reason}")
    if not problems:
        print(f"layer_check: every include of {src} runs downwards ({' < '.join(layers)})")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
