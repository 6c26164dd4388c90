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
//
// The code follows the talk's sections, one header each (as Jolt separates ClosestPoint.h,
// ConvexSupport.h and GJKClosestPoint.h); including this header includes them all:
//   gjk2d/types.hpp    the plain structs: shapes, Options, simplex, cache, input, output, trace
//   gjk2d/support.hpp  support points and transforms: TransformedShape, the compute frame
//   gjk2d/prepared.hpp prepared shapes: what a query learns about a shape once (PreparedShape)
//   gjk2d/rescale.hpp  the rescaled retry's exact scaling by powers of two
//   gjk2d/simplex.hpp  the simplex solvers solve2 and solve3, with their derivations
//   gjk2d/certify.hpp  the certified interval (Options::certify)
//   gjk2d/correct.hpp  the correctly rounded distance (Options::correctlyRounded)
//   gjk2d/expand.hpp   the signed distance on overlap (Options::signedDistance): EPA
//   gjk2d/distance.hpp this file: search direction, witness points, the loop, distance()
#pragma once

#include "gjk2d/certify.hpp"
#include "gjk2d/correct.hpp"
#include "gjk2d/detail/macros.hpp"
#include "gjk2d/math.hpp"
#include "gjk2d/prepared.hpp"
#include "gjk2d/rescale.hpp"
#include "gjk2d/simplex.hpp"
#include "gjk2d/support.hpp"
#include "gjk2d/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk
{

// --- Closest point, search direction, witness points ---------------------------------------------

// P, the point of the simplex closest to the origin, from the barycentric weights.
template <class T> Vec2<T> closestPoint(const Simplex<T>& s)
{
    switch (s.count)
    {
    case 1:
        return s.v[0].w;
    case 2:
        return s.v[0].a * s.v[0].w + s.v[1].a * s.v[1].w;
    default:
        return Vec2<T>{};
    }
}

// Whether the origin lies strictly on the left of the edge w1 -> w1 + e12: the talk's sign test
// for the edge search direction, and the canonical order of a cached edge (SimplexCache).
// originSide > 0: on the left; < 0: on the right; 0: on the edge's line (rounded).
template <class T> T originSide(Vec2<T> w1, Vec2<T> e12)
{
    return cross(e12, -w1);
}
template <class T> bool originOnLeft(Vec2<T> w1, Vec2<T> e12)
{
    return originSide(w1, e12) > T(0);
}

// The direction from P towards Q = 0 in which to look for the next support point.
// `base` is the edge's slot the sign test measures from: 0, but for the first iteration of a warm
// start from a reversed edge (SimplexCache::edgeBase), so that it makes the very test the cold
// query made (reversing the edge negates both factors of the cross product exactly). That matters
// for a long edge far from the origin: from its far end the test is a cancellation whose sign
// rounding decides: a warm repeat from the far end could search the other way.
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
template <class T>
GJK_INLINE void computeWitnessPoints(const Simplex<T>& s, Vec2<T>& pA, Vec2<T>& pB)
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
    case 1:
        return length(s.v[0].w);
    case 2:
    {
        const Vec2<T> e12 = edgeOfSafeSize(s.v[1].w - s.v[0].w);
        return std::abs(cross(s.v[0].w, e12)) / length(e12);
    }
    default:
        return T(0);
    }
}

inline std::int64_t packIndices(int indexA, int indexB)
{
    return (std::int64_t(indexA) << 32) | std::uint32_t(indexB);
}

// --- Section 3 and 4: the GJK loop ---------------------------------------------------------------

// The rescaled retry runs the loop again (defined below it).
template <class T>
void distanceRescaled(const DistanceInput<T>& input, SimplexCache& cache, const Options& options,
                      Trace<T>* trace, DistanceOutput<T>& out, bool onlyZeroSupports);

