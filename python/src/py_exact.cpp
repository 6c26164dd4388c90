// gjk2d.exact_distance: the exact side (gjk2d/exact.hpp, CGAL and GMP) from Python: the correctly
// rounded distance, the exact squared distance as a fractions.Fraction and the exact witnesses;
// with signed=True the signed distance and the penetration pair (exact::Options::penetration).
#include "arrays.hpp"
#include "bindings.hpp"

#include <gjk2d/exact.hpp>

#include <pybind11/stl.h>

#include <stdexcept>
#include <utility>

namespace gjk2d_python
{
namespace
{
using namespace pybind11::literals;

// One shape's arguments in double, as exact::Shape (any points, radius, position, rotation).
exact::Shape exactShape(const py::handle& points, double radius, const py::handle& position,
                        const py::handle& rotation, const std::string& side)
{
    const Array<double> p = pointArray<double>(points, "points_" + side);
    exact::Shape s;
    for (py::ssize_t i = 0; i < p.shape(0); ++i)
        s.points.push_back({p.at(i, 0), p.at(i, 1)});
    s.radius = finiteScalar<double>(radius, "radius_" + side);
    if (!(s.radius >= 0))
        badArgument("radius_" + side, "negative");
    const gjk::Vec2<double> t = finitePair<double>(position, "position_" + side);
    const gjk::Vec2<double> q = finitePair<double>(rotation, "rotation_" + side);
    s.px = t.x, s.py = t.y, s.c = q.x, s.s = q.y;
    return s;
}

py::object fraction(const std::string& num, const std::string& den = "1")
{
    static const py::object Fraction = py::module_::import("fractions").attr("Fraction");
    return Fraction(py::int_(py::str(num)), py::int_(py::str(den)));
}

py::tuple exactPoint(const exact::ExactPoint& p)
{
    const auto part = [](const std::string& v)
    {
        const auto slash = v.find('/');
        return slash == std::string::npos ? fraction(v)
                                          : fraction(v.substr(0, slash), v.substr(slash + 1));
    };
    return py::make_tuple(part(p.x), part(p.y));
}

py::dict answerOf(const exact::Result& r)
{
    py::dict d("distance"_a = r.distance, "squared"_a = fraction(r.squaredNum, r.squaredDen),
               "overlap"_a = r.overlap, "interval"_a = std::pair{r.lower, r.upper},
               "point_a"_a = std::pair{r.witnessA.x, r.witnessA.y},
               "point_b"_a = std::pair{r.witnessB.x, r.witnessB.y},
               "exact_point_a"_a = exactPoint(r.exactWitnessA),
               "exact_point_b"_a = exactPoint(r.exactWitnessB));
    if (r.hasSigned)
    { // exact::Options::penetration (docs/exact.md, "Penetration depth")
        d["signed_distance"] = r.signedDistance;
        d["signed_interval"] = std::pair{r.signedLower, r.signedUpper};
        d["depth_squared"] = r.depthSquaredNum.empty()
                                 ? py::object(py::none())
                                 : fraction(r.depthSquaredNum, r.depthSquaredDen);
        d["penetration_a"] = std::pair{r.penetrationA.x, r.penetrationA.y};
        d["penetration_b"] = std::pair{r.penetrationB.x, r.penetrationB.y};
    }
    return d;
}

py::dict exactDistance(const py::object& pointsA, const py::object& pointsB, double radiusA,
                       double radiusB, const py::object& positionA, const py::object& rotationA,
                       const py::object& positionB, const py::object& rotationB, bool isSigned)
{
    const exact::Shape a = exactShape(pointsA, radiusA, positionA, rotationA, "a");
    const exact::Shape b = exactShape(pointsB, radiusB, positionB, rotationB, "b");
    exact::Result r;
    {
        py::gil_scoped_release release;
        r = exact::distance(a, b, {.exactWitnesses = true, .penetration = isSigned});
    }
    return answerOf(r);
}

} // namespace

void bindExact(py::module_& m)
{
    m.def("exact_distance", &exactDistance, "points_a"_a, "points_b"_a, py::kw_only(),
          "radius_a"_a = 0.0, "radius_b"_a = 0.0, "position_a"_a = py::make_tuple(0.0, 0.0),
          "rotation_a"_a = py::make_tuple(1.0, 0.0), "position_b"_a = py::make_tuple(0.0, 0.0),
          "rotation_b"_a = py::make_tuple(1.0, 0.0), "signed"_a = false,
          "The exact side (exact::distance): a dict with distance (correctly rounded), squared "
          "(the exact squared distance of the hulls, before radii, a fractions.Fraction), "
          "overlap, interval, point_a and point_b (correctly rounded witnesses) and exact_point_a "
          "and exact_point_b (the hulls' closest points, Fractions). With signed=True also "
          "signed_distance (correctly rounded; -(depth + radii) on overlap), signed_interval, "
          "depth_squared (the cores' exact squared penetration depth, a Fraction; None when "
          "apart) and penetration_a, penetration_b (correctly rounded; penetration_a - "
          "penetration_b is the least translation of B to contact).");
}

} // namespace gjk2d_python
