// gjk2d.validate's C++ side (helper B replaces this stub).
#include "bindings.hpp"

namespace gjk2d_python
{

void bindValidate(pybind11::module_&) {}

} // namespace gjk2d_python
