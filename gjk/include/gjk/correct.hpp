// The correctly rounded distance (Options::correctlyRounded): the double nearest to the exact
// distance of the problem as given, max(0, dist(hull(A'), hull(B')) - rA - rB) with
// A' = {c x - s y + px, s x + c y + py} evaluated exactly (the exact side's semantics,
// exact/include/exact/exact.hpp), and 0 exactly when that exact value is 0.
//
// A filtered design, as in exact geometric computation: the cheap stage decides when it can prove
// its answer, and hands the rest on.
//   1. The plain GJK query (any Options) names the final features: the index pairs of its simplex
//      (SimplexCache).
//   2. CorrectPath::Double: containment (a triangle simplex) whose three orientation signs are
//      certified in double with a running error bound (gjk/certify.hpp): the exact distance is 0.
//   3. CorrectPath::DoubleDouble: the features' distance recomputed from the original input in
//      double-double, with error-free products (Dekker's TwoProduct with Veltkamp's split, no FMA:
//      std::fma is a library call on the x86-64 baseline) and sums (Knuth's TwoSum), every
//      quantity carrying a rigorous bound on its distance to the exact value. That gives
//        U = the distance from the origin to the feature (a point or a segment of Z = A' - B'),
//            an upper bound of the exact hull distance d*;
//        L = min over z in Z of n.z / |n| for the feature's direction n (the support-function,
//            or duality, bound), a lower bound of d* for any n. Only the vertices whose double
//            value along n lies within a certified error of the extreme one can attain the
//            minimum; those few are evaluated in double-double.
//      When the features are the closest ones, L = U = d* in exact arithmetic. If every value of
//      [L - rA - rB, U - rA - rB] (with the bounds) rounds to the same double, that double is the
//      answer; if all are <= 0, the answer is 0.
//   4. CorrectPath::NeedsExact: anything the bounds cannot decide (exact touching, a distance on a
//      rounding midpoint to within about 2^-90 relative, features that are not the closest, a
//      product of the features' coordinates beyond [2^-960, 2^900], a culled triangle). The output then holds the plain answer, and
//      the caller completes it with exact arithmetic: exact/include/exact/correct_fallback.hpp
//      (GMP, outside gjk/) does it in one call.
//
// Witness points and normal: those of the plain query (each within docs/error-bound.md's bound of
// a pair of closest points), except that when the correctly rounded distance is 0 and the plain
// one was not, both points are set to their midpoint and the normal to zero. A plain answer of 0
// for shapes that are apart always goes to NeedsExact (whose completion returns the exact side's
// closest points, correctly rounded).
//
// Only double queries are refined: a float query reports NeedsExact (the exact fallback of a float
// query is not provided: the correctly rounded float is not the exact side's double).
#pragma once

