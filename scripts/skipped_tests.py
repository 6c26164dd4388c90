#!/usr/bin/env python3
"""What a test stage skipped, and why: read from CTest's JUnit file (`ctest --output-junit F`).

Two kinds of skip are counted (docs/testing.md, "Skips"):
  - a test that exited with its SKIP_RETURN_CODE (77): its reason is the lines of its output that
    start with `skipped: `, else the last line it printed;
  - a part of a passing test that it could not run: each line of its output that starts with
    `skipped: ` (the docs test prints one for each documented command whose optional part is not
    built, before anything else: CTest keeps only the head of a passing test's output unless
    --test-output-size-passed says otherwise, as scripts/test.sh does).

Usage: scripts/skipped_tests.py STAGE JUNIT.xml. It prints the skips with their reasons, then the
stage's count as one line, `STAGE: N passed, N failed, N skipped`; exit 0, or 2 when the file is
missing or not CTest's JUnit.
"""
import sys
import xml.etree.ElementTree as ET


def reasons(output):
    return [
        line[len("skipped: ") :] for line in output.splitlines() if line.startswith("skipped: ")
    ]


def summary(stage, root):
    """The summary's lines for one stage's <testsuite>."""
    tests, parts = [], []
    for case in root.iter("testcase"):
        output = case.findtext("system-out") or ""
        if case.find("skipped") is not None:
            said = reasons(output) or [line for line in output.splitlines() if line.strip()][-1:]
            tests.append(f"- {case.get('name')}: {'; '.join(said) or 'no reason printed'}")
        elif case.get("status") == "run":
            parts += [f"- {case.get('name')}: {r}" for r in reasons(output)]
    failed = sum(1 for case in root.iter("testcase") if case.find("failure") is not None)
    passed = sum(1 for _ in root.iter("testcase")) - failed - len(tests)
    head = (
        f"skips ({stage}): {len(tests)} {'test' if len(tests) == 1 else 'tests'} skipped, "
        f"{len(parts)} {'part' if len(parts) == 1 else 'parts'} of passing tests skipped"
    )
    return (
        [head]
        + tests
        + parts
        + [f"{stage}: {passed} passed, {failed} failed, {len(tests)} skipped"]
    )


def main():
    if len(sys.argv) != 3:
        print("usage: scripts/skipped_tests.py STAGE JUNIT.xml", file=sys.stderr)
        return 2
    stage, path = sys.argv[1:]
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        print(f"skipped_tests.py: {path}: {e}", file=sys.stderr)
        return 2
    if root.tag != "testsuite":
        print(f"skipped_tests.py: {path}: not CTest's JUnit (root <{root.tag}>)", file=sys.stderr)
        return 2
    print("\n".join(summary(stage, root)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
