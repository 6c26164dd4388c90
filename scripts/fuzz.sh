#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, docs/fuzzing.md) with clang-14 under ASan + UBSan in
# build/fuzz and runs each for SECONDS_PER_TARGET seconds (default 60), one after the other, one
# process each, starting from a scratch copy of the committed corpus fuzz/corpus/<target>/.
#   scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET...]]   (targets: fuzz_case_file fuzz_distance
#   fuzz_truth; default all)
# Prints per target the inputs run (libFuzzer's stat::number_of_executed_units) and the seconds.
# Exit codes: 0 no finding; 1 a finding (the input is saved under build/fuzz/findings/<target>/,
# the log under build/fuzz/logs/); 2 bad argument; 3 missing packages (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${1:-60}"
targets=("${@:2}")
[[ ${#targets[@]} -eq 0 ]] && targets=(fuzz_case_file fuzz_distance fuzz_truth)
if ! [[ "$seconds" =~ ^[1-9][0-9]{0,6}$ ]]; then
  echo "usage: scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET...]]  (a positive integer, default 60)" >&2
  exit 2
fi
for target in "${targets[@]}"; do
  if [[ "$target" != fuzz_case_file && "$target" != fuzz_distance && "$target" != fuzz_truth ]]; then
    echo "scripts/fuzz.sh: unknown target '$target' (fuzz_case_file, fuzz_distance, fuzz_truth)" >&2
    exit 2
  fi
done

scripts/setup.sh --fuzz

# Only the fuzz targets and the two small libraries they link (no tests, no runner, no benchmarks).
cmake -S . -B build/fuzz -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGJK2D_BUILD_FUZZERS=ON -DGJK2D_BUILD_TESTS=OFF -DGJK2D_BUILD_VALIDATION=OFF \
  -DGJK2D_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build/fuzz -j 2 --target "${targets[@]}"

# Longest input per target: a case file up to 8 KiB (the committed ones are below); a distance
# query needs at most 2 + 2 * 418 bytes (20 points of raw doubles per shape).
# fuzz_truth: two shapes of up to 8 points, each number at most 9 bytes.
declare -A max_len=([fuzz_case_file]=8192 [fuzz_distance]=1024 [fuzz_truth]=512)

scratch=$(mktemp -d "${TMPDIR:-/tmp}/gjk2d-fuzz.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
mkdir -p build/fuzz/logs
status=0
for target in "${targets[@]}"; do
  corpus="$scratch/$target"
  findings="build/fuzz/findings/$target"
  log="build/fuzz/logs/$target.log"
  mkdir -p "$findings"
  cp -r "fuzz/corpus/$target" "$corpus"
  start=$(date +%s)
  rc=0
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ASAN_OPTIONS=detect_leaks=1 \
    "build/fuzz/fuzz/$target" "$corpus" -max_total_time="$seconds" -max_len="${max_len[$target]}" \
    -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings/" \
    >"$log" 2>&1 || rc=$?
  elapsed=$(($(date +%s) - start))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  if [[ $rc -eq 0 ]]; then
    echo "fuzz: $target: ${runs:-?} inputs in $elapsed s, no finding"
  else
    status=1
    echo "fuzz: $target: FINDING after ${runs:-?} inputs in $elapsed s (libFuzzer exit $rc)" >&2
    grep -E "FINDING|ERROR|SUMMARY|runtime error" "$log" | head -n 10 >&2 || true
    echo "fuzz: input saved in $findings/, full log $log; replay: build/fuzz/fuzz/$target FILE" >&2
  fi
done
exit $status
