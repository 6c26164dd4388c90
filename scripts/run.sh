#!/usr/bin/env bash
# The README's first command: set up, build, and run the default validation campaign.
# Extra arguments are passed to `gjk-validate run` (e.g. --family random:1000).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

scripts/setup.sh

cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs" --target gjk-validate
exec build/release/validation/gjk-validate run "$@"
