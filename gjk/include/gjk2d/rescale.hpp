// The rescaled retry: any finite input whose extent fits the exponent range gets an answer.
//
// Multiplying every point and translation by a power of two 2^k scales the problem exactly (no
// rounding, unless a value over- or underflows), and every rounding of the query with it: the
// answer of the scaled problem times 2^-k is the answer the query would give if the exponent range
// were unbounded. A query whose support points leave Tolerances<T>'s safe range is run once more,
// scaled so that its extent is about 1 (without it, two separated shapes at a scale of 1e-300 were
// answered 0).
//
// This header holds the arithmetic of the scaling: exact products by powers of two, and the choice
// of the exponent. The scaled shapes are set up in gjk2d/support.hpp (setUpScaledShapes); the retry
// itself (distanceRescaled) runs the loop of gjk2d/distance.hpp once more.
#pragma once

#include "gjk2d/math.hpp"
#include "gjk2d/types.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk
{

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
    return m > T(0) && m <= std::numeric_limits<T>::max()
               ? std::ilogb(m)
               : -4 * std::numeric_limits<T>::max_exponent;
}

// A support scan compares dot(d, p) over the shape's own (unscaled) points. On a rescaled query we
// scale d instead of every point (only comparisons are made, so any positive factor of d gives the
// same support point in exact arithmetic), choosing |d| ~ 2^e with e the points' scaling exponent
// (the points are about 2^-e in size), clamped so that d stays normal: the products dot(d, p) of
// the largest points are then of order 1, neither overflowing nor lost to underflow.
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
template <class T>
int rescaleExponent(const Polygon<T>& A, const Transform<T>& xfA, const Polygon<T>& B,
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
    return e < std::numeric_limits<T>::min_exponent - 2 * std::numeric_limits<T>::digits - 8 ? 0
                                                                                             : -e;
}

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
