#!/usr/bin/env bash
# The tree follows its own .clang-format: every C and C++ source git tracks (the .in templates
# too), checked with Debian 12's clang-format 14. Other versions format some constructs
# differently, so the check pins the version instead of chasing theirs.
#   scripts/check_format.sh [--fix]    (from anywhere; --fix rewrites the files in place)
# Exit codes: 0 every file follows the style (or --fix rewrote them); 1 files that do not, one
# line each ("clang-format: FILE: N lines differ"); 77 skipped: no clang-format 14 (with
# GJK2D_REQUIRE_ALL=1, as in CI, a missing formatter is a failure: scripts/setup.sh --tests
# installs it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
fmt=""
for candidate in clang-format-14 clang-format; do
  if command -v "$candidate" >/dev/null && "$candidate" --version | grep -q 'version 14\.'; then
    fmt=$candidate
    break
  fi
done
if [[ -z $fmt ]]; then
  if [[ ${GJK2D_REQUIRE_ALL:-0} == 1 ]]; then
    echo "check_format: clang-format 14 not found, and GJK2D_REQUIRE_ALL=1 makes a skip a failure (scripts/setup.sh --tests installs it)" >&2
    exit 1
  fi
  echo "SKIP check_format: clang-format 14 not found (scripts/setup.sh --tests installs it)"
  exit 77
fi
# Not docs/peers/repro/: the programs `gjk-validate repro` wrote for docs/peers.md, kept as it wrote
# them (scripts/peers_doc.py), since a maintainer runs them as they are.
mapfile -t files < <(git ls-files '*.c' '*.cpp' '*.h' '*.hpp' '*.hpp.in' ':!docs/peers/repro/*')
if [[ ${1:-} == --fix ]]; then
  "$fmt" -i --style=file "${files[@]}"
  echo "check_format: formatted ${#files[@]} files with $fmt"
  exit 0
fi
bad=0
for f in "${files[@]}"; do
  n=$("$fmt" --style=file "$f" | diff "$f" - | grep -c '^>' || true)
  if [[ $n != 0 ]]; then
    echo "clang-format: $f: $n lines differ (scripts/check_format.sh --fix rewrites it)"
    bad=1
  fi
done
[[ $bad == 0 ]] && echo "check_format: ${#files[@]} files follow .clang-format ($fmt)"
exit $bad
