// Route HullOfDifferences: every difference a_i - b_j of the transformed points,
// CGAL::convex_hull_2 of those n*m points gives Z = hull(A) - hull(B) directly; then the shared
// closest-feature step. O(nm log nm): the reference construction, slow for large inputs.
#include "cgal_common.hpp"

#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/property_map.h>

#include <numeric>

namespace exact::detail
{

ExactResult hullOfDifferences(const Shape& sa, const Shape& sb, bool wantPolygon)
{
    using namespace cg;
    const std::vector<P2> a = transformAll(sa), b = transformAll(sb);
    const std::size_t n = a.size(), m = b.size();
    std::vector<P2> diff;
    diff.reserve(n * m);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < m; ++j)
            diff.push_back(a[i] - (b[j] - CGAL::ORIGIN));
    // Hull over indices (index = i*m + j keeps the provenance of every hull vertex).
    std::vector<std::size_t> idx(diff.size());
    std::iota(idx.begin(), idx.end(), std::size_t(0));
    using Traits = CGAL::Convex_hull_traits_adapter_2<K, CGAL::Pointer_property_map<P2>::type>;
    std::vector<std::size_t> hull;
    CGAL::convex_hull_2(idx.begin(), idx.end(), std::back_inserter(hull),
                        Traits(CGAL::make_property_map(diff)));
    startAtLargestXY(hull, [&](std::size_t k) -> const P2& { return diff[k]; });
    std::vector<P2> z;
    z.reserve(hull.size());
    for (std::size_t k : hull)
        z.push_back(diff[k]);
    return solve(
        z,
        [&](int k, P2& pa, P2& pb)
        {
            pa = a[hull[k] / m];
            pb = b[hull[k] % m];
        },
        wantPolygon);
}

} // namespace exact::detail
