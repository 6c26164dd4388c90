// An example plugin (docs/validate-your-gjk.md): two implementations for gjk-validate to compare
// with gjk2d's own variants and with the exact truth. Each adapts the ABI's shapes to a GJK's own
// types, calls it, and copies its answer back. Here that GJK is gjk2d's header-only library (so
// that the example builds anywhere); in yours, the body of each function calls your routine.
//
//   example-gjk        double, the talk's reference options: it should match gjk2d's `double`
//   example-naive-f32  float, the naive search direction d = -P, which the talk warns is
//                      inaccurate on long edges: the report shows where it fails
#include <gjk2d/plugin.h>

#include <gjk2d/distance.hpp>

namespace
{

// ABI shape -> gjk::Polygon<T> + gjk::Transform<T>. The ABI's points are x0, y0, x1, y1, ...:
// gjk::Vec2<T> has that layout, so the array is used in place.
template <class T, class Shape> gjk::Polygon<T> polygonOf(const Shape& s)
{
    static_assert(sizeof(gjk::Vec2<T>) == 2 * sizeof(T));
    return {reinterpret_cast<const gjk::Vec2<T>*>(s.points), s.count, s.radius};
}

template <class T, class Shape> gjk::Transform<T> transformOf(const Shape& s)
{
    return {{s.position[0], s.position[1]}, {s.rotation[0], s.rotation[1]}};
}

template <class T, class Shape, class Result>
int32_t answer(const Shape* a, const Shape* b, Result* out, const gjk::Options& options)
{
    if (a->count < 1 || b->count < 1)
        return GJK2D_STATUS_REFUSED;
    const gjk::DistanceInput<T> in{polygonOf<T>(*a), polygonOf<T>(*b), transformOf<T>(*a),
                                   transformOf<T>(*b)};
    gjk::SimplexCache cache; // cold start
    const gjk::DistanceOutput<T> o = gjk::distance(in, cache, options);
    out->distance = o.distance;
    out->point_a[0] = o.pointA.x;
    out->point_a[1] = o.pointA.y;
    out->point_b[0] = o.pointB.x;
    out->point_b[1] = o.pointB.y;
    out->iterations = o.iterations;
    return GJK2D_STATUS_OK;
}

// [snippet: plugin-functions]
int32_t exampleGjk(const gjk2d_shape_d* a, const gjk2d_shape_d* b, void*, gjk2d_result_d* out)
{
    return answer<double>(a, b, out, gjk::referenceOptions);
}

int32_t exampleNaive(const gjk2d_shape_f* a, const gjk2d_shape_f* b, void*, gjk2d_result_f* out)
{
    return answer<float>(a, b, out, gjk::Options{.direction = gjk::SearchDirection::ClosestPoint});
}

// [end snippet]

// [snippet: plugin-description]
const gjk2d_implementation kImplementations[] = {
    // name, description, scalar, accepts, max_vertices (0: any), cache_bytes, distance_f,
    // distance_d
    {"example-gjk", "gjk2d's reference options behind the plugin ABI", GJK2D_SCALAR_DOUBLE,
     GJK2D_ACCEPTS_RADIUS, 0, 0, nullptr, &exampleGjk},
    {"example-naive-f32", "naive search direction d = -P in float", GJK2D_SCALAR_FLOAT,
     GJK2D_ACCEPTS_RADIUS, 0, 0, &exampleNaive, nullptr},
};

// contracts: nullptr holds both implementations to gjk2d's own (docs/plugin-abi.md).
const gjk2d_plugin kPlugin = {GJK2D_PLUGIN_ABI_VERSION, 2, kImplementations, nullptr};

} // namespace

// The one entry point gjk-validate looks for.
extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
{
    return &kPlugin;
}
// [end snippet]
