#include "bindings.hpp"

namespace gjk2d_python
{

void bindDistance(pybind11::module_&) {}

} // namespace gjk2d_python