// Whether a cache's indices fit shapes of these sizes (a warm start), else a cold start.
// Each range test is one unsigned compare: a negative index converts to a value above any count.
GJK_INLINE bool cacheFits(const SimplexCache& cache, int countA, int countB)
{
    bool fits = unsigned(cache.count - 1) < 3u;
    for (int i = 0; fits && i < cache.count; ++i)
        fits = unsigned(cache.indexA[i]) < unsigned(countA) &&
               unsigned(cache.indexB[i]) < unsigned(countB);
    return fits;
}

// The initial simplex, from the cache (warm) or cold; returns its edgeBase. Shared by the query
// below and the SIMD batch (gjk2d/batch.hpp).
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
        A.last =
            cache.searchA >= 0 && cache.searchA < A.poly.count ? cache.searchA : cache.indexA[0];
        B.last =
            cache.searchB >= 0 && cache.searchB < B.poly.count ? cache.searchB : cache.indexB[0];
        simplex.count = cache.count;
        for (int i = 0; i < cache.count; ++i)
            simplex.v[i] = makeVertex<T>(A, B, cache.indexA[i], cache.indexB[i]);
    }
    else
    {
        simplex.count = 1;
        const Vec2<T> d0 = B.xf.p - A.xf.p;
        simplex.v[0] = (d0.x != T(0) || d0.y != T(0)) ? findMinkowskiSupport<T>(A, B, d0)
                                                      : makeVertex<T>(A, B, 0, 0);
    }
    return edgeBase;
}

// The loop's state besides the simplex (startLoop sets it up, runLoop updates it), from which
// finishQuery makes the output and the cache. Shared by the query below and the SIMD batch
// (gjk2d/batch.hpp), whose lanes run the loop and end here. (The simplex is passed by reference:
// a copy in this struct slowed the scalar query, docs/speed.md, "Tried and rejected".)
template <class T> struct QueryEnd
{
    int edgeBase;
    int iteration;
    T maxAbs;              // largest support-point coordinate magnitude (the range check)
    std::int64_t saved[3]; // the simplex before the last solve (index pairs), and its size
    int savedCount;
    bool culledRepeat;      // the stopping support point was a vertex the last solve culled
    int searchA, searchB;   // where the last support searches started
    bool supportOutOfRange; // a support scan overflowed, or (rescaled) a point lost bits
};

// The cache keeps a final edge in canonical order (SimplexCache): reversed when the origin is
// strictly on the right of it (flip), with edgeBase following the base vertex. `cache.count` and
// the indices are set. Shared with the SIMD batch (gjk/src/batch.cpp), which ends lanes the same
// way.
GJK_INLINE void storeEdgeInCanonicalOrder(SimplexCache& cache, int edgeBase, bool flip)
{
    cache.edgeBase = cache.count == 2 ? edgeBase ^ int(flip) : 0;
    if (flip)
    {
        std::swap(cache.indexA[0], cache.indexA[1]);
        std::swap(cache.indexB[0], cache.indexB[1]);
    }
}

// The answer read off the final simplex: witness points, distance and unit normal from A to B,
// first in the compute frame, then (toWorldFrame) in world coordinates.
template <class T> struct Answer
{
    Vec2<T> pointA, pointB;
    T distance = T(0);
    Vec2<T> normal{};
    bool flipEdge = false; // the cache stores the final edge reversed (SimplexCache)
};

