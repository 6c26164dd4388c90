// Support points (talk section 3 "Support point code", section 4 "Property 2") and transforms:
// the support scans of one shape, a shape seen through a transform into the query's compute frame
// (TransformedShape), the support point of the Minkowski difference, and the compute frame's
// set-up, scaled (the rescaled retry, gjk2d/rescale.hpp) or not.
#pragma once

#include "gjk2d/detail/macros.hpp"
#include "gjk2d/math.hpp"
#include "gjk2d/rescale.hpp"
#include "gjk2d/types.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk
{

// Index of the vertex furthest along d. d need not be normalised: only comparisons are made.
// Ties keep the lowest index, so a repeated support point is recognised by its index.
// `finite` reports whether every dot product was finite: a sum of the values rides along (an
// independent chain, free next to the comparisons) and is non-finite as soon as one of them
// overflowed (a shape point times a direction: validation/cases/range-overflow.json, where the
// simplex stayed in range while the shapes' points did not).
// `sum` receives that sum (the query folds it into one check per query: TransformedShape).
template <class T> GJK_INLINE int findSupportSum(const Polygon<T>& poly, Vec2<T> d, T& sum)
{
    int index = 0;
    T maxValue = dot(d, poly.points[0]);
    sum = maxValue;
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
    return index;
}
template <class T> int findSupport(const Polygon<T>& poly, Vec2<T> d, bool& finite)
{
    T sum;
    const int index = findSupportSum(poly, d, sum);
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
        best =
            wrap(s - firstPast([&](int j) { return slope(s - j - 1) >= T(0) || f(s - j) < fs; }));

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

// A shape seen through a transform into the compute frame: the support runs on the shape's own
// points with the direction rotated into its frame; only the chosen point is transformed.
// In A's frame, A itself needs no transform: `identity` skips it (bit-identical result, since
// the identity transform is exact, but faster). `Scaled`: the rescaled retry's shapes
// (gjk2d/rescale.hpp); a separate type, so that the common query carries no test for it.
// `Checked`: the range checks run as the loop goes (the scans' overflow check here, the largest
// coordinate in runLoop); false only where a prepared query decided them before the loop
// (gjk2d/prepared.hpp, preparedQueryInRange).
// Made with designated initialisers, e.g. TransformedShape<T>{.poly = p, .identity = true}.
template <class T, bool Scaled = false, bool Checked = true> struct TransformedShape
{
    static constexpr bool checked = Checked;

    Polygon<T> poly;
    Transform<T> xf{};
    bool identity = false;

    bool binary = false;   // usesBinarySearch
    int last = 0;          // previous support index: where the galloping search starts
    bool overflow = false; // the binary search chose a point out of range (outOfRange)
    // The linear scans' overflow check, folded into arithmetic: each scan adds sum - sum, which is
    // +0 for a finite sum and NaN for an infinite or NaN one (NaN then stays: NaN + x is NaN), so
    // scanCheck != 0 exactly when some scan's sum was not finite (findSupport's `finite`). One
    // subtraction and one addition per scan, off the chain; tested once per query (overflowed).
    T scanCheck = T(0);

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
            T sum;
            const int i = findSupportSum(poly, local, sum);
            if constexpr (Checked) // else the sum is dead code, and the compiler drops it
                scanCheck += sum - sum;
            return i;
        }
        last = findSupportFrom(poly, local, last);
        // The binary search evaluates a few points only: check the chosen point's own size.
        const Vec2<T> p = poly.points[last];
        overflow =
            overflow || !(std::max(std::abs(p.x), std::abs(p.y)) <= Tolerances<T>::maxCoordinate);
        return last;
    }
    // Whether a support search overflowed (DistanceOutput::outOfRange).
    bool overflowed() const { return overflow || !(scanCheck == T(0)); }
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

// --- The compute frame ---------------------------------------------------------------------------

// The compute frame's two shapes for a rescaled query (scale != 0): every point, and the
// translations, multiplied by 2^scale. Returns the transform from the compute frame to world
// coordinates (unscaled). A and B arrive made with their polygons only.
template <class T>
[[gnu::noinline]] Transform<T>
setUpScaledShapes(const DistanceInput<T>& input, const Options& options, int scale,
                  TransformedShape<T, true>& A, TransformedShape<T, true>& B)
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

// The query's two shapes in its compute frame: A's local frame (world = xfA * local, the
// conventions of gjk2d/distance.hpp) or the world itself; for a rescaled query (Scaled) the scaled
// shapes above. A and B arrive made with their polygons only. Returns the transform from the
// compute frame to world coordinates.
template <class T, bool Scaled, bool Checked>
GJK_INLINE Transform<T> setUpShapes(const DistanceInput<T>& input, const Options& options,
                                    int scale, TransformedShape<T, Scaled, Checked>& A,
                                    TransformedShape<T, Scaled, Checked>& B)
{
    Transform<T> world;
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
    A.binary = usesBinarySearch(options.support, input.proxyA.count);
    B.binary = usesBinarySearch(options.support, input.proxyB.count);
    return world;
}

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
