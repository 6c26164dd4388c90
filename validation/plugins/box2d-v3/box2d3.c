/* The Box2D v3 adapter (a shipped plugin, gjk2d/plugin.h, ABI version 2): b2ShapeDistance, the GJK
 * of Erin Catto's current engine, compiled from the Box2D v3 source tree GJK2D_BOX2D3_SOURCE names
 * (validation/plugins/box2d-v3/CMakeLists.txt; docs/peers/box2d3.md).
 *
 * Called as Box2D calls itself (b2TimeOfImpact in its src/distance.c; the anchors'
 * harness_box2d.c): float proxies from b2MakeProxy in each shape's local frame, world transforms
 * from the case's position and (c, s) as given (not renormalised), input.transform =
 * b2InvMulTransforms(xfA, xfB) (B in A's frame), useRadii = true, a zeroed b2SimplexCache (cold),
 * no simplex capture. b2ShapeDistance answers in A's frame; its points are mapped to world with
 * b2TransformPoint(xfA, .), in float.
 *
 * Shapes prepared once (gjk2d_plugin_prepared, scope `shape`): a prepared shape is its
 * b2ShapeProxy; a query is what a Box2D v3 user pays on two kept proxies: the b2DistanceInput
 * (proxies copied in, b2InvMulTransforms), the zeroed cache, b2ShapeDistance and the two points
 * mapped to world. distance_f is prepare, query, release, so that the two forms answer alike, bit
 * for bit.
 *
 * What it takes: float; radii (rounded polygons, capsules, circles). What it refuses: a shape of
 * more than B2_MAX_POLYGON_VERTICES (8) points, because b2ShapeProxy holds 8 points and
 * b2MakeProxy silently keeps the first 8: the description says max_vertices = 8, so the runner
 * refuses such a case without calling (the check below repeats it for a direct caller). It adds
 * nothing to Box2D's answer and drops nothing: the test "plugins: box2d-v3: the adapter's answers
 * equal b2ShapeDistance called directly" compares every case of the default families bit for bit
 * with validation/plugins/box2d-v3/tests/direct.c.
 *
 * The contract (gjk2d_contract, kContract below), read in src/distance.c and
 * include/box2d/collision.h at erincatto/box2d 617d32ab (b2GetVersion 3.2.0), the anchors' tree:
 * - overlap `perimeter`: where the cores overlap, b2ShapeDistance returns early with distance 0 and
 *   the simplex's witness points, one common point of the cores (distance.c:497-508, and :518-534
 *   when the search direction vanishes); where only the rounded shapes overlap, "Keep closest
 * points on perimeter even if overlapped, this way the points move smoothly": distance max(0, d -
 * rA - rB), each point moved by its radius along the cores' normal (distance.c:598-608);
 * collision.h:404, distance "zero if overlapped";
 * - tolerance: none stated;
 * - margin 0: a b2ShapeProxy from b2MakeProxy has the case's radius only.
 *
 * Findings (docs/peers/box2d3.md, with the command): its distances leave gjk2d's bound only
 * at the ends of the float range (hard/tiny-scale, hard/extreme-scale, hard/range). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <gjk2d/plugin.h>

#include "box2d/collision.h"
#include "box2d/math_functions.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

static b2Transform transformOf(const gjk2d_shape_f* s)
{
    b2Transform xf;
    xf.p.x = s->position[0];
    xf.p.y = s->position[1];
    xf.q.c = s->rotation[0]; /* the case's (c, s) as given */
    xf.q.s = s->rotation[1];
    return xf;
}

static b2ShapeProxy proxyOf(const gjk2d_shape_f* s)
{
    b2Vec2 pts[B2_MAX_POLYGON_VERTICES];
    for (int i = 0; i < s->count; ++i)
    {
        pts[i].x = s->points[2 * i];
        pts[i].y = s->points[2 * i + 1];
    }
    return b2MakeProxy(pts, s->count, s->radius);
}

static int refusedShape(const gjk2d_shape_f* s)
{
    return s->count < 1 || s->count > B2_MAX_POLYGON_VERTICES;
}

