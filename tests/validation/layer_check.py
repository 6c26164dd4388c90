#!/usr/bin/env python3
"""The layer order of validation/src/ (docs/validation.md, "Layers"), checked: every
`#include "LAYER/..."` in validation/src/<layer>/ names its own layer or one below it.

Usage: layer_check.py [SRC]   (SRC: validation/src, the default found from this file)
Exit 0 when every include runs downwards; 1 with one line per backward include, naming the file,
the line and both layers. A folder of SRC that is not in LAYERS fails too (a new folder takes its
place in the order, here and in the docs, before it holds code).
"""
import pathlib
import re
import sys

# Lowest first: a layer may include itself and the layers before it.
LAYERS = ["common", "inputs", "evaluate", "statistics", "timing", "report", "campaign", "commands"]

# Backward includes allowed for now: (file relative to SRC, included layer) -> the reason.
# Empty: issue 31's first step moved everything that ran backwards. Add one only with its reason
# and the issue that removes it, so that it shows.
EXCEPTIONS = {}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([A-Za-z0-9_]+)/')


def check(src):
    rank = {name: i for i, name in enumerate(LAYERS)}
    problems = []
    for folder in sorted(p for p in src.iterdir() if p.is_dir()):
        if folder.name not in rank:
            problems.append(f"{folder}: a folder of validation/src/ that is not in the layer order "
                            f"(tests/validation/layer_check.py, LAYERS)")
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
                problems.append(f"validation/src/{rel}:{number}: layer '{own}' includes layer "
                                f"'{other}', which is above it ({' < '.join(LAYERS)})")
    return problems


def main():
    here = pathlib.Path(__file__).resolve().parent
    src = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else here.parent.parent / "validation" / "src"
    if not src.is_dir():
        print(f"layer_check: {src}: not a directory", file=sys.stderr)
        return 2
    problems = check(src)
    for p in problems:
        print(p, file=sys.stderr)
    for (rel, other), reason in EXCEPTIONS.items():
        print(f"allowed: validation/src/{rel} includes '{other}': {reason}")
    if not problems:
        print(f"layer_check: every include of {src} runs downwards ({' < '.join(LAYERS)})")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