// Closest points from the barycentric weights; distance and unit normal sharing one square root
// (simplexDistance's formulas). On an edge the normal is the exact perpendicular of the edge, more
// accurate than normalising the tiny difference pB - pA.
template <class T> GJK_INLINE Answer<T> readSimplex(const Simplex<T>& simplex, int edgeBase)
{
    Answer<T> a;
    computeWitnessPoints(simplex, a.pointA, a.pointB);
    if (simplex.count == 1)
    {
        a.distance = length(simplex.v[0].w);
        if (a.distance > T(0))
            a.normal = (T(1) / a.distance) * -simplex.v[0].w;
    }
    else if (simplex.count == 2)
    {
        // Everything is measured from the vertex at slot edgeBase (the query's own first vertex;
        // searchDirection's sign test uses it too). The normal is the vector searchDirection gives,
        // normalised: leftPerp(e) when the origin is on the left of w1 -> w2, else
        // rightPerp(e) == leftPerp(-e), exactly. flipEdge: the origin is strictly on the right, so
        // the cache stores the edge reversed (SimplexCache's canonical order). Not when it is on
        // the edge's line (side exactly 0): both orders would then fail the strict test and take
        // opposite directions, so the order stays (else warm repeats of duality-gap stops would
        // search on). Reversing the edge only negates e, and edgeBase follows the base vertex, so a
        // warm start from the cache reproduces the cold query's bits.
        const Vec2<T> e = edgeOfSafeSize(simplex.v[1].w - simplex.v[0].w);
        const Vec2<T> base = edgeBase ? simplex.v[1].w : simplex.v[0].w;
        const T side = originSide(base, e);
        a.flipEdge = side < T(0);
        const T len = length(e);
        a.distance = std::abs(cross(base, e)) / len;
        if (a.distance > T(0))
            a.normal = (T(1) / len) * leftPerp(side > T(0) ? e : -e);
    }
    return a;
}

// Back to world coordinates; returns whether the frame's rotation is out of range.
// A rescaled query (Scaled) first undoes its scaling: exact, but for a distance below the type's
// normal range (it then rounds once more, to a subnormal). Then the points go through the frame's
// transform, the normal through its rotation. A's frame of a rotation qA that is not a unit vector
// in T (a float engine's seen in double) measures lengths in units of |qA|: the distance is
// multiplied by |qA|, the normal (which rotate() lengthened by |qA|) divided by it. Skipped for a
// unit rotation (isUnitRotation, the same test as invMulTransforms'), as for every world-frame
// query (world.q is the identity). docs/error-bound.md, term 5.
template <class T, bool Scaled>
GJK_INLINE bool toWorldFrame(Answer<T>& a, const Transform<T>& world, int scale)
{
    if constexpr (Scaled)
    {
        a.distance = std::ldexp(a.distance, -scale);
        a.pointA = {std::ldexp(a.pointA.x, -scale), std::ldexp(a.pointA.y, -scale)};
        a.pointB = {std::ldexp(a.pointB.x, -scale), std::ldexp(a.pointB.y, -scale)};
    }
    const T frameSize2 = squaredSize(world.q);
    a.pointA = transformPoint(world, a.pointA);
    a.pointB = transformPoint(world, a.pointB);
    a.normal = rotate(world.q, a.normal);
    // |qA|^2 itself must be in range (its square root and the divisions by it keep their
    // relative accuracy): a rotation of size beyond ~1e-146..1e153 (double) is normalised by the
    // rescaled retry (rotationExponent).
    bool frameOutOfRange = false;
    if (!isUnitRotation(frameSize2)) [[unlikely]]
    {
        frameOutOfRange =
            !(frameSize2 >= Tolerances<T>::minCoordinate * Tolerances<T>::minCoordinate &&
              frameSize2 <= Tolerances<T>::maxCoordinate * Tolerances<T>::maxCoordinate);
        const T size = std::sqrt(frameSize2);
        a.distance *= size;
        a.normal = {a.normal.x / size, a.normal.y / size};
    }
    return frameOutOfRange;
}

