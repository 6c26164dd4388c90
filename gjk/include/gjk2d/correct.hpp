// The correctly rounded distance (Options::correctlyRounded): the double nearest to the exact
// distance of the problem as given, max(0, dist(hull(A'), hull(B')) - rA - rB) with
// A' = {c x - s y + px, s x + c y + py} evaluated exactly (the exact side's semantics,
// exact/include/gjk2d/exact.hpp), and 0 exactly when that exact value is 0.
//
// A filtered design, as in exact geometric computation: the cheap stage decides when it can prove
// its answer, and hands the rest on.
//   1. The plain GJK query (any Options) names the final features: the index pairs of its simplex
//      (SimplexCache). A triangle without containment (three points of Z on one line) is tried as
//      its three edges in turn (refine).
//   2. CorrectPath::Double: containment (a triangle simplex) whose three orientation signs are
//      certified in double: first by a semi-static filter (containsOriginFiltered: one bound per
//      coordinate from the inputs' magnitudes), then, where that cannot decide, by the running
//      error bound of gjk2d/certify.hpp. The exact distance is then 0.
//   3. CorrectPath::Extended: the features' points of Z recomputed from the original input in
//      double-double (stage 4's first steps, below); then the square root, the quotient, the radii
//      and the rounding decision in 80-bit extended precision (long double, where it is that
//      format), with a static error bound: about 2^-61 of the distance. A distance within that of
//      a rounding midpoint goes on to stage 4's double-double tail (rare: docs/gjk.md,
//      "Correctly rounded distance").
//   4. CorrectPath::DoubleDouble: the features' distance recomputed from the original input in
//      double-double, with error-free products (Dekker's TwoProduct with Veltkamp's split, or one
//      fused multiply-add where the CPU has it: "The error-free products", below; the same bits)
//      and sums (Knuth's TwoSum), every
//      quantity carrying a rigorous bound on its distance to the exact value (that arithmetic:
//      gjk2d/exact_arithmetic.hpp). That gives
//        U = the distance from the origin to the feature (a point or a segment of Z = A' - B'),
//            an upper bound of the exact hull distance d*;
//        L = min over z in Z of n.z / |n| for the feature's direction n (the support-function,
//            or duality, bound), a lower bound of d* for any n. Only the vertices whose double
//            value along n lies within a certified error of the extreme one can attain the
//            minimum; those few are evaluated in double-double.
//      In the common case L is not needed: when the features' own vertices attain both shapes'
//      support along n (featuresAttainSupport, one pass over each shape), d* = U exactly.
//      The points of Z are computed in two lanes (a point's x and y side by side:
//      minkowskiPointLanes, below).
//      When the features are the closest ones, L = U = d* in exact arithmetic. If every value of
//      [L - rA - rB, U - rA - rB] (with the bounds) rounds to the same double, that double is the
//      answer; if all are <= 0, the answer is 0. When the features are the closest ones and the
//      interval straddles one rounding midpoint (an exact tie, common with float-engine data), the
//      exact side of that midpoint is computed with floating-point expansions (Shewchuk), and a
//      tie goes to the even double.
//   5. CorrectPath::NeedsExact: anything the bounds cannot decide (exact touching, a distance on a
//      rounding midpoint when the features are not both shapes' support, features that are not
//      the closest, an expansion beyond its guards, a product of the features' coordinates
//      beyond [2^-960, 2^900], a culled triangle). The output then holds the plain answer, and
//      the caller completes it with exact arithmetic: exact/include/gjk2d/correct_fallback.hpp
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

