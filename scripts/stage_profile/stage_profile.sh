#!/usr/bin/env bash
# Instructions per cold query, per stage, under callgrind: gjk2d's query (double or float) or Box2D
# v3's b2ShapeDistance on the same cases (docs/speed.md, "The cold query on engine data").
#   scripts/stage_profile/stage_profile.sh OUTDIR CASES.txt d|f|b [REPS]
# CASES.txt: a case file converted by ../shared/anchors/json2txt.py. The driver is built by
# build_driver.sh (its flags). Needs g++, gcc, valgrind, addr2line and the
# anchors' directory beside the repository (ANCHORS to point elsewhere); GJK_INCLUDE profiles
# another revision's headers (e.g. a `git archive` of it). Exit codes: 0 printed,
# 2 bad usage or a missing tool or file.
set -euo pipefail
[[ $# -eq 3 || $# -eq 4 ]] || { echo "usage: $0 OUTDIR CASES.txt d|f|b [REPS]" >&2; exit 2; }
root=$(cd "$(dirname "$0")/../.." && pwd)
anchors=${ANCHORS:-$root/../shared/anchors}
gjk_include=${GJK_INCLUDE:-$root/gjk/include}
out=$1 cases=$2 mode=$3 reps=${4:-5}
for tool in g++ gcc valgrind addr2line python3; do
  command -v $tool >/dev/null || { echo "stage_profile: $tool not found" >&2; exit 2; }
done
[[ -f $anchors/cases.h && -f $cases ]] || { echo "stage_profile: no $anchors/cases.h or $cases" >&2; exit 2; }
ANCHORS=$anchors GJK_INCLUDE=$gjk_include "$root/scripts/stage_profile/build_driver.sh" "$out"
"$out/stage_driver" "$mode" "$cases" 1
valgrind --tool=callgrind --dump-instr=yes --callgrind-out-file="$out/callgrind.$mode" \
  "$out/stage_driver" "$mode" "$cases" "$reps" >/dev/null 2>&1
n=$(( $(grep -c '^case ' "$cases") * reps ))
if [[ $mode == b ]]; then
  python3 "$root/scripts/stage_profile/stages.py" "$out/callgrind.$mode" "$out/stage_driver" $n b2ShapeDistance bquery b2Solve b2FindSupport b2MakeSimplex b2ComputeWitness
else
  python3 "$root/scripts/stage_profile/stages.py" "$out/callgrind.$mode" "$out/stage_driver" $n ' gjk::distance<' ' gjk::solve' ' gjk::accurateCross' ' gjk::keep' 'gjk::scaleUpEdge' ' gjk::distanceRescaled' 'query<'
fi