// The radii are world lengths: the witness points move onto the rounded surfaces, or, when the
// rounded shapes overlap, distance 0 and one point in both.
template <class T> GJK_INLINE void applyRadii(Answer<T>& a, T rA, T rB)
{
    if (a.distance > rA + rB)
    {
        a.distance -= rA + rB;
        a.pointA = a.pointA + rA * a.normal;
        a.pointB = a.pointB - rB * a.normal;
    }
    else
    {
        // The point on the segment from A's closest point to B's (at most rA + rB long)
        // rA / (rA + rB) of the way, so within rA of A's and rB of B's. The midpoint was not: a
        // capsule of radius 0.39 touching a disc of radius 0.0016 got a point 0.19 outside the disc
        // (hard/rounded/17-capsule-disc).
        const T t = rA / (rA + rB);
        const Vec2<T> p = a.pointA + t * (a.pointB - a.pointA);
        a.pointA = p;
        a.pointB = p;
        a.distance = T(0);
        a.normal = Vec2<T>{};
    }
}

// The cache: the final simplex, a final edge in canonical order. After a culled repeat, the
// simplex before the last solve in its own order (and edgeBase as it was), which a warm start
// solves exactly as this query did (docs/gjk.md, "Warm start"). Then where the last support
// searches started.
template <class T>
GJK_INLINE void writeCache(SimplexCache& cache, const Simplex<T>& simplex, const QueryEnd<T>& end,
                           bool flipEdge)
{
    if (end.culledRepeat) [[unlikely]]
    {
        cache.count = end.savedCount;
        for (int i = 0; i < end.savedCount; ++i)
        {
            cache.indexA[i] = int(end.saved[i] >> 32);
            cache.indexB[i] = int(std::uint32_t(end.saved[i]));
        }
        cache.edgeBase = end.edgeBase;
    }
    else
    {
        cache.count = simplex.count;
        for (int i = 0; i < simplex.count; ++i)
        {
            cache.indexA[i] = simplex.v[i].indexA;
            cache.indexB[i] = simplex.v[i].indexB;
        }
        storeEdgeInCanonicalOrder(cache, end.edgeBase, flipEdge);
    }
    cache.searchA = end.searchA;
    cache.searchB = end.searchB;
}

// The range check (Tolerances<T>): support points all below minCoordinate, any above
// maxCoordinate, an overflowing support scan, or (rescaled) a point that lost bits to the
// scaling. An answer that does not fit in T fails the check too, never an unflagged inf or NaN: a
// rescaled distance or world witness point beyond T's largest value (two points near 1.5e308 on
// opposite sides), or a rotation (c, s) far from unit size (s = 3e307, c = 1e213, where std::max
// would drop the NaN from maxAbs). Each value is tested on its own.
template <class T>
GJK_INLINE bool rangeExceeded(const QueryEnd<T>& end, bool frameOutOfRange,
                              const DistanceOutput<T>& out)
{
    // x - x is +0 for a finite x and NaN for an infinite or NaN one, and a sum of +0s is +0 while
    // NaN absorbs: the sum is 0 exactly when every value is finite. Subtractions and additions
    // instead of seven absolute values, compares and flag merges (docs/speed.md, "The cold query
    // on engine data").
    auto zeroIfFinite = [](T x) { return x - x; };
    const T finiteSum =
        ((zeroIfFinite(out.distance) + zeroIfFinite(out.pointA.x)) +
         (zeroIfFinite(out.pointA.y) + zeroIfFinite(out.pointB.x))) +
        ((zeroIfFinite(out.pointB.y) + zeroIfFinite(out.normal.x)) + zeroIfFinite(out.normal.y));
    const bool answerNotFinite = !(finiteSum == T(0));
    return !(end.maxAbs <= Tolerances<T>::maxCoordinate) || frameOutOfRange ||
           (end.maxAbs > T(0) && end.maxAbs < Tolerances<T>::minCoordinate) ||
           end.supportOutOfRange || answerNotFinite;
}

