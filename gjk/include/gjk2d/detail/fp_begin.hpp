// Floating-point prologue of every gjk/ header: included after the header's own #includes (so that
// no standard-library code is compiled under it), before `namespace gjk`; gjk2d/detail/fp_end.hpp
// closes it after the namespace. No include guard: each header opens and closes its own region.
//
// Why: the exact perpendicular search direction (dot(d, e) == 0 needs -x*y + y*x to round both
// products alike), the error bound (docs/error-bound.md) and the bit-for-bit promises (warm start,
// batch) all assume that no a*b + c is contracted into a fused multiply-add. The project builds
// with -ffp-contract=off, but a user's build need not: GCC contracts by default whenever the target
// has FMA (-march=native, -march=x86-64-v3), in ISO mode too for C++, and Clang contracts within an
// expression by default. Before this prologue every such build gave other output bits than the
// project's, and gjk tests failed (docs/gjk.md, "Compiler flags").
//
// GCC: `optimize("fp-contract=off")` gives every function defined in the region (templates,
// lambdas and their instantiations included) the option, whatever the command line says. GCC does
// not inline a function with an optimize attribute into a caller whose options differ, so the
// library's functions are not inlined into a contracting user's code (a call, as if from another
// translation unit), and they inline among themselves as before. With the project's own flags the
// options are the same and nothing changes (docs/gjk.md: instruction counts of gjk_bench).
//
// GCC's SLP vectorizer also fuses behind -ffp-contract=off's back: its add-sub pattern turns
// (c*x - s*y, s*x + c*y) (transformPoint, with -march=native or x86-64-v3) into one vfmaddsub
// (GCC 12.2, -O2 and -O3; the command-line -ffp-contract=off does not stop it either: the Box2D
// issue erincatto/box2d#1086 reports the same of GCC's RISC-V vectorizer). So wherever the target
// may have FMA instructions, the region also turns SLP vectorization off. An x86 target without
// FMA (the project's own build: plain x86-64) keeps the command line's options untouched.
//
// Clang: `#pragma clang fp contract(off)` marks the expressions parsed in the region (template
// instantiations keep their definition's setting), and float_control(push)/(pop) restores the
// user's setting afterwards. The marks survive inlining. Clang ignores them under an explicit
// -ffp-contract=fast (Clang 14: the backend then fuses regardless; it rejects
// -ffp-contract=fast-honor-pragmas). No macro tells -ffp-contract=fast apart, so that case is
// documented and tested for its bound and certified interval, not detected.
//
// Not restorable by any pragma, and detected here: -ffast-math and its parts that reorder or
// assume away IEEE behaviour (the certified interval and the overflow checks rely on infinities,
// NaN and the exact order of operations), and x87 excess precision (FLT_EVAL_METHOD != 0, e.g.
// -m32 -mfpmath=387: products rounded to 64-bit mantissas, then again on store). Both stop the
// build; defining GJK2D_ALLOW_NON_IEEE_FLAGS turns the stop off, and with it every promise above.
#if !defined(GJK2D_ALLOW_NON_IEEE_FLAGS) && !defined(GJK2D_DETAIL_FP_CHECKED)
#define GJK2D_DETAIL_FP_CHECKED // once per translation unit, not once per header
#if defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__) ||           \
    defined(__ASSOCIATIVE_MATH__) || defined(__RECIPROCAL_MATH__) || defined(__NO_SIGNED_ZEROS__)
#error                                                                                             \
    "gjk: -ffast-math (or -ffinite-math-only, -fassociative-math, -freciprocal-math, -fno-signed-zeros) breaks the library's floating-point promises (docs/gjk.md, \"Compiler flags\"); define GJK2D_ALLOW_NON_IEEE_FLAGS to build anyway"
#endif
#if defined(__FLT_EVAL_METHOD__) && __FLT_EVAL_METHOD__ != 0
#error                                                                                             \
    "gjk: FLT_EVAL_METHOD != 0 (x87 excess precision, e.g. -m32 -mfpmath=387) breaks the library's floating-point promises (docs/gjk.md, \"Compiler flags\"); use SSE2 (-mfpmath=sse -msse2) or define GJK2D_ALLOW_NON_IEEE_FLAGS"
#endif
#endif

#if defined(__clang__)
#pragma float_control(push)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#if !(defined(__x86_64__) || defined(__i386__)) || defined(__FMA__) || defined(__FMA4__)
#pragma GCC optimize("no-tree-slp-vectorize")
#endif
#endif
