// A plugin with prepared shapes (gjk2d_plugin_prepared, gjk2d/plugin.h), for the test of the
// bridge's prepared path (tests/plugins/CMakeLists.txt, adapter_check.py --kind bridge-prepared).
// Two implementations of gjk2d's reference query in double, one per scope:
//   test-prepared-shape  GJK2D_PREPARED_SHAPE: a prepared shape holds the local points and the
//                        radius; the query takes the transforms from the case's shapes.
//   test-prepared-case   GJK2D_PREPARED_CASE: a prepared shape holds the world points (the
//                        case's transform applied in prepare); the query uses identity transforms.
// distance_d is prepare, distance, release, as plugin.h asks of a plugin with prepared shapes, so
// its answers and the prepared path's are the same bit for bit. A shape of exactly 7 points cannot
// be prepared (prepare returns NULL, distance_d answers GJK2D_STATUS_ERROR): the failure path.
#include <gjk2d/plugin.h>

#include <gjk2d/distance.hpp>

#include <vector>

namespace
{

struct Prepared
{
    std::vector<gjk::Vec2<double>> points;
    double radius = 0;
};

constexpr int32_t kUnpreparable = 7; // a shape of this many points: prepare returns NULL

int32_t scope(int32_t implementation)
{
    return implementation == 0 ? GJK2D_PREPARED_SHAPE : GJK2D_PREPARED_CASE;
}

void* prepare(int32_t implementation, const void* shape, const void*)
{
    const auto& s = *static_cast<const gjk2d_shape_d*>(shape);
    if (s.count == kUnpreparable)
        return nullptr;
    auto* p = new Prepared;
    p->radius = s.radius;
    const gjk::Transform<double> xf{{s.position[0], s.position[1]}, {s.rotation[0], s.rotation[1]}};
    for (int32_t k = 0; k < s.count; ++k)
    {
        const gjk::Vec2<double> local{s.points[2 * k], s.points[2 * k + 1]};
        p->points.push_back(
            scope(implementation) == GJK2D_PREPARED_SHAPE ? local : gjk::transformPoint(xf, local));
    }
    return p;
}

void release(int32_t, void* prepared)
{
    delete static_cast<Prepared*>(prepared);
}

int32_t distance(int32_t implementation, const void* preparedA, const void* a,
                 const void* preparedB, const void* b, void*, void* out)
{
    const auto& pa = *static_cast<const Prepared*>(preparedA);
    const auto& pb = *static_cast<const Prepared*>(preparedB);
    auto xf = [&](const void* shape)
    {
        const auto& s = *static_cast<const gjk2d_shape_d*>(shape);
        return scope(implementation) == GJK2D_PREPARED_SHAPE
                   ? gjk::Transform<double>{{s.position[0], s.position[1]},
                                            {s.rotation[0], s.rotation[1]}}
                   : gjk::Transform<double>{{0, 0}, {1, 0}};
    };
    const gjk::Polygon<double> polyA{pa.points.data(), int(pa.points.size()), pa.radius};
    const gjk::Polygon<double> polyB{pb.points.data(), int(pb.points.size()), pb.radius};
    gjk::SimplexCache cache;
    const auto o = gjk::distance(gjk::DistanceInput<double>{polyA, polyB, xf(a), xf(b)}, cache);
    auto* r = static_cast<gjk2d_result_d*>(out);
    r->distance = o.distance;
    r->point_a[0] = o.pointA.x;
    r->point_a[1] = o.pointA.y;
    r->point_b[0] = o.pointB.x;
    r->point_b[1] = o.pointB.y;
    r->iterations = o.iterations;
    return GJK2D_STATUS_OK;
}

// distance_d: prepare, distance, release.
template <int32_t Implementation>
int32_t distanceD(const gjk2d_shape_d* a, const gjk2d_shape_d* b, void* cache, gjk2d_result_d* out)
{
    const bool perCase = scope(Implementation) == GJK2D_PREPARED_CASE;
    void* pa = prepare(Implementation, a, perCase ? b : nullptr);
    void* pb = prepare(Implementation, b, perCase ? a : nullptr);
    const int32_t status =
        pa && pb ? distance(Implementation, pa, a, pb, b, cache, out) : int32_t(GJK2D_STATUS_ERROR);
    if (pa)
        release(Implementation, pa);
    if (pb)
        release(Implementation, pb);
    return status;
}

const gjk2d_implementation kImplementations[] = {
    {"test-prepared-shape", "a test plugin with prepared shapes, scope shape (tests/plugins)",
     GJK2D_SCALAR_DOUBLE, GJK2D_ACCEPTS_RADIUS, 0, 0, nullptr, &distanceD<0>},
    {"test-prepared-case", "a test plugin with prepared shapes, scope case (tests/plugins)",
     GJK2D_SCALAR_DOUBLE, GJK2D_ACCEPTS_RADIUS, 0, 0, nullptr, &distanceD<1>},
};

const gjk2d_plugin kPlugin = {GJK2D_PLUGIN_ABI_VERSION, 2, kImplementations, nullptr};

const gjk2d_prepared kPrepared = {&scope, &prepare, &distance, &release};

} // namespace

extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
{
    return &kPlugin;
}

extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_prepared* gjk2d_plugin_prepared(void)
{
    return &kPrepared;
}
