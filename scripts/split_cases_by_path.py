#!/usr/bin/env python3
"""Split a gjk-cases/1 file by the path a correctly rounded variant took on each case.

Usage: scripts/split_cases_by_path.py CASES.json CASES.jsonl [VARIANT]

CASES.jsonl is the per-case output of `gjk-validate run --cases CASES.json --per-case` with the
variant (default double-correct) among --variants. Writes, beside CASES.json, one file per path
(gjk::CorrectPath, docs/gjk.md "Correctly rounded distance"): STEM-double.json,
STEM-extended.json, STEM-double-double.json, STEM-exact.json, each with the cases that took that path (a path no case
took gets no file), so that `gjk-validate bench --cases` can time each path on its own.
Exit codes: 0 written, 2 bad input (unreadable file, a case without the variant's path).
"""
import json
import pathlib
import sys


def main():
    if len(sys.argv) not in (3, 4):
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    cases_path, jsonl_path = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    variant = sys.argv[3] if len(sys.argv) == 4 else "double-correct"
    try:
        cases = json.loads(cases_path.read_text())
        lines = jsonl_path.read_text().splitlines()
    except (OSError, ValueError) as e:
        print(f"split_cases_by_path: {e}", file=sys.stderr)
        return 2
    path_of = {}
    for number, line in enumerate(lines, 1):
        record = json.loads(line)
        try:
            path_of[record["name"]] = record["variants"][variant]["path"]
        except KeyError:
            print(
                f"split_cases_by_path: {jsonl_path}:{number}: case '{record.get('name')}' has no "
                f"path for variant '{variant}'",
                file=sys.stderr,
            )
            return 2
    groups = {}
    for case in cases["cases"]:
        if case["name"] not in path_of:
            print(
                f"split_cases_by_path: case '{case['name']}' is not in {jsonl_path}",
                file=sys.stderr,
            )
            return 2
        groups.setdefault(path_of[case["name"]], []).append(case)
    for path, group in sorted(groups.items()):
        out = cases_path.with_name(f"{cases_path.stem}-{path}.json")
        comment = f"the {len(group)} cases of {cases_path.name} where {variant} took path '{path}'"
        out.write_text(
            json.dumps(
                {
                    "format": "gjk-cases/1",
                    "comments": cases.get("comments", []) + [comment],
                    "cases": group,
                }
            )
            + "\n"
        )
        print(f"{out}: {len(group)} cases ({path})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
