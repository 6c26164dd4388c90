// gjk2d.validate's C++ side (docs/python.md, "Validating your own GJK from Python"): a Python
// callable registered as an in-process variant (validation/src/implementations/in_process.hpp),
// then `gjk-validate run` in this process, through the very entry point the program uses
// (runCommandLine), with the argument vector python/gjk2d/_validate.py builds from validate()'s
// keywords. Truth, judgement, statistics, timing and report are the runner's, not a copy.
// The campaign runs with the GIL released; each call of the callable takes it back. Nothing forks:
// the runner forks only for shared-library plugins, which validate() does not load by default.
#include "arrays.hpp"
#include "bindings.hpp"

#include "campaign/campaign.hpp"
#include "commands/command_line.hpp"
#include "common/output.hpp"
#include "evaluate/evaluate.hpp"
#include "implementations/in_process.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gjk2d_python
{
namespace
{
using namespace pybind11::literals;
using gjkval::ExternalAnswer;
using gjkval::PreparedCase;

// A Python exception that is not an Exception (KeyboardInterrupt, SystemExit): it ends the
// campaign (not an error of one case) and is raised again by validate. Its parts are held as raw
// references (moved through C++ frames that run without the GIL), restored once the GIL is back.
struct PythonAbort
{
    PyObject *type = nullptr, *value = nullptr, *trace = nullptr;
};

// What the callable did wrong, for the case's detail: "TypeError: ..." on one line.
std::string oneLine(std::string s)
{
    for (char& c : s)
        c = (c == '\n' || c == '\r') ? ' ' : c;
    return s;
}

// Runs `call` (Python work, the GIL held): a Python Exception becomes a std::runtime_error with
// its type and message (the runner counts the case as an error), any other exception a
// PythonAbort.
template <class F> void guarded(F&& call)
{
    py::gil_scoped_acquire gil;
    try
    {
        call();
    }
    catch (py::error_already_set& e)
    {
        if (!e.matches(PyExc_Exception))
        {
            e.restore();
            PythonAbort a;
            PyErr_Fetch(&a.type, &a.value, &a.trace);
            throw a;
        }
        throw std::runtime_error(oneLine(text(e.type().attr("__name__")) + ": " + text(e.value())));
    }
}

template <class T> py::array_t<T> pointsOf(const gjk::Polygon<T>& shape)
{
    py::array_t<T> a({py::ssize_t(shape.count), py::ssize_t(2)});
    T* p = a.mutable_data();
    for (int i = 0; i < shape.count; ++i)
        p[2 * i] = shape.points[i].x, p[2 * i + 1] = shape.points[i].y;
    return a;
}

template <class T> py::array_t<T> pairOf(T x, T y)
{
    py::array_t<T> a(2);
    a.mutable_data()[0] = x, a.mutable_data()[1] = y;
    return a;
}

// The case as the keyword arguments of gjk2d.distance, in the variant's scalar type (a float32
// variant sees the case rounded to float, as gjk-validate's float variants do).
template <class T> py::dict caseArguments(const PreparedCase& p)
{
    const gjk::DistanceInput<T> in = p.input<T>(); // the scalar type's view: PreparedCase::input
    const gjk::Transform<T>&xa = in.transformA, &xb = in.transformB;
    return py::dict(
        "points_a"_a = pointsOf(in.proxyA), "points_b"_a = pointsOf(in.proxyB),
        "radius_a"_a = py::float_(in.proxyA.radius), "radius_b"_a = py::float_(in.proxyB.radius),
        "position_a"_a = pairOf(xa.p.x, xa.p.y), "rotation_a"_a = pairOf(xa.q.c, xa.q.s),
        "position_b"_a = pairOf(xb.p.x, xb.p.y), "rotation_b"_a = pairOf(xb.q.c, xb.q.s));
}

// The fields of an answer: a mapping's keys, an object's attributes (gjk2d.DistanceResult), or a
// sequence (distance, point_a, point_b[, iterations]). Iterations may be missing (None).
struct Fields
{
    py::object distance, pointA, pointB, iterations;
};
Fields fieldsOf(const py::handle& r, const char* what)
{
    if (py::isinstance<py::dict>(r) || py::hasattr(r, "keys"))
        return {r["distance"], r["point_a"], r["point_b"], r.attr("get")("iterations", py::none())};
    if (py::hasattr(r, "distance"))
        return {r.attr("distance"), r.attr("point_a"), r.attr("point_b"),
                py::getattr(r, "iterations", py::none())};
    if (r.is_none() || !py::isinstance<py::sequence>(r) || py::isinstance<py::str>(r) ||
        (py::len(r) != 3 && py::len(r) != 4))
        throw py::type_error(std::string(what) + " returned " + text(py::repr(r)).substr(0, 80) +
                             ": expected (distance, point_a, point_b[, iterations]), or a dict or "
                             "an object with those names");
    const py::sequence s = py::reinterpret_borrow<py::sequence>(r);
    return {s[0], s[1], s[2], py::len(s) == 4 ? py::object(s[3]) : py::none()};
}

// A field as a float64 array of the given shape (numbers, lists, NumPy arrays of any dtype).
py::array_t<double> numbers(const py::object& value, const std::vector<py::ssize_t>& shape,
                            const char* name)
{
    py::array_t<double> a = py::module_::import("numpy").attr("asarray")(value, "float64");
    bool ok = a.ndim() == py::ssize_t(shape.size());
    for (std::size_t k = 0; ok && k < shape.size(); ++k)
        ok = a.shape(py::ssize_t(k)) == shape[k];
    if (!ok)
        throw py::value_error(std::string(name) + ": expected shape " +
                              text(py::repr(py::tuple(py::cast(shape)))) + ", got " + shapeText(a));
    return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

// A point: two numbers (a tuple, a list, a (2,) array).
std::array<double, 2> pointOf(const py::object& value, const char* name)
{
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) ||
        py::len(value) != 2)
        throw py::value_error(std::string(name) + ": expected two numbers, got " +
                              text(py::repr(value)).substr(0, 80));
    return {py::float_(value[py::int_(0)]), py::float_(value[py::int_(1)])};
}

void takeCase(const py::handle& r, ExternalAnswer& a)
{
    const Fields f = fieldsOf(r, "the callable");
    a.distance = py::float_(f.distance);
    a.pointA = pointOf(f.pointA, "point_a");
    a.pointB = pointOf(f.pointB, "point_b");
    a.iterations = f.iterations.is_none() ? -1 : f.iterations.cast<int>();
}

// The batch's cases packed as gjk2d.distance_batch takes them: every A shape, then every B shape,
// in one (N, 2) array; pair i's A is points[offsets_a[i]:offsets_a[i + 1]], its B
// points[offsets_b[i]:offsets_b[i + 1]]; radii (n,), positions and rotations (n, 2).
template <class T> struct Packing
{
    std::vector<T> points, radiusA, radiusB, positionA, rotationA, positionB, rotationB;
    std::vector<std::int64_t> offsetsA{0}, offsetsB;

    void shape(const std::vector<gjk::Vec2<T>>& pts, std::vector<std::int64_t>& offsets)
    {
        for (const auto& q : pts)
            points.push_back(q.x), points.push_back(q.y);
        offsets.push_back(std::int64_t(points.size() / 2));
    }
    static void pair(std::vector<T>& v, T x, T y) { v.push_back(x), v.push_back(y); }
};

template <class T> py::array_t<T> arrayOf(const std::vector<T>& v, std::vector<py::ssize_t> shape)
{
    py::array_t<T> a(shape);
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
}

struct Arguments
{
    py::tuple positional;
    py::dict keywords;
};

template <class T> Arguments batchArguments(const std::vector<const PreparedCase*>& cases)
{
    Packing<T> k;
    for (const PreparedCase* p : cases)
    {
        const auto in = p->input<T>();
        k.shape({in.proxyA.points, in.proxyA.points + in.proxyA.count}, k.offsetsA);
    }
    k.offsetsB.push_back(k.offsetsA.back());
    for (const PreparedCase* p : cases)
    {
        const auto in = p->input<T>();
        k.shape({in.proxyB.points, in.proxyB.points + in.proxyB.count}, k.offsetsB);
        k.radiusA.push_back(in.proxyA.radius), k.radiusB.push_back(in.proxyB.radius);
        Packing<T>::pair(k.positionA, in.transformA.p.x, in.transformA.p.y);
        Packing<T>::pair(k.rotationA, in.transformA.q.c, in.transformA.q.s);
        Packing<T>::pair(k.positionB, in.transformB.p.x, in.transformB.p.y);
        Packing<T>::pair(k.rotationB, in.transformB.q.c, in.transformB.q.s);
    }
    const auto n = py::ssize_t(cases.size());
    return {py::make_tuple(arrayOf(k.points, {py::ssize_t(k.points.size() / 2), 2}),
                           arrayOf(k.offsetsA, {n + 1}), arrayOf(k.offsetsB, {n + 1})),
            py::dict("radius_a"_a = arrayOf(k.radiusA, {n}), "radius_b"_a = arrayOf(k.radiusB, {n}),
                     "position_a"_a = arrayOf(k.positionA, {n, 2}),
                     "rotation_a"_a = arrayOf(k.rotationA, {n, 2}),
                     "position_b"_a = arrayOf(k.positionB, {n, 2}),
                     "rotation_b"_a = arrayOf(k.rotationB, {n, 2}))};
}

void takeBatch(const py::handle& r, std::vector<ExternalAnswer>& out)
{
    const Fields f = fieldsOf(r, "the batch callable");
    const auto n = py::ssize_t(out.size());
    const auto d = numbers(f.distance, {n}, "distance");
    const auto pa = numbers(f.pointA, {n, 2}, "point_a"), pb = numbers(f.pointB, {n, 2}, "point_b");
    py::array_t<std::int64_t> it;
    if (!f.iterations.is_none())
    {
        it = py::module_::import("numpy").attr("asarray")(f.iterations, "int64");
        if (it.ndim() != 1 || it.shape(0) != n)
            throw py::value_error("iterations: expected shape (" + std::to_string(n) + ",), got " +
                                  shapeText(it));
    }
    for (py::ssize_t i = 0; i < n; ++i)
    {
        ExternalAnswer& a = out[std::size_t(i)];
        a.distance = d.at(i);
        a.pointA = {pa.at(i, 0), pa.at(i, 1)};
        a.pointB = {pb.at(i, 0), pb.at(i, 1)};
        a.iterations = f.iterations.is_none() ? -1 : int(it.at(i));
    }
}

// The callbacks around the callable (held by the registry until validate releases them).
gjkval::InProcessCalls callsOf(const py::object& fn, bool batch, bool isFloat)
{
    gjkval::InProcessCalls calls;
    if (batch)
        calls.perBatch = [fn, isFloat](const std::vector<const PreparedCase*>& cases,
                                       std::vector<ExternalAnswer>& out)
        {
            guarded(
                [&]
                {
                    const Arguments args =
                        isFloat ? batchArguments<float>(cases) : batchArguments<double>(cases);
                    takeBatch(fn(*args.positional, **args.keywords), out);
                });
        };
    else
        calls.perCase = [fn, isFloat](const PreparedCase& p, ExternalAnswer& a)
        {
            guarded(
                [&] {
                    takeCase(fn(**(isFloat ? caseArguments<float>(p) : caseArguments<double>(p))),
                             a);
                });
        };
    return calls;
}

// Releases the variant's callbacks (and the callable) when validate returns, the GIL held.
struct Registration
{
    std::string name;
    ~Registration() { gjkval::releaseInProcessVariant(name); }
};

// One campaign at a time in a process (the runner's registries and outputs are global): another
// thread's validate, or fn calling validate, is refused. Read and written with the GIL held.
bool g_running = false;
struct Running
{
    Running()
    {
        if (g_running)
            throw std::runtime_error(
                "gjk2d.validate: another campaign runs in this process (one at a time)");
        g_running = true;
    }
    ~Running() { g_running = false; }
    Running(const Running&) = delete;
    Running& operator=(const Running&) = delete;
};

// The runner's failures as Python exceptions, with its one-line messages: InputError is
// gjk2d.InputError (a ValueError, python/src/py_cases.cpp registers it), an output that cannot be
// written OSError, a broken invariant of gjk2d RuntimeError.
[[noreturn]] void raisePython(PyObject* type, const std::string& message)
{
    PyErr_SetString(type, message.c_str());
    throw py::error_already_set();
}

int runInThisProcess(std::vector<std::string> args)
{
    std::vector<char*> argv;
    for (auto& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    try
    {
        py::gil_scoped_release release;
        return gjkval::runCommandLine({int(args.size()), argv.data(), "gjk2d.validate"});
    }
    catch (const PythonAbort& a)
    {
        PyErr_Restore(a.type, a.value, a.trace);
        throw py::error_already_set();
    }
    catch (const gjkval::OutputError& e)
    {
        raisePython(PyExc_OSError,
                    std::string(e.what()) + " (the previous output is left in place)");
    }
    catch (const std::logic_error& e)
    {
        raisePython(PyExc_RuntimeError,
                    "internal error: " + std::string(e.what()) +
                        " (a bug in gjk2d, not in the input: please report it)");
    }
}

int validate(const py::object& fn, const std::string& name, bool batch, const std::string& dtype,
             const std::string& source, const std::string& library, bool acceptsRadius,
             int maxVertices, const std::vector<std::string>& args)
{
    if (dtype != "float32" && dtype != "float64")
        badArgument("dtype", "float32 or float64, got " + dtype);
    const Running running;
    const bool isFloat = dtype == "float32";
    gjkval::InProcessVariant v;
    v.name = name;
    v.source = source;
    v.library = library;
    v.description = batch ? "a Python callable, called per batch" : "a Python callable";
    v.scalar = isFloat ? gjkval::Scalar::Float : gjkval::Scalar::Double;
    v.acceptsRadius = acceptsRadius;
    v.maxVertices = maxVertices;
    v.calls = callsOf(fn, batch, isFloat);
    gjkval::registerInProcessVariant(std::move(v));
    const Registration registered{name};
    std::vector<std::string> argv{"gjk2d.validate"};
    argv.insert(argv.end(), args.begin(), args.end());
    return runInThisProcess(std::move(argv));
}

} // namespace

void bindValidate(py::module_& m)
{
    m.def("_validate", &validate, "fn"_a, "name"_a, "batch"_a, "dtype"_a, "source"_a, "library"_a,
          "accepts_radius"_a, "max_vertices"_a, "args"_a,
          "gjk2d.validate's campaign (python/gjk2d/_validate.py builds the arguments of `run`): "
          "fn registered as the in-process variant `name`, then `gjk-validate run` with args, in "
          "this process; returns the exit code (0 or 1), raises the runner's errors.");
    m.def("_set_case_dir", &gjkval::setDefaultCaseDir, "dir"_a,
          "Where the default campaign's case files are (the runner looks beside its program, "
          "which is Python here): python/gjk2d/__init__.py gives its package's cases/ at import.");
}

} // namespace gjk2d_python
