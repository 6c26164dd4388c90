// The Box2D 2.4.1 adapter (a shipped plugin, gjk2d/plugin.h, ABI version 2): Erin Catto's own
// b2Distance, the engine the talk describes, as a comparison variant "box2d-2.4.1" in every
// default report.
//
// Built against Debian's libbox2d-dev. What it takes, checked in Box2D 2.4.1's sources:
// - b2DistanceProxy::Set(vertices, count, radius) stores the pointer and the count, with no limit
//   (b2_maxPolygonVertices bounds b2PolygonShape, not this path);
// - b2SimplexCache stores the vertex indices in uint8 (indexA[3], indexB[3]): a shape of more than
//   256 points would have its indices wrapped, so the description says max_vertices = 256 and the
//   runner refuses larger cases without calling;
// - it computes in float; radii are handled with useRadii = true (distance minus both radii,
//   witness points moved onto the rounded surfaces; 0 and the midpoint when they overlap);
// - the warm start is the b2SimplexCache (count = 0: cold), given as the plugin's cache bytes.
//
// The contract (gjk2d_contract, kContract below), read in Box2D 2.4.1's sources (erincatto/box2d
// tag v2.4.1; Debian's libbox2d-dev 2.4.1 ships its headers unchanged):
// - overlap `midpoint`: with useRadii, when the cores' distance is at most rA + rB (or at most
//   b2_epsilon, radius 0 too), "Move the witness points to the middle": both points at
//   0.5 (pointA + pointB), distance 0 (src/collision/b2_distance.cpp:588-596);
// - tolerance: none stated (b2_distance.h documents none);
// - margin 0: a b2DistanceProxy built with Set(vertices, count, radius) has the case's radius
//   only (b2_polygonRadius belongs to b2PolygonShape, not this path).
//
// gjk-validate interposes b2Distance for its engine families (inputs/engine.cpp) and exports that
// symbol from the program, where this library's own reference to b2Distance would bind too. The
// adapter therefore calls libbox2d's definition, found once with dlsym on libbox2d's handle, so
// that its answers and its ns/query are Box2D's alone.
#include <gjk2d/plugin.h>

#include <box2d/b2_distance.h>

#include <dlfcn.h>

#include <cstring>

namespace
{

using B2DistanceFn = void (*)(b2DistanceOutput*, b2SimplexCache*, const b2DistanceInput*);

B2DistanceFn libraryB2Distance()
{
    static const B2DistanceFn fn = []
    {
        void* lib = ::dlopen("libbox2d.so.2", RTLD_NOW | RTLD_NOLOAD);
        void* sym =
            lib ? ::dlsym(lib,
                          "_Z10b2DistanceP16b2DistanceOutputP14b2SimplexCachePK15b2DistanceInput")
                : nullptr;
        return sym ? reinterpret_cast<B2DistanceFn>(sym) : static_cast<B2DistanceFn>(&::b2Distance);
    }();
    return fn;
}

// At most 256 points per shape: the adapter hands Box2D b2Vec2 arrays (the layout of x0, y0, ...).
static_assert(sizeof(b2Vec2) == 2 * sizeof(float));

b2Transform transformOf(const gjk2d_shape_f& s)
{
    b2Transform xf;
    xf.p.Set(s.position[0], s.position[1]);
    xf.q.c = s.rotation[0]; // the case's (c, s) as given, not recomputed from an angle
    xf.q.s = s.rotation[1];
    return xf;
}

int32_t box2dDistance(const gjk2d_shape_f* a, const gjk2d_shape_f* b, void* cache,
                      gjk2d_result_f* out)
{
    if (a->count < 1 || b->count < 1 || a->count > 256 || b->count > 256)
        return GJK2D_STATUS_REFUSED;
    b2DistanceInput in;
    in.proxyA.Set(reinterpret_cast<const b2Vec2*>(a->points), a->count, a->radius);
    in.proxyB.Set(reinterpret_cast<const b2Vec2*>(b->points), b->count, b->radius);
    in.transformA = transformOf(*a);
    in.transformB = transformOf(*b);
    in.useRadii = true;
    b2SimplexCache* c = static_cast<b2SimplexCache*>(cache); // zeroed: count 0, a cold start
    b2DistanceOutput o;
    libraryB2Distance()(&o, c, &in);
    out->distance = o.distance;
    out->point_a[0] = o.pointA.x;
    out->point_a[1] = o.pointA.y;
    out->point_b[0] = o.pointB.x;
    out->point_b[1] = o.pointB.y;
    out->iterations = o.iterations;
    return GJK2D_STATUS_OK;
}

const gjk2d_implementation kImplementations[] = {
    {"box2d-2.4.1", "Box2D 2.4.1 b2Distance (Debian libbox2d), cold start, useRadii",
     GJK2D_SCALAR_FLOAT, GJK2D_ACCEPTS_RADIUS | GJK2D_ACCEPTS_WARM_START, 256,
     int32_t(sizeof(b2SimplexCache)), &box2dDistance, nullptr},
};

const gjk2d_contract kContract = {
    -1,
    -1,
    "",
    GJK2D_OVERLAP_MIDPOINT,
    "src/collision/b2_distance.cpp:588-596 (useRadii: \"Shapes are overlapped when radii are "
    "considered. Move the witness points to the middle.\": both points 0.5 (pointA + pointB), "
    "distance 0), Box2D 2.4.1 (erincatto/box2d tag v2.4.1)",
    0,
    ""};

const gjk2d_plugin kPlugin = {GJK2D_PLUGIN_ABI_VERSION, 1, kImplementations, &kContract};

} // namespace

extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
{
    return &kPlugin;
}

// The library it wraps, for the report's context (the optional export of gjk2d/plugin.h).
extern "C" GJK2D_PLUGIN_EXPORT const char* gjk2d_plugin_library(void)
{
    return "Box2D 2.4.1 (Debian libbox2d-dev)";
}
