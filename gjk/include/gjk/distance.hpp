// GJK distance between two convex shapes in 2D, following Erin Catto, "Computing Distance",
// GDC 2010 (the talk; section numbers below refer to it):
//   1. point to line segment      -> solve2      (Voronoi regions from barycentric (u, v))
//   2. point to triangle          -> solve3      (nine barycentric coordinates, talk's order)
//   3. point to convex polygon    -> distance()  (GJK: simplex, support point, search direction,
//                                                  termination cases 1-4)
//   4. polygon to polygon         -> findSupport on the Minkowski difference, never built
//
// Conventions (pinned by tests in tests/gjk/test_distance.cpp, "conventions"):
// - A shape is the convex hull of its points (any order, duplicates, collinear and interior points
//   allowed: a non-convex point is simply never a support point), grown by its radius.
// - The query runs on Z = A - B: a simplex vertex is w = wA - wB with wA a point of A and wB a
//   point of B. The talk writes Z = Y - X and searches for the point of Z closest to Q; here Q is
//   the origin, Y = A and X = B, as in Box2D v3.
// - The query runs in the local frame of shape A (Options::frame = Frame::LocalA): B's points are
//   mapped by inverse(xfA) * xfB, so a large common offset cancels before any rounding of the gap.
//   Witness points, normal and trace frame are returned in world coordinates.
// - normal is the unit vector from pointA to pointB when the shapes are apart, zero otherwise.
#pragma once