static int refused(const gjk2d_shape_f* a, const gjk2d_shape_f* b)
{
    return refusedShape(a) || refusedShape(b);
}

/* The query's input, as Box2D builds it (b2TimeOfImpact in its src/distance.c): zeroed, the two
 * proxies, B in A's frame. */
static b2DistanceInput inputOf(const b2ShapeProxy* proxyA, const b2ShapeProxy* proxyB,
                               b2Transform xfA, b2Transform xfB)
{
    b2DistanceInput in = {0};
    in.proxyA = *proxyA;
    in.proxyB = *proxyB;
    in.transform = b2InvMulTransforms(xfA, xfB);
    in.useRadii = true;
    return in;
}

/* A prepared shape (gjk2d_prepared, scope GJK2D_PREPARED_SHAPE): its b2ShapeProxy, made once by
 * b2MakeProxy in the shape's own frame, as a Box2D v3 user keeps a shape's proxy. The scope is the
 * shape's because Box2D takes the case's transform exactly (b2Transform's p and q.c, q.s are the
 * case's floats, set directly by transformOf), so one proxy serves every pose of the shape. A shape
 * b2MakeProxy cannot hold (no point, more than 8) is kept as refused, so that the query answers
 * GJK2D_STATUS_REFUSED as distance_f does. */
typedef struct
{
    b2ShapeProxy proxy;
    int refused;
} PreparedShape;

/* Prepared shapes live in a pool, as an engine keeps its shapes (Box2D v3's world holds them in
 * arrays): blocks of kPoolBlock, handed out in order, released ones reused first. Shapes
 * prepared one after another sit side by side in memory, as they would in the engine's arrays,
 * rather than wherever the allocator puts each one. */
enum
{
    kPoolBlock = 4096
};
typedef union PoolSlot
{
    PreparedShape shape;
    union PoolSlot* next; /* when free */
} PoolSlot;
typedef struct PoolBlock
{
    struct PoolBlock* previous;
    PoolSlot slots[kPoolBlock];
} PoolBlock;
static PoolBlock* g_poolBlocks = NULL;
static int32_t g_poolUsed = kPoolBlock; /* slots handed out of the newest block */
static PoolSlot* g_poolFree = NULL;

static PreparedShape* poolTake(void)
{
    if (g_poolFree != NULL)
    {
        PoolSlot* s = g_poolFree;
        g_poolFree = s->next;
        return &s->shape;
    }
    if (g_poolUsed == kPoolBlock)
    {
        PoolBlock* b = (PoolBlock*)malloc(sizeof *b);
        if (b == NULL)
            return NULL;
        b->previous = g_poolBlocks;
        g_poolBlocks = b;
        g_poolUsed = 0;
    }
    return &g_poolBlocks->slots[g_poolUsed++].shape;
}

static void poolGive(PreparedShape* p)
{
    PoolSlot* s = (PoolSlot*)p;
    s->next = g_poolFree;
    g_poolFree = s;
}

static void* preparedPrepare(int32_t implementation, const void* shape, const void* other)
{
    (void)other; /* scope shape: given NULL */
    const gjk2d_shape_f* s = (const gjk2d_shape_f*)shape;
    if (implementation != 0)
        return NULL;
    PreparedShape* p = poolTake();
    if (p == NULL)
        return NULL;
    p->refused = refusedShape(s);
    if (!p->refused)
        p->proxy = proxyOf(s);
    return p;
}

static void preparedRelease(int32_t implementation, void* prepared)
{
    (void)implementation;
    if (prepared != NULL)
        poolGive((PreparedShape*)prepared);
}

/* A kept proxy copied into a query's input: its count, radius and the points it holds
 * (b2ShapeDistance reads points[0 .. count) only), not all B2_MAX_POLYGON_VERTICES slots. */
static void keptProxyInto(b2ShapeProxy* to, const b2ShapeProxy* from)
{
    to->count = from->count;
    to->radius = from->radius;
    memcpy(to->points, from->points, (size_t)from->count * sizeof from->points[0]);
}

