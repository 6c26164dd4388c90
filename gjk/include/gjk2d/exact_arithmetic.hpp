// The arithmetic of the correctly rounded distance (gjk2d/correct.hpp), on doubles only: error-free
// transformations (Knuth's TwoSum, Dekker's TwoProduct or one fused multiply-add), double-double
// values that carry a rigorous bound on their distance to the exact value (Approx), exact sums of a
// few error-free pieces (Terms, exactSum), the same operations in two lanes (a point's x and y side
// by side), and Shewchuk's floating-point expansions (exact sums of any length, for exact ties).
// Every guard that fails turns a Context's `ok` false: the caller then needs exact arithmetic. The
// Context also names which error-free product its operations use (DekkerProducts or
// FmaProducts, below); both give the same bits.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

// The steps below are forced inline in optimised builds (for speed: docs/speed.md, "double-correct
// at 1.5x"), and only `inline` in checked builds (GJK2D_CHECKED: the sanitizer and fuzzing
// builds), where forcing them nearly doubles the compile time of every translation unit that
// instantiates the query.
// Spelled as GJK_INLINE (gjk2d/detail/macros.hpp) is, so that this header needs no other gjk
// header.
// GJK_CORRECT_LAMBDA_INLINE does the same for a lambda (a lambda is not inlined into
// gjk2d/correct.hpp's refineFma otherwise: GCC keeps functions whose options differ apart).
#if defined(GJK2D_CHECKED) || !defined(__GNUC__)
#define GJK_CORRECT_INLINE inline
#define GJK_CORRECT_LAMBDA_INLINE
#else
#define GJK_CORRECT_INLINE [[gnu::always_inline]] inline
#define GJK_CORRECT_LAMBDA_INLINE __attribute__((always_inline))
#endif

