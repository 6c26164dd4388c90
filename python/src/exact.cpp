#include "bindings.hpp"

namespace gjk2d_python
{

void bindExact(pybind11::module_&) {}

} // namespace gjk2d_python
