// The extension _gjk2d (python/, docs/python.md): one bind function per source file, called by
// module.cpp. The package gjk2d (python/gjk2d/__init__.py) re-exports what they define.
#pragma once

#include <pybind11/pybind11.h>

namespace gjk2d_python
{

void bindDistance(pybind11::module_& m); // py_distance.cpp: distance, distance_batch, SimplexCache
void bindExact(pybind11::module_& m);    // py_exact.cpp: exact_distance
void bindCases(pybind11::module_& m); // py_cases.cpp: families, generate, read_cases, write_cases
void bindValidate(pybind11::module_& m); // py_validate.cpp: the in-process campaign

} // namespace gjk2d_python
