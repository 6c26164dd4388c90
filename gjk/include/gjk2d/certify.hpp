// A certified distance interval: [lower, upper] provably containing the exact distance between the
// two given shapes (their points and transforms taken as exact numbers, the transform applied as
// x' = c*x - s*y + px, y' = s*x + c*y + py), computed from the final simplex of a GJK query.
//
//   upper: the distance from the origin to one point of Z = hull(A') - hull(B') that the simplex
//          names by its vertex indices and barycentric weights (any convex combination is a point
//          of Z, so its norm bounds the distance from above); zero when the simplex is a triangle
//          that provably contains the origin (all three orientation signs certified).
//   lower: the support-function (duality) bound for the direction n of the computed normal:
//          dist >= (min_j n.y'_j - max_i n.x'_i) / |n|, true for every n.
//
// Every quantity is evaluated in double with a running error bound (Wilkinson's running error
// analysis): each value carries e with |exact - value| <= e. One operation adds at most
// u |result| (plus 2^-1075 for an underflowing product); the bounds themselves are rounded, which
// the final safety factor (1 + 2^-40) more than covers (a few roundings of nonnegative sums can
// understate them by at most ~10 u relative). The endpoints are then rounded outwards. It works
// for float queries too: float inputs are exact doubles, and the interval is tighter than float.
//
// Cost: one scan of each shape (the lower bound needs every vertex) plus a few dozen operations.
// certifyDistance, at the end, fills DistanceOutput's interval (gjk2d/distance.hpp calls it).
#pragma once

