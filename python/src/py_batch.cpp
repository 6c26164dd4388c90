// gjk2d.distance_batch: many pairs in one call, gjk::distanceBatchLanes (gjk2d/batch.hpp, SIMD
// lanes) underneath. Shapes are ragged point sets packed into one (N, 2) array: pair i's shape A is
// points[offsets_a[i]:offsets_a[i + 1]], its shape B points[offsets_b[i]:offsets_b[i + 1]].
#include "arrays.hpp"
#include "bindings.hpp"

#include <gjk2d/batch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

namespace gjk2d_python
{
namespace
{
using namespace pybind11::literals;

struct BatchArgs
{
    py::object points, offsetsA, offsetsB;
    py::object radiusA, radiusB, positionA, rotationA, positionB, rotationB;
    bool certify;
};

// Offsets of n shapes: n + 1 nondecreasing integers from 0.. len(points), every shape non-empty.
std::vector<std::int64_t> offsetArray(const py::object& value, const char* name, py::ssize_t total)
{
    Array<std::int64_t> a = Array<std::int64_t>::ensure(value);
    if (!a || a.ndim() != 1 || a.shape(0) < 1)
        badArgument(name, "expected a 1-d integer array of n + 1 offsets");
    std::vector<std::int64_t> o(a.data(), a.data() + a.shape(0));
    for (std::size_t i = 0; i < o.size(); ++i)
        if (o[i] < 0 || o[i] > total || (i > 0 && o[i] - o[i - 1] < 1) ||
            (i > 0 && std::size_t(o[i] - o[i - 1]) > kMaxPoints))
            badArgument(name, "entry " + std::to_string(i) +
                                  " is out of range (offsets rise by 1 to " +
                                  std::to_string(kMaxPoints) + " points per shape within " +
                                  std::to_string(total) + " points)");
    return o;
}

// Per pair values: None (the default everywhere), one value for all pairs, or n values.
template <class T>
std::vector<T> perPair(const py::object& value, const char* name, std::size_t n, std::size_t width,
                       std::vector<T> fallback)
{
    std::vector<T> out(n * width);
    Array<double> a = value.is_none() ? Array<double>() : Array<double>::ensure(value);
    if (!value.is_none() && !a)
        badArgument(name, "not an array of numbers");
    const bool one = !value.is_none() && std::size_t(a.size()) == width;
    if (!value.is_none() && !one && std::size_t(a.size()) != n * width)
        badArgument(name, "expected " + std::string(width == 1 ? "a number or n numbers"
                                                               : "a pair or an (n, 2) array"));
    for (std::size_t i = 0; i < n * width; ++i)
        out[i] = value.is_none() ? fallback[i % width]
                                 : finiteScalar<T>(a.data()[one ? i % width : i], name);
    return out;
}

template <class T> struct Packed
{
    Array<T> points;
    std::vector<gjk::DistanceInput<T>> inputs;
};

template <class T> Packed<T> pack(const BatchArgs& b)
{
    Packed<T> p{pointArray<T>(b.points, "points", std::size_t(1) << 40), {}};
    const auto oa = offsetArray(b.offsetsA, "offsets_a", p.points.shape(0));
    const auto ob = offsetArray(b.offsetsB, "offsets_b", p.points.shape(0));
    if (oa.size() != ob.size())
        badArgument("offsets_b", "not as many offsets as offsets_a");
    const std::size_t n = oa.size() - 1;
    const auto ra = perPair<T>(b.radiusA, "radius_a", n, 1, {T(0)});
    const auto rb = perPair<T>(b.radiusB, "radius_b", n, 1, {T(0)});
    const auto pa = perPair<T>(b.positionA, "position_a", n, 2, {T(0), T(0)});
    const auto qa = perPair<T>(b.rotationA, "rotation_a", n, 2, {T(1), T(0)});
    const auto pb = perPair<T>(b.positionB, "position_b", n, 2, {T(0), T(0)});
    const auto qb = perPair<T>(b.rotationB, "rotation_b", n, 2, {T(1), T(0)});
    const auto* v = reinterpret_cast<const gjk::Vec2<T>*>(p.points.data());
    p.inputs.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        auto& in = p.inputs[i];
        in.proxyA = {v + oa[i], int(oa[i + 1] - oa[i]), ra[i]};
        in.proxyB = {v + ob[i], int(ob[i + 1] - ob[i]), rb[i]};
        in.transformA = {{pa[2 * i], pa[2 * i + 1]}, {qa[2 * i], qa[2 * i + 1]}};
        in.transformB = {{pb[2 * i], pb[2 * i + 1]}, {qb[2 * i], qb[2 * i + 1]}};
        if (!gjk::meetsInputContract(in))
            badArgument("pair " + std::to_string(i), "a negative radius or a rotation (0, 0)");
    }
    return p;
}

// The arrays of the outputs: distance, point_a, point_b, normal, iterations, stop (codes into
// gjk2d.STOP_REASONS), and lower, upper when certified.
template <class T> py::dict arraysOf(const std::vector<gjk::DistanceOutput<T>>& out, bool certify)
{
    const auto n = py::ssize_t(out.size());
    Array<T> distance(n), pointA({n, py::ssize_t(2)}), pointB({n, py::ssize_t(2)}),
        normal({n, py::ssize_t(2)});
    Array<std::int32_t> iterations(n);
    Array<std::uint8_t> stop(n);
    Array<double> lower(n), upper(n);
    T *dist = distance.mutable_data(), *a = pointA.mutable_data(), *b = pointB.mutable_data(),
      *u = normal.mutable_data();
    std::int32_t* it = iterations.mutable_data();
    std::uint8_t* st = stop.mutable_data();
    double *lo = lower.mutable_data(), *hi = upper.mutable_data();
    for (py::ssize_t i = 0; i < n; ++i)
    {
        const auto& o = out[std::size_t(i)];
        dist[i] = o.distance, it[i] = o.iterations, st[i] = std::uint8_t(o.stop);
        a[2 * i] = o.pointA.x, a[2 * i + 1] = o.pointA.y;
        b[2 * i] = o.pointB.x, b[2 * i + 1] = o.pointB.y;
        u[2 * i] = o.normal.x, u[2 * i + 1] = o.normal.y;
        lo[i] = o.lower, hi[i] = o.upper;
    }
    py::dict d("distance"_a = distance, "point_a"_a = pointA, "point_b"_a = pointB,
               "normal"_a = normal, "iterations"_a = iterations, "stop"_a = stop);
    if (certify)
        d["lower"] = lower, d["upper"] = upper;
    return d;
}

template <class T> py::dict batch(const BatchArgs& b)
{
    Packed<T> p = pack<T>(b);
    std::vector<gjk::SimplexCache> caches(p.inputs.size());
    std::vector<gjk::DistanceOutput<T>> out(p.inputs.size());
    {
        py::gil_scoped_release release;
        gjk::distanceBatchLanes(std::span<const gjk::DistanceInput<T>>(p.inputs), std::span(caches),
                                std::span(out), gjk::Options{.certify = b.certify});
    }
    return arraysOf(out, b.certify);
}

// The C++ loop alone on the same packed inputs, for the overhead measurement (docs/python.md):
// the seconds of one gjk::distanceBatchLanes call (cold caches), the median of `repeats`.
template <class T> double loopSeconds(const BatchArgs& b, int repeats)
{
    Packed<T> p = pack<T>(b);
    std::vector<gjk::SimplexCache> caches(p.inputs.size());
    std::vector<gjk::DistanceOutput<T>> out(p.inputs.size());
    std::vector<double> seconds;
    py::gil_scoped_release release;
    for (int r = 0; r < std::max(repeats, 1); ++r)
    {
        std::fill(caches.begin(), caches.end(), gjk::SimplexCache{});
        const auto t0 = std::chrono::steady_clock::now();
        gjk::distanceBatchLanes(std::span<const gjk::DistanceInput<T>>(p.inputs), std::span(caches),
                                std::span(out), gjk::Options{.certify = b.certify});
        seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::nth_element(seconds.begin(), seconds.begin() + seconds.size() / 2, seconds.end());
    return seconds[seconds.size() / 2];
}

bool isFloat32(const py::object& dtype, const py::object& points)
{
    if (!dtype.is_none())
    {
        const py::dtype d = py::dtype::from_args(dtype);
        if (!d.equal(py::dtype::of<float>()) && !d.equal(py::dtype::of<double>()))
            badArgument("dtype", "float32 or float64, got " + text(d.attr("name")));
        return d.equal(py::dtype::of<float>());
    }
    return py::isinstance<py::array>(points) &&
           py::reinterpret_borrow<py::array>(points).dtype().equal(py::dtype::of<float>());
}

} // namespace

void bindBatch(py::module_& m)
{
    py::list stops;
    for (std::size_t i = 0; i < gjk::stopReasonCount; ++i)
        stops.append(gjk::stopReasonName(gjk::StopReason(i)));
    m.attr("STOP_REASONS") = py::tuple(stops);
    const auto args = [](py::object points, py::object oa, py::object ob, py::object ra,
                         py::object rb, py::object pa, py::object qa, py::object pb, py::object qb,
                         bool certify)
    { return BatchArgs{points, oa, ob, ra, rb, pa, qa, pb, qb, certify}; };
    m.def(
        "distance_batch",
        [args](py::object points, py::object oa, py::object ob, py::object ra, py::object rb,
               py::object pa, py::object qa, py::object pb, py::object qb, py::object dtype,
               bool certify)
        {
            const BatchArgs b = args(points, oa, ob, ra, rb, pa, qa, pb, qb, certify);
            return isFloat32(dtype, points) ? batch<float>(b) : batch<double>(b);
        },
        "points"_a, "offsets_a"_a, "offsets_b"_a, py::kw_only(), "radius_a"_a = py::none(),
        "radius_b"_a = py::none(), "position_a"_a = py::none(), "rotation_a"_a = py::none(),
        "position_b"_a = py::none(), "rotation_b"_a = py::none(), "dtype"_a = py::none(),
        "certify"_a = false,
        "Many queries in one call (gjk::distanceBatchLanes): pair i's shapes are "
        "points[offsets_a[i]:offsets_a[i+1]] and points[offsets_b[i]:offsets_b[i+1]]. Returns a "
        "dict of arrays.");
    m.def(
        "_batch_loop_seconds",
        [args](py::object points, py::object oa, py::object ob, py::object ra, py::object rb,
               py::object pa, py::object qa, py::object pb, py::object qb, py::object dtype,
               bool certify, int repeats)
        {
            const BatchArgs b = args(points, oa, ob, ra, rb, pa, qa, pb, qb, certify);
            return isFloat32(dtype, points) ? loopSeconds<float>(b, repeats)
                                            : loopSeconds<double>(b, repeats);
        },
        "points"_a, "offsets_a"_a, "offsets_b"_a, py::kw_only(), "radius_a"_a = py::none(),
        "radius_b"_a = py::none(), "position_a"_a = py::none(), "rotation_a"_a = py::none(),
        "position_b"_a = py::none(), "rotation_b"_a = py::none(), "dtype"_a = py::none(),
        "certify"_a = false, "repeats"_a = 5,
        "The C++ gjk::distanceBatchLanes call alone on distance_batch's inputs: its median "
        "seconds.");
}

} // namespace gjk2d_python
