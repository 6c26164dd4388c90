#!/usr/bin/env bash
# The table of docs/gjk.md, "Compiler flags", from a flag-matrix run (ctest -L flags): per build,
# the consumer's hash of all float and all double outputs and the gjk tests' result.
#   flag_table.sh WORK_DIR   (WORK_DIR: <build>/tests/consumer/flags)
set -euo pipefail
work=$1
echo "| build | float outputs | double outputs | gjk tests (failed / test cases) |"
echo "|---|---|---|---|"
for dir in "$work"/*/; do
    name=$(basename "$dir")
    [[ -f $dir/hashes ]] || continue
    f=$(awk '$1 == "float" && $2 == "all" {print $3}' "$dir/hashes")
    d=$(awk '$1 == "double" && $2 == "all" {print $3}' "$dir/hashes")
    t="-"
    if [[ -f $dir/gjk_tests.xml ]]; then
        t=$(grep -o '<OverallResultsCases [^/]*' "$dir/gjk_tests.xml" | tail -n 1 |
            sed -E 's/.*successes="([0-9]+)" failures="([0-9]+)".*/\1 \2/' | awk '{print $2 " / " $1 + $2}')
    fi
    echo "| $name | \`$f\` | \`$d\` | $t |"
done