#include "gjk2d/detail/macros.hpp"
#include "gjk2d/math.hpp"
#include "gjk2d/types.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <cassert>
#define GJK_CERTIFY_ASSERT(c) assert(c)

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk::certify
{

inline constexpr double u = 0x1p-53;          // unit roundoff of double
inline constexpr double eta = 0x1p-1074;      // underflow: absolute error bound of a product
inline constexpr double safety = 1 + 0x1p-40; // covers the rounding of the error bounds themselves

// A double with a bound on its distance to the exact quantity it stands for.
struct Bounded
{
    double v = 0;
    double e = 0;
};

inline Bounded exactly(double v)
{
    return {v, 0};
}
inline Bounded operator+(Bounded a, Bounded b)
{
    const double v = a.v + b.v;
    return {v, a.e + b.e + u * std::abs(v)};
}
inline Bounded operator-(Bounded a, Bounded b)
{
    const double v = a.v - b.v;
    return {v, a.e + b.e + u * std::abs(v)};
}
inline Bounded operator*(Bounded a, Bounded b)
{
    const double v = a.v * b.v;
    return {v, std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + u * std::abs(v) + eta};
}
// The product of two exact doubles: one rounding (this is the common case here, and the general
// product above spends most of its work on error terms that are zero).
inline Bounded mulExact(double a, double b)
{
    const double v = a * b;
    return {v, u * std::abs(v) + eta};
}

// A double above (below) x: x + |x| 2^-52 + 2^-1074 rounded to nearest. The added amount is at
// least one ulp of x (|x| 2^-52 >= ulp(x)), so the rounded sum is at least the next double above x
// -- at most two ulps above, where std::nextafter would give one, but without its library call
// and branches (this runs in the query's hot path). Infinities and NaN are returned unchanged.
inline double up(double x)
{
    return std::abs(x) <= std::numeric_limits<double>::max() ? x + (std::abs(x) * 0x1p-52 + eta)
                                                             : x;
}
inline double down(double x)
{
    return -up(-x);
}
// Upper and lower ends of the exact value.
inline double hi(Bounded a)
{
    return up(a.v + a.e * safety);
}
inline double lo(Bounded a)
{
    return down(a.v - a.e * safety);
}

struct BoundedVec
{
    Bounded x, y;
};

// The origin strictly inside triangle W1 W2 W3: the three orientations cross(Wi, Wj) (i j cyclic)
// nonzero and of one sign; certified when each bound excludes zero. Shared by the certified
// interval (certifyDistance, below) and the correctly rounded query's containment (correct.hpp).
inline bool originCertainlyInside(const BoundedVec (&W)[3])
{
    int positive = 0, negative = 0;
    for (int i = 0; i < 3; ++i)
    {
        const BoundedVec &p = W[i], &q = W[(i + 1) % 3];
        const Bounded c = p.x * q.y - p.y * q.x;
        positive += lo(c) > 0;
        negative += hi(c) < 0;
    }
    return positive == 3 || negative == 3;
}

// World coordinates of a local point under (c, s, p), as the exact side defines them.
template <class T> BoundedVec toWorld(const Transform<T>& xf, Vec2<T> v)
{
    const double c = double(xf.q.c), s = double(xf.q.s), x = double(v.x), y = double(v.y);
    return {(mulExact(c, x) - mulExact(s, y)) + exactly(double(xf.p.x)),
            (mulExact(s, x) + mulExact(c, y)) + exactly(double(xf.p.y))};
}

// Upper bound on |p| for a point p known to lie in the box (p.x +- e, p.y +- e), divided by a
// positive weight sum w (also bounded).
inline double upperNorm(const BoundedVec& p, Bounded w)
{
    const double ax = up(std::abs(p.x.v) + p.x.e * safety);
    const double ay = up(std::abs(p.y.v) + p.y.e * safety);
    const double n = up(std::sqrt(up(up(ax * ax) + up(ay * ay))));
    const double wl = lo(w);
    if (!(wl > 0))
        return std::numeric_limits<double>::infinity();
    return up(n / wl);
}

// Upper bound of max_i n . (xf * points[i]) (or, with sign = -1, of -min_i) over a shape:
// n . (Q x + p) = m . x + n . p with m = Q^T n, so the scan costs two products per vertex; the
// rounding of m . x is bounded once from the largest |x| + |y| of the shape.
template <class T>
double supportUpper(const Transform<T>& xf, const Vec2<T>* pts, int count, Bounded nx, Bounded ny)
{
    GJK_CERTIFY_ASSERT(nx.e == 0 && ny.e == 0);
    // nx, ny are exact (the computed normal's components), so are c and s.
    const double c = double(xf.q.c), s = double(xf.q.s);
    const Bounded mx = mulExact(c, nx.v) + mulExact(s, ny.v);
    const Bounded my = mulExact(c, ny.v) - mulExact(s, nx.v);
    double best = -std::numeric_limits<double>::infinity();
    double extent = 0;
    for (int i = 0; i < count; ++i)
    {
        const double x = double(pts[i].x), y = double(pts[i].y);
        best = std::max(best, mx.v * x + my.v * y);
        extent = std::max(extent, std::abs(x) + std::abs(y));
    }
    // |m.x computed - m.x exact| <= (max(m.e) + 2u max|m.v| (1 + u)) (|x| + |y|) (1 + u) for every
    // vertex: the error of m itself, and the two roundings of the dot product.
    const double me = std::max(mx.e, my.e);
    const double mmax = std::max(std::abs(mx.v), std::abs(my.v));
    const double scanError = up(up(me + 2.0000001 * u * mmax) * up(extent * (1 + 2 * u)) + 2 * eta);
    const Bounded np = mulExact(double(xf.p.x), nx.v) + mulExact(double(xf.p.y), ny.v);
    return up(up(best + scanError) + hi(np));
}

// --- The certified interval of a query (Options::certify) ----------------------------------------

// Upper end of the hull distance: the point sum(a_i W_i) / sum(a_i) of Z named by the final
// simplex, W_i = xfA * A[iA] - xfB * B[iB]; 0 when the simplex is a triangle that certainly
// contains the origin.
template <class T> GJK_INLINE double upperHullBound(const DistanceInput<T>& in, const Simplex<T>& s)
{
    BoundedVec W[3];
    for (int i = 0; i < s.count; ++i)
    {
        const BoundedVec a = toWorld(in.transformA, in.proxyA.points[s.v[i].indexA]);
        const BoundedVec b = toWorld(in.transformB, in.proxyB.points[s.v[i].indexB]);
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
    return upperHull;
}

// Lower end of the hull distance: support functions along the computed world normal n (from A to
// B): dist >= (min_j n.B_j - max_i n.A_i) / |n|. 0 for a zero normal.
template <class T> GJK_INLINE double lowerHullBound(const DistanceInput<T>& in, Vec2<T> normal)
{
    double lowerHull = 0;
    if (normal.x != T(0) || normal.y != T(0))
    {
        const Bounded nx = exactly(double(normal.x)), ny = exactly(double(normal.y));
        const Bounded mnx = exactly(-double(normal.x)), mny = exactly(-double(normal.y));
        const double hA = supportUpper(in.transformA, in.proxyA.points, in.proxyA.count, nx, ny);
        const double hBneg =
            supportUpper(in.transformB, in.proxyB.points, in.proxyB.count, mnx, mny);
        const double gap = down(-hBneg - hA);
        const double nn = up(std::sqrt(up(up(nx.v * nx.v) + up(ny.v * ny.v))));
        if (gap > 0)
            lowerHull = down(gap / nn);
    }
    return lowerHull;
}

} // namespace gjk::certify

namespace gjk
{

// Fills out.lower and out.upper from the final simplex (indices and weights) and the world normal.
template <class T>
void certifyDistance(const DistanceInput<T>& in, const Simplex<T>& s, bool useRadii, Vec2<T> normal,
                     DistanceOutput<T>& out)
{
    using namespace certify;
    const double upperHull = upperHullBound(in, s);
    const double lowerHull = lowerHullBound(in, normal);

    const double rA = useRadii ? double(in.proxyA.radius) : 0.0;
    const double rB = useRadii ? double(in.proxyB.radius) : 0.0;
    // Subtracting the radii, rounded outwards (a zero radius subtracts exactly).
    const double rSum = rA + rB;
    const double rLow = rB == 0 ? rA : down(rSum), rHigh = rB == 0 ? rA : up(rSum);
    const double lower = rHigh == 0 ? lowerHull : std::max(0.0, down(lowerHull - rHigh));
    const double upper = rLow == 0 ? upperHull : up(upperHull - rLow);
    // Certified only when both ends are numbers and the upper end is finite: an overflow anywhere
    // above (world coordinates beyond the double range, inf - inf = NaN) must never pass for a
    // bound. std::max(0, NaN) is 0, which would turn an overflowed upper end into a certified
    // [0, 0] (points near 1.5e308 rotated by 45 degrees). Comparisons with NaN are false, so each
    // test below fails closed.
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

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
