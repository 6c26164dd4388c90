#!/usr/bin/env python3
"""CTest "docs: an optional part's commands are marked, and skipped with their reason where it is
not built": scripts/check_doc_commands.py's lacking_part and scripts/skipped_tests.py's summary,
on inputs made here, against values written by hand (docs/testing.md, "Skips"). Writes only under
a temporary directory."""
import pathlib
import subprocess
import sys
import tempfile

SCRIPTS = pathlib.Path(__file__).resolve().parent.parent / "scripts"
sys.path.insert(0, str(SCRIPTS))
from check_doc_commands import lacking_part  # noqa: E402

BENCH = "gjk-validate bench --family random:20 --against box2d-v3"
EXPLAIN = "gjk-validate explain x.json c --plugin build/release/validation/plugins/gjk2d-box2d3.so"
MARK = "The Box2D v3 row (needs the Box2D\n v3 sources):"  # wrapped, as a paragraph may be

JUNIT = """<?xml version="1.0" encoding="UTF-8"?>
<testsuite name="t" tests="4" failures="0" disabled="0" skipped="2">
  <testcase name="docs" status="run"><system-out>skipped: README.md:9: needs X: gjk-validate y
ran 3 commands
</system-out></testcase>
  <testcase name="plain" status="run"><system-out>ok
</system-out></testcase>
  <testcase name="v3" status="notrun"><skipped message="SKIP_RETURN_CODE=77"/><system-out>skipped: no sources
</system-out></testcase>
  <testcase name="chromium" status="notrun"><skipped message="SKIP_RETURN_CODE=77"/><system-out>check
Chromium missing
</system-out></testcase>
</testsuite>
"""
SUMMARY = """skips (release): 2 tests skipped, 1 part of passing tests skipped
- v3: no sources
- chromium: Chromium missing
- docs: README.md:9: needs X: gjk-validate y
release: 2 passed, 0 failed, 2 skipped
"""


def main():
    errors = []
    with tempfile.TemporaryDirectory(prefix="skips_check.") as t:
        t = pathlib.Path(t)
        lacking, built = t / "lacking", t / "built"
        (built / "validation" / "plugins").mkdir(parents=True)
        (built / "validation" / "plugins" / "gjk2d-box2d3.so").write_text("")
        lacking.mkdir()
        for command in (BENCH, EXPLAIN):
            e = []
            reason = lacking_part("d.md", 1, command, MARK, lacking, e)
            if e or not reason or not reason.startswith("needs the Box2D v3 sources, not given"):
                errors.append(f"marked, not built: {command}: reason {reason!r}, errors {e}")
            e = []
            if lacking_part("d.md", 1, command, MARK, built, e) is not None or e:
                errors.append(f"marked, built: {command} is skipped or an error: {e}")
            e = []
            lacking_part("d.md", 1, command, "no mark here", built, e)
            if len(e) != 1 or "needs an optional part (box2d-v3)" not in e[0]:
                errors.append(f"unmarked: {command}: errors {e}, expected one")
        e = []
        if lacking_part("d.md", 1, "gjk-validate bench --against planck", "", lacking, e) or e:
            errors.append(f"a command needing no optional part is skipped or an error: {e}")
        junit = t / "junit.xml"
        junit.write_text(JUNIT)
        r = subprocess.run(
            [sys.executable, str(SCRIPTS / "skipped_tests.py"), "release", str(junit)],
            capture_output=True,
            text=True,
        )
        if r.returncode != 0 or r.stdout != SUMMARY:
            errors.append(
                f"skipped_tests.py exited {r.returncode}, printed:\n{r.stdout}{r.stderr}"
                f"expected:\n{SUMMARY}"
            )
        r = subprocess.run(
            [sys.executable, str(SCRIPTS / "skipped_tests.py"), "release", str(t / "none.xml")],
            capture_output=True,
            text=True,
        )
        if r.returncode != 2 or "none.xml" not in r.stderr:
            errors.append(f"a missing JUnit file: exit {r.returncode}, {r.stderr!r}")
    for e in errors:
        print("FAIL: " + e)
    print(f"{len(errors)} failures")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