namespace gjk::correct
{

// --- Error-free transformations ----------------------------------------------------------------

struct DD
{
    double hi = 0, lo = 0;
};

// a + b = s + e exactly (Knuth), for any finite a, b whose sum does not overflow.
GJK_CORRECT_INLINE DD twoSum(double a, double b)
{
    const double s = a + b;
    const double bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}
// The same when |a| >= |b| (or a == 0) (Dekker).
GJK_CORRECT_INLINE DD fastTwoSum(double a, double b)
{
    const double s = a + b;
    return {s, b - (s - a)};
}
// a * b = p + e exactly (Dekker, Veltkamp's split by 2^27 + 1), when |a|, |b| <= 2^996 and no
// partial product underflows (guarded: Terms::addProduct).
GJK_CORRECT_INLINE DD twoProduct(double a, double b)
{
    constexpr double split = 134217729.0; // 2^27 + 1
    const double p = a * b;
    const double ca = split * a, ah = ca - (ca - a), al = a - ah;
    const double cb = split * b, bh = cb - (cb - b), bl = b - bh;
    return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}
#if defined(__GNUC__)
// The same with one fused multiply-add: e = fma(a, b, -p) is a b - p rounded once, and a b - p is
// a double wherever Dekker's e is exact (no partial product below 2^-1074: exactProduct's guard,
// and the ranges of mul, div and squareRoot), so there the two give the same e, bit for bit (an
// exact e is unique). Where a product underflows, both err by at most a few 2^-1074, which kTiny
// covers. Called only from code compiled for FMA (gjk2d/correct.hpp's refineFma); anywhere else
// __builtin_fma is a call to libm's fma, which is exact too, only slow.
GJK_CORRECT_INLINE DD twoProductFma(double a, double b)
{
    const double p = a * b;
    return {p, __builtin_fma(a, b, -p)};
}
#endif

// The error-free product an evaluation context uses (its template argument; defined with the
// lanes, below).
struct DekkerProducts;
struct FmaProducts;

// --- Double-double values with a bound ---------------------------------------------------------
//
// An Approx is hi + lo (|lo| <= ulp(hi) / 2) with |exact - (hi + lo)| <= err, exact being the
// quantity it stands for. Every operation below adds its own rounding, bounded by kRel times the
// result. The double-double algorithms are those of Joldes, Muller and Popescu, "Tight and
// rigorous error bounds for basic building blocks of double-word arithmetic" (ACM TOMS 2017):
// addition (AccurateDWPlusDW) <= 3u^2, product (DWTimesDW without FMA) <= 7u^2, quotient
// (DWDivDW2) <= 15u^2, and the square root (one Newton step from sqrt(hi), Dekker) <= 4u^2,
// u = 2^-53. kRel = 2^-96 = 1024 u^2 covers each with a wide margin, and also the few roundings
// of the bounds themselves (kSafe). Underflow: products of values below 2^-400 may lose up to a
// few 2^-1074 each, covered by kTiny per operation; divisors and square roots are guarded away
// from that range.
inline constexpr double kRel = 0x1p-96;
inline constexpr double kSafe = 1 + 0x1p-40;
inline constexpr double kTiny = 0x1p-900;

struct Approx
{
    double hi = 0, lo = 0, err = 0;
};

GJK_CORRECT_INLINE double mag(const Approx& a)
{
    return std::abs(a.hi) * (1 + 0x1p-50);
} // >= |hi + lo|

// The evaluation context: `ok` turns false when a guard fails (the caller then needs exact).
// Products (DekkerProducts or FmaProducts) is the error-free product of its operations.
template <class P> struct BasicContext
{
    using Products = P;
    bool ok = true;
    GJK_CORRECT_INLINE void require(bool c) { ok = ok && c; }
};
using Context = BasicContext<DekkerProducts>;
using FmaContext = BasicContext<FmaProducts>;

GJK_CORRECT_INLINE Approx exactly(double v)
{
    return {v, 0, 0};
}
GJK_CORRECT_INLINE Approx negate(const Approx& a)
{
    return {-a.hi, -a.lo, a.err};
}
GJK_CORRECT_INLINE Approx absolute(const Approx& a)
{
    return a.hi < 0 ? negate(a) : a;
}

GJK_CORRECT_INLINE Approx add(const Approx& a, const Approx& b)
{
    DD s = twoSum(a.hi, b.hi);
    const DD t = twoSum(a.lo, b.lo);
    s = fastTwoSum(s.hi, s.lo + t.hi);
    s = fastTwoSum(s.hi, s.lo + t.lo);
    return {s.hi, s.lo, (a.err + b.err + kRel * std::abs(s.hi)) * kSafe};
}
GJK_CORRECT_INLINE Approx sub(const Approx& a, const Approx& b)
{
    return add(a, negate(b));
}

template <class Cx> GJK_CORRECT_INLINE Approx mul(Cx& cx, const Approx& a, const Approx& b)
{
    cx.require(std::abs(a.hi) <= 0x1p450 && std::abs(b.hi) <= 0x1p450); // product <= 2^900
    const DD p = Cx::Products::twoProduct(a.hi, b.hi);
    const double t = a.hi * b.lo + a.lo * b.hi;
    const DD r = fastTwoSum(p.hi, p.lo + t);
    const double e =
        mag(a) * b.err + mag(b) * a.err + a.err * b.err + kRel * std::abs(r.hi) + kTiny;
    return {r.hi, r.lo, e * kSafe};
}

template <class Cx> GJK_CORRECT_INLINE Approx div(Cx& cx, const Approx& a, const Approx& b)
{
    const double bLow = std::abs(b.hi) * (1 - 0x1p-50) - b.err * kSafe; // <= |exact b|
    cx.require(std::abs(b.hi) >= 0x1p-400 && bLow > 0 && std::abs(a.hi) <= 0x1p900 &&
               std::abs(b.hi) <= 0x1p450);
    if (!cx.ok)
        return {};
    const double th = a.hi / b.hi;
    const DD c = Cx::Products::twoProduct(b.hi, th);
    const DD t = fastTwoSum(c.hi, b.lo * th);
    const DD r = fastTwoSum(t.hi, t.lo + c.lo);
    const DD pi = twoSum(a.hi, -r.hi);
    const double delta = pi.hi + ((pi.lo - r.lo) + a.lo);
    const DD q = fastTwoSum(th, delta / b.hi);
    // |a/b - av/bv| <= (|a - av| + |av/bv| |b - bv|) / |b|
    const double e = (a.err + std::abs(q.hi) * (1 + 0x1p-50) * b.err) / bLow +
                     kRel * std::abs(q.hi) + kTiny / bLow;
    return {q.hi, q.lo, e * kSafe};
}

template <class Cx> GJK_CORRECT_INLINE Approx squareRoot(Cx& cx, const Approx& a)
{
    const double aLow = a.hi * (1 - 0x1p-50) - a.err * kSafe; // <= exact a
    cx.require(a.hi >= 0x1p-800 && a.hi <= 0x1p900 && aLow > 0);
    if (!cx.ok)
        return {};
    const double s = std::sqrt(a.hi);
    const DD p = Cx::Products::twoProduct(s, s);
    const double r = ((a.hi - p.hi) - p.lo) + a.lo;
    const DD q = fastTwoSum(s, r / (2 * s));
    // |sqrt(a) - sqrt(av)| = |a - av| / (sqrt(a) + sqrt(av)) <= err / sqrt(aLow)
    const double e = a.err / std::sqrt(aLow) + kRel * std::abs(q.hi) + kTiny;
    return {q.hi, q.lo, e * kSafe};
}

// --- Exact sums --------------------------------------------------------------------------------

// TwoProduct(a, b) = p + e is exact when the factors cannot overflow the split and the exponents'
// sum is at least -961 (every partial product is then a multiple of 2^-1074, representable): a
// product of at least 2^-960 in magnitude, or a zero factor.
GJK_CORRECT_INLINE bool exactProduct(double a, double b, double p)
{
    const double m = std::abs(p);
    return (a == 0) | (b == 0) |
           ((m >= 0x1p-960) & (m <= 0x1p900) & (std::abs(a) <= 0x1p900) & (std::abs(b) <= 0x1p900));
}

// A short list of doubles whose exact sum is a wanted quantity (error-free pieces of products).
// The pieces are kept in two lists: `big` (products' leading parts, translations) and `small`
// (products' trailing parts, each below u times its leading part). `ok`: every piece is exact and
// the sum cannot overflow (else the caller needs exact).
struct Terms
{
    double big[10], small[10];
    int nb = 0, ns = 0;
    bool ok = true;
    GJK_CORRECT_INLINE void add(double x)
    {
        ok = ok && std::abs(x) <= 0x1p900;
        big[nb++] = x;
    }
    template <class P = DekkerProducts> GJK_CORRECT_INLINE void addProduct(double a, double b)
    {
        const DD p = P::twoProduct(a, b);
        ok = ok && exactProduct(a, b, p.hi);
        big[nb++] = p.hi;
        small[ns++] = p.lo;
    }
    // a * (x - y), the difference taken exactly first.
    template <class P = DekkerProducts>
    GJK_CORRECT_INLINE void addProductOfDifference(double a, double x, double y)
    {
        const DD d = twoSum(x, -y);
        addProduct<P>(a, d.hi);
        addProduct<P>(a, d.lo);
    }
};

// The exact sum of the terms as an Approx. Ogita, Rump and Oishi's VecSum (a cascade of TwoSum,
// error-free: the sum of the returned vector is the exact sum, its last element the
// floating-point sum) runs over the big pieces; the rest (its errors and the small pieces) is
// summed in double, its error bounded by the running bound n u sum|rest| (with room to spare:
// n 2^-52, n the number of pieces). That leaves a rest of about u sum|terms|; while it is larger
// than 2^-40 of the result (heavy cancellation: near touching, a small gap far from the origin),
// VecSum passes over all the pieces follow (up to three), each shrinking it by about u. A rest of
// 2^-40 leaves a bound of n 2^-92 of the result, far below the half ulp (2^-53) the final
// rounding must resolve.
template <class Cx> GJK_CORRECT_INLINE Approx exactSum(Cx& cx, Terms t)
{
    cx.require(t.ok);
    if (t.nb == 0)
        return {};
    for (int i = 1; i < t.nb; ++i)
    {
        const DD s = twoSum(t.big[i - 1], t.big[i]);
        t.big[i] = s.hi;
        t.big[i - 1] = s.lo;
    }
    double sum = t.big[t.nb - 1];
    double rest = 0, restAbs = 0;
    for (int i = 0; i + 1 < t.nb; ++i)
    {
        rest += t.big[i];
        restAbs += std::abs(t.big[i]);
    }
    for (int i = 0; i < t.ns; ++i)
    {
        rest += t.small[i];
        restAbs += std::abs(t.small[i]);
    }
    const int n = t.nb + t.ns;
    if (!(restAbs <= 0x1p-40 * std::abs(sum))) [[unlikely]]
    {
        // All pieces in one vector, the sum last.
        double v[20];
        int k = 0;
        for (int i = 0; i < t.ns; ++i)
            v[k++] = t.small[i];
        for (int i = 0; i < t.nb; ++i)
            v[k++] = t.big[i];
        for (int pass = 0; pass < 3; ++pass)
        {
            for (int i = 1; i < n; ++i)
            {
                const DD s = twoSum(v[i - 1], v[i]);
                v[i] = s.hi;
                v[i - 1] = s.lo;
            }
            rest = restAbs = 0;
            for (int i = 0; i + 1 < n; ++i)
            {
                rest += v[i];
                restAbs += std::abs(v[i]);
            }
            if (restAbs <= 0x1p-40 * std::abs(v[n - 1]))
                break;
        }
        sum = v[n - 1];
    }
    const DD s = twoSum(sum, rest);
    return {s.hi, s.lo, n * 0x1p-52 * restAbs * kSafe};
}

struct ApproxVec
{
    Approx x, y;
};

// --- Two lanes: a point's x and y --------------------------------------------------------------
//
// A world point's two coordinates take the same operations (c x - s y + px and s x + c y + py are
// (c, s) x + (-s, c) y + (px, py)), so the hot stages (below, and gjk2d/correct.hpp's
// minkowskiPointLanes) run them side by side: one SSE2 register with GCC's and Clang's vector
// extensions, a pair of doubles elsewhere. Each lane rounds exactly as the scalar code would (IEEE
// operations lane by lane, no contraction: the prologue above), so the derivations are the scalar
// ones. GJK_NO_VECTOR_EXTENSIONS selects the
// pair of doubles with GCC and Clang too (a check of that code).
#if defined(__GNUC__) && !defined(GJK_NO_VECTOR_EXTENSIONS)
typedef double V2 __attribute__((vector_size(16)));
typedef std::int64_t M2 __attribute__((vector_size(16))); // comparison masks: -1 (true) or 0
GJK_CORRECT_INLINE V2 abs2(V2 v)
{
    return V2(M2(v) & M2{INT64_MAX, INT64_MAX});
}
GJK_CORRECT_INLINE bool all2(M2 m)
{
    return (m[0] & m[1]) != 0;
}
#else
struct M2
{
    bool v[2];
    bool operator[](int i) const { return v[i]; }
    M2 operator&(M2 o) const { return {{v[0] && o.v[0], v[1] && o.v[1]}}; }
    M2 operator|(M2 o) const { return {{v[0] || o.v[0], v[1] || o.v[1]}}; }
};
struct V2
{
    double v[2];
    double operator[](int i) const { return v[i]; }
};
inline V2 operator+(V2 a, V2 b)
{
    return {{a.v[0] + b.v[0], a.v[1] + b.v[1]}};
}
inline V2 operator-(V2 a, V2 b)
{
    return {{a.v[0] - b.v[0], a.v[1] - b.v[1]}};
}
inline V2 operator*(V2 a, V2 b)
{
    return {{a.v[0] * b.v[0], a.v[1] * b.v[1]}};
}
inline V2 operator*(double a, V2 b)
{
    return {{a * b.v[0], a * b.v[1]}};
}
inline M2 operator<=(V2 a, V2 b)
{
    return {{a.v[0] <= b.v[0], a.v[1] <= b.v[1]}};
}
inline M2 operator<=(V2 a, double b)
{
    return {{a.v[0] <= b, a.v[1] <= b}};
}
inline M2 operator>=(V2 a, double b)
{
    return {{a.v[0] >= b, a.v[1] >= b}};
}
inline M2 operator==(V2 a, double b)
{
    return {{a.v[0] == b, a.v[1] == b}};
}
inline V2 abs2(V2 a)
{
    return {{std::abs(a.v[0]), std::abs(a.v[1])}};
}
inline bool all2(M2 m)
{
    return m.v[0] && m.v[1];
}
#endif
GJK_CORRECT_INLINE V2 pair(double x, double y)
{
    return V2{x, y};
}

struct DD2
{
    V2 hi, lo;
};
GJK_CORRECT_INLINE DD2 twoSum(V2 a, V2 b) // twoSum above, lane by lane
{
    const V2 s = a + b;
    const V2 bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}
GJK_CORRECT_INLINE DD2 twoProduct(V2 a, V2 b) // twoProduct above, lane by lane
{
    const V2 split = pair(134217729.0, 134217729.0);
    const V2 p = a * b;
    const V2 ca = split * a, ah = ca - (ca - a), al = a - ah;
    const V2 cb = split * b, bh = cb - (cb - b), bl = b - bh;
    return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}
// Each lane a float value (finite, and a float's exact double): a product of two such values has
// at most 48 significant bits and lies in [2^-298, 2^256] or is 0, so it is exact in double and
// inside exactProduct's range. The test converts only values in float's range (a conversion out
// of range is undefined).
GJK_CORRECT_INLINE M2 isFloat2(V2 v)
{
    const M2 inRange = abs2(v) <= 3.4028234663852886e38; // FLT_MAX
#if defined(__GNUC__) && !defined(GJK_NO_VECTOR_EXTENSIONS)
    typedef float F2 __attribute__((vector_size(8)));
    const V2 safe = V2(M2(v) & inRange);
    return inRange & (__builtin_convertvector(__builtin_convertvector(safe, F2), V2) == v);
#else
    auto lane = [&](int k) { return inRange[k] && double(float(v[k])) == v[k]; };
    return {{lane(0), lane(1)}};
#endif
}
// The 29 lowest significand bits zero in every lane of the four (as in every float's value): the
// cheap first test of float data, which fails at once on doubles' data.
GJK_CORRECT_INLINE bool low29BitsZero(V2 a, V2 b, V2 c, V2 d)
{
    constexpr std::uint64_t low = (std::uint64_t(1) << 29) - 1;
#if defined(__GNUC__) && !defined(GJK_NO_VECTOR_EXTENSIONS)
    typedef std::uint64_t U2 __attribute__((vector_size(16)));
    const U2 m = ((U2(a) | U2(b)) | (U2(c) | U2(d))) & low;
    return (m[0] | m[1]) == 0;
#else
    std::uint64_t m = 0;
    for (const V2& v : {a, b, c, d})
        m |= std::bit_cast<std::uint64_t>(v[0]) | std::bit_cast<std::uint64_t>(v[1]);
    return (m & low) == 0;
#endif
}
#if defined(__GNUC__)
GJK_CORRECT_INLINE DD2 twoProductFma(V2 a, V2 b) // twoProductFma above, lane by lane
{
    const V2 p = a * b;
    return {p, pair(__builtin_fma(a[0], b[0], -p[0]), __builtin_fma(a[1], b[1], -p[1]))};
}
#endif

// The two error-free products, as an evaluation context's template argument. Dekker's is the
// default and the only one where the compiler is not GCC or Clang.
struct DekkerProducts
{
    GJK_CORRECT_INLINE static DD twoProduct(double a, double b)
    {
        return correct::twoProduct(a, b);
    }
    GJK_CORRECT_INLINE static DD2 twoProduct(V2 a, V2 b) { return correct::twoProduct(a, b); }
};
#if defined(__GNUC__)
struct FmaProducts
{
    GJK_CORRECT_INLINE static DD twoProduct(double a, double b) { return twoProductFma(a, b); }
    GJK_CORRECT_INLINE static DD2 twoProduct(V2 a, V2 b) { return twoProductFma(a, b); }
};
#endif

// twoProduct for factors that are both floats (isFloat2): the product is exact, its trailing part
// 0, exactly what twoProduct returns for it.
GJK_CORRECT_INLINE DD2 floatProduct(V2 a, V2 b)
{
    return {a * b, pair(0.0, 0.0)};
}
// exactProduct's guard, lane by lane, with the factors' range tested at 2^450 (which also
// keeps the product below 2^900): exact unless a factor is zero or |a b| >= 2^-960.
GJK_CORRECT_INLINE M2 exactProduct(V2 a, V2 b, V2 p)
{
    const V2 aa = abs2(a), ab = abs2(b);
    return ((aa <= 0x1p450) & (ab <= 0x1p450)) &
           ((abs2(p) >= 0x1p-960) | (aa == 0.0) | (ab == 0.0));
}

GJK_CORRECT_INLINE DD2 fastTwoSum(V2 a, V2 b) // fastTwoSum above, lane by lane
{
    const V2 s = a + b;
    return {s, b - (s - a)};
}
// mul above, lane by lane: the products a0 b0 and a1 b1 at once.
template <class Cx>
GJK_CORRECT_INLINE void mulLanes(Cx& cx, const Approx& a0, const Approx& b0, const Approx& a1,
                                 const Approx& b1, Approx& r0, Approx& r1)
{
    const V2 ah = pair(a0.hi, a1.hi), al = pair(a0.lo, a1.lo), ae = pair(a0.err, a1.err);
    const V2 bh = pair(b0.hi, b1.hi), bl = pair(b0.lo, b1.lo), be = pair(b0.err, b1.err);
    cx.require(all2((abs2(ah) <= 0x1p450) & (abs2(bh) <= 0x1p450))); // products <= 2^900
    const DD2 p = Cx::Products::twoProduct(ah, bh);
    const V2 t = ah * bl + al * bh;
    const DD2 r = fastTwoSum(p.hi, p.lo + t);
    const V2 magA = (1 + 0x1p-50) * abs2(ah), magB = (1 + 0x1p-50) * abs2(bh); // mag() above
    const V2 e =
        kSafe * ((((magA * be + magB * ae) + ae * be) + kRel * abs2(r.hi)) + pair(kTiny, kTiny));
    r0 = {r.hi[0], r.lo[0], e[0]};
    r1 = {r.hi[1], r.lo[1], e[1]};
}
// Two products' factors p and q (each value hi + lo with its bound err) in two lanes.
struct ApproxVec2
{
    V2 ph, pl, pe, qh, ql, qe;
};
// add above, lane by lane: a0 + b0 and a1 + b1 at once.
GJK_CORRECT_INLINE void addLanes(const Approx& a0, const Approx& b0, const Approx& a1,
                                 const Approx& b1, Approx& r0, Approx& r1)
{
    DD2 s = twoSum(pair(a0.hi, a1.hi), pair(b0.hi, b1.hi));
    const DD2 t = twoSum(pair(a0.lo, a1.lo), pair(b0.lo, b1.lo));
    s = fastTwoSum(s.hi, s.lo + t.hi);
    s = fastTwoSum(s.hi, s.lo + t.lo);
    const V2 e =
        ((pair(a0.err, a1.err) + pair(b0.err, b1.err)) + kRel * abs2(s.hi)) * pair(kSafe, kSafe);
    r0 = {s.hi[0], s.lo[0], e[0]};
    r1 = {s.hi[1], s.lo[1], e[1]};
}
template <class Cx> GJK_CORRECT_INLINE Approx dot(Cx& cx, const ApproxVec& a, const ApproxVec& b)
{
    Approx p, q;
    mulLanes(cx, a.x, b.x, a.y, b.y, p, q);
    return add(p, q);
}
template <class Cx> GJK_CORRECT_INLINE Approx cross(Cx& cx, const ApproxVec& a, const ApproxVec& b)
{
    Approx p, q;
    mulLanes(cx, a.x, b.y, a.y, b.x, p, q);
    return sub(p, q);
}

// --- Floating-point expansions -----------------------------------------------------------------
//
// Shewchuk's expansion arithmetic ("Adaptive precision floating-point arithmetic and fast robust
// geometric predicates", 1997): an Expansion is a sum of doubles, nonoverlapping, in increasing
// magnitude, zeros eliminated, exact; its sign is its largest term's. Every product goes through
// TwoProduct under exactProduct's guard (a failure turns the Context's `ok` false).
struct Expansion
{
    static constexpr int kCapacity = 48; // a nonoverlapping sum of doubles has at most ~40 terms
    double t[kCapacity];
    int n = 0;
};

// e += b exactly (Grow-Expansion with zero elimination).
inline void grow(Context& cx, Expansion& e, double b)
{
    cx.require(std::abs(b) <= 0x1p900);
    double q = b;
    int k = 0;
    for (int i = 0; i < e.n; ++i)
    {
        const DD s = twoSum(q, e.t[i]);
        if (s.lo != 0)
            e.t[k++] = s.lo;
        q = s.hi;
    }
    if (q != 0)
    {
        if (k == Expansion::kCapacity)
        {
            cx.require(false);
            return;
        }
        e.t[k++] = q;
    }
    e.n = k;
}

// e += a b exactly (TwoProduct under exactProduct's guard).
inline void growProduct(Context& cx, Expansion& e, double a, double b)
{
    const DD p = twoProduct(a, b);
    cx.require(exactProduct(a, b, p.hi));
    grow(cx, e, p.lo);
    grow(cx, e, p.hi);
}

// out += sign a b for expansions a, b.
inline void growProduct(Context& cx, Expansion& out, const Expansion& a, const Expansion& b,
                        double sign)
{
    for (int i = 0; i < a.n && cx.ok; ++i)
        for (int j = 0; j < b.n && cx.ok; ++j)
            growProduct(cx, out, sign * a.t[i], b.t[j]);
}

inline int signOf(const Expansion& e)
{
    return e.n == 0 ? 0 : (e.t[e.n - 1] > 0 ? 1 : -1);
}

} // namespace gjk::correct

#include "gjk2d/detail/fp_end.hpp"
