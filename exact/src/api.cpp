// Public entry points: validation, route dispatch, point-to-shape distance.
#include "internal.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace exact
{

const char* routeName(Route r)
{
    switch (r)
    {
    case Route::HullOfDifferences:
        return "hull-of-differences";
    case Route::MinkowskiSum2:
        return "minkowski-sum-2";
    case Route::EdgeMerge:
        return "edge-merge";
    }
    return "unknown";
}

bool parseRoute(const std::string& name, Route& out)
{
    if (name == "default")
    {
        out = Route::Default;
        return true;
    }
    for (Route r : kAllRoutes)
    {
        if (name == routeName(r))
        {
            out = r;
            return true;
        }
    }
    return false;
}

void validateShape(const Shape& s, const char* name)
{
    const std::string who = name ? name : "shape";
    if (s.points.empty())
        throw std::invalid_argument("exact: " + who + " has no points");
    auto finite = [&](double v, const char* what)
    {
        if (!std::isfinite(v))
            throw std::invalid_argument("exact: " + who + " has a non-finite " + what);
    };
    finite(s.radius, "radius");
    if (s.radius < 0)
        throw std::invalid_argument("exact: " + who + " has a negative radius");
    finite(s.px, "translation");
    finite(s.py, "translation");
    finite(s.c, "rotation cosine");
    finite(s.s, "rotation sine");
    for (const Point& p : s.points)
    {
        finite(p.x, "point coordinate");
        finite(p.y, "point coordinate");
    }
}

Result distance(const Shape& a, const Shape& b, const Options& options)
{
    validateShape(a, "shape A");
    validateShape(b, "shape B");
    detail::ExactResult e;
    switch (options.route)
    {
    case Route::HullOfDifferences:
        e = detail::hullOfDifferences(a, b, options.penetration);
        break;
    case Route::MinkowskiSum2:
        e = detail::minkowskiSum2(a, b, options.penetration);
        break;
    case Route::EdgeMerge:
        return detail::edgeMergeResult(a, b, options);
    default:
        throw std::invalid_argument("exact: unknown route");
    }
    Result r = detail::finish(e, a.radius, b.radius, options.exactWitnesses);
    if (options.penetration)
        detail::finishSigned(e, a.radius, b.radius, r);
    r.fallbacks.gmp = true;
    return r;
}

Result distance(const PreparedShape& a, const PreparedShape& b, const Options& options)
{
    if (options.route == Route::EdgeMerge)
        return detail::edgeMergeResult(a.data(), b.data(), options); // validated when prepared
    return distance(a.shape(), b.shape(), options);
}

double pointToShapeDistance(const Shape& shape, Point p, bool* gmpRoute)
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw std::invalid_argument("exact: non-finite query point");
    return pointToShapeDistance(PreparedShape(shape, "shape B"), p, gmpRoute);
}

double pointToShapeDistance(const PreparedShape& shape, Point p, bool* gmpRoute)
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw std::invalid_argument("exact: non-finite query point");
    bool gmp = false;
    const double d = detail::preparedPointDistance(shape.data(), p, gmp);
    if (gmpRoute)
        *gmpRoute = gmp;
    return d;
}

} // namespace exact
