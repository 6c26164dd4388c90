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
// - the warm start is the b2SimplexCache (count = 0: cold), given as the plugin's cache bytes;
// - shapes prepared once (gjk2d_plugin_prepared, scope `shape`): a prepared shape is its points
//   copied and its b2DistanceProxy, in its own frame; a query builds the b2DistanceInput from two
//   proxies and the case's transforms and calls b2Distance. distance_f is prepare, query, release,
//   so that the two forms answer alike, bit for bit.
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

#include <new>
#include <vector>

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

b2Transform transformOf(const gjk2d_shape_f& s)
{
    b2Transform xf;
    xf.p.Set(s.position[0], s.position[1]);
    xf.q.c = s.rotation[0]; // the case's (c, s) as given, not recomputed from an angle
    xf.q.s = s.rotation[1];
    return xf;
}

// A prepared shape (gjk2d_prepared, scope GJK2D_PREPARED_SHAPE): its points copied once, in its own
// frame, and the b2DistanceProxy over them, as a Box2D 2.4.1 user keeps a shape's proxy
// (b2DistanceProxy::Set stores the pointer: "The vertices must remain in scope while the proxy is
// in use"). The scope is the shape's because Box2D takes the case's transform exactly:
// b2Transform's p and q.c, q.s are the case's floats, set directly (transformOf), so one proxy
// serves every pose of the shape. Up to b2_maxPolygonVertices (8) points are held in the prepared
// shape itself, as b2PolygonShape holds its vertices, larger shapes in a vector of their own. A
// shape Box2D cannot take (no point, more than 256) is kept as refused, so that the query answers
// GJK2D_STATUS_REFUSED as distance_f does.
struct Prepared
{
    b2DistanceProxy proxy;
    bool refused = false;
    b2Vec2 few[b2_maxPolygonVertices];
    std::vector<b2Vec2> many;
};

void* prepare(int32_t implementation, const void* shape, const void* /*other*/)
{
    if (implementation != 0)
        return nullptr;
    const auto& s = *static_cast<const gjk2d_shape_f*>(shape);
    auto* p = new (std::nothrow) Prepared;
    if (p == nullptr)
        return nullptr;
    p->refused = s.count < 1 || s.count > 256;
    if (!p->refused)
    {
        if (s.count > b2_maxPolygonVertices)
            p->many.resize(std::size_t(s.count));
        b2Vec2* points = s.count > b2_maxPolygonVertices ? p->many.data() : p->few;
        for (int32_t i = 0; i < s.count; ++i)
            points[i].Set(s.points[2 * i], s.points[2 * i + 1]);
        p->proxy.Set(points, s.count, s.radius);
    }
    return p;
}

void release(int32_t /*implementation*/, void* prepared)
{
    delete static_cast<Prepared*>(prepared);
}

// The query, what a Box2D 2.4.1 user pays for one: the b2DistanceInput from the two kept proxies
// and the case's transforms, useRadii, b2Distance with the given b2SimplexCache (zeroed: count 0,
// a cold start), the output copied out.
int32_t distance(int32_t /*implementation*/, const void* preparedA, const void* a,
                 const void* preparedB, const void* b, void* cache, void* result)
{
    const auto& pa = *static_cast<const Prepared*>(preparedA);
    const auto& pb = *static_cast<const Prepared*>(preparedB);
    if (pa.refused || pb.refused)
        return GJK2D_STATUS_REFUSED;
    b2DistanceInput in;
    in.proxyA = pa.proxy;
    in.proxyB = pb.proxy;
    in.transformA = transformOf(*static_cast<const gjk2d_shape_f*>(a));
    in.transformB = transformOf(*static_cast<const gjk2d_shape_f*>(b));
    in.useRadii = true;
    b2DistanceOutput o;
    libraryB2Distance()(&o, static_cast<b2SimplexCache*>(cache), &in);
    auto* out = static_cast<gjk2d_result_f*>(result);
    out->distance = o.distance;
    out->point_a[0] = o.pointA.x;
    out->point_a[1] = o.pointA.y;
    out->point_b[0] = o.pointB.x;
    out->point_b[1] = o.pointB.y;
    out->iterations = o.iterations;
    return GJK2D_STATUS_OK;
}

int32_t scope(int32_t /*implementation*/)
{
    return GJK2D_PREPARED_SHAPE;
}

// distance_f is the prepared form on one case: prepare both shapes, query, release.
int32_t box2dDistance(const gjk2d_shape_f* a, const gjk2d_shape_f* b, void* cache,
                      gjk2d_result_f* out)
{
    void* pa = prepare(0, a, nullptr);
    void* pb = prepare(0, b, nullptr);
    const int32_t status = pa && pb ? distance(0, pa, a, pb, b, cache, out) : GJK2D_STATUS_ERROR;
    release(0, pa);
    release(0, pb);
    return status;
}

const gjk2d_prepared kPrepared = {&scope, &prepare, &distance, &release};

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

// Shapes prepared once (the optional export of gjk2d/plugin.h): the b2DistanceProxy of each shape.
extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_prepared* gjk2d_plugin_prepared(void)
{
    return &kPrepared;
}
