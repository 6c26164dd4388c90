#!/usr/bin/env bash
# Builds stage_driver.cpp into OUTDIR/stage_driver: the release build's flags (-O3 -ffp-contract=off
# -DNDEBUG) plus -g, Box2D v3's sources with the anchors' harness flags (-O2 -ffp-contract=off
# -DNDEBUG) plus -g. The one home of these flags, so that stage_profile.sh's and weigh_parts.py's
# counts compare.
#   scripts/stage_profile/build_driver.sh OUTDIR
# ANCHORS: the anchors' directory (default: beside the repository); GJK_INCLUDE: the headers to
# build against (default: this tree's gjk/include). Exit codes: 0 built, 2 bad usage or a missing
# tool or file, else the compiler's.
set -euo pipefail
[[ $# -eq 1 ]] || { echo "usage: $0 OUTDIR" >&2; exit 2; }
root=$(cd "$(dirname "$0")/../.." && pwd)
anchors=${ANCHORS:-$root/../shared/anchors}
gjk_include=${GJK_INCLUDE:-$root/gjk/include}
out=$1
for tool in g++ gcc; do
  command -v $tool >/dev/null || { echo "build_driver: $tool not found" >&2; exit 2; }
done
[[ -f $anchors/cases.h ]] || { echo "build_driver: no $anchors/cases.h" >&2; exit 2; }
mkdir -p "$out"
b2=$anchors/box2d-v3
for f in distance math_functions core; do
  gcc -std=c17 -O2 -g -ffp-contract=off -DNDEBUG -I"$b2/include" -I"$b2/src" -c "$b2/src/$f.c" -o "$out/box2d_$f.o"
done
g++ -std=c++20 -O3 -g -ffp-contract=off -DNDEBUG -I"$gjk_include" -I"$b2/include" -I"$anchors" \
  "$root/scripts/stage_profile/stage_driver.cpp" "$out"/box2d_{distance,math_functions,core}.o -o "$out/stage_driver" -lm