// The end of the query: the answer in world coordinates, radii, certified interval, the cache,
// the range check and (out of range) the rescaled retry, then the correctly rounded refinement.
// `stop`: why the loop stopped.
template <class T, bool Scaled>
GJK_INLINE DistanceOutput<T> finishQuery(const DistanceInput<T>& input, SimplexCache& cache,
                                         const Options& options, Trace<T>* trace, int scale,
                                         const Transform<T>& world, StopReason stop,
                                         const Simplex<T>& simplex, const QueryEnd<T>& end)
{
    Answer<T> a = readSimplex(simplex, end.edgeBase);
    const bool frameOutOfRange = toWorldFrame<T, Scaled>(a, world, scale);
    if (options.useRadii && (input.proxyA.radius > T(0) || input.proxyB.radius > T(0)))
        applyRadii(a, input.proxyA.radius, input.proxyB.radius);

    DistanceOutput<T> out;
    out.stop = stop;
    if (options.certify)
        certifyDistance(input, simplex, options.useRadii, a.normal, out);
    // "+ 0" turns a negative zero into +0 and changes nothing else (round to nearest): the sign of
    // a zero component depends on the order of the edge's vertices (x - x is +0, -(x - x) is -0),
    // which a warm start may reverse (axis-aligned normals).
    const Vec2<T> zero{};
    out.pointA = a.pointA + zero;
    out.pointB = a.pointB + zero;
    out.normal = a.normal + zero;
    out.distance = a.distance;
    out.iterations = end.iteration;
    out.simplexCount = simplex.count;
    writeCache(cache, simplex, end, a.flipEdge);

    // Out of range, the query runs once more on the problem scaled by a power of two
    // (gjk2d/rescale.hpp); the rescaled query stays flagged when that could not help.
    const bool exceeded = rangeExceeded(end, frameOutOfRange, out);
    if constexpr (Scaled)
    {
        out.rescaled = true;
        out.outOfRange = out.outOfRange || exceeded;
    }
    // The retry, at the very end, warm-started from the cache this pass just wrote (any valid
    // indices are a legitimate start; the answer depends on the input and the incoming cache only).
    // One exit, no copy of the incoming cache. Why: docs/speed.md, "One exit for the rescaled
    // retry". Every support point exactly 0 is not a range failure by itself (two shapes that
    // overlap exactly), but it is also what shapes of subnormal size give once their transformed
    // points underflow (float inputs near 1e-45: exact distance 1.4e-45, answered 0).
    // distanceRescaled tells the two apart from the shapes' extent.
    if constexpr (!Scaled)
    {
        if (exceeded | (end.maxAbs == T(0))) [[unlikely]]
            distanceRescaled(input, cache, options, trace, out, !exceeded);
        // Options::correctlyRounded (gjk2d/correct.hpp): the refinement of the answer, out of line.
        if (options.correctlyRounded) [[unlikely]]
            correctlyRound(input, cache, options, out);
    }
    return out;
}

// Compute the closest point P on the simplex and cull non-contributing vertices.
template <class T> GJK_INLINE void solveSimplex(Simplex<T>& simplex)
{
    switch (simplex.count)
    {
    case 1:
        break;
    case 2:
        solve2(simplex);
        break;
    case 3:
        solve3(simplex);
        break;
    }
}

// The loop's state before it runs: the start simplex from the cache (warm) or cold
// (startSimplex), the largest coordinate so far, no saved simplex, the searches' starts.
template <class T, class Shape>
GJK_INLINE void startLoop(const SimplexCache& cache, Shape& A, Shape& B, Simplex<T>& simplex,
                          QueryEnd<T>& end)
{
    // The slot of a final edge the distance and the edge's sign test are measured from: the
    // query's own first vertex (SimplexCache::edgeBase), 0 once the simplex has changed.
    end.edgeBase = startSimplex<T>(cache, A, B, simplex);
    end.iteration = 0;
    end.maxAbs = T(0);
    for (int i = 0; i < simplex.count; ++i)
        end.maxAbs = std::max({end.maxAbs, std::abs(simplex.v[i].w.x), std::abs(simplex.v[i].w.y)});
    end.saved[0] = end.saved[1] = end.saved[2] = -1;
    end.savedCount = 0;
    end.culledRepeat = false;
    end.searchA = A.last;
    end.searchB = B.last;
}

