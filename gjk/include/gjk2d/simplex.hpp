// The simplex solvers (talk sections 1 and 2): the closest point of a segment (solve2) and of a
// triangle (solve3) to the origin, as barycentric weights, culling the vertices that do not
// contribute; and edges of any length brought to a safe size first (edgeOfSafeSize).
#pragma once

#include "gjk2d/detail/macros.hpp"
#include "gjk2d/math.hpp"
#include "gjk2d/types.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk
{

// --- Edges of any length ------------------------------------------------------------------------
//
// Every use of a simplex edge e below is homogeneous in it: the barycentric numerators u, v
// (degree 1, and u + v = |e|^2), the signs of cross products, the search direction (any positive
// multiple of a perpendicular), the distance |cross(w1, e)| / |e| (degree 0) and the unit normal.
// So an edge shorter than minEdgeComponent (2^-484 in double, 2^-51 in float, at or just above
// Tolerances<T>::minCoordinate) in both components is multiplied by the power of two that brings
// it to size ~1, exactly, and nothing else changes in exact arithmetic. Unscaled, such an edge
// lost the query (validation/cases/tiny-edges.json): its
// squared length went subnormal (a 3.5e-162 edge in double, 5.9e-23 in float: the distance far
// off), or below 1/max, where the weights' reciprocal 1/(u + v) overflowed (inf weights, NaN
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
    constexpr int e =
        (std::numeric_limits<T>::min_exponent - 1 + std::numeric_limits<T>::digits) / 2;
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
    constexpr T split =
        T((1 << ((std::numeric_limits<T>::digits + 1) / 2)) + 1); // 2^27 + 1, 2^12 + 1
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

// The regions of solve3, each a named step: keep vertex i; keep edge ij with the segment
// coordinates (ui, vj) of its endpoints, positive (so their sum is, and the division is safe).
template <class T> GJK_INLINE void keepVertex(Simplex<T>& s, int i)
{
    s.v[0] = s.v[i];
    s.v[0].a = T(1);
    s.count = 1;
}
template <class T> GJK_INLINE void keepEdge(Simplex<T>& s, int i, int j, T ui, T vj)
{
    const T inv = T(1) / (ui + vj);
    const SimplexVertex<T> a = s.v[i], b = s.v[j];
    s.v[0] = a;
    s.v[1] = b;
    s.v[0].a = ui * inv;
    s.v[1].a = vj * inv;
    s.count = 2;
}

// Region w1w2w3 of solve3 (the origin inside): the weights, given the triangle coordinates u123,
// v123, w123, all positive. Only the witness point uses them: containment ends the query.
// Cramer's rule for w1 + b (w2 - w1) + c (w3 - w1) = 0 with cross products to a few u relative
// (accurateCross), so that b and c are each within ~7u of their own size and the residual sum
// a_k w_k within ~18u W of the origin whatever the triangle's shape (docs/error-bound.md, "Witness
// points"). The areas of solve3 carry 2u |w|^2 each, against a sum |n123| that a needle or a
// nearly flat triangle makes small: A's witness was 6e-14 outside B in random/35820 (witness bound
// 1.2e-14), 3.1 outside in hard/mixed-scale/60, and Cramer's rule with plain cross products still
// left 2.7e-7 on a flat triangle. If n vanishes or is not finite, the areas' weights. Each weight
// clamped at 0, then divided by their sum.
// Origin outside after all: solve3 chose this region from plain products, which a nearly flat
// triangle can leave wrong. b and c are within 7u of their own size, so a negative one says, with
// the right sign, that the origin is outside the edge opposite its vertex; a1 = 1 - b - c is within
// 9u (absolute), so below -16u it says the same of edge w2w3. Clamping such a weight to 0 and
// renormalising moved the point sum a_k w_k along the triangle's flat direction, up to 67 times the
// witness bound from the origin in float (validation/cases/flat-containment.json: 20 of 1e7 random
// cases, b or a1 from -2e-5 to -3e-4; docs/error-bound.md "Witness points"). The region's decision
// stands (containment, distance 0: the origin is within rounding of the triangle), but the weights
// become the closest edge's (keepClosestEdge's solve2 on each edge), the third vertex's 0: the
// point is then the origin's projection on that edge, as far from the origin as the origin is from
// the triangle.
// The thresholds (below them the origin is certainly outside), for the scalar query and the batch
// lanes (gjk/src/batch_lanes.hpp) alike.
template <class T>
inline constexpr T kOutsideWeightBC = 4 * (std::numeric_limits<T>::epsilon() / 2);
template <class T>
inline constexpr T kOutsideWeightA1 = 16 * (std::numeric_limits<T>::epsilon() / 2);
template <class T> GJK_INLINE void keepClosestEdge(Simplex<T>& s);
template <class T> GJK_INLINE void closestEdgeWeights(Simplex<T>& s)
{
    Simplex<T> e = s;
    keepClosestEdge(e);
    for (int k = 0; k < 3; ++k)
    {
        s.v[k].a = T(0);
        for (int j = 0; j < e.count; ++j)
            if (e.v[j].indexA == s.v[k].indexA && e.v[j].indexB == s.v[k].indexB)
                s.v[k].a = e.v[j].a;
    }
    s.count = 3;
}
template <class T> GJK_INLINE void keepTriangle(Simplex<T>& s, T u123, T v123, T w123)
{
    const Vec2<T> w1 = s.v[0].w;
    const Vec2<T> w2 = s.v[1].w;
    const Vec2<T> w3 = s.v[2].w;
    const Vec2<T> d12 = w2 - w1, d13 = w3 - w1;
    const T n = accurateCross(d12, d13);
    if ((n > T(0) || n < T(0)) && std::abs(n) <= std::numeric_limits<T>::max())
    {
        T b = accurateCross(d13, w1) / n, c = accurateCross(w1, d12) / n;
        if (b < -kOutsideWeightBC<T> || c < -kOutsideWeightBC<T> ||
            (T(1) - b) - c < -kOutsideWeightA1<T>)
            return closestEdgeWeights(s); // origin outside after all
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
    // Three divisions, not a reciprocal: for a sum in the subnormal range 1/sum overflows and the
    // weights would be inf, the witness points NaN (float coordinates near 2^-89). Each quotient is
    // in [0, 1]. Once per query (containment ends it).
    const T sum = (u123 + v123) + w123;
    s.v[0].a = u123 / sum;
    s.v[1].a = v123 / sum;
    s.v[2].a = w123 / sum;
    s.count = 3;
}

// solve3 when rounding made the nine signs inconsistent (a nearly degenerate triangle, no region
// matched): keep the closest of the three edges, each solved as in section 1. Never divides by the
// area. The first edge is kept unless a later one is strictly closer: when every squared distance
// overflows (inf or NaN compare false), edge w1w2 is kept, never an unset simplex (coordinates near
// 1e265 would otherwise leave it empty, its weights uninitialised).
template <class T> GJK_INLINE void keepClosestEdge(Simplex<T>& s)
{
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

// --- Section 2: point (the origin) to triangle ---------------------------------------------------
//
// Nine barycentric coordinates (numerators only):
//   three segments as in solve2: (u12, v12), (u13, v13), (u23, v23),
//   the triangle from signed areas: u123 = area(Q w2 w3), v123 = area(Q w3 w1), w123 = area(Q w1
//   w2), each multiplied by the sign of area(w1 w2 w3) so their signs are right whatever the
//   winding: u123 = sgn(n) cross(w2, w3), v123 = sgn(n) cross(w3, w1), w123 = sgn(n) cross(w1, w2),
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

    // First: vertex regions, from the segment coordinates.
    if (v12 <= T(0) && v13 <= T(0))
        return keepVertex(s, 0); // region w1
    if (u12 <= T(0) && v23 <= T(0))
        return keepVertex(s, 1); // region w2
    if (u13 <= T(0) && u23 <= T(0))
        return keepVertex(s, 2); // region w3

    // Second: edge regions: between the edge's endpoints and outside it (triangle coordinate of the
    // opposite vertex not positive).
    if (u12 > T(0) && v12 > T(0) && w123 <= T(0))
        return keepEdge(s, 0, 1, u12, v12); // region w1w2
    if (u13 > T(0) && v13 > T(0) && v123 <= T(0))
        return keepEdge(s, 0, 2, u13, v13); // region w1w3
    if (u23 > T(0) && v23 > T(0) && u123 <= T(0))
        return keepEdge(s, 1, 2, u23, v23); // region w2w3

    // Third: the interior. All three triangle coordinates are positive here whenever the segment
    // tests were consistent; their sum |n123| is then positive and the division is safe.
    if (u123 > T(0) && v123 > T(0) && w123 > T(0))
        return keepTriangle(s, u123, v123, w123); // region w1w2w3

    // Rounding made the nine signs inconsistent (a nearly degenerate triangle): no region matched.
    keepClosestEdge(s);
}

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
