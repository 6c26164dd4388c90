// The last stage of gjk's correctly rounded distance (gjk::Options::correctlyRounded,
// gjk/include/gjk2d/correct.hpp): when the header-only stages cannot decide, the query reports
// gjk::CorrectPath::NeedsExact and this completes it with exact arithmetic (exact::distance: CGAL
// and GMP, in the exact library). Header-only glue; link with the exact library.
//
//   gjk::DistanceOutput<double> out = gjk::distance(input, cache, {.correctlyRounded = true});
//   exact::completeCorrectlyRounded(input, options, out); // no-op unless out.path == NeedsExact
//
// After it, out.distance is exact::distance(...).distance (the correctly rounded distance), the
// witness points are the exact side's closest points (correctly rounded, on the rounded surfaces)
// and the normal their direction (zero when the distance is 0); out.path is CorrectPath::Exact.
#pragma once

#include "gjk2d/distance.hpp"
#include "gjk2d/exact.hpp"

#include <cmath>

namespace exact
{

// The exact side's shape of a gjk shape and its transform (values converted exactly to double).
template <class T>
Shape shapeOf(const gjk::Polygon<T>& p, const gjk::Transform<T>& xf, bool useRadius)
{
    Shape s;
    s.points.reserve(std::size_t(p.count));
    for (int i = 0; i < p.count; ++i)
        s.points.push_back({double(p.points[i].x), double(p.points[i].y)});
    s.radius = useRadius ? double(p.radius) : 0.0;
    s.px = double(xf.p.x);
    s.py = double(xf.p.y);
    s.c = double(xf.q.c);
    s.s = double(xf.q.s);
    return s;
}

inline void completeCorrectlyRounded(const gjk::DistanceInput<double>& in,
                                     const gjk::Options& options, gjk::DistanceOutput<double>& out)
{
    if (out.path != gjk::CorrectPath::NeedsExact)
        return;
    const Result r = distance(shapeOf(in.proxyA, in.transformA, options.useRadii),
                              shapeOf(in.proxyB, in.transformB, options.useRadii));
    out.distance = r.distance;
    out.pointA = {r.witnessA.x, r.witnessA.y};
    out.pointB = {r.witnessB.x, r.witnessB.y};
    out.normal = {};
    if (r.distance > 0)
    {
        const gjk::Vec2<double> d = out.pointB - out.pointA;
        const double len = std::hypot(d.x, d.y);
        if (len > 0)
            out.normal = {d.x / len, d.y / len};
    }
    out.outOfRange = false; // answered exactly, whatever range the plain query left
    out.path = gjk::CorrectPath::Exact;
}

} // namespace exact