#include "gjk/certify.hpp"
#include "gjk/distance.hpp"
#include "gjk/math.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "gjk/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk::correct
{

// --- Error-free transformations ----------------------------------------------------------------

struct DD
{
    double hi = 0, lo = 0;
};

// a + b = s + e exactly (Knuth), for any finite a, b whose sum does not overflow.
inline DD twoSum(double a, double b)
{
    const double s = a + b;
    const double bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}
// The same when |a| >= |b| (or a == 0) (Dekker).
inline DD fastTwoSum(double a, double b)
{
    const double s = a + b;
    return {s, b - (s - a)};
}
// a * b = p + e exactly (Dekker, Veltkamp's split by 2^27 + 1), when |a|, |b| <= 2^996 and no
// partial product underflows (guarded: Terms::addProduct).
inline DD twoProduct(double a, double b)
{
    constexpr double split = 134217729.0; // 2^27 + 1
    const double p = a * b;
    const double ca = split * a, ah = ca - (ca - a), al = a - ah;
    const double cb = split * b, bh = cb - (cb - b), bl = b - bh;
    return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}

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

inline double mag(const Approx& a) { return std::abs(a.hi) * (1 + 0x1p-50); } // >= |hi + lo|

// The evaluation context: `ok` turns false when a guard fails (the caller then needs exact).
struct Context
{
    bool ok = true;
    void require(bool c) { ok = ok && c; }
};

inline Approx exactly(double v) { return {v, 0, 0}; }
inline Approx negate(const Approx& a) { return {-a.hi, -a.lo, a.err}; }
inline Approx absolute(const Approx& a) { return a.hi < 0 ? negate(a) : a; }

inline Approx add(const Approx& a, const Approx& b)
{
    DD s = twoSum(a.hi, b.hi);
    const DD t = twoSum(a.lo, b.lo);
    s = fastTwoSum(s.hi, s.lo + t.hi);
    s = fastTwoSum(s.hi, s.lo + t.lo);
    return {s.hi, s.lo, (a.err + b.err + kRel * std::abs(s.hi)) * kSafe};
}
inline Approx sub(const Approx& a, const Approx& b) { return add(a, negate(b)); }

inline Approx mul(Context& cx, const Approx& a, const Approx& b)
{
    cx.require(std::abs(a.hi) <= 0x1p450 && std::abs(b.hi) <= 0x1p450); // product <= 2^900
    const DD p = twoProduct(a.hi, b.hi);
    const double t = a.hi * b.lo + a.lo * b.hi;
    const DD r = fastTwoSum(p.hi, p.lo + t);
    const double e = mag(a) * b.err + mag(b) * a.err + a.err * b.err + kRel * std::abs(r.hi) + kTiny;
    return {r.hi, r.lo, e * kSafe};
}

inline Approx div(Context& cx, const Approx& a, const Approx& b)
{
    const double bLow = std::abs(b.hi) * (1 - 0x1p-50) - b.err * kSafe; // <= |exact b|
    cx.require(std::abs(b.hi) >= 0x1p-400 && bLow > 0 && std::abs(a.hi) <= 0x1p900 &&
               std::abs(b.hi) <= 0x1p450);
    if (!cx.ok)
        return {};
    const double th = a.hi / b.hi;
    const DD c = twoProduct(b.hi, th);
    const DD t = fastTwoSum(c.hi, b.lo * th);
    const DD r = fastTwoSum(t.hi, t.lo + c.lo);
    const DD pi = twoSum(a.hi, -r.hi);
    const double delta = pi.hi + ((pi.lo - r.lo) + a.lo);
    const DD q = fastTwoSum(th, delta / b.hi);
    // |a/b - av/bv| <= (|a - av| + |av/bv| |b - bv|) / |b|
    const double e = (a.err + std::abs(q.hi) * (1 + 0x1p-50) * b.err) / bLow + kRel * std::abs(q.hi) +
                     kTiny / bLow;
    return {q.hi, q.lo, e * kSafe};
}

inline Approx squareRoot(Context& cx, const Approx& a)
{
    const double aLow = a.hi * (1 - 0x1p-50) - a.err * kSafe; // <= exact a
    cx.require(a.hi >= 0x1p-800 && a.hi <= 0x1p900 && aLow > 0);
    if (!cx.ok)
        return {};
    const double s = std::sqrt(a.hi);
    const DD p = twoProduct(s, s);
    const double r = ((a.hi - p.hi) - p.lo) + a.lo;
    const DD q = fastTwoSum(s, r / (2 * s));
    // |sqrt(a) - sqrt(av)| = |a - av| / (sqrt(a) + sqrt(av)) <= err / sqrt(aLow)
    const double e = a.err / std::sqrt(aLow) + kRel * std::abs(q.hi) + kTiny;
    return {q.hi, q.lo, e * kSafe};
}

// --- Exact sums --------------------------------------------------------------------------------

// A short list of doubles whose exact sum is a wanted quantity (error-free pieces of products).
// The pieces are kept in two lists: `big` (products' leading parts, translations) and `small`
// (products' trailing parts, each below u times its leading part). `ok`: every piece is exact and
// the sum cannot overflow (else the caller needs exact).
struct Terms
{
    double big[10], small[10];
    int nb = 0, ns = 0;
    bool ok = true;
    void add(double x)
    {
        ok = ok && std::abs(x) <= 0x1p900;
        big[nb++] = x;
    }
    // TwoProduct is exact when the factors cannot overflow the split and the exponents' sum is at
    // least -961 (every partial product is then a multiple of 2^-1074, representable): a product
    // of at least 2^-960 in magnitude, or a zero factor.
    void addProduct(double a, double b)
    {
        const DD p = twoProduct(a, b);
        const double m = std::abs(p.hi);
        ok = ok && ((a == 0) | (b == 0) |
                    ((m >= 0x1p-960) & (m <= 0x1p900) & (std::abs(a) <= 0x1p900) & (std::abs(b) <= 0x1p900)));
        big[nb++] = p.hi;
        small[ns++] = p.lo;
    }
    // a * (x - y), the difference taken exactly first.
    void addProductOfDifference(double a, double x, double y)
    {
        const DD d = twoSum(x, -y);
        addProduct(a, d.hi);
        addProduct(a, d.lo);
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
inline Approx exactSum(Context& cx, Terms t)
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

inline Approx dot(Context& cx, const ApproxVec& a, const ApproxVec& b)
{
    return add(mul(cx, a.x, b.x), mul(cx, a.y, b.y));
}
inline Approx cross(Context& cx, const ApproxVec& a, const ApproxVec& b)
{
    return sub(mul(cx, a.x, b.y), mul(cx, a.y, b.x));
}

// The world point of a local one, as terms: (c x - s y + px, s x + c y + py), with sign +1 or -1.
inline void addWorldPoint(Terms& tx, Terms& ty, const Transform<double>& xf, Vec2<double> v, double sign)
{
    tx.addProduct(sign * xf.q.c, v.x);
    tx.addProduct(-sign * xf.q.s, v.y);
    tx.add(sign * xf.p.x);
    ty.addProduct(sign * xf.q.s, v.x);
    ty.addProduct(sign * xf.q.c, v.y);
    ty.add(sign * xf.p.y);
}

// W = xfA * A[i] - xfB * B[j], a point of Z.
inline ApproxVec minkowskiPoint(Context& cx, const DistanceInput<double>& in, int i, int j)
{
    Terms tx, ty;
    addWorldPoint(tx, ty, in.transformA, in.proxyA.points[i], 1);
    addWorldPoint(tx, ty, in.transformB, in.proxyB.points[j], -1);
    return {exactSum(cx, tx), exactSum(cx, ty)};
}

// e = W(i2, j2) - W(i1, j1) from the local differences (the translations cancel exactly).
inline ApproxVec minkowskiEdge(Context& cx, const DistanceInput<double>& in, int i1, int j1, int i2, int j2)
{
    Terms tx, ty;
    auto side = [&](const Transform<double>& xf, Vec2<double> p2, Vec2<double> p1, double sign)
    {
        tx.addProductOfDifference(sign * xf.q.c, p2.x, p1.x);
        tx.addProductOfDifference(-sign * xf.q.s, p2.y, p1.y);
        ty.addProductOfDifference(sign * xf.q.s, p2.x, p1.x);
        ty.addProductOfDifference(sign * xf.q.c, p2.y, p1.y);
    };
    if (i1 != i2)
        side(in.transformA, in.proxyA.points[i2], in.proxyA.points[i1], 1);
    if (j1 != j2)
        side(in.transformB, in.proxyB.points[j2], in.proxyB.points[j1], -1);
    return {exactSum(cx, tx), exactSum(cx, ty)};
}

// The sign of a.b, certified in double from the values' bounds (+1, -1, or 0: not decided).
inline int signOfDot(const ApproxVec& a, const ApproxVec& b)
{
    const double g = a.x.hi * b.x.hi + a.y.hi * b.y.hi;
    auto term = [](const Approx& p, const Approx& q)
    {
        const double dp = std::abs(p.lo) + p.err, dq = std::abs(q.lo) + q.err;
        return 3 * 0x1p-53 * std::abs(p.hi * q.hi) + dp * std::abs(q.hi) + dq * std::abs(p.hi) + dp * dq;
    };
    const double bound = (term(a.x, b.x) + term(a.y, b.y)) * kSafe + 0x1p-1000;
    return g > bound ? 1 : (g < -bound ? -1 : 0);
}

// The vertices of a shape that can attain min (sign = +1) or max (sign = -1) of n.(Q x) over its
// points: those whose double value lies within twice a certified bound of the extreme one. The
// bound covers the rounding of m = Q^T n (n = hi + lo, only hi used: |lo| <= u |hi|), and of the
// dot products: |computed - exact| <= (3u + 2u (1 + 4u)) (|c| + |s|) max|n| max(|x| + |y|), taken
// as 8u, plus an absolute 2^-1000 for underflow. Returns the count (at most kMaxCandidates; more
// returns kMaxCandidates + 1).
inline constexpr int kMaxCandidates = 4;
inline int supportCandidates(const Polygon<double>& p, const Transform<double>& xf, const ApproxVec& n,
                             double sign, int* out)
{
    const double nx = n.x.hi, ny = n.y.hi, c = xf.q.c, s = xf.q.s;
    const double mx = sign * (c * nx + s * ny), my = sign * (c * ny - s * nx);
    // The values are kept for the second loop when they fit in a small buffer.
    constexpr int kBuffer = 64;
    double values[kBuffer];
    const bool buffered = p.count <= kBuffer;
    double best = std::numeric_limits<double>::infinity(), extent = 0;
    for (int i = 0; i < p.count; ++i)
    {
        const double v = mx * p.points[i].x + my * p.points[i].y;
        if (buffered)
            values[i] = v;
        best = std::min(best, v);
        extent = std::max(extent, std::abs(p.points[i].x) + std::abs(p.points[i].y));
    }
    if (!(std::abs(best) <= 0x1p900 && extent <= 0x1p900))
        return kMaxCandidates + 1; // overflow: no certified candidates
    const double eps = 8 * 0x1p-53 * (std::abs(c) + std::abs(s)) * std::max(std::abs(nx), std::abs(ny)) * extent + 0x1p-1000;
    const double limit = best + 2 * eps * kSafe;
    int count = 0;
    for (int i = 0; i < p.count; ++i)
        if ((buffered ? values[i] : mx * p.points[i].x + my * p.points[i].y) <= limit)
        {
            if (count == kMaxCandidates)
                return kMaxCandidates + 1;
            out[count++] = i;
        }
    return count;
}

// Certified containment in double (CorrectPath::Double): the origin strictly inside the triangle
// of the three simplex points, every orientation sign certified by certify.hpp's running bound.
inline bool containsOriginCertified(const DistanceInput<double>& in, const SimplexCache& cache)
{
    using namespace certify;
    BoundedVec W[3];
    for (int i = 0; i < 3; ++i)
    {
        const BoundedVec a = toWorld(in.transformA, in.proxyA.points[cache.indexA[i]]);
        const BoundedVec b = toWorld(in.transformB, in.proxyB.points[cache.indexB[i]]);
        W[i] = {a.x - b.x, a.y - b.y};
    }
    return originCertainlyInside(W);
}

// The decision: the exact x lies in [xl, xh] (each an Approx, with its bound). Returns the
// correctly rounded max(0, x), or a negative value when the bounds cannot decide.
inline double roundInterval(const Approx& xl, const Approx& xh)
{
    using certify::down;
    using certify::up;
    // All of [.., xh + err] <= 0: the answer is exactly 0.
    if (xh.hi <= -up(xh.lo + xh.err))
        return 0;
    // Positive for sure: xl - err > 0.
    if (!(xl.hi > up(xl.err - xl.lo)))
        return -1;
    const double m = xh.hi; // xh rounded to nearest (hi = fl(hi + lo))
    if (!(m >= 0x1p-900 && m <= 0x1p900))
        return -1;
    // The neighbours of m > 0 (normal, finite) by its bit pattern, without std::nextafter's call.
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(m);
    const double gapAbove = std::bit_cast<double>(bits + 1) - m;
    const double gapBelow = m - std::bit_cast<double>(bits - 1);
    // The upper end below the midpoint above m: xh.lo + err < gapAbove / 2.
    if (!(up(xh.lo + xh.err) < 0.5 * gapAbove))
        return -1;
    // The lower end above the midpoint below m: (xl.hi - m) + xl.lo - err > -gapBelow / 2.
    // xl.hi - m is exact when xl.hi is within a factor 2 of m (Sterbenz).
    if (!(xl.hi >= 0.5 * m && xl.hi <= 2 * m))
        return -1;
    if (!(down(down((xl.hi - m) + xl.lo) - xl.err) > -0.5 * gapBelow))
        return -1;
    return m;
}

// The refinement of a plain double query's output (Options::correctlyRounded). `cache` is the
// cache the plain query returned: its index pairs are the final features. Out of line, so that
// gjk::distance does not carry its code and stack frame into the default query.
[[gnu::noinline]] inline void refine(const DistanceInput<double>& in, const SimplexCache& cache, const Options& options,
                   DistanceOutput<double>& out)
{
    out.path = CorrectPath::NeedsExact;
    const double rA = options.useRadii ? in.proxyA.radius : 0.0;
    const double rB = options.useRadii ? in.proxyB.radius : 0.0;
    if (out.outOfRange || !(rA <= 0x1p900 && rB <= 0x1p900))
        return;
    const DD rs = twoSum(rA, rB);
    const Approx r = {rs.hi, rs.lo, 0};

    if (cache.count == 3)
    {
        if (out.stop != StopReason::Containment || !containsOriginCertified(in, cache))
            return;
        // The hulls overlap: the exact distance is max(0, 0 - rA - rB) = 0.
        out.path = CorrectPath::Double;
        out.distance = 0;
        return;
    }

    // The output of a decided answer (a negative one: not decided).
    auto finish = [&out](double answer)
    {
        if (!(answer >= 0))
            return;
        if (answer > 0 && !(out.distance > 0))
            return; // a plain overlap answer: the exact completion gives the witness points
        if (answer == 0 && out.distance > 0)
        {
            const Vec2<double> mid = 0.5 * (out.pointA + out.pointB);
            out.pointA = out.pointB = mid;
            out.normal = {};
        }
        out.distance = answer;
        out.path = CorrectPath::DoubleDouble;
    };
    Context cx;
    const int a1 = cache.indexA[0], b1 = cache.indexB[0];
    const ApproxVec W1 = minkowskiPoint(cx, in, a1, b1);
    ApproxVec W2{}, n{};
    // |n_v| for the direction n_v = n's values (below), and U.
    Approx normV, U, unum;
    auto valuesOf = [](const ApproxVec& v) { return ApproxVec{{v.x.hi, v.x.lo, 0}, {v.y.hi, v.y.lo, 0}}; };
    const bool isEdge = cache.count == 2;
    if (!isEdge)
    {
        // Vertex feature: n = W1, U = |W1| = |n_v| within |W1 - n_v| <= W1.x.err + W1.y.err.
        n = W1;
        if (!cx.ok)
            return;
        normV = squareRoot(cx, dot(cx, valuesOf(W1), valuesOf(W1)));
        U = {normV.hi, normV.lo, (normV.err + W1.x.err + W1.y.err) * kSafe};
    }
    else
    {
        // Edge feature W1 W2: the distance to its line, |cross(e, W1)| / |e|, is the distance to
        // the segment when the origin projects inside it: u = W2.e > 0 and v = -W1.e > 0.
        // e = W2 - W1; recomputed from the shapes' local differences (the translations cancel
        // before any rounding) when that difference is not accurate to 2^-80 of e.
        const int a2 = cache.indexA[1], b2 = cache.indexB[1];
        W2 = minkowskiPoint(cx, in, a2, b2);
        ApproxVec e = {sub(W2.x, W1.x), sub(W2.y, W1.y)};
        if (!(std::max(e.x.err, e.y.err) <= 0x1p-80 * std::max(std::abs(e.x.hi), std::abs(e.y.hi))))
            e = minkowskiEdge(cx, in, a1, b1, a2, b2);
        if (!cx.ok || signOfDot(W2, e) != 1 || signOfDot(W1, e) != -1)
            return;
        unum = cross(cx, e, W1);
        // |n_v| = |e_v| (a perpendicular), and |e| within e.x.err + e.y.err of it.
        normV = squareRoot(cx, dot(cx, valuesOf(e), valuesOf(e)));
        if (!cx.ok)
            return;
        U = div(cx, absolute(unum), {normV.hi, normV.lo, (normV.err + e.x.err + e.y.err) * kSafe});
        // n: the perpendicular of e towards Z (n.W1 > 0).
        n = unum.hi > 0 ? ApproxVec{negate(e.y), e.x} : ApproxVec{e.y, negate(e.x)};
    }
    if (!cx.ok)
        return;
    const Approx xh = sub(U, r);
    // Apart by less than the radii: 0 whatever the other bound.
    if (xh.hi <= -certify::up(xh.lo + xh.err))
    {
        if (out.distance > 0)
        {
            const Vec2<double> mid = 0.5 * (out.pointA + out.pointB);
            out.pointA = out.pointB = mid;
            out.normal = {};
        }
        out.distance = 0;
        out.path = CorrectPath::DoubleDouble;
        return;
    }
    if (isEdge && !(std::abs(unum.hi) > unum.err * kSafe + std::abs(unum.lo)))
        return; // the origin on (or too near) the edge's line: the side is not decided

    // L: the support bound along n_v = (n.x.hi + n.x.lo, n.y.hi + n.y.lo), taken as an exact
    // direction (any direction gives a lower bound): min over the candidate pairs of n_v.W / |n_v|.
    const ApproxVec nv = valuesOf(n);
    int candA[kMaxCandidates + 1], candB[kMaxCandidates + 1];
    const int ca = supportCandidates(in.proxyA, in.transformA, nv, 1, candA);
    const int cb = supportCandidates(in.proxyB, in.transformB, nv, -1, candB);
    if (ca > kMaxCandidates || cb > kMaxCandidates)
        return;
    // The common case: the candidates are the features' own vertices, for the exact n too (the
    // candidates' bound covers |n - n.hi| when n's own bound is below 2^-60 of it). Then the
    // minimum of n.z over Z is attained at the feature: for a vertex W1 (n = W1), n.z >= n.W1;
    // for an edge of one shape against a vertex of the other, n is perpendicular to that edge, so
    // both its ends give n.W1. Z lies in the half-plane n.z >= n.W1, whose closest point to the
    // origin lies on the feature (u, v > 0 above): d* = U exactly, and L is not needed.
    auto within = [](const int* c, int count, int i1, int i2)
    {
        for (int k = 0; k < count; ++k)
            if (c[k] != i1 && c[k] != i2)
                return false;
        return true;
    };
    const int a2 = isEdge ? cache.indexA[1] : a1, b2 = isEdge ? cache.indexB[1] : b1;
    if (std::max(n.x.err, n.y.err) <= 0x1p-60 * std::max(std::abs(n.x.hi), std::abs(n.y.hi)) &&
        within(candA, ca, a1, a2) && within(candB, cb, b1, b2) && (a1 == a2 || b1 == b2))
    {
        finish(roundInterval(xh, xh));
        return;
    }
    Approx lowest;
    bool first = true;
    double lowestEnd = 0;
    // The values, as plain arrays (an array of Approx would be zeroed on every query).
    double his[kMaxCandidates * kMaxCandidates], los[kMaxCandidates * kMaxCandidates],
        errs[kMaxCandidates * kMaxCandidates];
    int count = 0;
    for (int i = 0; i < ca; ++i)
        for (int j = 0; j < cb; ++j)
        {
            const int ia = candA[i], jb = candB[j];
            const ApproxVec W = (ia == a1 && jb == b1) ? W1
                                : (isEdge && ia == cache.indexA[1] && jb == cache.indexB[1]) ? W2
                                                                                              : minkowskiPoint(cx, in, ia, jb);
            const Approx value = dot(cx, nv, W);
            his[count] = value.hi;
            los[count] = value.lo;
            errs[count++] = value.err;
            const double end = value.hi - (value.err - value.lo);
            if (first || end < lowestEnd)
            {
                lowest = value;
                lowestEnd = end;
                first = false;
            }
        }
    // The minimum lies within lowest's bound, widened to cover every other value's lower end.
    for (int k = 0; k < count; ++k)
    {
        const double reach = ((lowest.hi - his[k]) + (lowest.lo - los[k]) + errs[k]) * kSafe + 0x1p-1000;
        lowest.err = std::max(lowest.err, reach);
    }
    const Approx L = div(cx, lowest, normV);
    if (!cx.ok)
        return;
    finish(roundInterval(sub(L, r), xh));
}

} // namespace gjk::correct

namespace gjk
{

template <class T>
void correctlyRound(const DistanceInput<T>& input, const SimplexCache& cache, const Options& options,
                    DistanceOutput<T>& out)
{
    if constexpr (std::is_same_v<T, double>)
        correct::refine(input, cache, options, out);
    else
        out.path = CorrectPath::NeedsExact;
}

} // namespace gjk

#include "gjk/detail/fp_end.hpp"
