// Small 2D vector algebra for the GJK library: vectors, rotations stored as (cos, sin), rigid
// transforms, and the scalar traits that hold every tolerance. Header-only, no allocation, no I/O.
#pragma once

#include "gjk2d/detail/macros.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk
{

template <class T> struct Vec2
{
    T x{}, y{};
};

template <class T> constexpr Vec2<T> operator+(Vec2<T> a, Vec2<T> b)
{
    return {a.x + b.x, a.y + b.y};
}
template <class T> constexpr Vec2<T> operator-(Vec2<T> a, Vec2<T> b)
{
    return {a.x - b.x, a.y - b.y};
}
template <class T> constexpr Vec2<T> operator-(Vec2<T> a)
{
    return {-a.x, -a.y};
}
template <class T> constexpr Vec2<T> operator*(T s, Vec2<T> a)
{
    return {s * a.x, s * a.y};
}
template <class T> constexpr bool operator==(Vec2<T> a, Vec2<T> b)
{
    return a.x == b.x && a.y == b.y;
}

template <class T> constexpr T dot(Vec2<T> a, Vec2<T> b)
{
    return a.x * b.x + a.y * b.y;
}
// The 2D cross product is the scalar z-component of the 3D one: twice the signed area of the
// triangle (0, a, b), positive when b lies counter-clockwise of a.
template <class T> constexpr T cross(Vec2<T> a, Vec2<T> b)
{
    return a.x * b.y - a.y * b.x;
}
// cross(v, z) and cross(z, v) with z the plane normal: the two perpendiculars of v. The talk's
// "accurate search direction": dot(v, leftPerp(v)) = -x*y + y*x, which is exactly zero in floating
// point because both products round identically (this needs -ffp-contract=off).
template <class T> constexpr Vec2<T> leftPerp(Vec2<T> v)
{
    return {-v.y, v.x};
}
template <class T> constexpr Vec2<T> rightPerp(Vec2<T> v)
{
    return {v.y, -v.x};
}
// v == (0, 0) exactly (either zero's sign), as one integer test: a floating-point zero is the only
// value whose bits are all zero but the sign bit, so the test is the bits of both components,
// OR-ed, shifted left by one. `v.x == 0 && v.y == 0` compiled to two compares, flag moves and a
// stored flag per GJK iteration (docs/speed.md, "The cold query on engine data").
template <class T> GJK_INLINE bool isZero(Vec2<T> v)
{
    using U = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
    return U((std::bit_cast<U>(v.x) | std::bit_cast<U>(v.y)) << 1) == U(0);
}
// sqrt(x^2 + y^2) without std::hypot's scaling (slow): inside the query's documented range
// (Tolerances<T>::maxCoordinate) the squares can neither overflow nor lose accuracy to underflow.
template <class T> T length(Vec2<T> v)
{
    return std::sqrt(v.x * v.x + v.y * v.y);
}

// Every tolerance of the library, per scalar type. No FLT_EPSILON in templated code.
template <class T> struct Tolerances
{
    // Unit roundoff u = eps/2 of round-to-nearest.
    static constexpr T unitRoundoff = std::numeric_limits<T>::epsilon() / T(2);
    // DualityGap stopping rule: stop when dot(v, v) - dot(v, w) <= dualityGap * dot(v, v), i.e.
    // when the new support point w can lower the squared distance by less than a few roundings of
    // the dot products (each carries up to ~2u relative error with respect to the larger term).
    static constexpr T dualityGap = T(16) * unitRoundoff;
    // The expanding polygon's GapClosed rule (gjk2d/expand.hpp, Options::signedDistance): stop
    // when the support point w along the closest edge's outward normal n lies beyond the edge by
    // dot(n, w - v) <= expandGap * dot(n, w), i.e. when the certified interval [edge distance,
    // support value] is narrower than 4u of the support value. The edge distance itself,
    // cross(v, e) / |e|, is rounded by at least 3u relative (two products and a difference, a
    // square root and a division: docs/error-bound.md, "Penetration depth"), so a narrower gap
    // cannot be resolved by expanding further; 4u is the next power-of-two multiple. Its share of
    // the depth bound is 4u times the depth (docs/error-bound.md).
    static constexpr T expandGap = T(4) * unitRoundoff;
    // Options::signedDistance also expands when GJK ends apart at a distance of at most
    // expandNearZero times the final simplex's largest coordinate: there the last side test of an
    // edge through the origin (a cross product, rounded by ~2u of that size) may have sent the
    // search the wrong way, on shapes that overlap deeply (gjk-validate search: nested shapes,
    // distance 7.4e-17 for a depth of 3.9). The expansion's own verdict then decides (origin
    // strictly inside its polygon: overlap; else the distance stands). 64u: well above the cross
    // product's 2u, still 7.6e-6 of the size in float.
    static constexpr T expandNearZero = T(64) * unitRoundoff;
    // Range in which the query's products neither overflow nor lose precision to underflow.
    // The largest products are dots and crosses of two simplex vertices, at most ~8 R^2 for
    // coordinates of magnitude R: R <= sqrt(max)/8 keeps them finite (float: 2.3e18). Below
    // R = sqrt(min_normal / u) the products R^2 fall under min_normal/u and lose relative accuracy
    // to gradual underflow (float: 4.4e-16, double: 1.5e-146). A query whose support points leave
    // [minCoordinate, maxCoordinate] runs again rescaled, and is flagged DistanceOutput::outOfRange
    // only when that cannot help (gjk2d/rescale.hpp; docs/gjk.md, "Range").
    static inline const T maxCoordinate = std::sqrt(std::numeric_limits<T>::max()) / T(8);
    static inline const T minCoordinate = std::sqrt(std::numeric_limits<T>::min() / unitRoundoff);
    // A rotation whose computed squared size c^2 + s^2 is within this of 1 is used as a unit one:
    // A's frame inverts it by transposing it and skips the division by |qA|^2 and the final
    // multiplication by |qA| (docs/gjk.md, "Transforms"). The computed size carries 2u, so the true
    // |qA|^2 is then within 4u of 1, and the transpose within 4u of the inverse:
    // docs/error-bound.md, term 1 (6u instead of the division's 5u). Why not exactly 1: a computed
    // (cos t, sin t) pair often has c^2 + s^2 != 1, and a test against exactly 1 made the branch
    // unpredictable; within 2u a double or float (cos t, sin t) is a unit rotation and a float pair
    // seen in double (|c^2 + s^2 - 1| ~ 1e-8 .. 1e-7) is not (docs/speed.md, "Transforms as
    // given").
    static constexpr T unitRotation = T(2) * unitRoundoff;
};

// |q|^2 computed, within Tolerances<T>::unitRotation of 1.
template <class T> constexpr bool isUnitRotation(T n2)
{
    return std::abs(n2 - T(1)) <= Tolerances<T>::unitRotation;
}

// A rotation stored as the two numbers the caller computed once, c = cos(angle), s = sin(angle).
// They are used as given (never recomputed from an angle, never normalised), so the exact side can
// apply the very same map to judge the result. (c, s) need not be a unit vector: any finite
// (c, s) != (0, 0) is the map Q = [c -s; s c] = |q| R, a rotation R times the size
// |q| = sqrt(c^2 + s^2). A float engine's (cos, sin) pair is a unit vector only to float rounding
// (|c^2 + s^2 - 1| up to ~1e-7 seen in double), and the query computes the distance for
// the map as given (docs/gjk.md, "Transforms").
template <class T> struct Rot
{
    T c = T(1), s = T(0);
};

// |q|^2 = c^2 + s^2: 1 for a unit rotation.
template <class T> constexpr T squaredSize(Rot<T> q)
{
    return q.c * q.c + q.s * q.s;
}

template <class T> constexpr Vec2<T> rotate(Rot<T> q, Vec2<T> v)
{
    return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y};
}
// Q^T v, the transpose. It is Q's inverse only when |q| = 1 (Q^-1 = Q^T / |q|^2), but it is all a
// support direction needs, whatever |q|: argmax_x d.(Q x) = argmax_x (Q^T d).x.
template <class T> constexpr Vec2<T> invRotate(Rot<T> q, Vec2<T> v)
{
    return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y};
}
// a^T b (the inverse of a times b when |a| = 1)
template <class T> constexpr Rot<T> invMulRot(Rot<T> a, Rot<T> b)
{
    return {a.c * b.c + a.s * b.s, a.c * b.s - a.s * b.c};
}

