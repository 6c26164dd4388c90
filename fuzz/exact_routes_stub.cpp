// Stands in for the two CGAL routes of the exact side (exact/src/cgal_hull.cpp and
// cgal_minkowski.cpp) in the fuzz build: the fuzzers call only the default route (edge-merge), and
// the CGAL routes take minutes to compile under the sanitizers. Reaching one is a bug of the
// fuzzer.
#include "internal.hpp"

#include <stdexcept>

namespace exact::detail
{

ExactResult hullOfDifferences(const Shape&, const Shape&, bool)
{
    throw std::logic_error("fuzz build: the hull-of-differences route is not built in");
}

ExactResult minkowskiSum2(const Shape&, const Shape&, bool)
{
    throw std::logic_error("fuzz build: the minkowski-sum-2 route is not built in");
}

} // namespace exact::detail