#include "gjk/certify.hpp"
#include "gjk/math.hpp"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#if defined(GJK2D_CHECKED)
#include <cstdio>
#include <cstdlib>
#define GJK_ASSERT(c)                                                                              \
    ((c) ? (void)0                                                                                 \
         : (std::fprintf(stderr, "%s:%d: GJK contract violated: %s\n", __FILE__, __LINE__, #c),     \
            std::abort()))
#else
#define GJK_ASSERT(c) assert(c)
#endif

// The small steps of one GJK iteration (the Minkowski support, the search direction) are forced
// inline. Why: docs/speed.md, "Forced inlining".
#if defined(__GNUC__)
#define GJK_INLINE [[gnu::always_inline]] inline
#else
#define GJK_INLINE inline
#endif

#include "gjk/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk
{

// A convex shape: the hull of `count` points in its local frame, plus a radius (a rounded shape,
// capsule or disc). A view: the points are owned by the caller.
template <class T> struct Polygon
{
    const Vec2<T>* points = nullptr;
    int count = 0;
    T radius = T(0);
};

// --- Variants are data ---------------------------------------------------------------------------

enum class SearchDirection : std::uint8_t
{
    // Talk, "An accurate search direction": on an edge, d = cross(edge, z) with its sign fixed
    // towards the origin. dot(d, edge) == 0 exactly in floating point. No division.
    EdgePerpendicular,
    // The naive rule, d = Q - P from the barycentric closest point: dot(d, edge) carries roundoff
    // (the talk's single-precision example gives 3.2e-6), which can pick a wrong support point.
    ClosestPoint,
};

constexpr const char* searchDirectionName(SearchDirection d)
{
    switch (d)
    {
    case SearchDirection::EdgePerpendicular: return "edge-perpendicular";
    case SearchDirection::ClosestPoint: return "closest-point";
    }
    return "?";
}

enum class StoppingRule : std::uint8_t
{
    // Talk, "Termination conditions", case 1: stop when the support point is already a vertex of
    // the simplex (compared by index pair). Exact: no tolerance at all.
    RepeatedSupport,
    // Also stop when the new support point w cannot lower the distance by more than roundoff:
    // dot(v, v) - dot(v, w) <= Tolerances<T>::dualityGap * dot(v, v) (v: current closest point).
    // The duality gap bounds the distance error: d(v) - d* <= (v.v - v.w) / |v|.
    DualityGap,
};

constexpr const char* stoppingRuleName(StoppingRule r)
{
    switch (r)
    {
    case StoppingRule::RepeatedSupport: return "repeated-support";
    case StoppingRule::DualityGap: return "duality-gap";
    }
    return "?";
}

enum class Frame : std::uint8_t
{
    LocalA, // compute in A's local frame (see the conventions above)
    World,  // transform both shapes to world coordinates first (loses small gaps far from 0)
};

constexpr const char* frameName(Frame f)
{
    switch (f)
    {
    case Frame::LocalA: return "local-a";
    case Frame::World: return "world";
    }
    return "?";
}

enum class SupportStrategy : std::uint8_t
{
    Linear,       // the talk's loop over all vertices: any point order
    BinarySearch, // O(log n): needs the points in convex order (either winding, collinear
                  // points allowed, no repeated consecutive point), e.g. a hull routine's output.
                  // Gallops from the previous support point, so converging queries cost less.
                  // Shapes of at most 16 points still use the linear scan (it is faster there).
};

constexpr const char* supportStrategyName(SupportStrategy s)
{
    switch (s)
    {
    case SupportStrategy::Linear: return "linear";
    case SupportStrategy::BinarySearch: return "binary-search";
    }
    return "?";
}

struct Options
{
    SearchDirection direction = SearchDirection::EdgePerpendicular;
    StoppingRule stopping = StoppingRule::RepeatedSupport;
    Frame frame = Frame::LocalA;
    SupportStrategy support = SupportStrategy::Linear;
    // Iteration limit; 0 means automatic: 32 + 2 * (countA + countB). With exact arithmetic the
    // distance decreases strictly at every iteration, so a long run means a cycle made by rounding;
    // reaching the limit is reported as StopReason::IterationLimit, never silently.
    int maxIterations = 0;
    // Apply the radii at the end (rounded shapes). false: distance between the core hulls.
    bool useRadii = true;
    // Also return a certified interval [lower, upper] that provably contains the exact distance
    // (gjk/certify.hpp). Costs one more scan of each shape.
    bool certify = false;
    // Return the correctly rounded distance of the exact problem (gjk/correct.hpp): the double
    // nearest to it, 0 exactly when it is 0. DistanceOutput::path says how it was decided;
    // CorrectPath::NeedsExact asks the caller for the exact completion
    // (exact/include/exact/correct_fallback.hpp). double queries only.
    bool correctlyRounded = false;
};

// The reference variant, with a stable name. The default Options{} is this variant.
inline constexpr Options referenceOptions{};

// Why the loop stopped; every stopping rule of the talk has its own name.
enum class StopReason : std::uint8_t
{
    RepeatedSupport, // case 1 (and cases 3b and 4 end here when d points away from new vertices)
    Containment,     // case 2: all three triangle barycentric coordinates positive
    ZeroDirection,   // case 3a: the closest point is the origin itself (vertex overlap)
    DualityGap,      // StoppingRule::DualityGap met
    IterationLimit,  // Options::maxIterations reached: the answer is the best simplex so far
};

constexpr const char* stopReasonName(StopReason r)
{
    switch (r)
    {
    case StopReason::RepeatedSupport: return "repeated-support";
    case StopReason::Containment: return "containment";
    case StopReason::ZeroDirection: return "zero-direction";
    case StopReason::DualityGap: return "duality-gap";
    case StopReason::IterationLimit: return "iteration-limit";
    }
    return "?";
}

// How Options::correctlyRounded decided the distance (gjk/correct.hpp).
enum class CorrectPath : std::uint8_t
{
    Plain,        // the option is off: the plain answer
    Double,       // containment certified in double (a static filter, then a running error bound)
    Extended,     // the features' distance in 80-bit extended precision with a static error bound
    DoubleDouble, // the features' distance and its support bound in double-double
    NeedsExact,   // not decided: the output holds the plain answer, the caller completes it
    Exact,        // completed with exact arithmetic (set by the completion, outside gjk/)
};

constexpr const char* correctPathName(CorrectPath p)
{
    switch (p)
    {
    case CorrectPath::Plain: return "plain";
    case CorrectPath::Double: return "double";
    case CorrectPath::Extended: return "extended";
    case CorrectPath::DoubleDouble: return "double-double";
    case CorrectPath::NeedsExact: return "needs-exact";
    case CorrectPath::Exact: return "exact";
    }
    return "?";
}

// How many StopReason values there are (IterationLimit is the last: checked below).
inline constexpr std::size_t stopReasonCount = std::size_t(StopReason::IterationLimit) + 1;
static_assert(stopReasonName(StopReason(stopReasonCount - 1))[0] != '?' &&
                  stopReasonName(StopReason(stopReasonCount))[0] == '?',
              "stopReasonCount: a StopReason was added after IterationLimit");

// --- Simplex -------------------------------------------------------------------------------------

template <class T> struct SimplexVertex
{
    Vec2<T> wA;     // support point of A (compute frame)
    Vec2<T> wB;     // support point of B (compute frame)
    Vec2<T> w;      // wA - wB, a point of the Minkowski difference Z
    T a;            // barycentric weight of this vertex in the closest point
    int indexA;     // index of wA in A's points
    int indexB;     // index of wB in B's points
};

template <class T> struct Simplex
{
    SimplexVertex<T> v[3];
    int count = 0;
};

// Warm start: the indices of the final simplex. A value-initialised cache is a cold start; pass the
// output cache back in for the next query between the same shapes.
// A final edge is stored in canonical order, the origin on the left of Z's edge from slot 0 to
// slot 1: a warm start's first search direction then always takes the same side of its sign test,
// which the branch predictor learns (why: docs/speed.md, "Canonical cache order"). `edgeBase` is the
// slot the distance was measured from (the query's own first vertex), so that a repeated query
// returns the very same bits as the cold one.
struct SimplexCache
{
    int count = 0;
    int indexA[3] = {0, 0, 0};
    int indexB[3] = {0, 0, 0};
    int edgeBase = 0;
    // Where the last support searches of A and B started (SupportStrategy::BinarySearch gallops
    // from there, and near ties the result depends on the start): a warm start makes its first
    // search from the same place, so that it finds what the last search found. -1: from indexA[0]
    // and indexB[0].
    int searchA = -1;
    int searchB = -1;
};

// --- Input, output, trace ------------------------------------------------------------------------

template <class T> struct DistanceInput
{
    Polygon<T> proxyA;
    Polygon<T> proxyB;
    Transform<T> transformA;
    Transform<T> transformB;
};

template <class T> struct DistanceOutput
{
    Vec2<T> pointA{};    // closest point on A (world), on the rounded surface when radii are used
    Vec2<T> pointB{};    // closest point on B (world)
    Vec2<T> normal{};    // unit, from pointA towards pointB when distance > 0; zero otherwise
    T distance = T(0);   // >= 0
    int iterations = 0;  // support points computed
    int simplexCount = 0;
    StopReason stop = StopReason::RepeatedSupport;
    // The query left its safe range and rescaling could not bring it back: a support point had a
    // coordinate outside [Tolerances<T>::minCoordinate, maxCoordinate] (all of them below the
    // minimum, or any above the maximum), or a support scan's dot products overflowed, and the
    // rescaled retry too (the problem's points span more than the exponent range, so scaling lost
    // bits of some); or the rescaled answer does not fit in T (a distance or world witness point
    // beyond T's largest value). The output is not trustworthy.
    bool outOfRange = false;
    // The first pass left the safe range and the query ran again on the problem scaled by a power
    // of two (exact): the answer is then as accurate as in range. outOfRange stays set only when
    // that could not help.
    bool rescaled = false;
    // Options::certify: the exact distance lies in [lower, upper] (double, rounded outwards).
    // certified is false when the bounds could not be computed (an overflow): [0, inf] then.
    bool certified = false;
    // Options::correctlyRounded: how the distance was decided. Beside the flags, in their padding:
    // the output keeps its size.
    CorrectPath path = CorrectPath::Plain;
    double lower = 0;
    double upper = std::numeric_limits<double>::infinity();
};

// One GJK iteration as the talk's demo draws it: the simplex after culling, its closest point to
// the origin, the search direction and the support point it found. Compute-frame coordinates;
// Trace::frame maps them to world.
template <class T> struct TraceStep
{
    Simplex<T> simplex;
    Vec2<T> closest;
    Vec2<T> direction;
    bool hasSupport = false;
    SimplexVertex<T> support;
};

template <class T> struct Trace
{
    Transform<T> frame; // world from compute frame
    // Compute-frame coordinates are the frame's times 2^scaleExponent (a rescaled query; 0 else).
    int scaleExponent = 0;
    std::vector<TraceStep<T>> steps;
};

// --- Support points (talk section 3 "Support point code", section 4 "Property 2") ---------------

// Index of the vertex furthest along d. d need not be normalised: only comparisons are made.
// Ties keep the lowest index, so a repeated support point is recognised by its index.
// `finite` reports whether every dot product was finite: a sum of the values rides along (an
// independent chain, free next to the comparisons) and is non-finite as soon as one of them
// overflowed (a shape point times a direction: found by hard/range, validation/cases/
// range-overflow.json, where the simplex stayed in range while the shapes' points did not).
template <class T> int findSupport(const Polygon<T>& poly, Vec2<T> d, bool& finite)
{
    int index = 0;
    T maxValue = dot(d, poly.points[0]);
    T sum = maxValue;
    for (int i = 1; i < poly.count; ++i)
    {
        const T value = dot(d, poly.points[i]);
        sum += value;
        if (value > maxValue)
        {
            index = i;
            maxValue = value;
        }
    }
    finite = std::abs(sum) <= std::numeric_limits<T>::max();
    return index;
}

template <class T> int findSupport(const Polygon<T>& poly, Vec2<T> d)
{
    bool finite;
    return findSupport(poly, d, finite);
}

// Support by galloping binary search on a convex polygon in counter-clockwise or clockwise order,
// from a start vertex s (the shape's previous support point): O(log k) for a support point k
// vertices away, O(log n) at worst.
//
// Along a convex polygon the values f(i) = dot(d, P[i]) rise (edges with dot(d, e_i) > 0), fall,
// and rise again back to s: the maximum ends the first rising run. Starting at s on a rising edge,
// vertex s + j is "past the maximum" when its outgoing edge does not rise, or when it is already
// below f(s) (then it is on the second rising run, which climbs from the minimum back to
// f(s - 1) < f(s)). That predicate is monotone in j, so we gallop (j = 1, 2, 4, ...) until it
// holds and then bisect. When s is on a falling edge the same runs backwards. A flat edge
// (dot(d, e) == 0, possible with collinear points) is first stepped over so that s ends a flat
// run. Rounding can only blur nearly tied vertices, within roundoff of each other along d; a final
// climb to a strictly better neighbour polishes the result.
template <class T> int findSupportFrom(const Polygon<T>& poly, Vec2<T> d, int s)
{
    const Vec2<T>* P = poly.points;
    const int n = poly.count;
    auto wrap = [n](int i) { return i >= n ? i - n : (i < 0 ? i + n : i); };
    auto f = [&](int i) { return dot(d, P[wrap(i)]); };
    auto slope = [&](int i) { return dot(d, P[wrap(i + 1)] - P[wrap(i)]); }; // along edge i

    for (int guard = 0; guard < n && slope(s) == T(0); ++guard)
        s = wrap(s + 1);
    const T fs = f(s);

    // First j in [1, n] with past(j), for a predicate monotone in j (past(n) is taken as true):
    // gallop j = 1, 2, 4, ... until it holds, then bisect.
    auto firstPast = [n](auto past)
    {
        int lo = 0, hi = 1; // !past(lo) (lo = 0 by the caller's condition); past(hi) or hi == n
        while (hi < n && !past(hi))
        {
            lo = hi;
            hi = std::min(2 * hi, n);
        }
        while (hi - lo > 1)
        {
            const int mid = lo + (hi - lo) / 2;
            (past(mid) ? hi : lo) = mid;
        }
        return hi;
    };

    int best = s;
    if (slope(s) > T(0)) // forward: first j with slope(s + j) <= 0 or f(s + j) < f(s)
        best = wrap(s + firstPast([&](int j) { return slope(s + j) <= T(0) || f(s + j) < fs; }));
    else if (slope(s - 1) < T(0)) // backward: f(s - 1) > f(s), the mirror image
        best = wrap(s - firstPast([&](int j) { return slope(s - j - 1) >= T(0) || f(s - j) < fs; }));

    // Polish: climb to a strictly better neighbour (undoes rounding-blurred near-ties).
    T value = f(best);
    for (int guard = 0; guard < n; ++guard)
    {
        const int next = wrap(best + 1), prev = wrap(best - 1);
        const T vn = f(next), vp = f(prev);
        if (vn > value && vn >= vp)
            best = next, value = vn;
        else if (vp > value)
            best = prev, value = vp;
        else
            break;
    }
    return best;
}

// --- Rescaling: any finite input whose extent fits the exponent range gets an answer -----------
//
// Multiplying every point and translation by a power of two 2^k scales the problem exactly (no
// rounding, unless a value over- or underflows), and every rounding of the query with it: the
// answer of the scaled problem times 2^-k is the answer the query would give if the exponent range
// were unbounded. A query whose support points leave Tolerances<T>'s safe range is run once more,
// scaled so that its extent is about 1 (without it, two separated shapes at a scale of 1e-300 were
// answered 0).

// v * 2^k; `inexact` is set when that loses bits (overflow or gradual underflow).
template <class T> T scaleExactly(T v, int k, bool& inexact)
{
    const T s = std::ldexp(v, k);
    inexact = inexact || std::ldexp(s, -k) != v;
    return s;
}
template <class T> Vec2<T> scaleExactly(Vec2<T> v, int k, bool& inexact)
{
    return {scaleExactly(v.x, k, inexact), scaleExactly(v.y, k, inexact)};
}

// Exponent e with 2^e <= m < 2^(e+1) for finite m > 0; a very negative sentinel for 0 (or NaN).
template <class T> int exponentOf(T m)
{
    return m > T(0) && m <= std::numeric_limits<T>::max() ? std::ilogb(m) : -4 * std::numeric_limits<T>::max_exponent;
}

// A support scan compares dot(d, p) over the shape's own (unscaled) points. On a rescaled query we
// scale d instead of every point (only comparisons are made, so any positive factor of d gives the
// same support point in exact arithmetic), choosing |d| ~ 2^e with e the points' scaling exponent
// (the points are about 2^-e in size), clamped so that d stays normal: the products dot(d, p) of the largest points are then of
// order 1, neither overflowing nor lost to underflow.
template <class T> [[gnu::noinline]] Vec2<T> directionForScan(Vec2<T> d, int e)
{
    constexpr int limit = std::numeric_limits<T>::max_exponent - std::numeric_limits<T>::digits;
    e = std::clamp(e, -limit, limit);
    const int ed = exponentOf(std::max(std::abs(d.x), std::abs(d.y)));
    if (ed < std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits)
        return d; // zero (the scan then keeps vertex 0)
    return {std::ldexp(d.x, e - ed), std::ldexp(d.y, e - ed)};
}

// The exponent e of a rotation's size: q = 2^e q^ with max(|c^|, |s^|) in [1, 2), so that
// |q^|^2 = c^2 + s^2 lies in [1, 8) and can neither overflow nor underflow. The rescaled query
// computes with q^ and moves 2^e into the shape's point scaling (exact, like the rescaling).
template <class T> int rotationExponent(Rot<T> q)
{
    return exponentOf(std::max(std::abs(q.c), std::abs(q.s)));
}

// The k that brings the compute frame's extent to about 1: minus the largest exponent among the
// points (times 2^e of their rotation, rotationExponent: the rotations themselves are normalised)
// and the translations. Computed on exponents, so that sizes beyond the floating-point range
// (1e300 * 1e300) cannot overflow. 0 when everything is zero.
template <class T> int rescaleExponent(const Polygon<T>& A, const Transform<T>& xfA, const Polygon<T>& B,
                                      const Transform<T>& xfB, Frame frame)
{
    auto pointsExp = [](const Polygon<T>& p)
    {
        T m = T(0);
        for (int i = 0; i < p.count; ++i)
            m = std::max({m, std::abs(p.points[i].x), std::abs(p.points[i].y)});
        return exponentOf(m);
    };
    auto vecExp = [](Vec2<T> v) { return exponentOf(std::max(std::abs(v.x), std::abs(v.y))); };
    const int eA = rotationExponent(xfA.q), eB = rotationExponent(xfB.q);
    int e;
    if (frame == Frame::LocalA)
    {
        // A's points times 2^eA; B's through q^B (size < 2^1.5) and the inverse of q^A (size
        // <= 1); the offset pB - pA (one more bit) through the inverse of q^A.
        e = std::max(pointsExp(A) + eA, pointsExp(B) + eB + 2);
        e = std::max(e, std::max(vecExp(xfA.p), vecExp(xfB.p)) + 1);
    }
    else
        e = std::max({pointsExp(A) + eA + 2, pointsExp(B) + eB + 2, vecExp(xfA.p), vecExp(xfB.p)});
    return e < std::numeric_limits<T>::min_exponent - 2 * std::numeric_limits<T>::digits - 8 ? 0 : -e;
}

// A shape seen through a transform into the compute frame: the support runs on the shape's own
// points with the direction rotated into its frame; only the chosen point is transformed.
// In A's frame, A itself needs no transform: `identity` skips it (bit-identical result, since
// the identity transform is exact, but faster). `Scaled`: the rescaled retry's shapes (below);
// a separate type, so that the common query carries no test for it.
template <class T, bool Scaled = false> struct TransformedShape
{
    Polygon<T> poly;
    Transform<T> xf;
    bool identity = false;

    bool binary = false;   // SupportStrategy::BinarySearch and more than 16 points
    int last = 0;          // previous support index: where the galloping search starts
    bool overflow = false; // a support scan's products overflowed (DistanceOutput::outOfRange)

    // Scaled: every point is multiplied by 2^scale, exact unless it underflows (then `inexact` is
    // set and the query stays flagged outOfRange).
    int scale = 0;
    bool inexact = false;

    GJK_INLINE int support(Vec2<T> d)
    {
        Vec2<T> local = identity ? d : invRotate(xf.q, d);
        if constexpr (Scaled)
            local = directionForScan(local, scale);
        if (!binary)
        {
            bool finite;
            const int i = findSupport(poly, local, finite);
            overflow = overflow || !finite;
            return i;
        }
        last = findSupportFrom(poly, local, last);
        // The binary search evaluates a few points only: check the chosen point's own size.
        const Vec2<T> p = poly.points[last];
        overflow = overflow || !(std::max(std::abs(p.x), std::abs(p.y)) <= Tolerances<T>::maxCoordinate);
        return last;
    }
    Vec2<T> vertex(int i)
    {
        if constexpr (Scaled)
        {
            const Vec2<T> p = scaleExactly(poly.points[i], scale, inexact);
            return identity ? p : transformPoint(xf, p);
        }
        else
            return identity ? poly.points[i] : transformPoint(xf, poly.points[i]);
    }
};

// support(Z, d) = support(A, d) - support(B, -d): the Minkowski difference is never built.
template <class T, class Shape>
GJK_INLINE SimplexVertex<T> makeVertex(Shape& A, Shape& B, int iA, int iB)
{
    SimplexVertex<T> v;
    v.indexA = iA;
    v.indexB = iB;
    v.wA = A.vertex(iA);
    v.wB = B.vertex(iB);
    v.w = v.wA - v.wB;
    v.a = T(1);
    return v;
}

template <class T, class Shape>
GJK_INLINE SimplexVertex<T> findMinkowskiSupport(Shape& A, Shape& B, Vec2<T> d)
{
    return makeVertex<T>(A, B, A.support(d), B.support(-d));
}

// --- Edges of any length ------------------------------------------------------------------------
//
// Every use of a simplex edge e below is homogeneous in it: the barycentric numerators u, v
// (degree 1, and u + v = |e|^2), the signs of cross products, the search direction (any positive
// multiple of a perpendicular), the distance |cross(w1, e)| / |e| (degree 0) and the unit normal.
// So an edge shorter than minEdgeComponent (2^-484 in double, 2^-51 in float, at or just above
// Tolerances<T>::minCoordinate) in both components is multiplied by the power of two that brings
// it to size ~1, exactly, and nothing else changes in exact arithmetic. Unscaled, such an edge
// lost the query (reproducers found by an adversarial search, validation/cases/tiny-edges.json): its
// squared length went subnormal (a 3.5e-162 edge in double, 5.9e-23 in float: a distance 10 % off),
// or below 1/max, where the weights' reciprocal 1/(u + v) overflowed (inf weights, NaN
// witness points, flagged outOfRange with no answer). Scaled, u + v = |e|^2 ~ 1 and the products
// with in-range points stay normal.
template <class T> [[gnu::noinline]] Vec2<T> scaleUpEdge(Vec2<T> e)
{
    const T m = std::max(std::abs(e.x), std::abs(e.y));
    if (!(m > T(0)))
        return e; // a zero edge (repeated point): the vertex regions take it
    const int k = -std::ilogb(m);
    return {std::ldexp(e.x, k), std::ldexp(e.y, k)};
}
// The threshold, a power of two at or just above minCoordinate = sqrt(min_normal / u), as a
// compile-time constant (minCoordinate itself is computed with std::sqrt).
template <class T> constexpr T minEdgeComponent()
{
    constexpr int e = (std::numeric_limits<T>::min_exponent - 1 + std::numeric_limits<T>::digits) / 2;
    T v = T(1);
    for (int i = 0; i > e; --i)
        v /= T(2);
    return v;
}
template <class T> GJK_INLINE Vec2<T> edgeOfSafeSize(Vec2<T> e)
{
    constexpr T m = minEdgeComponent<T>();
    if (std::max(std::abs(e.x), std::abs(e.y)) < m) [[unlikely]]
        return scaleUpEdge(e);
    return e;
}

// --- Section 1: point (the origin) to line segment -----------------------------------------------
//
// Segment w1 w2 and query point Q = 0. With n = (w2 - w1)/|w2 - w1| the barycentric coordinates
// of the projection of Q are
//   u = dot(Q - w2, w1 - w2) / |w2 - w1|^2   (weight of w1)
//   v = dot(Q - w1, w2 - w1) / |w2 - w1|^2   (weight of w2),   u + v = 1.
// Only their numerators decide the Voronoi region (no division):
//   u <= 0 -> region w2,  v <= 0 -> region w1,  otherwise region w1w2 with P = u w1 + v w2.
template <class T> void solve2(Simplex<T>& s)
{
    const Vec2<T> w1 = s.v[0].w;
    const Vec2<T> w2 = s.v[1].w;
    const Vec2<T> e12 = edgeOfSafeSize(w2 - w1);

    const T u = dot(w2, e12);  // numerator of u: dot(0 - w2, w1 - w2)
    const T v = -dot(w1, e12); // numerator of v: dot(0 - w1, w2 - w1)

    if (v <= T(0)) // region w1
    {
        s.v[0].a = T(1);
        s.count = 1;
        return;
    }
    if (u <= T(0)) // region w2
    {
        s.v[1].a = T(1);
        s.v[0] = s.v[1];
        s.count = 1;
        return;
    }
    // region w1w2: u, v > 0 so their sum is positive and the division is safe.
    const T inv = T(1) / (u + v);
    s.v[0].a = u * inv;
    s.v[1].a = v * inv;
    s.count = 2;
}

// cross(a, b) to about 3u relative (not 2u |a| |b| absolute): both products error-free (Dekker's
// TwoProduct with Veltkamp's split; no FMA, which is a library call on the x86-64 baseline), then
// (h1 - h2) + (l1 - l2). For components up to 2 Tolerances<T>::maxCoordinate the split cannot
// overflow; products below T's normal range lose their low parts (an absolute error of a few
// subnormals). solve3's containment weights use it; gjk/src/batch_lanes.hpp has the same steps.
template <class T> T accurateCross(Vec2<T> a, Vec2<T> b)
{
    constexpr T split = T((1 << ((std::numeric_limits<T>::digits + 1) / 2)) + 1); // 2^27 + 1, 2^12 + 1
    auto twoProduct = [](T x, T y, T& lo)
    {
        const T p = x * y;
        const T cx = split * x, xh = cx - (cx - x), xl = x - xh;
        const T cy = split * y, yh = cy - (cy - y), yl = y - yh;
        lo = ((xh * yh - p) + xh * yl + xl * yh) + xl * yl;
        return p;
    };
    T l1, l2;
    const T h1 = twoProduct(a.x, b.y, l1), h2 = twoProduct(a.y, b.x, l2);
    return (h1 - h2) + (l1 - l2);
}

// --- Section 2: point (the origin) to triangle ---------------------------------------------------
//
// Nine barycentric coordinates (numerators only):
//   three segments as in solve2: (u12, v12), (u13, v13), (u23, v23),
//   the triangle from signed areas: u123 = area(Q w2 w3), v123 = area(Q w3 w1), w123 = area(Q w1 w2),
//   each multiplied by the sign of area(w1 w2 w3) so their signs are right whatever the winding:
//   u123 = sgn(n) cross(w2, w3), v123 = sgn(n) cross(w3, w1), w123 = sgn(n) cross(w1, w2),
//   n = cross(e12, e13).
// Regions are tested in the talk's order, lowest dimension first: vertices, then edges, then the
// interior. The area n is never divided by to choose a region: for a collinear (zero-area) triangle
// all triangle coordinates are 0, every edge test "w123 <= 0" passes, and a vertex or edge region
// is chosen from the segment coordinates alone (talk, "Collinear vertices").
template <class T> void solve3(Simplex<T>& s)
{
    const Vec2<T> w1 = s.v[0].w;
    const Vec2<T> w2 = s.v[1].w;
    const Vec2<T> w3 = s.v[2].w;

    const Vec2<T> e12 = edgeOfSafeSize(w2 - w1);
    const T u12 = dot(w2, e12);
    const T v12 = -dot(w1, e12);

    const Vec2<T> e13 = edgeOfSafeSize(w3 - w1);
    const T u13 = dot(w3, e13);
    const T v13 = -dot(w1, e13);

    const Vec2<T> e23 = edgeOfSafeSize(w3 - w2);
    const T u23 = dot(w3, e23);
    const T v23 = -dot(w2, e23);

    // The talk multiplies each signed area by n123 = area(w1 w2 w3) to fix its sign for either
    // winding. We multiply by the sign of n123 instead: the same signs, but the products stay of
    // size R^2 rather than R^4 (R the size of the simplex), which matters in float (R^4
    // overflows for R > 4e9). Weights below are ratios, so the missing factor |n123| cancels.
    const T n123 = cross(e12, e13);
    const T sign = n123 > T(0) ? T(1) : (n123 < T(0) ? T(-1) : T(0));
    const T u123 = sign * cross(w2, w3);
    const T v123 = sign * cross(w3, w1);
    const T w123 = sign * cross(w1, w2);

    auto keepVertex = [&s](int i)
    {
        s.v[0] = s.v[i];
        s.v[0].a = T(1);
        s.count = 1;
    };
    auto keepEdge = [&s](int i, int j, T ui, T vj)
    {
        const T inv = T(1) / (ui + vj);
        const SimplexVertex<T> a = s.v[i], b = s.v[j];
        s.v[0] = a;
        s.v[1] = b;
        s.v[0].a = ui * inv;
        s.v[1].a = vj * inv;
        s.count = 2;
    };

    // First: vertex regions, from the segment coordinates.
    if (v12 <= T(0) && v13 <= T(0))
        return keepVertex(0); // region w1
    if (u12 <= T(0) && v23 <= T(0))
        return keepVertex(1); // region w2
    if (u13 <= T(0) && u23 <= T(0))
        return keepVertex(2); // region w3

    // Second: edge regions: between the edge's endpoints and outside it (triangle coordinate of the
    // opposite vertex not positive).
    if (u12 > T(0) && v12 > T(0) && w123 <= T(0))
        return keepEdge(0, 1, u12, v12); // region w1w2
    if (u13 > T(0) && v13 > T(0) && v123 <= T(0))
        return keepEdge(0, 2, u13, v13); // region w1w3
    if (u23 > T(0) && v23 > T(0) && u123 <= T(0))
        return keepEdge(1, 2, u23, v23); // region w2w3

    // Third: the interior. All three triangle coordinates are positive here whenever the segment
    // tests were consistent; their sum |n123| is then positive and the division is safe.
    if (u123 > T(0) && v123 > T(0) && w123 > T(0))
    {
        // The weights (only the witness point uses them: containment ends the query): Cramer's
        // rule for w1 + b (w2 - w1) + c (w3 - w1) = 0 with cross products to a few u relative
        // (accurateCross), so that b and c are each within ~7u of their own size and the residual
        // sum a_k w_k within ~18u W of the origin whatever the triangle's shape (docs/error-bound.md,
        // "Witness points"). The areas above carry 2u |w|^2 each, against a sum |n123| that a
        // needle or a nearly flat triangle makes small: A's witness was 6e-14 outside B in
        // random/35820 (witness bound 1.2e-14), 3.1 outside in hard/mixed-scale/60, and Cramer's
        // rule with plain cross products still left 2.7e-7 on a flat triangle found by
        // `gjk-validate search`. If n vanishes or is not finite, the areas' weights. Each weight
        // clamped at 0, then divided by their sum.
        const Vec2<T> d12 = w2 - w1, d13 = w3 - w1;
        const T n = accurateCross(d12, d13);
        if ((n > T(0) || n < T(0)) && std::abs(n) <= std::numeric_limits<T>::max())
        {
            T b = accurateCross(d13, w1) / n, c = accurateCross(w1, d12) / n;
            b = b > T(0) ? b : T(0);
            c = c > T(0) ? c : T(0);
            T a1 = (T(1) - b) - c;
            a1 = a1 > T(0) ? a1 : T(0);
            // Normalised: a clamped weight (the origin within rounding of an edge) would leave the
            // sum above 1, the point off A.
            const T t = (a1 + b) + c;
            s.v[0].a = a1 / t;
            s.v[1].a = b / t;
            s.v[2].a = c / t;
            s.count = 3;
            return;
        }
        // Three divisions, not a reciprocal: for a sum in the subnormal range 1/sum overflows and
        // the weights became inf, the witness points NaN (the fuzzer, float coordinates near
        // 2^-89). Each quotient is in [0, 1]. Once per query (containment ends it).
        const T sum = (u123 + v123) + w123;
        s.v[0].a = u123 / sum;
        s.v[1].a = v123 / sum;
        s.v[2].a = w123 / sum;
        s.count = 3;
        return;
    }

    // Rounding made the nine signs inconsistent (a nearly degenerate triangle): no region matched.
    // Keep the closest of the three edges, each solved as in section 1. Never divides by the area.
    // The first edge is kept unless a later one is strictly closer: when every squared distance
    // overflows (inf or NaN compare false), edge w1w2 is kept, never an unset simplex (once,
    // coordinates near 1e265 left the simplex empty and its weights uninitialised).
    Simplex<T> best;
    T bestDist2 = T(0);
    const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (int k = 0; k < 3; ++k)
    {
        Simplex<T> e;
        e.v[0] = s.v[pairs[k][0]];
        e.v[1] = s.v[pairs[k][1]];
        e.count = 2;
        solve2(e);
        const Vec2<T> c = e.count == 1 ? e.v[0].w : e.v[0].a * e.v[0].w + e.v[1].a * e.v[1].w;
        if (k == 0 || dot(c, c) < bestDist2)
        {
            bestDist2 = dot(c, c);
            best = e;
        }
    }
    GJK_ASSERT(best.count == 1 || best.count == 2);
    s = best;
}

// --- Closest point, search direction, witness points ---------------------------------------------

// P, the point of the simplex closest to the origin, from the barycentric weights.
template <class T> Vec2<T> closestPoint(const Simplex<T>& s)
{
    switch (s.count)
    {
    case 1: return s.v[0].w;
    case 2: return s.v[0].a * s.v[0].w + s.v[1].a * s.v[1].w;
    default: return Vec2<T>{};
    }
}

// Whether the origin lies strictly on the left of the edge w1 -> w1 + e12: the talk's sign test
// for the edge search direction, and the canonical order of a cached edge (SimplexCache).
// originSide > 0: on the left; < 0: on the right; 0: on the edge's line (rounded).
template <class T> T originSide(Vec2<T> w1, Vec2<T> e12) { return cross(e12, -w1); }
template <class T> bool originOnLeft(Vec2<T> w1, Vec2<T> e12) { return originSide(w1, e12) > T(0); }

// The direction from P towards Q = 0 in which to look for the next support point.
// `base` is the edge's slot the sign test measures from: 0, but for the first iteration of a warm
// start from a reversed edge (SimplexCache::edgeBase), so that it makes the very test the cold
// query made (reversing the edge negates both factors of the cross product exactly). That matters
// for a long edge far from the origin: from its far end the test is a cancellation whose sign
// rounding decides (the fuzzer found warm repeats searching the other way).
template <class T>
GJK_INLINE Vec2<T> searchDirection(const Simplex<T>& s, SearchDirection rule, int base = 0)
{
    if (s.count == 1)
        return -s.v[0].w;
    if (rule == SearchDirection::ClosestPoint)
        return -closestPoint(s);
    // Talk, "An accurate search direction" and "Fixing the sign": d = cross(e, z) or cross(z, e),
    // whichever has dot(d, Q - w1) > 0. When the origin is on the edge (cases 3b and 4) the sign is
    // arbitrary: we take rightPerp, and the loop ends by a repeated vertex or containment.
    const Vec2<T> e12 = edgeOfSafeSize(s.v[1].w - s.v[0].w);
    return originOnLeft(s.v[base].w, e12) ? leftPerp(e12) : rightPerp(e12);
}

// Closest points on A and B from the barycentric weights (talk section 4, "Closest point on
// polygons"): the same weights applied to the simplex vertices' own points.
template <class T> GJK_INLINE void computeWitnessPoints(const Simplex<T>& s, Vec2<T>& pA, Vec2<T>& pB)
{
    switch (s.count)
    {
    case 1:
        pA = s.v[0].wA;
        pB = s.v[0].wB;
        break;
    case 2:
        pA = s.v[0].a * s.v[0].wA + s.v[1].a * s.v[1].wA;
        pB = s.v[0].a * s.v[0].wB + s.v[1].a * s.v[1].wB;
        break;
    default:
        pA = s.v[0].a * s.v[0].wA + s.v[1].a * s.v[1].wA + s.v[2].a * s.v[2].wA;
        pB = pA; // containment: the shapes overlap
        break;
    }
}

// Distance from the origin to the simplex. For an edge we use |cross(w1, e12)| / |e12|, the
// height of the triangle (0, w1, w2): it does not suffer the cancellation of |u w1 + v w2|, and
// unlike cross(w1, w2) its rounding error stays of order u |w1| even for a short edge far from
// the origin (cross(w1, w2) would carry u |w1| |w2| / |e12|).
template <class T> T simplexDistance(const Simplex<T>& s)
{
    switch (s.count)
    {
    case 1: return length(s.v[0].w);
    case 2:
    {
        const Vec2<T> e12 = edgeOfSafeSize(s.v[1].w - s.v[0].w);
        return std::abs(cross(s.v[0].w, e12)) / length(e12);
    }
    default: return T(0);
    }
}

// --- Certified interval (gjk/certify.hpp) --------------------------------------------------------

// Fills out.lower and out.upper from the final simplex (indices and weights) and the world normal.
template <class T>
void certifyDistance(const DistanceInput<T>& in, const Simplex<T>& s, bool useRadii, Vec2<T> normal,
                     DistanceOutput<T>& out)
{
    using namespace certify;
    const Polygon<T>& A = in.proxyA;
    const Polygon<T>& B = in.proxyB;

    // Upper bound: the point sum(a_i W_i) / sum(a_i) of Z, W_i = xfA * A[iA] - xfB * B[iB].
    BoundedVec W[3];
    for (int i = 0; i < s.count; ++i)
    {
        const BoundedVec a = toWorld(in.transformA, A.points[s.v[i].indexA]);
        const BoundedVec b = toWorld(in.transformB, B.points[s.v[i].indexB]);
        W[i] = {a.x - b.x, a.y - b.y};
    }
    double upperHull = std::numeric_limits<double>::infinity();
    const bool inside = s.count == 3 && originCertainlyInside(W);
    if (inside)
        upperHull = 0;
    else
    {
        BoundedVec v{};
        Bounded sum{};
        for (int i = 0; i < s.count; ++i)
        {
            const Bounded a = exactly(std::max(double(s.v[i].a), 0.0));
            v = {v.x + a * W[i].x, v.y + a * W[i].y};
            sum = sum + a;
        }
        upperHull = upperNorm(v, sum);
    }

    // Lower bound: support functions along the computed normal n (from A to B):
    // dist >= (min_j n.B_j - max_i n.A_i) / |n|.
    double lowerHull = 0;
    if (normal.x != T(0) || normal.y != T(0))
    {
        const Bounded nx = exactly(double(normal.x)), ny = exactly(double(normal.y));
        const Bounded mnx = exactly(-double(normal.x)), mny = exactly(-double(normal.y));
        const double hA = supportUpper(in.transformA, A.points, A.count, nx, ny);
        const double hBneg = supportUpper(in.transformB, B.points, B.count, mnx, mny);
        const double gap = down(-hBneg - hA);
        const double nn = up(std::sqrt(up(up(nx.v * nx.v) + up(ny.v * ny.v))));
        if (gap > 0)
            lowerHull = down(gap / nn);
    }

    const double rA = useRadii ? double(A.radius) : 0.0;
    const double rB = useRadii ? double(B.radius) : 0.0;
    // Subtracting the radii, rounded outwards (a zero radius subtracts exactly).
    const double rSum = rA + rB;
    const double rLow = rB == 0 ? rA : down(rSum), rHigh = rB == 0 ? rA : up(rSum);
    const double lower = rHigh == 0 ? lowerHull : std::max(0.0, down(lowerHull - rHigh));
    const double upper = rLow == 0 ? upperHull : up(upperHull - rLow);
    // Certified only when both ends are numbers and the upper end is finite: an overflow anywhere
    // above (world coordinates beyond the double range, inf - inf = NaN) must never pass for a
    // bound. std::max(0, NaN) is 0, which once turned an overflowed upper end into a certified
    // [0, 0] (points near 1.5e308 rotated by 45 degrees). Comparisons with NaN
    // are false, so each test below fails closed.
    if (lower >= 0 && upper <= std::numeric_limits<double>::max() && lower <= std::max(upper, 0.0))
    {
        out.lower = lower;
        out.upper = std::max(upper, 0.0);
        out.certified = true;
    }
    else
    {
        out.lower = 0;
        out.upper = std::numeric_limits<double>::infinity();
        out.certified = false;
    }
}

inline std::int64_t packIndices(int indexA, int indexB)
{
    return (std::int64_t(indexA) << 32) | std::uint32_t(indexB);
}

// --- Section 3 and 4: the GJK loop ---------------------------------------------------------------

// The compute frame's two shapes for a rescaled query (scale != 0): every point, and the
// translations, multiplied by 2^scale. Returns the transform from the compute frame to world
// coordinates (unscaled). A and B arrive value-initialised with their polygons and options set.
template <class T>
[[gnu::noinline]] Transform<T> setUpScaledShapes(const DistanceInput<T>& input, const Options& options,
                                                 int scale, TransformedShape<T, true>& A,
                                                 TransformedShape<T, true>& B)
{
    Transform<T> xfA = input.transformA, xfB = input.transformB;
    // Rotations of any size, normalised: q = 2^e q^, the 2^e moved into the points' scaling.
    const int eA = rotationExponent(xfA.q), eB = rotationExponent(xfB.q);
    bool rotInexact = false;
    xfA.q = {scaleExactly(xfA.q.c, -eA, rotInexact), scaleExactly(xfA.q.s, -eA, rotInexact)};
    xfB.q = {scaleExactly(xfB.q.c, -eB, rotInexact), scaleExactly(xfB.q.s, -eB, rotInexact)};
    A.scale = scale + eA;
    B.scale = scale + eB;
    A.inexact = rotInexact; // a component lost to underflow: not the given rotation any more
    if (options.frame == Frame::LocalA)
    {
        // Scale the offset pB - pA, computed as the unscaled query does when it is finite (the
        // same rounding), else from the scaled ends (it overflowed).
        const Vec2<T> dp = xfB.p - xfA.p;
        if (std::isfinite(dp.x) && std::isfinite(dp.y))
            xfB.p = scaleExactly(dp, scale, B.inexact);
        else
            xfB.p = scaleExactly(xfB.p, scale, B.inexact) - scaleExactly(xfA.p, scale, B.inexact);
        const Transform<T> world = {xfA.p, xfA.q};
        xfA.p = Vec2<T>{};
        A.identity = true;
        B.xf = invMulTransforms(xfA, xfB);
        return world;
    }
    A.xf = {scaleExactly(xfA.p, scale, A.inexact), xfA.q};
    B.xf = {scaleExactly(xfB.p, scale, B.inexact), xfB.q};
    return Transform<T>{};
}

template <class T>
void distanceRescaled(const DistanceInput<T>& input, SimplexCache& cache, const Options& options,
                      Trace<T>* trace, DistanceOutput<T>& out, bool onlyZeroSupports);

template <class T>
void correctlyRound(const DistanceInput<T>& input, const SimplexCache& cache, const Options& options,
                    DistanceOutput<T>& out); // gjk/correct.hpp

// Whether a cache's indices fit shapes of these sizes (a warm start), else a cold start.
GJK_INLINE bool cacheFits(const SimplexCache& cache, int countA, int countB)
{
    bool fits = cache.count >= 1 && cache.count <= 3;
    for (int i = 0; fits && i < cache.count; ++i)
        fits = cache.indexA[i] >= 0 && cache.indexA[i] < countA && cache.indexB[i] >= 0 && cache.indexB[i] < countB;
    return fits;
}

// The initial simplex, from the cache (warm) or cold; returns its edgeBase. Shared by the query
// below and the SIMD batch (gjk/batch.hpp).
template <class T, class Shape>
GJK_INLINE int startSimplex(const SimplexCache& cache, Shape& A, Shape& B, Simplex<T>& simplex)
{
    // Start from the cache (warm) or, cold, from "an arbitrary initial simplex": the support point
    // of Z in the direction from A's origin to B's, whose closest points usually face each other
    // (why: docs/speed.md, "Cold start between the shapes"), or vertex 0 of each shape when the
    // origins coincide. Stale indices (shapes
    // changed) fall back to a cold start.
    int edgeBase = 0;
    if (cacheFits(cache, A.poly.count, B.poly.count))
    {
        edgeBase = cache.count >= 2 ? (cache.edgeBase & 1) : 0;
        A.last = cache.searchA >= 0 && cache.searchA < A.poly.count ? cache.searchA : cache.indexA[0];
        B.last = cache.searchB >= 0 && cache.searchB < B.poly.count ? cache.searchB : cache.indexB[0];
        simplex.count = cache.count;
        for (int i = 0; i < cache.count; ++i)
            simplex.v[i] = makeVertex<T>(A, B, cache.indexA[i], cache.indexB[i]);
    }
    else
    {
        simplex.count = 1;
        const Vec2<T> d0 = B.xf.p - A.xf.p;
        simplex.v[0] = (d0.x != T(0) || d0.y != T(0)) ? findMinkowskiSupport<T>(A, B, d0) : makeVertex<T>(A, B, 0, 0);
    }
    return edgeBase;
}

// The loop's final state besides the simplex, from which finishQuery makes the output and the
// cache. Shared by the query below and the SIMD batch (gjk/batch.hpp), whose lanes run the loop
// and end here. (The simplex is passed by reference: copied into this struct, it cost the scalar
// query 6-20 %, docs/speed.md, "Batches in SIMD lanes".)
template <class T> struct QueryEnd
{
    int edgeBase;
    int iteration;
    T maxAbs; // largest support-point coordinate magnitude (the range check)
    std::int64_t saved[3]; // the simplex before the last solve (index pairs), and its size
    int savedCount;
    bool culledRepeat; // the stopping support point was a vertex the last solve culled
    int searchA, searchB; // where the last support searches started
    bool supportOutOfRange; // a support scan overflowed, or (rescaled) a point lost bits
};

// The end of the query: witness points, distance and normal in world coordinates, radii,
// certified interval, the cache, the range check and (out of range) the rescaled retry.
// `stop`: why the loop stopped.
template <class T, bool Scaled>
GJK_INLINE DistanceOutput<T> finishQuery(const DistanceInput<T>& input, SimplexCache& cache, const Options& options,
                                         Trace<T>* trace, int scale, const Transform<T>& world, StopReason stop,
                                         const Simplex<T>& simplex, const QueryEnd<T>& end)
{
    DistanceOutput<T> out;
    out.stop = stop;
    const Polygon<T>& polyA = input.proxyA;
    const Polygon<T>& polyB = input.proxyB;
    const int edgeBase = end.edgeBase, iteration = end.iteration, savedCount = end.savedCount;
    const T maxAbs = end.maxAbs;
    const std::int64_t* saved = end.saved;
    const bool culledRepeat = end.culledRepeat;
    const int searchA = end.searchA, searchB = end.searchB;
    (void)scale;

    // Output: closest points from the barycentric weights, in world coordinates.
    Vec2<T> pA, pB;
    computeWitnessPoints(simplex, pA, pB);
    // Distance and unit normal from A to B, sharing one square root (simplexDistance's formulas).
    // On an edge the normal is the exact perpendicular of the edge, more accurate than normalising
    // the tiny difference pB - pA.
    T dist = T(0);
    Vec2<T> normal{};
    bool flipEdge = false;
    if (simplex.count == 1)
    {
        dist = length(simplex.v[0].w);
        if (dist > T(0))
            normal = (T(1) / dist) * -simplex.v[0].w;
    }
    else if (simplex.count == 2)
    {
        // Everything is measured from the vertex at slot edgeBase (the query's own first vertex;
        // searchDirection's sign test uses it too). The normal is the vector searchDirection gives,
        // normalised: leftPerp(e) when the origin is on the left of w1 -> w2, else
        // rightPerp(e) == leftPerp(-e), exactly. flipEdge: the origin is strictly on the right, so
        // the cache stores the edge reversed (SimplexCache's canonical order). Not when it is on
        // the edge's line (side exactly 0): both orders would then fail the strict test and take
        // opposite directions, so the order stays (the fuzzer found warm repeats of duality-gap
        // stops searching on). Reversing the edge only negates e, and edgeBase follows the base
        // vertex, so a warm start from the cache reproduces the cold query's bits.
        const Vec2<T> e = edgeOfSafeSize(simplex.v[1].w - simplex.v[0].w);
        const Vec2<T> base = edgeBase ? simplex.v[1].w : simplex.v[0].w;
        const T side = originSide(base, e);
        flipEdge = side < T(0);
        const T len = length(e);
        dist = std::abs(cross(base, e)) / len;
        if (dist > T(0))
            normal = (T(1) / len) * leftPerp(side > T(0) ? e : -e);
    }
    if constexpr (Scaled)
    {
        // Back from the scaled compute frame: exact, but for a distance below the type's normal
        // range (it then rounds once more, to a subnormal).
        dist = std::ldexp(dist, -scale);
        pA = {std::ldexp(pA.x, -scale), std::ldexp(pA.y, -scale)};
        pB = {std::ldexp(pB.x, -scale), std::ldexp(pB.y, -scale)};
    }

    // Back to world coordinates: the points through the frame's transform, the normal through its
    // rotation. A's frame of a rotation qA that is not a unit vector in T (a float engine's seen in
    // double) measures lengths in units of |qA|: the distance is multiplied by |qA|, the
    // normal (which rotate() lengthened by |qA|) divided by it. Skipped for a unit rotation
    // (isUnitRotation, the same test as invMulTransforms'), as for every world-frame query
    // (world.q is the identity). docs/error-bound.md, term 5.
    const T frameSize2 = squaredSize(world.q);
    Vec2<T> worldA = transformPoint(world, pA), worldB = transformPoint(world, pB);
    normal = rotate(world.q, normal);
    // |qA|^2 itself must be in range (its square root and the divisions by it keep their
    // relative accuracy): a rotation of size beyond ~1e-146..1e153 (double) is normalised by the
    // rescaled retry (rotationExponent).
    bool frameOutOfRange = false;
    if (!isUnitRotation(frameSize2)) [[unlikely]]
    {
        frameOutOfRange = !(frameSize2 >= Tolerances<T>::minCoordinate * Tolerances<T>::minCoordinate &&
                            frameSize2 <= Tolerances<T>::maxCoordinate * Tolerances<T>::maxCoordinate);
        const T size = std::sqrt(frameSize2);
        dist *= size;
        normal = {normal.x / size, normal.y / size};
    }

    // The radii are world lengths.
    if (options.useRadii && (polyA.radius > T(0) || polyB.radius > T(0)))
    {
        const T rA = polyA.radius, rB = polyB.radius;
        if (dist > rA + rB)
        {
            // Move the witness points onto the rounded surfaces.
            dist -= rA + rB;
            worldA = worldA + rA * normal;
            worldB = worldB - rB * normal;
        }
        else
        {
            // The rounded shapes overlap, distance 0: one point in both, on the segment from A's
            // closest point to B's (at most rA + rB long) rA / (rA + rB) of the way, so within rA of
            // A's and rB of B's. The midpoint was not: a capsule of radius 0.39 touching a disc of
            // radius 0.0016 got a point 0.19 outside the disc (hard/rounded/17-capsule-disc).
            const T t = rA / (rA + rB);
            const Vec2<T> p = worldA + t * (worldB - worldA);
            worldA = p;
            worldB = p;
            dist = T(0);
            normal = Vec2<T>{};
        }
    }

    if (options.certify)
        certifyDistance(input, simplex, options.useRadii, normal, out);

    // "+ 0" turns a negative zero into +0 and changes nothing else (round to nearest): the sign of
    // a zero component depends on the order of the edge's vertices (x - x is +0, -(x - x) is -0),
    // which a warm start may reverse (found by the fuzzer: axis-aligned normals).
    const Vec2<T> zero{};
    out.pointA = worldA + zero;
    out.pointB = worldB + zero;
    out.normal = normal + zero;
    out.distance = dist;
    out.iterations = iteration;
    out.simplexCount = simplex.count;

    // The cache: the final simplex, a final edge in canonical order. After a culled repeat, the
    // simplex before the last solve in its own order (and edgeBase as it was), which a warm start
    // solves exactly as this query did (docs/gjk.md, "Warm start").
    if (culledRepeat) [[unlikely]]
    {
        cache.count = savedCount;
        for (int i = 0; i < savedCount; ++i)
        {
            cache.indexA[i] = int(saved[i] >> 32);
            cache.indexB[i] = int(std::uint32_t(saved[i]));
        }
        cache.edgeBase = edgeBase;
    }
    else
    {
        cache.count = simplex.count;
        for (int i = 0; i < simplex.count; ++i)
        {
            cache.indexA[i] = simplex.v[i].indexA;
            cache.indexB[i] = simplex.v[i].indexB;
        }
        cache.edgeBase = simplex.count == 2 ? edgeBase ^ int(flipEdge) : 0;
        if (flipEdge)
        {
            std::swap(cache.indexA[0], cache.indexA[1]);
            std::swap(cache.indexB[0], cache.indexB[1]);
        }
    }

    // The range check (Tolerances<T>): support points all below minCoordinate, any above
    // maxCoordinate, an overflowing support scan, or (rescaled) a point that lost bits to the
    // scaling. When it fails, the query runs once more on the problem scaled by a power of two
    // (rescaling, above), at the very end; the rescaled query stays flagged when that could not
    // help.
    // An answer that does not fit in T fails the check too, never an unflagged inf or NaN: a
    // rescaled distance or world witness point beyond T's largest value (two points near 1.5e308
    // on opposite sides), or a rotation (c, s) far from unit size (s = 3e307, c = 1e213: found by
    // the fuzzer; std::max dropped the NaN from maxAbs). Each value is tested on its own.
    constexpr T big = std::numeric_limits<T>::max();
    const bool answerNotFinite = !(std::abs(dist) <= big) | !(std::abs(out.pointA.x) <= big) |
                                 !(std::abs(out.pointA.y) <= big) | !(std::abs(out.pointB.x) <= big) |
                                 !(std::abs(out.pointB.y) <= big) | !(std::abs(out.normal.x) <= big) |
                                 !(std::abs(out.normal.y) <= big);
    const bool rangeExceeded = !(maxAbs <= Tolerances<T>::maxCoordinate) || frameOutOfRange ||
                               (maxAbs > T(0) && maxAbs < Tolerances<T>::minCoordinate) ||
                               end.supportOutOfRange ||
                               answerNotFinite;
    if constexpr (Scaled)
    {
        out.rescaled = true;
        out.outOfRange = out.outOfRange || rangeExceeded;
    }

    cache.searchA = searchA;
    cache.searchB = searchB;

    // Out of range: the retry, at the very end, warm-started from the cache this pass just wrote
    // (any valid indices are a legitimate start; the answer depends on the input and the incoming
    // cache only). One exit, no copy of the incoming cache. Why: docs/speed.md, "One exit for the
    // rescaled retry".
    // Every support point exactly 0 is not a range failure by itself (two shapes that overlap
    // exactly), but it is also what shapes of subnormal size give once their transformed points
    // underflow (float inputs near 1e-45: exact distance 1.4e-45, answered 0; found by
    // `gjk-validate search`). distanceRescaled tells the two apart from the shapes' extent.
    if constexpr (!Scaled)
    {
        if (rangeExceeded | (maxAbs == T(0))) [[unlikely]]
            distanceRescaled(input, cache, options, trace, out, !rangeExceeded);
        // Options::correctlyRounded (gjk/correct.hpp): the refinement of the answer, out of line.
        if (options.correctlyRounded) [[unlikely]]
            correctlyRound(input, cache, options, out);
    }
    return out;
}

// The query. `Scaled`: the rescaled retry (rescaling, above), a second instantiation kept out of
// line (distanceRescaled), so that the common query carries no test for it.
template <class T, bool Scaled>
GJK_INLINE DistanceOutput<T> distanceImpl(const DistanceInput<T>& input, SimplexCache& cache,
                                          const Options& options, Trace<T>* trace, int scale)
{
    const Polygon<T>& polyA = input.proxyA;
    const Polygon<T>& polyB = input.proxyB;
    GJK_ASSERT(polyA.count > 0 && polyB.count > 0);
    GJK_ASSERT(polyA.radius >= T(0) && polyB.radius >= T(0));
    // Any finite rotation (c, s) but (0, 0), which maps a shape to one point (docs/gjk.md).
    GJK_ASSERT(!(input.transformA.q.c == T(0) && input.transformA.q.s == T(0)));
    GJK_ASSERT(!(input.transformB.q.c == T(0) && input.transformB.q.s == T(0)));

    // The compute frame: A's local frame (world = xfA * local) or the world itself.
    Transform<T> world;
    TransformedShape<T, Scaled> A{polyA, {}, false, false, 0, false};
    TransformedShape<T, Scaled> B{polyB, {}, false, false, 0, false};
    if constexpr (Scaled)
        world = setUpScaledShapes(input, options, scale, A, B);
    else if (options.frame == Frame::LocalA)
    {
        world = input.transformA;
        A.identity = true;
        B.xf = invMulTransforms(input.transformA, input.transformB);
    }
    else
    {
        A.xf = input.transformA;
        B.xf = input.transformB;
    }
    if (options.support == SupportStrategy::BinarySearch)
    {
        A.binary = polyA.count > 16;
        B.binary = polyB.count > 16;
    }
    if (trace)
    {
        trace->frame = world;
        trace->scaleExponent = scale;
        trace->steps.clear();
    }

    // Start from the cache (warm) or, cold, from the support point between the shapes (startSimplex).
    Simplex<T> simplex;
    // The slot of a final edge the distance and the edge's sign test are measured from: the
    // query's own first vertex (SimplexCache::edgeBase), 0 once the simplex has changed.
    int edgeBase = startSimplex<T>(cache, A, B, simplex);

    const int maxIterations =
        options.maxIterations > 0 ? options.maxIterations : 32 + 2 * (polyA.count + polyB.count);

    DistanceOutput<T> out;
    out.stop = StopReason::IterationLimit;
    int iteration = 0;
    // Largest coordinate magnitude of the support points seen, for the range check.
    T maxAbs = T(0);
    for (int i = 0; i < simplex.count; ++i)
        maxAbs = std::max({maxAbs, std::abs(simplex.v[i].w.x), std::abs(simplex.v[i].w.y)});
    // The simplex before the last solve (index pairs), and whether the stopping support point was
    // one of its vertices that the last solve culled (see the cache at the end).
    std::int64_t saved[3] = {-1, -1, -1};
    int savedCount = 0;
    bool culledRepeat = false;
    int searchA = A.last, searchB = B.last; // where the last support searches started
    for (;;)
    {
        // Remember the simplex vertices to detect a repeated support point (case 1).
        // Index pairs packed in one integer each; unused slots hold a pair no vertex can have.
        // Three fixed comparisons instead of a loop over 1 to 3 vertices. Why: docs/speed.md,
        // "Repeated-support check".
        for (int i = 0; i < 3; ++i)
            saved[i] = i < simplex.count ? packIndices(simplex.v[i].indexA, simplex.v[i].indexB) : -1;
        savedCount = simplex.count;

        // Compute the closest point P on the simplex and cull non-contributing vertices.
        switch (simplex.count)
        {
        case 1: break;
        case 2: solve2(simplex); break;
        case 3: solve3(simplex); break;
        }

        if (simplex.count == 3) // case 2: containment, the origin is inside Z
        {
            out.stop = StopReason::Containment;
            if (trace)
                trace->steps.push_back({simplex, Vec2<T>{}, Vec2<T>{}, false, {}});
            break;
        }

        const Vec2<T> d = searchDirection(simplex, options.direction, edgeBase);
        if (d.x == T(0) && d.y == T(0)) // case 3a: P = Q, vertex overlap (exact zero, no tolerance)
        {
            out.stop = StopReason::ZeroDirection;
            if (trace)
                trace->steps.push_back({simplex, closestPoint(simplex), d, false, {}});
            break;
        }
        if (iteration == maxIterations)
        {
            out.stop = StopReason::IterationLimit;
            if (trace)
                trace->steps.push_back({simplex, closestPoint(simplex), d, false, {}});
            break;
        }

        // New support point of Z in direction d.
        searchA = A.last;
        searchB = B.last;
        const SimplexVertex<T> w = findMinkowskiSupport<T>(A, B, d);
        ++iteration;
        maxAbs = std::max({maxAbs, std::abs(w.w.x), std::abs(w.w.y)});
        if (trace)
            trace->steps.push_back({simplex, closestPoint(simplex), d, true, w});

        // Case 1: the support point is already in the simplex: no more progress possible.
        const std::int64_t key = packIndices(w.indexA, w.indexB);
        if ((key == saved[0]) | (key == saved[1]) | (key == saved[2]))
        {
            out.stop = StopReason::RepeatedSupport;
            // Usually the repeated point is a vertex of the final simplex (of at most two
            // vertices here). When rounding made the last solve cull it (a nearly degenerate
            // triangle, found by the fuzzer), the cache keeps the simplex before that solve.
            culledRepeat = key != packIndices(simplex.v[0].indexA, simplex.v[0].indexB) &&
                           (simplex.count == 1 || key != packIndices(simplex.v[1].indexA, simplex.v[1].indexB));
            break;
        }

        if (options.stopping == StoppingRule::DualityGap)
        {
            const Vec2<T> v = closestPoint(simplex);
            const T vv = dot(v, v);
            if (vv - dot(v, w.w) <= Tolerances<T>::dualityGap * vv)
            {
                out.stop = StopReason::DualityGap;
                break;
            }
        }

        simplex.v[simplex.count] = w;
        ++simplex.count;
        edgeBase = 0; // a new simplex: measured from slot 0, as a cold query does
    }

    return finishQuery<T, Scaled>(input, cache, options, trace, scale, world, out.stop, simplex,
                                  {edgeBase, iteration, maxAbs, {saved[0], saved[1], saved[2]}, savedCount,
                                   culledRepeat, searchA, searchB,
                                   A.overflow || B.overflow || (Scaled && (A.inexact || B.inexact))});
}

// The rescaled retry, out of line: the common query never runs it.
// onlyZeroSupports: the first pass was in range, but every support point was exactly 0. That
// answer stands when the shapes are of normal size (an exact overlap: nothing underflowed) or all
// zero (k = 0); it is retried when their extent is below minCoordinate, where the transform's
// products may have underflowed to 0.
template <class T>
[[gnu::noinline]] void distanceRescaled(const DistanceInput<T>& input, SimplexCache& cache,
                                        const Options& options, Trace<T>* trace, DistanceOutput<T>& out,
                                        bool onlyZeroSupports)
{
    const int k = rescaleExponent(input.proxyA, input.transformA, input.proxyB, input.transformB, options.frame);
    if (onlyZeroSupports && !(k > -exponentOf(Tolerances<T>::minCoordinate)))
        return;
    if (k != 0)
        out = distanceImpl<T, true>(input, cache, options, trace, k);
    else
        out.outOfRange = true;
}

template <class T>
DistanceOutput<T> distance(const DistanceInput<T>& input, SimplexCache& cache,
                           const Options& options = referenceOptions, Trace<T>* trace = nullptr)
{
    return distanceImpl<T, false>(input, cache, options, trace, 0);
}

// Batch entry point for many pairs at once (e.g. a broad phase's output): outputs[i] is
// distance(inputs[i], caches[i], options). The spans must have equal sizes. Same results as the
// single query, bit for bit (test "batch"). This header-only one is the single-query loop; the
// overloads of gjk/batch.hpp (target gjk::batch) run the queries in SIMD lanes (docs/gjk.md).
template <class T>
void distanceBatch(std::span<const DistanceInput<T>> inputs, std::span<SimplexCache> caches,
                   std::span<DistanceOutput<T>> outputs, const Options& options = referenceOptions)
{
    GJK_ASSERT(inputs.size() == caches.size() && inputs.size() == outputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i)
        outputs[i] = distance(inputs[i], caches[i], options);
}

// Convenience: a cold query (value-initialised cache).
template <class T>
DistanceOutput<T> distance(const DistanceInput<T>& input, const Options& options = referenceOptions)
{
    SimplexCache cache;
    return distance(input, cache, options);
}

} // namespace gjk

#include "gjk/detail/fp_end.hpp"

#include "gjk/correct.hpp" // Options::correctlyRounded
