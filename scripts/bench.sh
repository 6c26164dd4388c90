#!/usr/bin/env bash
# Development: set up, build and run the speed measurements of docs/speed.md in one go.
#  1. the GJK Google Benchmark program (gjk_bench): cold, learned-predictor, batch and warm
#     queries on the `random` distribution, and the cost against n of both support strategies;
#  2. the exact side's benchmark program (exact_bench);
#  3. `gjk-validate bench` on 20,000 `random` cases for every variant (GJK alone, no exact side),
#     writing its JSON (with the context block) to build/release/bench-random.json.
# Medians of repeated passes, single-threaded. The machine is noisy: compare ratios within a run.
# Extra arguments are passed to gjk_bench (e.g. --benchmark_filter=BM_Random).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

scripts/setup.sh

cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs" --target gjk_bench exact_bench gjk-validate

build/release/gjk/gjk_bench --benchmark_min_time=0.3 --benchmark_repetitions=5 \
    --benchmark_report_aggregates_only=true "$@"
build/release/exact/exact_bench --benchmark_min_time=0.2
build/release/validation/gjk-validate bench --family random:20000 --variants all \
    --json build/release/bench-random.json