// The GJK loop (talk section 3): solve the simplex, stop on containment (case 2) or a zero search
// direction (case 3a), else add the support point in the search direction unless it repeats a
// vertex (case 1) or cannot lower the distance (StoppingRule::DualityGap). Returns why it stopped;
// `end` holds the rest of the final state (startLoop set it up).
template <class T, class Shape>
GJK_INLINE StopReason runLoop(Shape& A, Shape& B, const Options& options, Trace<T>* trace,
                              int maxIterations, Simplex<T>& simplex, QueryEnd<T>& end)
{
    for (;;)
    {
        // Remember the simplex vertices to detect a repeated support point (case 1). Index pairs
        // packed in one integer each; unused slots hold a pair no vertex can have. Three fixed
        // comparisons instead of a loop over 1 to 3 vertices. Why: docs/speed.md, "Repeated-support
        // check".
        for (int i = 0; i < 3; ++i)
            end.saved[i] =
                i < simplex.count ? packIndices(simplex.v[i].indexA, simplex.v[i].indexB) : -1;
        end.savedCount = simplex.count;
        solveSimplex(simplex);
        if (simplex.count == 3) // case 2: containment, the origin is inside Z
        {
            if (trace)
                trace->steps.push_back({simplex, Vec2<T>{}, Vec2<T>{}, false, {}});
            return StopReason::Containment;
        }
        const Vec2<T> d = searchDirection(simplex, options.direction, end.edgeBase);
        const bool zeroDirection = isZero(d); // case 3a: P = Q, vertex overlap (exact)
        if (zeroDirection || end.iteration == maxIterations)
        {
            if (trace)
                trace->steps.push_back({simplex, closestPoint(simplex), d, false, {}});
            return zeroDirection ? StopReason::ZeroDirection : StopReason::IterationLimit;
        }

        // New support point of Z in direction d.
        end.searchA = A.last;
        end.searchB = B.last;
        const SimplexVertex<T> w = findMinkowskiSupport<T>(A, B, d);
        ++end.iteration;
        if constexpr (Shape::checked) // else decided before the loop (gjk2d/prepared.hpp)
            end.maxAbs = std::max({end.maxAbs, std::abs(w.w.x), std::abs(w.w.y)});
        if (trace)
            trace->steps.push_back({simplex, closestPoint(simplex), d, true, w});

        // Case 1: the support point is already in the simplex: no more progress possible.
        // Usually it is a vertex of the final simplex (of at most two vertices here). When rounding
        // made the last solve cull it (a nearly degenerate triangle), the cache keeps the simplex
        // before that solve (culledRepeat).
        const std::int64_t key = packIndices(w.indexA, w.indexB);
        if ((key == end.saved[0]) | (key == end.saved[1]) | (key == end.saved[2]))
        {
            end.culledRepeat = key != packIndices(simplex.v[0].indexA, simplex.v[0].indexB) &&
                               (simplex.count == 1 ||
                                key != packIndices(simplex.v[1].indexA, simplex.v[1].indexB));
            return StopReason::RepeatedSupport;
        }
        if (options.stopping == StoppingRule::DualityGap)
        {
            const Vec2<T> v = closestPoint(simplex);
            const T vv = dot(v, v);
            if (vv - dot(v, w.w) <= Tolerances<T>::dualityGap * vv)
                return StopReason::DualityGap;
        }
        simplex.v[simplex.count] = w;
        ++simplex.count;
        end.edgeBase = 0; // a new simplex: measured from slot 0, as a cold query does
    }
}

// Options::signedDistance's step after the loop (gjk2d/expand.hpp, included at the end of this
// file): replaces an overlapping answer by the signed one; returns whether it left the safe range.
template <class T, bool Scaled, class Shape>
bool signedAnswer(const DistanceInput<T>& input, const Options& options, Shape& A, Shape& B,
                  const Transform<T>& world, int scale, StopReason stop, const Simplex<T>& simplex,
                  int edgeBase, DistanceOutput<T>& out);