// x_world = rotate(q, x_local) + p, evaluated as c*x - s*y + px (the order the exact side uses).
template <class T> struct Transform
{
    Vec2<T> p{};
    Rot<T> q{};
};

template <class T> constexpr Vec2<T> transformPoint(const Transform<T>& xf, Vec2<T> v)
{
    return {(xf.q.c * v.x - xf.q.s * v.y) + xf.p.x, (xf.q.s * v.x + xf.q.c * v.y) + xf.p.y};
}
// inverse(a) * b: maps B's local coordinates into A's local frame. The translation is
// invRotate(qA, pB - pA): the common offset of two shapes far from the origin cancels in the
// subtraction (exactly, by Sterbenz's lemma, when pB and pA are within a factor two) before any
// rounding of the small quantities happens.
// A's rotation of any size: both parts are divided by |qA|^2 = cA^2 + sA^2 (its true inverse is
// qA^T / |qA|^2), skipped for a unit rotation (isUnitRotation). Each division adds one rounding,
// and the computed |qA|^2 carries at most 2u: docs/error-bound.md, term 1.
template <class T>
constexpr Transform<T> invMulTransforms(const Transform<T>& a, const Transform<T>& b)
{
    Transform<T> r{invRotate(a.q, b.p - a.p), invMulRot(a.q, b.q)};
    const T n = squaredSize(a.q);
    if (!isUnitRotation(n)) [[unlikely]]
    {
        // The four quotients from one array, so that GCC divides each value once (it had divided
        // the packed and the scalar copies it kept of r separately: five divisions, eight lanes).
        T v[4] = {r.p.x, r.p.y, r.q.c, r.q.s};
        for (T& x : v)
            x /= n;
        r = {{v[0], v[1]}, {v[2], v[3]}};
    }
    return r;
}

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
