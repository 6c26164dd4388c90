// The extension module _gjk2d: the package gjk2d imports it (python/gjk2d/__init__.py).
#include "bindings.hpp"

PYBIND11_MODULE(_gjk2d, m)
{
    m.doc() = "gjk2d's C++ side: GJK distance, the exact ground truth, cases and validation";
    gjk2d_python::bindDistance(m);
    gjk2d_python::bindExact(m);
    gjk2d_python::bindCases(m);
    gjk2d_python::bindValidate(m);
}