// The plain query with the reference options and no trace, out of line: a prepared query's way
// back when its shapes or transforms do not let it skip the range checks (below).
template <class T>
[[gnu::noinline]] DistanceOutput<T> distanceUnprepared(const DistanceInput<T>& input,
                                                       SimplexCache& cache);

// The query. `Scaled`: the rescaled retry (gjk2d/rescale.hpp), a second instantiation kept out of
// line (distanceRescaled), so that the common query carries no test for it. `Checked` false: a
// query on prepared shapes (preparedA and preparedB) with the reference options and no trace,
// whose range checks are decided before the loop (gjk2d/prepared.hpp); where they cannot be, it
// runs as the plain query.
template <class T, bool Scaled, bool Checked = true>
GJK_INLINE DistanceOutput<T> distanceImpl(const DistanceInput<T>& input, SimplexCache& cache,
                                          const Options& options, Trace<T>* trace, int scale,
                                          const PreparedShape<T>* preparedA = nullptr,
                                          const PreparedShape<T>* preparedB = nullptr)
{
    GJK_ASSERT(meetsInputContract(input));
    TransformedShape<T, Scaled, Checked> A{.poly = input.proxyA};
    TransformedShape<T, Scaled, Checked> B{.poly = input.proxyB};
    const Transform<T> world = setUpShapes(input, options, scale, A, B);
    if constexpr (!Checked)
    {
        if (!preparedQueryInRange(*preparedA, *preparedB, B.xf)) [[unlikely]]
            return distanceUnprepared(input, cache);
    }
    if (trace)
    {
        trace->frame = world;
        trace->scaleExponent = scale;
        trace->steps.clear();
    }
    Simplex<T> simplex;
    QueryEnd<T> end;
    startLoop<T>(cache, A, B, simplex, end);
    if constexpr (!Checked) // the range check's lower side (preparedQueryInRange)
    {
        if (!(end.maxAbs >= Tolerances<T>::minCoordinate)) [[unlikely]]
            return distanceUnprepared(input, cache);
    }
    const StopReason stop =
        runLoop<T>(A, B, options, trace,
                   iterationLimit(options, input.proxyA.count, input.proxyB.count), simplex, end);
    end.supportOutOfRange =
        A.overflowed() || B.overflowed() || (Scaled && (A.inexact || B.inexact));
    DistanceOutput<T> out =
        finishQuery<T, Scaled>(input, cache, options, trace, scale, world, stop, simplex, end);
    // Options::signedDistance (on overlap, distance 0 after the radii, or a distance within
    // rounding of 0: signedAnswer decides), when this pass's answer stands (not replaced by the
    // rescaled retry, which makes this step itself). Out of range, the query runs again rescaled,
    // as finishQuery's own check does.
    if (options.signedDistance && (Scaled || !out.rescaled) && !out.outOfRange) [[unlikely]]
    {
        const bool exceeded = signedAnswer<T, Scaled>(input, options, A, B, world, scale, stop,
                                                      simplex, end.edgeBase, out);
        if constexpr (Scaled)
            out.outOfRange = out.outOfRange || exceeded;
        else if (exceeded)
            distanceRescaled(input, cache, options, trace, out, false);
    }
    return out;
}