/* The query, what a Box2D v3 user pays for one on two kept proxies: the b2DistanceInput (the
 * proxies copied in, b2InvMulTransforms of the case's two transforms), a zeroed b2SimplexCache,
 * b2ShapeDistance, and its frame-A points mapped to world with b2TransformPoint(xfA, .). */
static int32_t preparedDistance(int32_t implementation, const void* preparedA, const void* a,
                                const void* preparedB, const void* b, void* cache, void* result)
{
    (void)implementation;
    (void)cache; /* cache_bytes 0: every call is cold */
    const PreparedShape* pa = (const PreparedShape*)preparedA;
    const PreparedShape* pb = (const PreparedShape*)preparedB;
    if (pa->refused || pb->refused)
        return GJK2D_STATUS_REFUSED;
    const b2Transform xfA = transformOf((const gjk2d_shape_f*)a);
    const b2Transform xfB = transformOf((const gjk2d_shape_f*)b);
    b2DistanceInput in; /* as inputOf builds it, the proxies' unused points left out */
    keptProxyInto(&in.proxyA, &pa->proxy);
    keptProxyInto(&in.proxyB, &pb->proxy);
    in.transform = b2InvMulTransforms(xfA, xfB);
    in.useRadii = true;
    b2SimplexCache simplexCache = {0};
    const b2DistanceOutput o = b2ShapeDistance(&in, &simplexCache, NULL, 0);
    const b2Vec2 wa = b2TransformPoint(xfA, o.pointA), wb = b2TransformPoint(xfA, o.pointB);
    gjk2d_result_f* out = (gjk2d_result_f*)result;
    out->distance = o.distance;
    out->point_a[0] = wa.x;
    out->point_a[1] = wa.y;
    out->point_b[0] = wb.x;
    out->point_b[1] = wb.y;
    out->iterations = o.iterations;
    return GJK2D_STATUS_OK;
}

static int32_t preparedScope(int32_t implementation)
{
    (void)implementation;
    return GJK2D_PREPARED_SHAPE;
}

static const gjk2d_prepared kPrepared = {&preparedScope, &preparedPrepare, &preparedDistance,
                                         &preparedRelease};

/* distance_f is the prepared form on one case: prepare both shapes, query, release. */
static int32_t box2d3Distance(const gjk2d_shape_f* a, const gjk2d_shape_f* b, void* cache,
                              gjk2d_result_f* out)
{
    void* pa = preparedPrepare(0, a, NULL);
    void* pb = preparedPrepare(0, b, NULL);
    const int32_t status = pa != NULL && pb != NULL ? preparedDistance(0, pa, a, pb, b, cache, out)
                                                    : GJK2D_STATUS_ERROR;
    preparedRelease(0, pa);
    preparedRelease(0, pb);
    return status;
}

static const gjk2d_implementation kImplementations[] = {
    {GJK2D_BOX2D3_NAME,
     "Box2D v3 b2ShapeDistance (" GJK2D_BOX2D3_LIBRARY "), float, cold start, useRadii",
     GJK2D_SCALAR_FLOAT, GJK2D_ACCEPTS_RADIUS, B2_MAX_POLYGON_VERTICES, 0, &box2d3Distance, NULL},
};

/* The timing loop (gjk2d/plugin.h, gjk2d_plugin_timing), as the anchors' harness_box2d.c times
 * b2ShapeDistance: the b2DistanceInputs built once (above), then only the calls are timed; cold, a
 * zeroed b2SimplexCache per query; warm, each case's own cache, seeded by one query and rewritten
 * by every query after it (the harness's "reuses its own cache from the previous pass"). The
 * outputs are summed as the harness sums them, so that no call can be optimised away. */
typedef struct
{
    b2DistanceInput* inputs;
    b2SimplexCache* caches; /* warm only */
    int32_t count;
    volatile double sink;
} TimedCases;

