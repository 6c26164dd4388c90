#!/usr/bin/env bash
# The README's second command: set up, build and run every test.
#  1. installs missing Debian packages (scripts/setup.sh --tests),
#  2. builds the release preset (library, exact side, runner, tests) and runs all tests with CTest,
#  3. builds everything again under the address + undefined-behaviour sanitizer preset (the GJK
#     core, the exact side, the runner and their tests) and runs every test there too,
#  4. runs the libFuzzer targets for a bounded time under ASan + UBSan (scripts/fuzz.sh),
#  5. prints what each test stage skipped, and why (scripts/skipped_tests.py; docs/testing.md,
#     "Skips"): in a user's clone, the Box2D v3 adapter's tests and the documented commands that
#     need its sources; in CI (GJK2D_REQUIRE_ALL=1) nothing but a flag build this CPU cannot run.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

scripts/setup.sh --tests

cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs"
# --test-output-size-passed: the JUnit file keeps a passing test's whole output (CTest keeps 1 KB),
# where the docs test lists the commands it skipped.
ctest --preset release -j "$jobs" --output-junit "$PWD/build/release/ctest-junit.xml" \
  --test-output-size-passed 1000000

cmake --preset sanitize -DGJK2D_BUILD_VALIDATION=ON >/dev/null
cmake --build --preset sanitize -j "$jobs"
# Labels flags and cross build with their own compilers and flags; release-only gives the same answer
# from either build (docs/testing.md, "The tests"): each runs once, above.
ctest --preset sanitize -j "$jobs" -LE "flags|release-only|cross|browser" \
  --output-junit "$PWD/build/sanitize/ctest-junit.xml" --test-output-size-passed 1000000

# The libFuzzer targets under ASan + UBSan, 30 s each (docs/fuzzing.md).
scripts/fuzz.sh 30

python3 scripts/skipped_tests.py release build/release/ctest-junit.xml
python3 scripts/skipped_tests.py sanitize build/sanitize/ctest-junit.xml
