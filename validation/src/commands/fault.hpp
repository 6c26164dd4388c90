// A hook for the tests of the program's top-level handlers.
#pragma once

namespace gjkval
{

// Test-only: GJK2D_VALIDATE_TEST_FAULT=logic_error|bad_alloc|unknown makes the program throw that
// once its arguments are checked, so that tests reach the top-level handlers (exit codes 4, 5).
void testFault();

} // namespace gjkval
