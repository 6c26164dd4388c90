// Independent exact checks for the exact-side tests: plain GMP rationals, written without reference
// to the library's internals.
#pragma once

#include <gjk2d/exact.hpp>

#include <gmpxx.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace exact_test
{

using exact::Point;
using exact::Shape;

struct Q2
{
    mpq_class x, y;
};

// "num/den" or "num" -> rational.
inline mpq_class parseQ(const std::string& s)
{
    mpq_class q(s, 10);
    q.canonicalize();
    return q;
}
inline mpq_class squaredOf(const exact::Result& r)
{
    mpq_class q(r.squaredNum + "/" + r.squaredDen, 10);
    q.canonicalize();
    return q;
}
inline Q2 exactPoint(const exact::ExactPoint& p)
{
    return {parseQ(p.x), parseQ(p.y)};
}

// The world-frame points of a shape, exactly (mpq from double is exact).
inline std::vector<Q2> worldPoints(const Shape& s)
{
    std::vector<Q2> out;
    const mpq_class c(s.c), sn(s.s), px(s.px), py(s.py);
    for (const Point& p : s.points)
    {
        const mpq_class x(p.x), y(p.y);
        out.push_back({c * x - sn * y + px, sn * x + c * y + py});
    }
    return out;
}

// Exact membership of p in the convex hull of pts: p is outside iff some direction strictly
// separates it; the direction from the hull's closest point to p is an edge normal (a pair of
// points) or p minus a point.
inline bool inHull(const Q2& p, const std::vector<Q2>& pts)
{
    auto outside = [&](const mpq_class& dx, const mpq_class& dy)
    {
        if (sgn(dx) == 0 && sgn(dy) == 0)
            return false;
        const mpq_class v = dx * p.x + dy * p.y;
        bool above = true, below = true;
        for (const Q2& s : pts)
        {
            const mpq_class w = dx * s.x + dy * s.y;
            if (w >= v)
                above = false;
            if (w <= v)
                below = false;
        }
        return above || below;
    };
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
        if (outside(p.x - pts[i].x, p.y - pts[i].y))
            return false;
        for (std::size_t j = i + 1; j < pts.size(); ++j)
            if (outside(pts[i].y - pts[j].y, pts[j].x - pts[i].x))
                return false;
    }
    return true;
}

// sign(sqrt(q) - r - m) for q >= 0, exactly.
inline int cmpSqrtMinus(const mpq_class& q, const mpq_class& r, const mpq_class& m)
{
    const mpq_class t = m + r;
    if (sgn(t) < 0)
        return 1;
    return cmp(q, t * t);
}

inline bool evenMantissa(double d)
{
    if (d == 0)
        return true;
    int e;
    const double f = std::frexp(std::fabs(d), &e);
    const double k = std::fabs(d) < DBL_MIN ? std::ldexp(std::fabs(d), 1074)
                                            : std::ldexp(f, 53); // integer < 2^53
    return std::fmod(k, 2.0) == 0;
}

// Is d the correctly rounded (to nearest, ties to even) value of the number x, given through
// cmpTo(m) = sign(x - m) for any rational m? x >= 0 assumed, d >= 0 finite.
template <class Cmp> bool roundsTo(double d, Cmp cmpTo)
{
    if (!(d >= 0) || !std::isfinite(d))
        return false;
    const double up = std::nextafter(d, INFINITY);
    mpq_class hi = (mpq_class(d) + mpq_class(std::isfinite(up) ? up : DBL_MAX)) / 2;
    if (!std::isfinite(up))
        hi = mpq_class(DBL_MAX) + (mpq_class(DBL_MAX) - mpq_class(std::nextafter(DBL_MAX, 0))) / 2;
    const int ch = cmpTo(hi);
    if (ch > 0 || (ch == 0 && !evenMantissa(d)))
        return false;
    if (d == 0)
        return true; // everything at or below 2^-1075 rounds to 0 (clamped values included)
    const mpq_class lo = (mpq_class(d) + mpq_class(std::nextafter(d, 0))) / 2;
    const int cl = cmpTo(lo);
    return cl > 0 || (cl == 0 && evenMantissa(d));
}

// Same for a number of any sign.
template <class Cmp> bool roundsToSigned(double d, Cmp cmpTo)
{
    if (d > 0)
        return roundsTo(d, cmpTo);
    if (d < 0)
        return roundsTo(-d, [&](const mpq_class& m) { return -cmpTo(-m); });
    // 0 is the nearest double exactly on [-2^-1075, 2^-1075] (ties go to 0, which is even)
    const mpq_class tiny = mpq_class(std::nextafter(0.0, 1.0)) / 2;
    return cmpTo(tiny) <= 0 && cmpTo(-tiny) >= 0;
}

