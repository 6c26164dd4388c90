#include "bindings.hpp"

namespace gjk2d_python
{

void bindCases(pybind11::module_&) {}

} // namespace gjk2d_python
