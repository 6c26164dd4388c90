// Route MinkowskiSum2: CGAL::convex_hull_2 of each transformed point set, then
// Z = CGAL::minkowski_sum_2(hull(A), hull(-B)) (reduced convolution on Polygon_2), then the shared
// closest-feature step. minkowski_sum_2 needs simple polygons, so when either hull is a point or a
// segment, Z is the convex hull of the (at most 2n or 2m) pairwise vertex differences instead.
//
// CGAL 5.5's arrangement code crashes (segfault in Arr_segment_traits_2::Intersect_2) when the
// lazy kernel's interval approximations overflow, e.g. for coordinates near 1e300. So the polygons
// handed to minkowski_sum_2 are first scaled by a power of two (exact) to magnitudes near 1; the
// closest feature is located on the scaled Z (all predicates are scale invariant) and the exact
// result is constructed from the unscaled points.
#include "cgal_common.hpp"

#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/minkowski_sum_2.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>

namespace exact::detail
{
namespace
{

using namespace cg;

// Approximate binary exponent of the largest transformed coordinate (from the input doubles).
int magnitude(const Shape& s, int current)
{
    auto lg = [](double v) { return v == 0 ? INT_MIN / 4 : std::ilogb(v); };
    for (const Point& p : s.points)
    {
        current = std::max(
            {current, lg(s.c) + lg(p.x), lg(s.s) + lg(p.y), lg(s.s) + lg(p.x), lg(s.c) + lg(p.y)});
    }
    return std::max({current, lg(s.px), lg(s.py)});
}

FT scaled(FT v, int e)
{ // v * 2^e, exactly, in steps a double can hold
    while (e != 0)
    {
        const int step = std::clamp(e, -1000, 1000);
        v = v * FT(std::ldexp(1.0, step));
        e -= step;
    }
    return v;
}

std::vector<std::size_t> hullIndices(const std::vector<P2>& pts)
{
    std::vector<std::size_t> idx(pts.size()), out;
    std::iota(idx.begin(), idx.end(), std::size_t(0));
    using Traits =
        CGAL::Convex_hull_traits_adapter_2<K, CGAL::Pointer_property_map<P2>::const_type>;
    CGAL::convex_hull_2(idx.begin(), idx.end(), std::back_inserter(out),
                        Traits(CGAL::make_property_map(pts)));
    return out;
}

// The vertices of Z = hull(A) - hull(B): CGAL's minkowski_sum_2 of hull(A) and -hull(B) when both
// are polygons, the hull of the pairwise differences otherwise (a point or a segment).
std::vector<P2> minkowskiVertices(const std::vector<P2>& as, const std::vector<P2>& bs,
                                  const std::vector<std::size_t>& ha,
                                  const std::vector<std::size_t>& hb)
{
    std::vector<P2> z;
    if (ha.size() >= 3 && hb.size() >= 3)
    {
        CGAL::Polygon_2<K> pa, pnb;
        for (std::size_t i : ha)
            pa.push_back(as[i]);
        for (std::size_t j : hb)
            pnb.push_back(P2(-bs[j].x(), -bs[j].y())); // point reflection keeps ccw order
        const CGAL::Polygon_with_holes_2<K> sum = CGAL::minkowski_sum_2(pa, pnb);
        const CGAL::Polygon_2<K>& outer = sum.outer_boundary();
        std::vector<P2> raw(outer.vertices_begin(), outer.vertices_end());
        // The convolution may leave vertices in the middle of an edge: keep the corners only, so
        // that every vertex is the difference of a unique pair of hull vertices.
        const std::size_t k = raw.size();
        for (std::size_t t = 0; t < k; ++t)
            if (!CGAL::collinear(raw[(t + k - 1) % k], raw[t], raw[(t + 1) % k]))
                z.push_back(raw[t]);
    }
    else
    {
        std::vector<P2> diff;
        for (std::size_t i : ha)
            for (std::size_t j : hb)
                diff.push_back(as[i] - (bs[j] - CGAL::ORIGIN));
        CGAL::convex_hull_2(diff.begin(), diff.end(), std::back_inserter(z), K());
    }
    return z;
}

} // namespace

ExactResult minkowskiSum2(const Shape& sa, const Shape& sb, bool wantPolygon)
{
    const std::vector<P2> a = transformAll(sa), b = transformAll(sb);
    const int mag = magnitude(sb, magnitude(sa, INT_MIN / 4));
    const bool rescale = mag > 200 || (mag < -200 && mag > INT_MIN / 8);
    std::vector<P2> as = a, bs = b; // the points minkowski_sum_2 sees
    if (rescale)
    {
        for (auto* v : {&as, &bs})
            for (P2& p : *v)
                p = P2(scaled(p.x(), -mag), scaled(p.y(), -mag));
    }
    const std::vector<std::size_t> ha = hullIndices(as), hb = hullIndices(bs);

    std::vector<P2> z = minkowskiVertices(as, bs, ha, hb);
    startAtLargestXY(z, [](const P2& p) -> const P2& { return p; });

    // Provenance of a Z vertex v: the hull vertex q of B for which v + q is a hull vertex of A.
    std::vector<std::size_t> sortedA = ha;
    const K::Less_xy_2 less;
    std::sort(sortedA.begin(), sortedA.end(),
              [&](std::size_t i, std::size_t j) { return less(as[i], as[j]); });
    return solve(
        z,
        [&](int k, P2& pa, P2& pb)
        {
            const P2& v = z[k];
            for (std::size_t j : hb)
            {
                const P2 cand = bs[j] + (v - CGAL::ORIGIN);
                auto it =
                    std::lower_bound(sortedA.begin(), sortedA.end(), cand,
                                     [&](std::size_t i, const P2& c) { return less(as[i], c); });
                if (it != sortedA.end() && as[*it] == cand)
                {
                    pa = a[*it]; // unscaled
                    pb = b[j];
                    return;
                }
            }
            throw std::logic_error("exact: minkowski-sum-2 vertex without a vertex pair");
        },
        wantPolygon);
}

} // namespace exact::detail
