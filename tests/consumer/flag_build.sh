#!/usr/bin/env bash
# One build of the flag matrix (docs/gjk.md, "Compiler flags"): compiles the consumer program
# (tests/consumer/hash_outputs.cpp) and the GJK core tests (tests/gjk/test_distance.cpp,
# test_segment_triangle.cpp, test_properties.cpp) with a user's compiler and flags -- invoked
# directly, so none of the project's own options (-ffp-contract=off) apply -- runs both, and
# compares the consumer's hashes with the reference build's.
#
#   flag_build.sh SOURCE_DIR WORK_DIR NAME COMPILER [FLAGS...]
#
# NAME "reference" writes WORK_DIR/reference.hashes and the certified intervals
# (reference.intervals); any other NAME must reproduce the hashes bit for bit, except a NAME
# starting with "unguaranteed-" (flags whose bits are not promised, docs/gjk.md): it runs only
# the consumer's own checks, which every build runs too -- each error within the a-priori bound,
# each certified interval intersecting the reference build's.
# GJK_INCLUDE_DIR overrides the library's include directory (to measure another revision);
# CATCH2_MAIN (the Catch2WithMain library) and CATCH2_INCLUDE_DIR default to Debian's paths;
# GJK_CONSUMER_ONLY=1 skips the tests.
# Exit codes: 0 pass, 1 fail (hashes differ, a test fails, or the build fails), 77 skipped (the
# compiler is missing, or the CPU cannot run code built for these flags: said on stdout). With
# GJK2D_REQUIRE_ALL=1 (CI: .ci/run) a missing compiler is a failure (scripts/setup.sh --tests
# installs both); only a CPU feature this machine lacks still skips.
set -uo pipefail
src=$1 work=$2 name=$3 cxx=$4
shift 4
flags=("$@")
include=${GJK_INCLUDE_DIR:-$src/gjk/include}
out=$work/$name
mkdir -p "$out"

if ! command -v "$cxx" >/dev/null 2>&1; then
    if [[ ${GJK2D_REQUIRE_ALL:-0} == 1 ]]; then
        echo "FAIL $name: compiler $cxx not found, and GJK2D_REQUIRE_ALL=1 makes a skip a failure (scripts/setup.sh --tests installs it)"
        exit 1
    fi
    echo "SKIP $name: compiler $cxx not found (scripts/setup.sh --tests installs it)"
    exit 77
fi
# The flag sets target x86-64 (-march=x86-64-v3: AVX2 and FMA). -march=native runs wherever it
# was built; x86-64-v3 needs the CPU features below (the kernel's names, /proc/cpuinfo).
for f in "${flags[@]}"; do
    if [[ $f == -march=x86-64-v3 ]]; then
        missing=()
        for feature in avx avx2 bmi1 bmi2 f16c fma abm movbe xsave; do
            grep -qw "$feature" /proc/cpuinfo 2>/dev/null || missing+=("$feature")
        done
        if ((${#missing[@]})); then
            echo "SKIP $name: this CPU cannot run -march=x86-64-v3 code (missing: ${missing[*]})"
            exit 77
        fi
    fi
done

echo "$name: $cxx ${flags[*]}"
build() { # object file, source
    "$cxx" "${flags[@]}" -I"$include" -I"$src/gjk/bench" -I"${CATCH2_INCLUDE_DIR:-/usr/include}" -c "$2" \
        -o "$out/$1" ||
        { echo "FAIL $name: compiling $2"; exit 1; }
}
build hash_outputs.o "$src/tests/consumer/hash_outputs.cpp"
"$cxx" "${flags[@]}" "$out/hash_outputs.o" -o "$out/hash_outputs" || { echo "FAIL $name: linking"; exit 1; }
if [[ $name == reference ]]; then
    check=(--dump "$work/reference.intervals")
else
    check=(--against "$work/reference.intervals")
fi
"$out/hash_outputs" "${check[@]}" >"$out/hashes" 2>"$out/bound.txt" ||
    { cat "$out/hashes" "$out/bound.txt"; echo "FAIL $name: consumer run (its own checks)"; exit 1; }
cat "$out/bound.txt"

status=0
if [[ $name == reference ]]; then
    cp "$out/hashes" "$work/reference.hashes"
elif [[ $name == unguaranteed-* ]]; then
    echo "consumer: bits not compared (not promised for these flags); bound and intervals hold"
elif [[ ! -f $work/reference.hashes ]]; then
    echo "FAIL $name: no $work/reference.hashes (run the reference build first)"
    status=1
elif ! diff "$work/reference.hashes" "$out/hashes" >"$out/hashes.diff"; then
    echo "FAIL $name: output bits differ from the reference build (< reference, > this build):"
    cat "$out/hashes.diff"
    status=1
else
    echo "consumer: identical to the reference ($(grep -c . "$out/hashes") lines)"
fi
grep ' all ' "$out/hashes"

if [[ ${GJK_CONSUMER_ONLY:-0} != 1 && $name != unguaranteed-* ]]; then
    build test_distance.o "$src/tests/gjk/test_distance.cpp"
    build test_segment_triangle.o "$src/tests/gjk/test_segment_triangle.cpp"
    build test_properties.o "$src/tests/gjk/test_properties.cpp"
    "$cxx" "${flags[@]}" "$out/test_distance.o" "$out/test_segment_triangle.o" "$out/test_properties.o" \
        "${CATCH2_MAIN:-/usr/lib/libCatch2WithMain.a}" -o "$out/gjk_tests" || { echo "FAIL $name: linking gjk_tests"; exit 1; }
    # The XML report names each test case with its overall result (Catch2 v2).
    "$out/gjk_tests" -r xml -o "$out/gjk_tests.xml" >/dev/null 2>&1
    rc=$?
    failed=$(awk '/<TestCase name=/ { match($0, /name="[^"]*"/); n = substr($0, RSTART + 6, RLENGTH - 7) }
                  /<OverallResult success="false"/ { print "  failed: " n }' "$out/gjk_tests.xml")
    summary=$(grep -o '<OverallResultsCases [^/]*' "$out/gjk_tests.xml" | tail -n 1 | sed 's/<OverallResultsCases //')
    if [[ $rc == 0 && -z $failed ]]; then
        echo "gjk_tests: pass, test cases $summary"
    else
        echo "gjk_tests: exit $rc, test cases $summary"
        [[ -n $failed ]] && echo "$failed"
        echo "FAIL $name: gjk_tests (report: $out/gjk_tests.xml)"
        status=1
    fi
fi
exit $status
