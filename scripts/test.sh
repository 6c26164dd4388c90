#!/usr/bin/env bash
# The README's second command: set up, build and run every test.
#  1. installs missing Debian packages (scripts/setup.sh --tests),
#  2. builds the release preset (library, exact side, runner, tests) and runs all tests with CTest,
#  3. builds the GJK core tests again under the address + undefined-behaviour sanitizer preset
#     (without the CGAL side, which is slow to compile instrumented) and runs them.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

scripts/setup.sh --tests

cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs"
ctest --preset release -j "$jobs"

cmake --preset sanitize -DGJK2D_BUILD_VALIDATION=OFF >/dev/null
cmake --build --preset sanitize -j "$jobs"
ctest --preset sanitize -j "$jobs"

# The libFuzzer targets under ASan + UBSan, 30 s each (docs/fuzzing.md).
scripts/fuzz.sh 30