#include "gjk2d/certify.hpp"
#include "gjk2d/detail/macros.hpp"
#include "gjk2d/exact_arithmetic.hpp"
#include "gjk2d/math.hpp"
#include "gjk2d/types.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <type_traits>

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk::correct
{

// The world point of a local one, as terms: (c x - s y + px, s x + c y + py), with sign +1 or -1.
template <class P = DekkerProducts>
GJK_CORRECT_INLINE void addWorldPoint(Terms& tx, Terms& ty, const Transform<double>& xf,
                                      Vec2<double> v, double sign)
{
    tx.addProduct<P>(sign * xf.q.c, v.x);
    tx.addProduct<P>(-sign * xf.q.s, v.y);
    tx.add(sign * xf.p.x);
    ty.addProduct<P>(sign * xf.q.s, v.x);
    ty.addProduct<P>(sign * xf.q.c, v.y);
    ty.add(sign * xf.p.y);
}

// W = xfA * A[i] - xfB * B[j] from the same ten pieces as the scalar Terms (four exact products,
// their trailing parts, two translations), both coordinates at once: one VecSum pass over the six
// leading pieces, the rest (its five errors and the four trailing parts) summed in double. The
// bound is exactSum's: n 2^-52 sum|rest| with n = 10 (recursive summation of nine values errs by
// at most 8u sum|rest|, 2^-52 = 2u). False when a guard fails or the rest is not below 2^-40 of
// the sum in both lanes (heavy cancellation): exactSum's further passes then decide. Float data
// (the four coordinates and both rotations floats, as float engines give) skip the products'
// splits and guards (floatProduct): the pieces, and so W, are bit for bit the same.
template <class P = DekkerProducts>
GJK_CORRECT_INLINE bool minkowskiPointLanes(const DistanceInput<double>& in, int i, int j,
                                            ApproxVec& W)
{
    const Transform<double>&xa = in.transformA, &xb = in.transformB;
    const Vec2<double> a = in.proxyA.points[i], b = in.proxyB.points[j];
    const V2 f1 = pair(xa.q.c, xa.q.s), g1 = pair(a.x, a.x);
    const V2 f2 = pair(-xa.q.s, xa.q.c), g2 = pair(a.y, a.y);
    const V2 f3 = pair(-xb.q.c, -xb.q.s), g3 = pair(b.x, b.x);
    const V2 f4 = pair(xb.q.s, -xb.q.c), g4 = pair(b.y, b.y);
    const V2 tA = pair(xa.p.x, xa.p.y), tB = pair(-xb.p.x, -xb.p.y);
    M2 exact = (abs2(tA) <= 0x1p900) & (abs2(tB) <= 0x1p900);
    DD2 p1, p2, p3, p4;
    const V2 va = pair(a.x, a.y), vb = pair(b.x, b.y);
    if (low29BitsZero(va, vb, f1, f3) &&
        all2(isFloat2(va) & isFloat2(vb) & isFloat2(f1) & isFloat2(f3)))
    {
        // Float data (a float engine's): every product exact as it is (floatProduct).
        p1 = floatProduct(f1, g1), p2 = floatProduct(f2, g2), p3 = floatProduct(f3, g3),
        p4 = floatProduct(f4, g4);
    }
    else
    {
        p1 = P::twoProduct(f1, g1), p2 = P::twoProduct(f2, g2), p3 = P::twoProduct(f3, g3),
        p4 = P::twoProduct(f4, g4);
        exact = exact & exactProduct(f1, g1, p1.hi) & exactProduct(f2, g2, p2.hi) &
                exactProduct(f3, g3, p3.hi) & exactProduct(f4, g4, p4.hi);
    }
    const DD2 s1 = twoSum(p1.hi, p2.hi);
    const DD2 s2 = twoSum(s1.hi, tA);
    const DD2 s3 = twoSum(s2.hi, p3.hi);
    const DD2 s4 = twoSum(s3.hi, p4.hi);
    const DD2 s5 = twoSum(s4.hi, tB);
    const V2 rest =
        (((s1.lo + s2.lo) + (s3.lo + s4.lo)) + (s5.lo + (p1.lo + p2.lo))) + (p3.lo + p4.lo);
    const V2 restAbs = (((abs2(s1.lo) + abs2(s2.lo)) + (abs2(s3.lo) + abs2(s4.lo))) +
                        (abs2(s5.lo) + (abs2(p1.lo) + abs2(p2.lo)))) +
                       (abs2(p3.lo) + abs2(p4.lo));
    if (!all2(exact & (restAbs <= 0x1p-40 * abs2(s5.hi))))
        return false;
    const DD2 r = twoSum(s5.hi, rest);
    const V2 err = (10 * 0x1p-52 * kSafe) * restAbs;
    W = {{r.hi[0], r.lo[0], err[0]}, {r.hi[1], r.lo[1], err[1]}};
    return true;
}

// W = xfA * A[i] - xfB * B[j], a point of Z.
template <class Cx>
GJK_CORRECT_INLINE ApproxVec minkowskiPoint(Cx& cx, const DistanceInput<double>& in, int i, int j)
{
    using P = typename Cx::Products;
    ApproxVec W;
    if (minkowskiPointLanes<P>(in, i, j, W)) [[likely]]
        return W;
    Terms tx, ty;
    addWorldPoint<P>(tx, ty, in.transformA, in.proxyA.points[i], 1);
    addWorldPoint<P>(tx, ty, in.transformB, in.proxyB.points[j], -1);
    return {exactSum(cx, tx), exactSum(cx, ty)};
}

// e = W(i2, j2) - W(i1, j1) from the local differences (the translations cancel exactly).
template <class Cx>
GJK_CORRECT_INLINE ApproxVec minkowskiEdge(Cx& cx, const DistanceInput<double>& in, int i1, int j1,
                                           int i2, int j2)
{
    using P = typename Cx::Products;
    Terms tx, ty;
    auto side = [&](const Transform<double>& xf, Vec2<double> p2, Vec2<double> p1, double sign)
                    GJK_CORRECT_LAMBDA_INLINE
    {
        tx.addProductOfDifference<P>(sign * xf.q.c, p2.x, p1.x);
        tx.addProductOfDifference<P>(-sign * xf.q.s, p2.y, p1.y);
        ty.addProductOfDifference<P>(sign * xf.q.s, p2.x, p1.x);
        ty.addProductOfDifference<P>(sign * xf.q.c, p2.y, p1.y);
    };
    if (i1 != i2)
        side(in.transformA, in.proxyA.points[i2], in.proxyA.points[i1], 1);
    if (j1 != j2)
        side(in.transformB, in.proxyB.points[j2], in.proxyB.points[j1], -1);
    return {exactSum(cx, tx), exactSum(cx, ty)};
}

// a2.e > 0 and a1.e < 0 for certain (the origin projects strictly inside the segment a1 a2 of
// direction e), each sign certified in double from the values' bounds; both in two lanes.
GJK_CORRECT_INLINE bool projectsInside(const ApproxVec& a2, const ApproxVec& a1, const ApproxVec& e)
{
    auto lanes = [](const Approx& p0, const Approx& p1, const Approx& q)
                     GJK_CORRECT_LAMBDA_INLINE -> ApproxVec2
    {
        return {pair(p0.hi, p1.hi), pair(p0.lo, p1.lo), pair(p0.err, p1.err),
                pair(q.hi, q.hi),   pair(q.lo, q.lo),   pair(q.err, q.err)};
    };
    const ApproxVec2 x = lanes(a2.x, a1.x, e.x), y = lanes(a2.y, a1.y, e.y);
    const V2 g = x.ph * x.qh + y.ph * y.qh;
    auto term = [](const ApproxVec2& t) GJK_CORRECT_LAMBDA_INLINE
    {
        const V2 dp = abs2(t.pl) + t.pe, dq = abs2(t.ql) + t.qe;
        return (((3 * 0x1p-53) * abs2(t.ph * t.qh) + dp * abs2(t.qh)) + dq * abs2(t.ph)) + dp * dq;
    };
    const V2 bound = (term(x) + term(y)) * pair(kSafe, kSafe) + pair(0x1p-1000, 0x1p-1000);
    return g[0] > bound[0] && g[1] < -bound[1];
}

// The vertices of a shape that can attain min (sign = +1) or max (sign = -1) of n.(Q x) over its
// points: those whose double value lies within twice a certified bound of the extreme one. The
// bound covers the rounding of m = Q^T n (n = hi + lo, only hi used: |lo| <= u |hi|), and of the
// dot products: |computed - exact| <= (3u + 2u (1 + 4u)) (|c| + |s|) max|n| (|x| + |y|), taken
// as 8u with max|x| + max|y| (>= every |x| + |y|) for the last factor, plus an absolute 2^-1000
// for underflow. Returns the count (at most kMaxCandidates; more returns kMaxCandidates + 1). The
// common case does not come here (featuresAttainSupport, above).
inline constexpr int kMaxCandidates = 4;
inline int supportCandidates(const Polygon<double>& p, const Transform<double>& xf,
                             const ApproxVec& n, double sign, int* out)
{
    const double nx = n.x.hi, ny = n.y.hi, c = xf.q.c, s = xf.q.s;
    const double mx = sign * (c * nx + s * ny), my = sign * (c * ny - s * nx);
    // The values are kept for the second pass when they fit in a small buffer. Both passes are
    // free of data-dependent branches: the candidates are few and their positions random.
    constexpr int kBuffer = 64;
    double values[kBuffer];
    const bool buffered = p.count <= kBuffer;
    double best = std::numeric_limits<double>::infinity(), maxX = 0, maxY = 0;
    for (int i = 0; i < p.count; ++i)
    {
        const double v = mx * p.points[i].x + my * p.points[i].y;
        if (buffered)
            values[i] = v;
        best = std::min(best, v);
        maxX = std::max(maxX, std::abs(p.points[i].x));
        maxY = std::max(maxY, std::abs(p.points[i].y));
    }
    const double extent = maxX + maxY; // >= max(|x| + |y|)
    if (!(std::abs(best) <= 0x1p900 && extent <= 0x1p900))
        return kMaxCandidates + 1; // overflow (or NaN): no certified candidates
    const double eps =
        8 * 0x1p-53 * (std::abs(c) + std::abs(s)) * std::max(std::abs(nx), std::abs(ny)) * extent +
        0x1p-1000;
    const double limit = best + 2 * eps * kSafe;
    int count = 0;
    for (int i = 0; i < p.count; ++i)
    {
        const double v = buffered ? values[i] : mx * p.points[i].x + my * p.points[i].y;
        out[count] = i; // out has room for kMaxCandidates + 1
        count += v <= limit;
        if (count > kMaxCandidates) [[unlikely]]
            return kMaxCandidates + 1;
    }
    return count;
}

// The common case's test, in one pass with no buffer: every vertex of the shape but the features'
// own (i1, i2) lies certainly above the features' lowest value of n.(Q x) (sign = +1; below the
// highest with sign = -1). Vertex i's computed value errs by at most eps_i, supportCandidates's
// bound taken at the vertex's own |x| + |y| instead of the shape's largest; so exact(i) >=
// v_i - eps_i > v_f + eps_f >= exact(f) for a feature vertex f, and no other vertex can attain
// the minimum: the same conclusion as supportCandidates's candidates all lying in {i1, i2}, for
// the exact n too (eps covers |n - n.hi| when n's own bound is below kDirectionAccuracy of it:
// refine's guards, below).
inline bool featuresAttainSupport(const Polygon<double>& p, const Transform<double>& xf,
                                  const ApproxVec& n, double sign, int i1, int i2)
{
    const double nx = n.x.hi, ny = n.y.hi, c = xf.q.c, s = xf.q.s;
    const double mx = sign * (c * nx + s * ny), my = sign * (c * ny - s * nx);
    const double k =
        8 * 0x1p-53 * kSafe * (std::abs(c) + std::abs(s)) * std::max(std::abs(nx), std::abs(ny));
    auto value = [&](int i) { return mx * p.points[i].x + my * p.points[i].y; };
    auto eps = [&](int i)
    { return k * (std::abs(p.points[i].x) + std::abs(p.points[i].y)) + 0x1p-1000; };
    const double limit = std::min(value(i1) + eps(i1), value(i2) + eps(i2));
    if (!(std::abs(limit) <= 0x1p900))
        return false; // overflow (or NaN)
    int above = 0;
    for (int i = 0; i < p.count; ++i)
        above += (value(i) - eps(i) > limit) | (i == i1) | (i == i2);
    return above == p.count;
}

// Containment first through a semi-static filter, in two lanes. Each coordinate of
// W = (c x - s y + p)_A - (c x - s y + p)_B passes through at most four roundings (a product, two
// sums, the difference), so |W - W exact| <= gamma_4 m <= 5u m per lane, m = |c x| + |s y| + |p| of
// A plus the same of B (computed: at most five roundings low, which 5u against gamma_4's 4.0001u
// covers), plus 2^-1068 for four products that may underflow. An orientation
// o = Wi.x Wj.y - Wi.y Wj.x then errs by at most
//   ex_i |Wj.y| + ey_j |Wi.x| + ex_i ey_j + ey_i |Wj.x| + ex_j |Wi.y| + ey_i ex_j    (the inputs'
//   error)
//   + 2u (1 + u) (|Wi.x Wj.y| + |Wi.y Wj.x|)                                       (o's own
//   roundings)
// taken with the safety factor and 2^-1000 for underflow. True: the three signs agree for certain
// (the origin is strictly inside); false: not decided here (containsOriginCertified's running
// bound, tighter, then tries).
GJK_CORRECT_INLINE bool containsOriginFiltered(const DistanceInput<double>& in,
                                               const SimplexCache& cache)
{
    const Transform<double>&xa = in.transformA, &xb = in.transformB;
    const V2 ca = pair(xa.q.c, xa.q.s), sa = pair(-xa.q.s, xa.q.c), ta = pair(xa.p.x, xa.p.y);
    const V2 cb = pair(xb.q.c, xb.q.s), sb = pair(-xb.q.s, xb.q.c), tb = pair(xb.p.x, xb.p.y);
    V2 W[3], E[3];
    for (int k = 0; k < 3; ++k)
    {
        const Vec2<double> a = in.proxyA.points[cache.indexA[k]],
                           b = in.proxyB.points[cache.indexB[k]];
        const V2 ax = pair(a.x, a.x), ay = pair(a.y, a.y), bx = pair(b.x, b.x), by = pair(b.y, b.y);
        const V2 pa1 = ca * ax, pa2 = sa * ay, pb1 = cb * bx, pb2 = sb * by;
        W[k] = ((pa1 + pa2) + ta) - ((pb1 + pb2) + tb);
        const V2 m = ((abs2(pa1) + abs2(pa2)) + abs2(ta)) + ((abs2(pb1) + abs2(pb2)) + abs2(tb));
        E[k] = (5 * 0x1p-53) * m + pair(0x1p-1068, 0x1p-1068);
    }
    int positive = 0, negative = 0;
    for (int k = 0; k < 3; ++k)
    {
        const int l = (k + 1) % 3;
        const double p = W[k][0] * W[l][1], q = W[k][1] * W[l][0];
        const double o = p - q;
        const double bound =
            (E[k][0] * std::abs(W[l][1]) + E[l][1] * std::abs(W[k][0]) + E[k][0] * E[l][1] +
             E[k][1] * std::abs(W[l][0]) + E[l][0] * std::abs(W[k][1]) + E[k][1] * E[l][0] +
             2 * 0x1p-53 * (1 + 0x1p-53) * (std::abs(p) + std::abs(q))) *
                kSafe +
            0x1p-1000;
        positive += o > bound;
        negative += o < -bound;
    }
    return positive == 3 || negative == 3;
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

// What the rounding steps below (and refine) return when their bounds cannot decide: any negative
// value is not an answer, since every answer is >= 0.
inline constexpr double kUndecided = -1;

// The decision: the exact x lies in [xl, xh] (each an Approx, with its bound). Returns the
// correctly rounded max(0, x), or a negative value when the bounds cannot decide.
GJK_CORRECT_INLINE double roundInterval(const Approx& xl, const Approx& xh)
{
    using certify::down;
    using certify::up;
    // All of [.., xh + err] <= 0: the answer is exactly 0.
    if (xh.hi <= -up(xh.lo + xh.err))
        return 0;
    // Positive for sure: xl - err > 0.
    if (!(xl.hi > up(xl.err - xl.lo)))
        return kUndecided;
    const double m = xh.hi; // xh rounded to nearest (hi = fl(hi + lo))
    if (!(m >= 0x1p-900 && m <= 0x1p900))
        return kUndecided;
    // The neighbours of m > 0 (normal, finite) by its bit pattern, without std::nextafter's call.
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(m);
    const double gapAbove = std::bit_cast<double>(bits + 1) - m;
    const double gapBelow = m - std::bit_cast<double>(bits - 1);
    // The upper end below the midpoint above m: xh.lo + err < gapAbove / 2.
    if (!(up(xh.lo + xh.err) < 0.5 * gapAbove))
        return kUndecided;
    // The lower end above the midpoint below m: (xl.hi - m) + xl.lo - err > -gapBelow / 2.
    // xl.hi - m is exact when xl.hi is within a factor 2 of m (Sterbenz).
    if (!(xl.hi >= 0.5 * m && xl.hi <= 2 * m))
        return kUndecided;
    if (!(down(down((xl.hi - m) + xl.lo) - xl.err) > -0.5 * gapBelow))
        return kUndecided;
    return m;
}

// --- Exact ties ---------------------------------------------------------------------------------
//
// Float-engine data make exact ties common: a distance whose exact value has few bits (sums of
// products of floats) can sit exactly on a midpoint between two doubles, where no bound can
// decide (common on engine/pyramid-toi: docs/gjk.md, "Correctly rounded distance"). When the
// features are the closest ones and the interval around X = U - rA - rB straddles one midpoint T,
// the sign of U* - (T + rA + rB) is computed exactly with expansions (gjk2d/exact_arithmetic.hpp);
// a guard that fails leaves the query to the exact side. Vertex: U*^2 = |W1|^2; edge: U* = |C| /
// |e| with C = cross(e, W1), compared as C^2 against T'^2 |e|^2 (T' = T + rA + rB > 0).

// The exact point W(i, j) of Z, both coordinates: the exact pieces of Terms (addWorldPoint), summed
// into expansions.
inline void exactPoint(Context& cx, const DistanceInput<double>& in, int i, int j, Expansion& x,
                       Expansion& y)
{
    Terms tx, ty;
    addWorldPoint(tx, ty, in.transformA, in.proxyA.points[i], 1);
    addWorldPoint(tx, ty, in.transformB, in.proxyB.points[j], -1);
    cx.require(tx.ok && ty.ok);
    for (int k = 0; k < tx.ns; ++k)
        grow(cx, x, tx.small[k]);
    for (int k = 0; k < tx.nb; ++k)
        grow(cx, x, tx.big[k]);
    for (int k = 0; k < ty.ns; ++k)
        grow(cx, y, ty.small[k]);
    for (int k = 0; k < ty.nb; ++k)
        grow(cx, y, ty.big[k]);
}

// sign(U* - (tHi + tLo + rA + rB)), U* the exact distance from the origin to the feature (the
// vertex W(a1, b1), or the edge's line through W(a1, b1) and W(a2, b2)), for a positive target;
// 2 when a guard fails.
inline int exactSideOfTarget(const DistanceInput<double>& in, const SimplexCache& cache, double tHi,
                             double tLo, double rA, double rB)
{
    Context cx;
    Expansion x1, y1, T;
    exactPoint(cx, in, cache.indexA[0], cache.indexB[0], x1, y1);
    grow(cx, T, tLo);
    grow(cx, T, tHi);
    grow(cx, T, rA);
    grow(cx, T, rB);
    Expansion lhs, rhs, T2;
    growProduct(cx, T2, T, T, 1);
    if (cache.count == 1)
    {
        growProduct(cx, lhs, x1, x1, 1); // |W1|^2
        growProduct(cx, lhs, y1, y1, 1);
        rhs = T2;
    }
    else
    {
        Expansion x2, y2, C, C2, e2;
        exactPoint(cx, in, cache.indexA[1], cache.indexB[1], x2, y2);
        Expansion ex = x2, ey = y2; // e = W2 - W1
        for (int i = 0; i < x1.n; ++i)
            grow(cx, ex, -x1.t[i]);
        for (int i = 0; i < y1.n; ++i)
            grow(cx, ey, -y1.t[i]);
        growProduct(cx, C, ex, y1, 1); // cross(e, W1)
        growProduct(cx, C, ey, x1, -1);
        growProduct(cx, lhs, C, C, 1);
        growProduct(cx, e2, ex, ex, 1);
        growProduct(cx, e2, ey, ey, 1);
        growProduct(cx, rhs, T2, e2, 1);
    }
    for (int i = 0; i < rhs.n; ++i)
        grow(cx, lhs, -rhs.t[i]);
    return cx.ok ? signOf(lhs) : 2;
}

// The correctly rounded X* = U* - rA - rB > 0 when [xh.hi + xh.lo +- xh.err] straddles exactly
// one midpoint between two positive doubles (normal, below 2^900): the exact side of that
// midpoint decides, a tie goes to the even one (round half to even). Negative: not decided.
inline double roundAtMidpoint(const DistanceInput<double>& in, const SimplexCache& cache,
                              const Approx& xh, double rA, double rB)
{
    using certify::down;
    using certify::up;
    const double m = xh.hi;
    if (!(m >= 0x1p-900 && m <= 0x1p900) || !(xh.hi > up(xh.err - xh.lo)))
        return kUndecided;
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(m);
    const double below = std::bit_cast<double>(bits - 1), above = std::bit_cast<double>(bits + 1);
    const double halfBelow = 0.5 * (m - below), halfAbove = 0.5 * (above - m); // exact
    // X within [m + dLow, m + dHigh] (d = xh.lo +- err, rounded outwards), and strictly between
    // two neighbouring doubles lo < hi whose midpoint it straddles (so the answer is lo or hi).
    const double dHigh = up(xh.lo + xh.err), dLow = down(xh.lo - xh.err);
    double lo, hi, tLo;
    if (dHigh >= halfAbove && dLow > -halfBelow && dHigh < 2 * halfAbove)
        lo = m, hi = above, tLo = halfAbove; // m < X < above
    else if (dLow <= -halfBelow && dHigh < halfAbove && dLow > -2 * halfBelow)
        lo = below, hi = m, tLo = -halfBelow; // below < X < m
    else
        return kUndecided;
    const int side = exactSideOfTarget(in, cache, m, tLo, rA, rB);
    if (side == 2)
        return kUndecided;
    if (side != 0)
        return side > 0 ? hi : lo;
    return (std::bit_cast<std::uint64_t>(lo) & 1) == 0 ? lo : hi; // a tie: the even one
}

// --- The extended-precision stage (CorrectPath::Extended) ---------------------------------------
//
// Where long double is the x87 80-bit format (a 64-bit significand: GCC and Clang on x86 Linux,
// at the x87 unit's default precision control, checked), the separated case's tail runs in it
// with a static error bound: from the points of Z in double-double (refine, below) to the length,
// the square root, the quotient, the radii and the rounding decision. Unit roundoff u = 2^-64 per
// operation, and no operation can underflow or overflow: products and sums of doubles stay far
// inside its exponent range (+-16382). Its error, about 2^-61 of the distance, leaves undecided
// only distances that close to a rounding midpoint (a small share, which go on to the
// double-double tail), at a fraction of that tail's chains of dependent operations. Computing the
// points of Z in extended precision too was tried: each coordinate then errs by u times its
// terms' magnitudes, not its own, which left far more of `random` undecided (docs/gjk.md).
// Elsewhere (long double is double with MSVC, binary128 in software on AArch64) the stage is
// skipped.
using Ext = long double;
inline constexpr bool kExtended = std::numeric_limits<Ext>::digits == 64;
inline constexpr Ext uExt = 0x1p-64L;
inline constexpr Ext kSafeExt = 1 + 0x1p-20L; // covers the rounding of the bounds themselves

// The x87 control word at its default for this stage: precision control 64 bits (bits 8-9 = 11)
// and rounding to nearest (bits 10-11 = 00). A program may change it (fldcw); then the stage is
// skipped and double-double decides. One fnstcw per query.
GJK_CORRECT_INLINE bool extendedPrecisionOn()
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    unsigned short cw;
    __asm__ volatile("fnstcw %0" : "=m"(cw));
    return (cw & 0x0F00) == 0x0300;
#else
    return kExtended;
#endif
}

// The tail of the separated case in extended precision. In: v = e (edge) or W1 (vertex), each
// coordinate a double-double value within its bound of the exact one; for an edge,
// num = cross(e, W1) (double-double, its bound); r = rA + rB. The exact distance from the origin
// to the feature is U* = |num| / |e| (edge) or |W1| (vertex). Out: X = U - r in extended
// precision with eX >= |X* - X|; false when a relative bound exceeds 2^-10 (then the
// double-double tail decides).
//   v rounded to extended: each coordinate within E = err + u |v| of the exact one, so the exact
//   length is |v| within Ex + Ey; s = sqrt(vx^2 + vy^2) rounded is |v| within 3.01u (gamma_2 of
//   the sum of squares, halved by the square root, and the root's own rounding). So the exact
//   length is s (1 + beta), |beta| <= rb = 4u + (Ex + Ey) / s.
//   Edge: U = |C| / s rounded, C = num rounded, within ra = eC / |C|: U* / U lies within
//   1 +- (ra + rb + 2u)(1 + 2^-8) for ra, rb <= 2^-10 (1 / (1 - x) <= 1 + x (1 + 2x)). Vertex:
//   U = s, within rb. X = U - r rounds twice (r = rA + rB, then the difference).
GJK_CORRECT_INLINE bool distanceExtended(const ApproxVec& v, const Approx* num, double rA,
                                         double rB, Ext& X, Ext& eX)
{
    const Ext vx = Ext(v.x.hi) + v.x.lo, vy = Ext(v.y.hi) + v.y.lo;
    const Ext Ex = v.x.err + uExt * std::abs(vx), Ey = v.y.err + uExt * std::abs(vy);
    const Ext s = std::sqrt(vx * vx + vy * vy);
    const Ext rb = (4 * uExt + (Ex + Ey) / s) * kSafeExt;
    Ext U = s, rel = rb;
    if (num)
    {
        const Ext C = std::abs(Ext(num->hi) + num->lo);
        const Ext ra = (num->err + uExt * C) * kSafeExt / C;
        if (!(ra <= 0x1p-10L && rb <= 0x1p-10L))
            return false;
        U = C / s;
        rel = (ra + rb + 2 * uExt) * (1 + 0x1p-8L);
    }
    if (!(rel <= 0x1p-10L))
        return false;
    const Ext r = Ext(rA) + rB;
    X = U - r;
    eX = (rel * U + uExt * r + uExt * std::abs(X)) * kSafeExt;
    return true;
}

// The correctly rounded max(0, X*) from X with |X* - X| <= eX (both > 0 decided by the caller),
// or a negative value: the nearest double m, and X's interval strictly inside m's rounding
// interval (X - m is exact: Sterbenz).
GJK_CORRECT_INLINE double roundExtended(Ext X, Ext eX)
{
    const double m = double(X);
    if (!(m >= 0x1p-1000 && m <= 0x1p1000))
        return kUndecided;
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(m);
    const Ext gapAbove = Ext(std::bit_cast<double>(bits + 1)) - m,
              gapBelow = Ext(m) - std::bit_cast<double>(bits - 1);
    const Ext d = X - m;
    return d + eX < 0.5L * gapAbove && d - eX > -0.5L * gapBelow ? m : kUndecided;
}

// --- The refinement: refine and its steps --------------------------------------------------------

// refine's guards, each with the derivation of its value.
// The largest radius refined: the range of every guard of gjk2d/exact_arithmetic.hpp (pieces and
// products at most 2^900), so that r = rA + rB and U - r stay far from overflow.
inline constexpr double kMaxRadius = 0x1p900;
// An edge e = W2 - W1 whose bound exceeds this fraction of |e| (cancellation: a short edge far from
// the origin) is recomputed from the shapes' local differences, where the translations cancel
// before any rounding. 2^-80 keeps e's share of U's relative bound below the extended stage's own
// rounding (2^-64) and far below the half ulp (2^-53) the rounding must resolve, and an edge's n
// (e turned) within kDirectionAccuracy.
inline constexpr double kEdgeAccuracy = 0x1p-80;
// featuresAttainSupport's certificate holds for the exact direction n too when n's own bound is
// below this fraction of n: its eps, 8u (|c| + |s|) max|n| (|x| + |y|), exceeds the roundings it
// covers (5u: supportCandidates) by 3u = 2^-51.4 of that scale, far more than the
// 2^-60 (|c| + |s|) max|n| (|x| + |y|) such a direction error can move a vertex's value.
inline constexpr double kDirectionAccuracy = 0x1p-60;
// An absolute slack beside the relative kSafe in a candidate's reach (lowestSupportValue), as in
// projectsInside and supportCandidates: it keeps the widened bound rigorous for values so small
// that a relative margin vanishes (near underflow, multiples of 2^-1074), and lies far below any
// distance the refinement decides (roundInterval and roundAtMidpoint answer only from 2^-900 on).
inline constexpr double kUnderflowMargin = 0x1p-1000;

// The features the plain query ended on, as points of Z in double-double with their bounds.
struct Features
{
    int a1 = 0, b1 = 0, a2 = 0, b2 = 0; // index pairs of the simplex; a vertex has a2 = a1, b2 = b1
    bool isEdge = false;
    ApproxVec W1, W2, e; // W(a1, b1); an edge's W(a2, b2) and e = W2 - W1
    Approx unum;         // an edge's cross(e, W1) = cross(W2, W1): U's numerator
    ApproxVec n, nv;     // the direction towards Z (n.W1 > 0), and n's values as an exact direction
    int attained = -1;   // supportAttained's answer once evaluated: 1 or 0 (-1: not yet)
};

GJK_CORRECT_INLINE ApproxVec valuesOf(const ApproxVec& v)
{
    return {{v.x.hi, v.x.lo, 0}, {v.y.hi, v.y.lo, 0}};
}

// Writes a decided answer (a negative one is not decided) with its path; false when not written.
// Plain `inline`, as supportAttained: the compiler keeps both out of line, as it did the lambdas
// they were.
inline bool writeAnswer(DistanceOutput<double>& out, double answer, CorrectPath path)
{
    if (!(answer >= 0))
        return false;
    if (answer > 0 && !(out.distance > 0))
        return false; // a plain overlap answer: the exact completion gives the witness points
    if (answer == 0 && out.distance > 0)
    {
        const Vec2<double> mid = 0.5 * (out.pointA + out.pointB);
        out.pointA = out.pointB = mid;
        out.normal = {};
    }
    out.distance = answer;
    out.path = path;
    return true;
}

// A triangle simplex (CorrectPath::Double): the hulls overlap for certain when the plain query
// stopped on containment and the three orientation signs are certified in double.
GJK_CORRECT_INLINE bool containmentCertified(const DistanceInput<double>& in,
                                             const SimplexCache& cache,
                                             const DistanceOutput<double>& out)
{
    return out.stop == StopReason::Containment &&
           (containsOriginFiltered(in, cache) || containsOriginCertified(in, cache));
}

// Edge feature W1 W2: the distance to its line, |cross(e, W1)| / |e|, is the distance to the
// segment when the origin projects inside it: u = W2.e > 0 and v = -W1.e > 0. e = W2 - W1;
// recomputed from the shapes' local differences when that difference is not accurate to
// kEdgeAccuracy of e. cross(e, W1) = cross(W2, W1), computed beside e rather than after it.
// False when a guard fails or the projection is not certainly inside.
template <class Cx>
GJK_CORRECT_INLINE bool edgeFeature(Cx& cx, const DistanceInput<double>& in, Features& f)
{
    f.W2 = minkowskiPoint(cx, in, f.a2, f.b2);
    f.unum = cross(cx, f.W2, f.W1);
    addLanes(f.W2.x, negate(f.W1.x), f.W2.y, negate(f.W1.y), f.e.x, f.e.y); // W2 - W1
    if (!(std::max(f.e.x.err, f.e.y.err) <=
          kEdgeAccuracy * std::max(std::abs(f.e.x.hi), std::abs(f.e.y.hi))))
        f.e = minkowskiEdge(cx, in, f.a1, f.b1, f.a2, f.b2);
    if (!cx.ok || !projectsInside(f.W2, f.W1, f.e))
        return false;
    // n: the perpendicular of e towards Z (n.W1 > 0).
    f.n = f.unum.hi > 0 ? ApproxVec{negate(f.e.y), f.e.x} : ApproxVec{f.e.y, negate(f.e.x)};
    return true;
}

// The final features of a one- or two-point simplex, their points of Z and direction n. False
// when a guard fails or an edge's side is not decided (the caller then needs exact).
template <class Cx>
GJK_CORRECT_INLINE bool featuresOf(Cx& cx, const DistanceInput<double>& in,
                                   const SimplexCache& cache, Features& f)
{
    f.isEdge = cache.count == 2;
    f.a1 = cache.indexA[0], f.b1 = cache.indexB[0];
    f.a2 = f.isEdge ? cache.indexA[1] : f.a1, f.b2 = f.isEdge ? cache.indexB[1] : f.b1;
    f.W1 = minkowskiPoint(cx, in, f.a1, f.b1);
    if (!f.isEdge)
        f.n = f.W1; // vertex feature: n = W1, U = |W1|
    else if (!edgeFeature(cx, in, f))
        return false;
    if (!cx.ok)
        return false;
    f.nv = valuesOf(f.n);
    return true;
}

// The common case: the features' own vertices attain the support of each shape along n, for
// the exact n too (n's own bound below kDirectionAccuracy of it: featuresAttainSupport). Then the
// minimum of n.z over Z is attained at the feature: for a vertex W1 (n = W1), n.z >= n.W1; for an
// edge of one shape against a vertex of the other, n is perpendicular to that edge, so both its
// ends give n.W1. Z lies in the half-plane n.z >= n.W1, whose closest point to the origin lies on
// the feature (u, v > 0: edgeFeature): d* = U exactly, and L is not needed. Evaluated once, when
// first needed.
inline bool supportAttained(const DistanceInput<double>& in, Features& f)
{
    if (f.attained < 0)
        f.attained = std::max(f.n.x.err, f.n.y.err) <=
                         kDirectionAccuracy * std::max(std::abs(f.n.x.hi), std::abs(f.n.y.hi)) &&
                     (f.a1 == f.a2 || f.b1 == f.b2) &&
                     featuresAttainSupport(in.proxyA, in.transformA, f.nv, 1, f.a1, f.a2) &&
                     featuresAttainSupport(in.proxyB, in.transformB, f.nv, -1, f.b1, f.b2);
    return f.attained == 1;
}

// CorrectPath::Extended: the square root, the quotient and the rounding in extended precision,
// where the double-double ones are the longest chains of dependent operations. True when it
// decided (the answer written).
GJK_CORRECT_INLINE bool decideExtended(const DistanceInput<double>& in, Features& f, double rA,
                                       double rB, DistanceOutput<double>& out)
{
    if constexpr (kExtended)
    {
        Ext X, eX;
        if (!extendedPrecisionOn() ||
            !distanceExtended(f.isEdge ? f.e : f.W1, f.isEdge ? &f.unum : nullptr, rA, rB, X, eX))
            return false;
        double answer = kUndecided;
        if (X + eX <= 0)
            answer = 0; // apart by less than the radii (U* bounds d* from above: a point of Z)
        else if (X - eX > 0 && supportAttained(in, f))
            answer = roundExtended(X, eX);
        return writeAnswer(out, answer, CorrectPath::Extended);
    }
    else
        return false;
}

// U, the distance from the origin to the feature (|W1|, or |cross(e, W1)| / |e|), in double-double
// with its bound. normV = |n_v| for the direction n_v = n's values (sq = |n_v|^2); the exact
// length (|W1| or |e|) lies within lengthErr of it.
template <class Cx> GJK_CORRECT_INLINE Approx upperBound(Cx& cx, const Features& f, Approx& normV)
{
    const ApproxVec& v = f.isEdge ? f.e : f.W1;
    const Approx sq = dot(cx, valuesOf(v), valuesOf(v));
    const double lengthErr = v.x.err + v.y.err;
    normV = squareRoot(cx, sq);
    if (!cx.ok)
        return {};
    const Approx length = {normV.hi, normV.lo, (normV.err + lengthErr) * kSafe};
    return f.isEdge ? div(cx, absolute(f.unum), length) : length;
}

// The lowest of n_v.W over the candidate pairs' points W of Z, its bound widened to cover every
// other value's lower end: the minimum of the exact values lies within it.
template <class Cx>
GJK_CORRECT_INLINE Approx lowestSupportValue(Cx& cx, const DistanceInput<double>& in,
                                             const Features& f, const int* candA, int ca,
                                             const int* candB, int cb)
{
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
            const ApproxVec W = (ia == f.a1 && jb == f.b1) ? f.W1
                                : (f.isEdge && ia == f.a2 && jb == f.b2)
                                    ? f.W2
                                    : minkowskiPoint(cx, in, ia, jb);
            const Approx value = dot(cx, f.nv, W);
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
    for (int k = 0; k < count; ++k)
    {
        const double reach =
            ((lowest.hi - his[k]) + (lowest.lo - los[k]) + errs[k]) * kSafe + kUnderflowMargin;
        lowest.err = std::max(lowest.err, reach);
    }
    return lowest;
}

// L: the support bound along n_v = (n.x.hi + n.x.lo, n.y.hi + n.y.lo), taken as an exact
// direction (any direction gives a lower bound): min over the candidate pairs of n_v.W / |n_v|,
// from the few vertices that can attain the support. False when there are too many candidates
// or a guard fails.
template <class Cx>
GJK_CORRECT_INLINE bool lowerBound(Cx& cx, const DistanceInput<double>& in, const Features& f,
                                   const Approx& normV, Approx& L)
{
    int candA[kMaxCandidates + 1], candB[kMaxCandidates + 1];
    const int ca = supportCandidates(in.proxyA, in.transformA, f.nv, 1, candA);
    const int cb = supportCandidates(in.proxyB, in.transformB, f.nv, -1, candB);
    if (ca > kMaxCandidates || cb > kMaxCandidates)
        return false;
    L = div(cx, lowestSupportValue(cx, in, f, candA, ca, candB, cb), normV);
    return cx.ok;
}

// The refinement of a plain double query's output with the error-free products of Cx (Context or
// FmaContext). `cache` is the cache the plain query returned: its index pairs are the final
// features.
template <class Cx>
GJK_CORRECT_INLINE void refineWith(const DistanceInput<double>& in, const SimplexCache& cache,
                                   const Options& options, DistanceOutput<double>& out)
{
    out.path = CorrectPath::NeedsExact;
    const double rA = options.useRadii ? in.proxyA.radius : 0.0;
    const double rB = options.useRadii ? in.proxyB.radius : 0.0;
    if (out.outOfRange || !(rA <= kMaxRadius && rB <= kMaxRadius))
        return;
    const DD rs = twoSum(rA, rB);
    const Approx r = {rs.hi, rs.lo, 0};
    if (cache.count == 3)
    {
        if (!containmentCertified(in, cache, out))
            return;
        // The hulls overlap: the exact distance is max(0, 0 - rA - rB) = 0.
        out.path = CorrectPath::Double;
        out.distance = 0;
        return;
    }
    Cx cx;
    Features f;
    if (!featuresOf(cx, in, cache, f) || decideExtended(in, f, rA, rB, out))
        return;
    Approx normV;
    const Approx U = upperBound(cx, f, normV);
    if (!cx.ok)
        return;
    const Approx xh = sub(U, r);
    // Apart by less than the radii: 0 whatever the other bound.
    if (xh.hi <= -certify::up(xh.lo + xh.err))
    {
        writeAnswer(out, 0, CorrectPath::DoubleDouble);
        return;
    }
    if (f.isEdge && !(std::abs(f.unum.hi) > f.unum.err * kSafe + std::abs(f.unum.lo)))
        return; // the origin on (or too near) the edge's line: the side is not decided
    if (supportAttained(in, f))
    {
        const double answer = roundInterval(xh, xh);
        writeAnswer(out, answer >= 0 ? answer : roundAtMidpoint(in, cache, xh, rA, rB),
                    CorrectPath::DoubleDouble);
        return;
    }
    Approx L;
    if (lowerBound(cx, in, f, normV, L))
        writeAnswer(out, roundInterval(sub(L, r), xh), CorrectPath::DoubleDouble);
}

// --- The error-free products: Dekker's, or the FMA's where the CPU has it ------------------------
//
// x86-64's baseline has no fused multiply-add, so a build for it cannot use one directly (std::fma
// is a library call there). With GCC and Clang on x86 the refinement is compiled twice: as it is
// (Dekker's TwoProduct) and, in refineFma, for a target with FMA (each TwoProduct one multiply and
// one fused multiply-subtract: twoProductFma). The CPU is asked once (fmaAvailable), on the first
// refinement. Both give the same bits (twoProductFma: an exact product's error is unique), so
// the choice changes only the speed (docs/speed.md, "double-correct at 1.5x"). The environment
// variable GJK2D_NO_FMA, set and neither empty nor "0", forces Dekker's products (read once, on
// the first refinement): a compiler flag such as -mno-fma cannot, since the FMA code is compiled
// for its own target whatever the flags. GJK2D_NO_FMA_DISPATCH (a macro) compiles Dekker's path
// alone.
enum class Products
{
    Dekker,
    Fma,
};

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__)) &&                             \
    !defined(GJK2D_NO_FMA_DISPATCH)
