// The test-only fault hook (commands/fault.hpp).
#include "commands/fault.hpp"

#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>

namespace gjkval
{

void testFault()
{
    const char* f = std::getenv("GJK2D_VALIDATE_TEST_FAULT");
    if (f == nullptr)
        return;
    const std::string fault = f;
    if (fault == "logic_error")
        throw std::logic_error("test fault: a broken invariant");
    if (fault == "bad_alloc")
        throw std::bad_alloc();
    if (fault == "unknown")
        throw 42;
}

} // namespace gjkval