// sign(w + a / sqrt(q) - m) for q > 0.
inline int cmpShifted(const mpq_class& w, const mpq_class& a, const mpq_class& q,
                      const mpq_class& m)
{
    const mpq_class b = m - w; // compare a / sqrt(q) with b
    const int sa = sgn(a), sb = sgn(b);
    if (sa != sb)
        return sa > sb ? 1 : -1;
    if (sa == 0)
        return 0;
    const int c = cmp(a * a, b * b * q); // |a|/sqrt(q) vs |b|
    return sa > 0 ? c : -c;
}

// d == round(max(0, sqrt(q) - r))
inline bool distanceRoundsTo(double d, const mpq_class& q, const mpq_class& r)
{
    return roundsTo(d, [&](const mpq_class& m) { return cmpSqrtMinus(q, r, m); });
}
// d == round(q) for q >= 0 (d may be +inf when q rounds above DBL_MAX)
inline bool rationalRoundsTo(double d, const mpq_class& q)
{
    if (std::isinf(d))
    {
        const mpq_class limit =
            mpq_class(DBL_MAX) + (mpq_class(DBL_MAX) - mpq_class(std::nextafter(DBL_MAX, 0))) / 2;
        return q >= limit;
    }
    return roundsTo(d, [&](const mpq_class& m) { return cmp(q, m); });
}
// lower <= max(0, sqrt(q) - r) <= upper
inline bool encloses(double lower, double upper, const mpq_class& q, const mpq_class& r)
{
    if (!(lower <= upper))
        return false;
    const bool positive = cmpSqrtMinus(q, r, 0) > 0;
    const bool lowerOk = lower <= 0 ? true : positive && cmpSqrtMinus(q, r, mpq_class(lower)) >= 0;
    const bool upperOk = upper >= 0 && (!positive || cmpSqrtMinus(q, r, mpq_class(upper)) <= 0);
    return lowerOk && upperOk;
}

inline mpq_class radii(const Shape& a, const Shape& b)
{
    return mpq_class(a.radius) + mpq_class(b.radius);
}

inline Shape shape(std::vector<Point> pts, double radius = 0)
{
    Shape s;
    s.points = std::move(pts);
    s.radius = radius;
    return s;
}

// The fields of the truth (overlap, the squared rational and double, the distance, its enclosure,
// the witnesses) in which r and s differ, bit for bit; empty when they are the same result.
inline std::vector<std::string> differentFields(const exact::Result& r, const exact::Result& s)
{
    auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    std::vector<std::string> out;
    auto field = [&out](bool equal, const char* name)
    {
        if (!equal)
            out.push_back(name);
    };
    field(r.overlap == s.overlap, "overlap");
    field(r.squaredNum == s.squaredNum, "squaredNum");
    field(r.squaredDen == s.squaredDen, "squaredDen");
    field(same(r.squared, s.squared), "squared");
    field(same(r.distance, s.distance), "distance");
    field(same(r.lower, s.lower), "lower");
    field(same(r.upper, s.upper), "upper");
    field(same(r.witnessA.x, s.witnessA.x), "witnessA.x");
    field(same(r.witnessA.y, s.witnessA.y), "witnessA.y");
    field(same(r.witnessB.x, s.witnessB.x), "witnessB.x");
    field(same(r.witnessB.y, s.witnessB.y), "witnessB.y");
    return out;
}

inline bool sameBits(double x, double y)
{
    return std::memcmp(&x, &y, sizeof x) == 0;
}

// The signed fields (Options::penetration) in which r and s differ, bit for bit (the pair only
// when `pair`).
inline std::vector<std::string> differentSigned(const exact::Result& r, const exact::Result& s,
                                                bool pair)
{
    std::vector<std::string> out;
    auto field = [&out](bool equal, const char* name)
    {
        if (!equal)
            out.push_back(name);
    };
    field(r.hasSigned == s.hasSigned, "hasSigned");
    field(sameBits(r.signedDistance, s.signedDistance), "signedDistance");
    field(sameBits(r.signedLower, s.signedLower), "signedLower");
    field(sameBits(r.signedUpper, s.signedUpper), "signedUpper");
    field(r.depthSquaredNum == s.depthSquaredNum, "depthSquaredNum");
    field(r.depthSquaredDen == s.depthSquaredDen, "depthSquaredDen");
    if (pair)
    {
        field(sameBits(r.penetrationA.x, s.penetrationA.x), "penetrationA.x");
        field(sameBits(r.penetrationA.y, s.penetrationA.y), "penetrationA.y");
        field(sameBits(r.penetrationB.x, s.penetrationB.x), "penetrationB.x");
        field(sameBits(r.penetrationB.y, s.penetrationB.y), "penetrationB.y");
    }
    return out;
}

} // namespace exact_test