#define GJK2D_FMA_DISPATCH 1
// GCC's SLP vectorizer fuses a * b +- c * d into a fused multiply-add behind -ffp-contract=off's
// back where the target has FMA (gjk2d/detail/fp_begin.hpp): refineFma's other arithmetic would
// then round differently from Dekker's path. Clang does not. GCC inlines the forced-inline steps
// into it nonetheless.
#if defined(__clang__)
#define GJK2D_FMA_TARGET __attribute__((target("fma")))
#else
#define GJK2D_FMA_TARGET __attribute__((target("fma"), optimize("no-tree-slp-vectorize")))
#endif

// True when the CPU (and the OS, which must save the AVX registers) can run FMA code.
inline bool fmaAvailable()
{
    __builtin_cpu_init();
    return __builtin_cpu_supports("fma");
}

[[gnu::noinline]] GJK2D_FMA_TARGET inline void refineFma(const DistanceInput<double>& in,
                                                         const SimplexCache& cache,
                                                         const Options& options,
                                                         DistanceOutput<double>& out)
{
    refineWith<FmaContext>(in, cache, options, out);
}
#else
inline bool fmaAvailable()
{
    return false;
}
#endif

// The products the refinement uses: the FMA's when the CPU has it and GJK2D_NO_FMA does not say
// otherwise.
inline Products chooseProducts()
{
    const char* off = std::getenv("GJK2D_NO_FMA");
    const bool forced = off != nullptr && off[0] != '\0' && !(off[0] == '0' && off[1] == '\0');
    return !forced && fmaAvailable() ? Products::Fma : Products::Dekker;
}
inline Products productsInUse()
{
    static const Products chosen = chooseProducts(); // once: a thread-safe static
    return chosen;
}

