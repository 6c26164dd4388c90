// NumPy arrays in, checked: the one place that turns a Python argument into points or pairs of
// scalars, and refuses a bad one with a ValueError naming the argument (docs/python.md).
#pragma once

#include "inputs/cases.hpp"

#include <gjk2d/math.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <string>
#include <vector>

namespace gjk2d_python
{

namespace py = pybind11;

// The most points one shape may have: a case file's limit (gjkval::kMaxShapePoints), so that every
// shape gjk2d takes can also be written to a gjk-cases/1 file.
inline constexpr std::size_t kMaxPoints = gjkval::kMaxShapePoints;

[[noreturn]] inline void badArgument(const std::string& name, const std::string& what)
{
    throw py::value_error(name + ": " + what);
}

// The text of a Python object (str()).
inline std::string text(const py::handle& h)
{
    return std::string(py::str(h));
}

template <class T> std::string dtypeName()
{
    return text(py::dtype::of<T>().attr("name"));
}

inline std::string shapeText(const py::array& a)
{
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i)
        s += (i ? ", " : "") + std::to_string(a.shape(i));
    return s + (a.ndim() == 1 ? ",)" : ")");
}

template <class T> using Array = py::array_t<T, py::array::c_style | py::array::forcecast>;

// An (n, 2) array of finite values of T, n >= 1 (at most `limit` rows).
template <class T>
Array<T> pointArray(const py::handle& value, const std::string& name,
                    std::size_t limit = kMaxPoints)
{
    py::array raw = py::array::ensure(value);
    if (!raw)
        badArgument(name, "not an array of numbers");
    if (raw.ndim() != 2 || raw.shape(1) != 2)
        badArgument(name, "expected an (n, 2) array, got shape " + shapeText(raw));
    if (raw.shape(0) == 0)
        badArgument(name, "no points (an (n, 2) array needs n >= 1)");
    if (std::size_t(raw.shape(0)) > limit)
        badArgument(name, std::to_string(raw.shape(0)) + " points, more than the limit of " +
                              std::to_string(limit));
    Array<T> a = Array<T>::ensure(raw);
    if (!a)
        badArgument(name, "not convertible to " + dtypeName<T>());
    const T* p = a.data();
    for (py::ssize_t i = 0; i < a.size(); ++i)
        if (!std::isfinite(p[i]))
            badArgument(name, "row " + std::to_string(i / 2) + " is not finite (as " +
                                  dtypeName<T>() + ")");
    return a;
}

// A finite number of T.
template <class T> T finiteScalar(double v, const std::string& name)
{
    const T t = T(v);
    if (!std::isfinite(t))
        badArgument(name, "not finite (as " + dtypeName<T>() + ")");
    return t;
}

// A pair (x, y) of finite numbers of T.
template <class T> gjk::Vec2<T> finitePair(const py::handle& value, const std::string& name)
{
    py::array a = Array<double>::ensure(value);
    if (!a || a.ndim() != 1 || a.shape(0) != 2)
        badArgument(name, "expected two numbers");
    const double* p = static_cast<const double*>(a.data());
    return {finiteScalar<T>(p[0], name), finiteScalar<T>(p[1], name)};
}

} // namespace gjk2d_python
