// gjk2d.distance (one query) and gjk2d.distance_batch (gjk::distanceBatchLanes over ragged point
// sets packed with offsets), float32 or float64 (docs/python.md, "One query", "A batch of
// queries").
#include "arrays.hpp"
#include "bindings.hpp"

#include <gjk2d/batch.hpp>
#include <gjk2d/correct_fallback.hpp>
#include <gjk2d/distance.hpp>

#include <pybind11/stl.h>

#include <chrono>
#include <optional>
#include <utility>

namespace gjk2d_python
{
namespace
{

// One shape's arguments, read and checked in T.
template <class T> struct ShapeArgs
{
    Array<T> points;
    T radius;
    gjk::Transform<T> transform;
};

template <class T>
ShapeArgs<T> shapeArgs(const py::handle& points, double radius, const py::handle& position,
                       const py::handle& rotation, const char* side)
{
    const std::string s(side);
    ShapeArgs<T> out{pointArray<T>(points, "points_" + s),
                     finiteScalar<T>(radius, "radius_" + s),
                     {finitePair<T>(position, "position_" + s), {}}};
    if (!(out.radius >= T(0)))
        badArgument("radius_" + s, "negative");
    const gjk::Vec2<T> q = finitePair<T>(rotation, "rotation_" + s);
    if (q.x == T(0) && q.y == T(0))
        badArgument("rotation_" + s, "(0, 0) maps the shape to one point");
    out.transform.q = {q.x, q.y};
    return out;
}

template <class T> gjk::Polygon<T> polygonOf(const ShapeArgs<T>& s)
{
    return {reinterpret_cast<const gjk::Vec2<T>*>(s.points.data()), int(s.points.shape(0)),
            s.radius};
}

// The answer of one query as Python sees it: doubles (a float answer converts exactly).
struct Result
{
    double distance;
    std::pair<double, double> pointA, pointB, normal;
    int iterations;
    std::string stop, path, expand;
    // certify, or signed on overlap (gjk::DistanceOutput's certified interval)
    std::optional<std::pair<double, double>> interval;
    bool outOfRange, rescaled;
    gjk::SimplexCache cache;
};

template <class T>
Result resultOf(const gjk::DistanceOutput<T>& o, const gjk::SimplexCache& cache, bool certify,
                bool isSigned)
{
    Result r{double(o.distance),
             {double(o.pointA.x), double(o.pointA.y)},
             {double(o.pointB.x), double(o.pointB.y)},
             {double(o.normal.x), double(o.normal.y)},
             o.iterations,
             gjk::stopReasonName(o.stop),
             gjk::correctPathName(o.path),
             gjk::expandStopName(o.expand),
             std::nullopt,
             o.outOfRange,
             o.rescaled,
             cache};
    if (certify || (isSigned && o.certified))
        r.interval = std::pair{o.lower, o.upper};
    return r;
}

// A warm cache indexes the shapes' points: one from other shapes may index beyond them, which the
// query would read out of bounds.
void checkCache(const gjk::SimplexCache& c, int countA, int countB)
{
    const auto in = [](int i, int n) { return 0 <= i && i < n; };
    bool ok = 0 <= c.count && c.count <= 3 && (c.searchA == -1 || in(c.searchA, countA)) &&
              (c.searchB == -1 || in(c.searchB, countB));
    for (int i = 0; ok && i < c.count; ++i)
        ok = in(c.indexA[i], countA) && in(c.indexB[i], countB);
    if (!ok)
        badArgument("cache", "indexes points beyond these shapes' (a cache of other shapes)");
}

struct QueryArgs
{
    py::handle pointsA, pointsB;
    double radiusA, radiusB;
    py::handle positionA, rotationA, positionB, rotationB;
    bool certify, correctlyRounded, isSigned;
    std::optional<gjk::SimplexCache> cache;
};

template <class T> Result query(const QueryArgs& q)
{
    const ShapeArgs<T> a = shapeArgs<T>(q.pointsA, q.radiusA, q.positionA, q.rotationA, "a");
    const ShapeArgs<T> b = shapeArgs<T>(q.pointsB, q.radiusB, q.positionB, q.rotationB, "b");
    const gjk::DistanceInput<T> in{polygonOf(a), polygonOf(b), a.transform, b.transform};
    gjk::Options options;
    options.certify = q.certify;
    options.correctlyRounded = q.correctlyRounded;
    options.signedDistance = q.isSigned;
    gjk::SimplexCache cache = q.cache.value_or(gjk::SimplexCache{});
    checkCache(cache, in.proxyA.count, in.proxyB.count);
    py::gil_scoped_release release;
    gjk::DistanceOutput<T> out = gjk::distance(in, cache, options);
    if constexpr (std::is_same_v<T, double>)
        exact::completeCorrectlyRounded(in, options, out); // only when out.path == NeedsExact
    return resultOf(out, cache, q.certify, q.isSigned);
}

// float32 or float64: dtype if given, else the points' (float32 only when both are float32).
bool useFloat(const py::object& dtype, const py::handle& pointsA, const py::handle& pointsB)
{
    if (!dtype.is_none())
    {
        const py::dtype d = py::dtype::from_args(dtype);
        if (d.is(py::dtype::of<float>()) || d.equal(py::dtype::of<float>()))
            return true;
        if (d.equal(py::dtype::of<double>()))
            return false;
        badArgument("dtype", "float32 or float64, got " + text(d.attr("name")));
    }
    const auto isFloat32 = [](const py::handle& h)
    {
        return py::isinstance<py::array>(h) &&
               py::reinterpret_borrow<py::array>(h).dtype().equal(py::dtype::of<float>());
    };
    return isFloat32(pointsA) && isFloat32(pointsB);
}

Result distanceFunction(const py::object& pointsA, const py::object& pointsB, double radiusA,
                        double radiusB, const py::object& positionA, const py::object& rotationA,
                        const py::object& positionB, const py::object& rotationB,
                        const py::object& dtype, bool certify, bool correctlyRounded, bool isSigned,
                        std::optional<gjk::SimplexCache> cache)
{
    const QueryArgs q{pointsA,   pointsB,   radiusA, radiusB,          positionA, rotationA,
                      positionB, rotationB, certify, correctlyRounded, isSigned,  cache};
    if (isSigned && correctlyRounded)
        badArgument("signed", "not with correctly_rounded (the correctly rounded distance is the "
                              "unsigned one)");
    if (useFloat(dtype, pointsA, pointsB))
    {
        if (correctlyRounded)
            badArgument("correctly_rounded", "float64 only (gjk2d/correct.hpp refines double "
                                             "queries; a float query is never decided)");
        return query<float>(q);
    }
    return query<double>(q);
}

void bindResult(py::module_& m)
{
    py::class_<gjk::SimplexCache>(m, "SimplexCache",
                                  "Warm start: the indices of a query's final simplex. Pass a "
                                  "result's cache to the next query between the same shapes.")
        .def(py::init<>())
        .def_readonly("count", &gjk::SimplexCache::count)
        .def_property_readonly("index_a", [](const gjk::SimplexCache& c)
                               { return std::vector<int>(c.indexA, c.indexA + c.count); })
        .def_property_readonly("index_b", [](const gjk::SimplexCache& c)
                               { return std::vector<int>(c.indexB, c.indexB + c.count); });
    py::class_<Result>(m, "DistanceResult", "The answer of gjk2d.distance (docs/python.md).")
        .def_readonly("distance", &Result::distance)
        .def_readonly("point_a", &Result::pointA)
        .def_readonly("point_b", &Result::pointB)
        .def_readonly("normal", &Result::normal)
        .def_readonly("iterations", &Result::iterations)
        .def_readonly("stop", &Result::stop)
        .def_readonly("path", &Result::path)
        .def_readonly("expand", &Result::expand)
        .def_readonly("interval", &Result::interval)
        .def_readonly("out_of_range", &Result::outOfRange)
        .def_readonly("rescaled", &Result::rescaled)
        .def_readonly("cache", &Result::cache)
        .def("__repr__",
             [](const Result& r)
             {
                 return "DistanceResult(distance=" + std::string(py::str(py::float_(r.distance))) +
                        ", stop='" + r.stop + "', iterations=" + std::to_string(r.iterations) + ")";
             });
}

} // namespace

void bindBatch(py::module_& m);

void bindDistance(py::module_& m)
{
    using namespace pybind11::literals;
    bindResult(m);
    m.def("distance", &distanceFunction, "points_a"_a, "points_b"_a, py::kw_only(),
          "radius_a"_a = 0.0, "radius_b"_a = 0.0, "position_a"_a = py::make_tuple(0.0, 0.0),
          "rotation_a"_a = py::make_tuple(1.0, 0.0), "position_b"_a = py::make_tuple(0.0, 0.0),
          "rotation_b"_a = py::make_tuple(1.0, 0.0), "dtype"_a = py::none(), "certify"_a = false,
          "correctly_rounded"_a = false, "signed"_a = false, "cache"_a = py::none(),
          "The distance between two convex shapes (the hulls of (n, 2) point arrays, grown by "
          "their radii, placed by position and rotation (c, s)): gjk::distance<float> for "
          "float32 points, <double> otherwise. signed=True: minus the penetration depth on "
          "overlap (gjk::Options::signedDistance).");
    bindBatch(m);
}

} // namespace gjk2d_python