// The refinement with the given products (the tests run both): Products::Fma needs
// fmaAvailable().
inline void refineWithProducts(Products products, const DistanceInput<double>& in,
                               const SimplexCache& cache, const Options& options,
                               DistanceOutput<double>& out)
{
#if defined(GJK2D_FMA_DISPATCH)
    if (products == Products::Fma)
        refineFma(in, cache, options, out);
    else
        refineWith<Context>(in, cache, options, out);
#else
    (void)products;
    refineWith<Context>(in, cache, options, out);
#endif
}

// The refinement of a plain double query's output (Options::correctlyRounded). Out of line, so that
// gjk::distance does not carry its code and stack frame into the default query.
[[gnu::noinline]] inline void refine(const DistanceInput<double>& in, const SimplexCache& cache,
                                     const Options& options, DistanceOutput<double>& out)
{
    refineWithProducts(productsInUse(), in, cache, options, out);
}

} // namespace gjk::correct

namespace gjk
{

template <class T>
void correctlyRound(const DistanceInput<T>& input, const SimplexCache& cache,
                    const Options& options, DistanceOutput<T>& out)
{
    if constexpr (std::is_same_v<T, double>)
        correct::refine(input, cache, options, out);
    else
        out.path = CorrectPath::NeedsExact;
}

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
