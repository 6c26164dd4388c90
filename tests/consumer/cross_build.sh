#!/usr/bin/env bash
# One build of the cross-platform check (docs/gjk.md, "The same bits on every platform"): builds the
# consumer program (tests/consumer/hash_outputs.cpp with -DGJK_HASH_BATCH, gjk/src/batch.cpp
# linked) for one target, runs it, and requires the hashes recorded in the repository
# (tests/consumer/platform.hashes) and those of the native build made in the same CTest run.
#
#   cross_build.sh SOURCE_DIR WORK_DIR TARGET
#
# TARGET native: g++ with the project's flags (-std=c++20 -O2 -ffp-contract=off), writes
# WORK_DIR/native.hashes, and must print the recorded hashes: a change of the native bits fails
# here, and the recorded file is then updated on purpose (the command is printed).
# TARGET aarch64, riscv64 or s390x: Debian's <target>-linux-gnu-g++, linked statically and run
# under qemu-<target> (qemu-user), twice: with the project's flags, and with -O3 and the compiler's
# default FP contraction (GCC contracts a*b+c into FMA there by default; the headers' pragmas undo
# it). Each must print the native build's hashes and the recorded ones.
# Exit codes: 0 pass, 1 fail (hashes differ, a build fails, or the program's own checks fail), 77
# skipped (the cross compiler or qemu-user is missing: said on stdout). With GJK2D_REQUIRE_ALL=1
# (CI: .ci/run) a missing tool is a failure (scripts/setup.sh --tests installs them).
set -uo pipefail
src=$1 work=$2 target=$3
recorded=$src/tests/consumer/platform.hashes
out=$work/$target
mkdir -p "$out"

missingTool() {
    if [[ ${GJK2D_REQUIRE_ALL:-0} == 1 ]]; then
        echo "FAIL $target: $1 not found, and GJK2D_REQUIRE_ALL=1 makes a skip a failure (scripts/setup.sh --tests installs it)"
        exit 1
    fi
    echo "SKIP $target: $1 not found (scripts/setup.sh --tests installs it)"
    exit 77
}

# build NAME COMPILER FLAGS...: out/NAME/hash_outputs
build() {
    local name=$1 cxx=$2
    shift 2
    mkdir -p "$out/$name"
    local start=$SECONDS
    "$cxx" "$@" -DGJK_HASH_BATCH -I"$src/gjk/include" -c "$src/tests/consumer/hash_outputs.cpp" \
        -o "$out/$name/hash_outputs.o" &&
        "$cxx" "$@" -Wno-psabi -I"$src/gjk/include" -c "$src/gjk/src/batch.cpp" -o "$out/$name/batch.o" &&
        "$cxx" "$@" "$out/$name/hash_outputs.o" "$out/$name/batch.o" -o "$out/$name/hash_outputs" ||
        { echo "FAIL $target: building with $cxx $*"; exit 1; }
    echo "$name: built with $cxx $* in $((SECONDS - start)) s"
}

# check NAME EXPECTED-FILE WHAT [RUNNER...]: runs out/NAME/hash_outputs, compares its stdout.
check() {
    local name=$1 expected=$2 what=$3
    shift 3
    local start=$SECONDS
    "$@" "$out/$name/hash_outputs" >"$out/$name/hashes" 2>"$out/$name/stderr.txt" ||
        { cat "$out/$name/hashes" "$out/$name/stderr.txt"; echo "FAIL $target $name: the program's own checks"; exit 1; }
    cat "$out/$name/stderr.txt"
    if ! diff <(grep -v '^#' "$expected") "$out/$name/hashes" >"$out/$name/hashes.diff"; then
        echo "FAIL $target $name: output bits differ from $what (< expected, > this build):"
        cat "$out/$name/hashes.diff"
        return 1
    fi
    echo "$name: ran in $((SECONDS - start)) s, identical to $what ($(grep -c . "$out/$name/hashes") lines)"
}

status=0
if [[ $target == native ]]; then
    build reference g++ -std=c++20 -O2 -ffp-contract=off
    check reference "$recorded" "the recorded hashes ($recorded)" || {
        echo "If the change of bits is intended: $out/reference/hash_outputs >$recorded.new" \
            "2>/dev/null, keep the comment lines of $recorded, and say why in the commit"
        status=1
    }
    cp "$out/reference/hashes" "$work/native.hashes"
    grep ' all ' "$out/reference/hashes"
    exit $status
fi

cxx=$target-linux-gnu-g++
command -v "$cxx" >/dev/null 2>&1 || missingTool "$cxx"
command -v "qemu-$target" >/dev/null 2>&1 || missingTool "qemu-$target (Debian package qemu-user)"
[[ -f $work/native.hashes ]] || { echo "FAIL $target: no $work/native.hashes (the native build runs first)"; exit 1; }
for flags in "O2-ref|-std=c++20 -O2 -ffp-contract=off" "O3-default|-std=c++20 -O3"; do
    name=${flags%%|*}
    read -ra args <<<"${flags#*|}"
    build "$name" "$cxx" "${args[@]}" -static
    check "$name" "$work/native.hashes" "the native x86-64 build" "qemu-$target" || status=1
    diff -q <(grep -v '^#' "$recorded") "$out/$name/hashes" >/dev/null ||
        { echo "FAIL $target $name: output bits differ from the recorded hashes ($recorded)"; status=1; }
done
grep ' all ' "$out/O2-ref/hashes"
exit $status