// The rescaled retry, out of line: the common query never runs it.
// onlyZeroSupports: the first pass was in range, but every support point was exactly 0. That
// answer stands when the shapes are of normal size (an exact overlap: nothing underflowed) or all
// zero (k = 0); it is retried when their extent is below minCoordinate, where the transform's
// products may have underflowed to 0.
template <class T>
[[gnu::noinline]] void distanceRescaled(const DistanceInput<T>& input, SimplexCache& cache,
                                        const Options& options, Trace<T>* trace,
                                        DistanceOutput<T>& out, bool onlyZeroSupports)
{
    const int k = rescaleExponent(input.proxyA, input.transformA, input.proxyB, input.transformB,
                                  options.frame);
    if (onlyZeroSupports && !(k > -exponentOf(Tolerances<T>::minCoordinate)))
        return;
    if (k != 0)
        out = distanceImpl<T, true>(input, cache, options, trace, k);
    else
        out.outOfRange = true;
}

template <class T>
[[gnu::noinline]] DistanceOutput<T> distanceUnprepared(const DistanceInput<T>& input,
                                                       SimplexCache& cache)
{
    return distanceImpl<T, false>(input, cache, referenceOptions, nullptr, 0);
}

// Whether `options` are the reference ones: their twelve bytes compared at once, where Options'
// defaulted == compares member by member, a branch each, at every query (docs/speed.md, "Prepared
// shapes and the warm path").
GJK_INLINE bool isReferenceOptions(const Options& options)
{
    static_assert(std::has_unique_object_representations_v<Options>,
                  "Options: every byte must be a member's (no padding) to compare them at once");
    return std::memcmp(&options, &referenceOptions, sizeof(Options)) == 0;
}

template <class T>
DistanceOutput<T> distance(const DistanceInput<T>& input, SimplexCache& cache,
                           const Options& options = referenceOptions, Trace<T>* trace = nullptr)
{
    // The reference options without a trace, the common call, run a copy of the query in which
    // every option is a constant: GCC folds the per-step tests of the search direction, the
    // stopping rule, the support strategy, the frame and the trace away (docs/speed.md, "The
    // cold query on engine data"). The same code, so the same bits.
    if (trace == nullptr && isReferenceOptions(options))
        return distanceImpl<T, false>(input, cache, referenceOptions, nullptr, 0);
    return distanceImpl<T, false>(input, cache, options, trace, 0);
}

// The query on prepared shapes (gjk2d/prepared.hpp): the same answer and cache as
// distance({A.polygon, B.polygon, xfA, xfB}, cache, options, trace), bit for bit (test "prepared
// shapes"). With the reference options and no trace it runs without the per-step range checks
// where the shapes' bounds and the transforms decide them before the loop.
template <class T>
DistanceOutput<T> distance(const PreparedShape<T>& A, const Transform<T>& xfA,
                           const PreparedShape<T>& B, const Transform<T>& xfB, SimplexCache& cache,
                           const Options& options = referenceOptions, Trace<T>* trace = nullptr)
{
    const DistanceInput<T> input{A.polygon, B.polygon, xfA, xfB};
    if (trace == nullptr && isReferenceOptions(options))
        return distanceImpl<T, false, false>(input, cache, referenceOptions, nullptr, 0, &A, &B);
    return distanceImpl<T, false>(input, cache, options, trace, 0);
}

// Convenience: a cold query on prepared shapes (value-initialised cache).
template <class T>
DistanceOutput<T> distance(const PreparedShape<T>& A, const Transform<T>& xfA,
                           const PreparedShape<T>& B, const Transform<T>& xfB,
                           const Options& options = referenceOptions)
{
    SimplexCache cache;
    return distance(A, xfA, B, xfB, cache, options);
}

// Batch entry point for many pairs at once (e.g. a broad phase's output): outputs[i] is
// distance(inputs[i], caches[i], options). The spans must have equal sizes. Same results as the
// single query, bit for bit (test "batch"). This header-only one is the single-query loop;
// distanceBatchLanes (gjk2d/batch.hpp, target gjk::batch) runs the queries in SIMD lanes, under a
// name of its own so that including it never changes which function this name calls (docs/gjk.md).
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

#include "gjk2d/detail/fp_end.hpp"

#include "gjk2d/expand.hpp" // signedAnswer (Options::signedDistance)
