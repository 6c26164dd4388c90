#!/usr/bin/env bash
# The tree follows one formatter per language, each pinned to one version, since other versions
# format some constructs differently:
#   C and C++  .clang-format, with Debian 12's clang-format 14 (every C/C++ source git tracks,
#              the .in templates too);
#   Python     black 23.1 (Debian 12's), line length 100 as the C++ (pyproject.toml, [tool.black]);
#   JavaScript prettier, pinned by scripts/format/package-lock.json and installed into
#              build/npm/format/ by scripts/setup_npm.sh (.prettierrc.json: width 100 as the C++).
#   scripts/check_format.sh [--fix] [cpp|python|js ...]   (from anywhere; no language: all three;
#                                                       --fix rewrites the files in place)
# Not docs/peers/repro/: the programs `gjk-validate repro` wrote for docs/peers.md, kept as it wrote
# them (scripts/peers_doc.py), since a maintainer runs them as they are.
# Exit codes: 0 every file follows its formatter (or --fix rewrote them); 1 files that do not, one
# line each ("FORMATTER: FILE: ..."); 77 skipped: a formatter is missing (with GJK2D_REQUIRE_ALL=1,
# as in CI, a missing formatter is a failure: scripts/setup.sh --tests installs them).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
fix=0
if [[ ${1:-} == --fix ]]; then
  fix=1
  shift
fi
languages=("$@")
[[ ${#languages[@]} == 0 ]] && languages=(cpp python js)

skip() {
  if [[ ${GJK2D_REQUIRE_ALL:-0} == 1 ]]; then
    echo "check_format: $1 not found, and GJK2D_REQUIRE_ALL=1 makes a skip a failure (scripts/setup.sh --tests installs it)" >&2
    exit 1
  fi
  echo "SKIP check_format: $1 not found (scripts/setup.sh --tests installs it)"
  exit 77
}

check_cpp() {
  local fmt="" candidate f n bad=0
  for candidate in clang-format-14 clang-format; do
    if command -v "$candidate" >/dev/null && "$candidate" --version | grep -q 'version 14\.'; then
      fmt=$candidate
      break
    fi
  done
  [[ -z $fmt ]] && skip "clang-format 14"
  mapfile -t files < <(git ls-files '*.c' '*.cpp' '*.h' '*.hpp' '*.hpp.in' ':!docs/peers/repro/*')
  if [[ $fix == 1 ]]; then
    "$fmt" -i --style=file "${files[@]}"
    echo "check_format: formatted ${#files[@]} C/C++ files with $fmt"
    return 0
  fi
  for f in "${files[@]}"; do
    n=$("$fmt" --style=file "$f" | diff "$f" - | grep -c '^>' || true)
    if [[ $n != 0 ]]; then
      echo "clang-format: $f: $n lines differ (scripts/check_format.sh --fix cpp rewrites it)"
      bad=1
    fi
  done
  [[ $bad == 0 ]] && echo "check_format: ${#files[@]} C/C++ files follow .clang-format ($fmt)"
  return $bad
}

check_python() {
  command -v black >/dev/null && black --version | grep -q ' 23\.1\.' || skip "black 23.1"
  mapfile -t files < <(git ls-files '*.py' '*.pyi' ':!docs/peers/repro/*')
  if [[ $fix == 1 ]]; then
    black --quiet "${files[@]}"
    echo "check_format: formatted ${#files[@]} Python files with black"
    return 0
  fi
  # black --check names each file it would change on stderr: "would reformat FILE".
  local out
  if ! out=$(black --check "${files[@]}" 2>&1); then
    grep '^would reformat ' <<<"$out" |
      sed 's/^would reformat \(.*\)$/black: \1: would reformat (scripts\/check_format.sh --fix python rewrites it)/'
    grep -v '^would reformat \|^Oh no\|files\? would be reformatted\|^All done' <<<"$out" >&2 || true
    return 1
  fi
  echo "check_format: ${#files[@]} Python files follow black"
}

check_js() {
  local prettier=$root/build/npm/format/node_modules/.bin/prettier
  [[ -x $prettier ]] || skip "prettier (build/npm/format, scripts/setup_npm.sh)"
  mapfile -t files < <(git ls-files '*.js' '*.mjs' '*.cjs' ':!docs/peers/repro/*')
  if [[ $fix == 1 ]]; then
    "$prettier" --log-level warn --write "${files[@]}"
    echo "check_format: formatted ${#files[@]} JavaScript files with prettier"
    return 0
  fi
  # prettier --list-different prints each file that differs.
  local out
  out=$("$prettier" --list-different "${files[@]}" || true)
  if [[ -n $out ]]; then
    sed 's/^\(.*\)$/prettier: \1: differs (scripts\/check_format.sh --fix js rewrites it)/' <<<"$out"
    return 1
  fi
  echo "check_format: ${#files[@]} JavaScript files follow prettier ($("$prettier" --version))"
}

status=0
for language in "${languages[@]}"; do
  case $language in
    cpp) check_cpp || status=1 ;;
    python) check_python || status=1 ;;
    js) check_js || status=1 ;;
    *) echo "check_format: unknown language '$language' (cpp, python or js)" >&2; exit 2 ;;
  esac
done
exit $status
