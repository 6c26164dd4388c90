// Prepared shapes: what a query can learn about a shape once, for the many queries an engine makes
// with it (docs/gjk.md, "Prepared shapes"). The query on two prepared shapes and their transforms
// is gjk::distance's overload in gjk2d/distance.hpp; its answers are the plain query's, bit for
// bit.
//
// What preparing buys: the plain query checks at every support scan that no dot product overflowed
// (a running sum per scan, TransformedShape::scanCheck) and tracks the largest coordinate of every
// support point (the range check). For a prepared shape the bounds of its points are known, and
// for a query whose transforms are of ordinary size (preparedQueryInRange) both checks are then
// decided before the loop starts: the loop runs without them. Why this is the same answer, bit for
// bit: preparedQueryInRange's comment.
//
// A start hint is not kept: any cold start but the plain query's (the support point in the
// direction from A's origin to B's) would change the answers' bits.
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

// A shape prepared for many queries (prepare()). A view, as Polygon: the points stay the caller's,
// and must outlive it. Allocation-free; cheap to copy.
template <class T> struct PreparedShape
{
    Polygon<T> polygon;
    // The points' bounds in the shape's own frame (NaN if a coordinate is NaN).
    Vec2<T> lower{}, upper{};
    // The largest coordinate magnitude, max(|x|, |y|) over the points (NaN if any is NaN).
    T maxAbs = T(0);
    // count * maxAbs <= Tolerances<T>::maxCoordinate and count <= 2^20 (false for a NaN or an
    // infinite coordinate): no support scan of this shape can overflow in a query that
    // preparedQueryInRange admits. The query falls back to the plain query's checks without it.
    bool scanSafe = false;
};

// Prepares a shape: one pass over its points. The polygon must meet the query's contract (at least
// one point, radius >= 0).
template <class T> PreparedShape<T> prepare(const Polygon<T>& polygon)
{
    PreparedShape<T> s;
    s.polygon = polygon;
    s.lower = s.upper = polygon.points[0];
    bool finite = true;
    for (int i = 0; i < polygon.count; ++i)
    {
        const Vec2<T> p = polygon.points[i];
        finite = finite && std::isfinite(p.x) && std::isfinite(p.y);
        s.lower = {std::min(s.lower.x, p.x), std::min(s.lower.y, p.y)};
        s.upper = {std::max(s.upper.x, p.x), std::max(s.upper.y, p.y)};
    }
    if (!finite)
    {
        s.maxAbs = std::numeric_limits<T>::quiet_NaN();
        s.lower = s.upper = {s.maxAbs, s.maxAbs};
        return s;
    }
    s.maxAbs = std::max({-s.lower.x, -s.lower.y, s.upper.x, s.upper.y});
    s.scanSafe =
        polygon.count <= (1 << 20) && s.maxAbs <= Tolerances<T>::maxCoordinate / T(polygon.count);
    return s;
}

// Whether a query of the reference options on prepared shapes A and B may run without the per-scan
// overflow check and the per-step largest coordinate; xfB is B's transform into A's frame (the
// compute frame, invMulTransforms(xfA, xfB) as the query computes it). R = maxCoordinate.
//
// - Every support point is in range: a point of A has coordinates at most M_A; a point of B
//   mapped by (c, s, t) at most (|c| + |s|) M_B + |t|, rounded up by (1 + u)^3, and their
//   difference w by (1 + u) more. With |c|, |s| <= 2 and M_A + 4 M_B + |t| <= R / 2 (rounded
//   below a factor 2 of margin), every |w| <= R: the range check's upper side can never fire, and
//   no w is infinite or NaN.
// - So every search direction d has |d| <= 2R (or, for a tiny edge scaled up by edgeOfSafeSize,
//   |d| < 2): -w, or the perpendicular of a difference of two such w. Rotated into B's frame,
//   |d| <= 4 (2R)(1 + u)^2. A scan's dot products are then at most 2 |d| M (1 + u)^2 <= 17 R M,
//   and its running sum, count values of it, at most 17 R count M (1 + u)^count <= 18 R^2 (count
//   <= 2^20, u <= 2^-24) when count M <= R (scanSafe): below T's largest value, 64 R^2. The
//   per-scan check would have found every sum finite.
// - The range check's lower side (all support points below minCoordinate, or all 0) needs the
//   largest coordinate over every support point; it is at least the start simplex's, so when that
//   is at least minCoordinate the side cannot fire either (the query checks this after the start,
//   and otherwise runs as the plain query).
// Both checks would have passed; everything else is the same arithmetic in the same order.
template <class T>
GJK_INLINE bool preparedQueryInRange(const PreparedShape<T>& A, const PreparedShape<T>& B,
                                     const Transform<T>& xfB)
{
    const T c = std::abs(xfB.q.c), s = std::abs(xfB.q.s);
    const T t = std::max(std::abs(xfB.p.x), std::abs(xfB.p.y));
    return A.scanSafe & B.scanSafe & (c <= T(2)) & (s <= T(2)) &
           (A.maxAbs + T(4) * B.maxAbs + t <= Tolerances<T>::maxCoordinate / T(2));
}

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