static void* timingPrepare(int32_t implementation, const void* a, const void* b, int32_t count,
                           int32_t warm)
{
    const gjk2d_shape_f* sa = (const gjk2d_shape_f*)a;
    const gjk2d_shape_f* sb = (const gjk2d_shape_f*)b;
    if (implementation != 0 || count < 0)
        return NULL;
    TimedCases* t = (TimedCases*)calloc(1, sizeof *t);
    if (t == NULL)
        return NULL;
    t->inputs = (b2DistanceInput*)calloc((size_t)count + 1, sizeof(b2DistanceInput));
    t->caches = warm ? (b2SimplexCache*)calloc((size_t)count + 1, sizeof(b2SimplexCache)) : NULL;
    if (t->inputs == NULL || (warm && t->caches == NULL))
    {
        free(t->inputs);
        free(t->caches);
        free(t);
        return NULL;
    }
    for (int32_t i = 0; i < count; ++i)
    {
        if (refused(&sa[i], &sb[i])) /* the runner leaves such cases out (max_vertices) */
            continue;
        const b2ShapeProxy proxyA = proxyOf(&sa[i]), proxyB = proxyOf(&sb[i]);
        t->inputs[t->count] = inputOf(&proxyA, &proxyB, transformOf(&sa[i]), transformOf(&sb[i]));
        if (warm)
            b2ShapeDistance(&t->inputs[t->count], &t->caches[t->count], NULL, 0);
        t->count += 1;
    }
    return t;
}

static double nowNs(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static double timingPass(void* prepared, int32_t reps)
{
    TimedCases* t = (TimedCases*)prepared;
    double sum = 0.0;
    const double t0 = nowNs();
    if (t->caches == NULL) /* the harness's pass_cold */
        for (int32_t r = 0; r < reps; ++r)
            for (int32_t i = 0; i < t->count; ++i)
            {
                b2SimplexCache cache = {0};
                b2DistanceOutput o = b2ShapeDistance(&t->inputs[i], &cache, NULL, 0);
                sum += o.distance + o.pointA.x + o.iterations;
            }
    else /* its pass_warm */
        for (int32_t r = 0; r < reps; ++r)
            for (int32_t i = 0; i < t->count; ++i)
            {
                b2DistanceOutput o = b2ShapeDistance(&t->inputs[i], &t->caches[i], NULL, 0);
                sum += o.distance + o.pointA.x + o.iterations;
            }
    const double t1 = nowNs();
    t->sink = t->sink + sum;
    return t1 - t0;
}

static void timingRelease(void* prepared)
{
    TimedCases* t = (TimedCases*)prepared;
    if (t == NULL)
        return;
    free(t->inputs);
    free(t->caches);
    free(t);
}

static const gjk2d_timing kTiming = {&timingPrepare, &timingPass, &timingRelease};

static const gjk2d_contract kContract = {
    -1,
    -1,
    "",
    GJK2D_OVERLAP_PERIMETER,
    "src/distance.c:497-508, 518-534 (cores overlapping: distance 0, one common point), 598-608 "
    "(useRadii: \"Keep closest points on perimeter even if overlapped\"), "
    "include/box2d/collision.h:404, read at erincatto/box2d 617d32ab; this "
    "build: " GJK2D_BOX2D3_LIBRARY,
    0,
    ""};

static const gjk2d_plugin kPlugin = {GJK2D_PLUGIN_ABI_VERSION, 1, kImplementations, &kContract};

GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
{
    return &kPlugin;
}

/* The library it wraps, for the report's context (the optional export of gjk2d/plugin.h). */
GJK2D_PLUGIN_EXPORT const char* gjk2d_plugin_library(void)
{
    return GJK2D_BOX2D3_LIBRARY;
}

/* Its own timing loop, for `gjk-validate bench --against box2d-v3` (the optional export of
 * gjk2d/plugin.h). */
GJK2D_PLUGIN_EXPORT const gjk2d_timing* gjk2d_plugin_timing(void)
{
    return &kTiming;
}

/* Shapes prepared once (the optional export of gjk2d/plugin.h): the b2ShapeProxy of each shape. */
GJK2D_PLUGIN_EXPORT const gjk2d_prepared* gjk2d_plugin_prepared(void)
{
    return &kPrepared;
}
