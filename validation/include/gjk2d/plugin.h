/* gjk2d plugin ABI: how `gjk-validate --plugin PATH.so` loads a distance routine that is not
 * gjk2d's, and validates it against the exact truth (docs/validate-your-gjk.md).
 *
 * Plain C, no gjk2d header needed. A shared library exports one entry point,
 *
 *     const gjk2d_plugin* gjk2d_plugin_describe(void);
 *
 * returning a description that lives as long as the library (a static object). It describes one
 * or more implementations; each becomes a variant of the report, named by `name`.
 *
 * Versioning: `abi_version` is 1 or 2 (GJK2D_PLUGIN_ABI_MIN_VERSION .. GJK2D_PLUGIN_ABI_VERSION);
 * any other is refused (exit 2). Version 2 appends `contracts` to gjk2d_plugin (what each
 * implementation promises, below); a version-1 plugin loads as before and is held to gjk2d's own
 * contract. A change to a struct below increments the version; a new optional entry point, looked
 * up by name as the three below are, does not.
 *
 * The runner calls `distance_f` / `distance_d` in a child process (a crash or a hang costs one
 * case, never the campaign), one call at a time, never from two threads at once.
 */
#ifndef GJK2D_PLUGIN_H
#define GJK2D_PLUGIN_H

#include <stdint.h>

#ifdef __cplusplus
extern "C"
{
#endif

#define GJK2D_PLUGIN_ABI_VERSION 2
#define GJK2D_PLUGIN_ABI_MIN_VERSION 1
#define GJK2D_PLUGIN_ENTRY_POINT "gjk2d_plugin_describe"

/* Optional (the ABI version is unchanged: a plugin without it loads as before):
 *
 *     const char* gjk2d_plugin_library(void);
 *
 * the name and version of the library the plugin wraps, one line that lives as long as the
 * library, e.g. "Box2D 2.4.1 (Debian libbox2d-dev)". The report records it with the plugin's
 * variants (variants[].plugin.library; "" when the plugin does not export it). */
#define GJK2D_PLUGIN_LIBRARY_ENTRY "gjk2d_plugin_library"

/* Optional (the ABI version is unchanged: a plugin without it loads as before):
 *
 *     const gjk2d_timing* gjk2d_plugin_timing(void);
 *
 * the plugin's own timing loop, for `gjk-validate bench --against` (docs/plugin-abi.md,
 * "Optional exports"): the library timed the way its own benchmark would time it, over inputs it
 * prepared once in its own types, rather than call by call through distance_f/distance_d. The
 * runner calls prepare once, then pass once per timed pass (alternated with gjk2d's passes), then
 * release, all in one child process; the table lives as long as the library. */
#define GJK2D_PLUGIN_TIMING_ENTRY "gjk2d_plugin_timing"

/* Optional (the ABI version is unchanged: a plugin without it loads as before):
 *
 *     const gjk2d_prepared* gjk2d_plugin_prepared(void);
 *
 * shapes prepared once, as the library's users build them: its proxy, its FCL or Bullet object.
 * Where a plugin exports it, `run` and `bench` time its queries on prepared shapes (the query
 * alone: ns/query), and its preparation apart (ns per shape); the accuracy run answers each case
 * through prepare, distance and release too, so that what is judged is what is timed. Without it
 * the plugin is timed through distance_f/distance_d, and the report says that its figure includes
 * shape set-up. The table (below) lives as long as the library. */
#define GJK2D_PLUGIN_PREPARED_ENTRY "gjk2d_plugin_prepared"

/* Optional (the ABI version is unchanged: a plugin without it loads as before):
 *
 *     const gjk2d_depth_contract* gjk2d_plugin_depth(void);
 *
 * `count` depth clauses, one per implementation in the description's order: how close to the
 * exact penetration depth an implementation whose contract says GJK2D_OVERLAP_PENETRATION
 * promises its depth to be, and where the library says so. Without it (or with both tolerances
 * negative) the depth is held to gjk2d's depth bound for the scalar type, and the report says that
 * no tolerance is stated (docs/peers.md, "What each peer promises (its contract)"). */
#define GJK2D_PLUGIN_DEPTH_ENTRY "gjk2d_plugin_depth"

    /* The scalar type the implementation computes in: the runner gives it the case's inputs rounded
     * to that type and judges it against the exact truth of those rounded inputs. */
    enum gjk2d_scalar
    {
        GJK2D_SCALAR_FLOAT = 0,
        GJK2D_SCALAR_DOUBLE = 1
    };

    /* What the implementation accepts (bits of gjk2d_implementation.accepts). A case it does not
     * accept is counted as refused without calling it. */
    enum gjk2d_accepts
    {
        GJK2D_ACCEPTS_RADIUS = 1u << 0,    /* shapes with radius > 0 (rounded polygons, capsules) */
        GJK2D_ACCEPTS_WARM_START = 1u << 1 /* reads and updates `cache` (cache_bytes of it) */
    };

    /* The answer of one call. */
    enum gjk2d_status
    {
        GJK2D_STATUS_OK = 0,      /* distance and witness points are set */
        GJK2D_STATUS_REFUSED = 1, /* cannot take this case: counted as refused, not as a failure */
        GJK2D_STATUS_ERROR = 2 /* tried and failed: counted as an error (a failure when judged) */
    };

    /* A shape as the case gives it: `count` points (x0, y0, x1, y1, ...) in the shape's local
     * frame, a radius, and the transform to the world: world = R * local + position, with R = [[c,
     * -s], [s, c]] (rotation = {c, s}, given as the case's two numbers, not an angle). */
    typedef struct gjk2d_shape_f
    {
        const float* points;
        int32_t count;
        float radius;
        float position[2];
        float rotation[2];
    } gjk2d_shape_f;

    typedef struct gjk2d_shape_d
    {
        const double* points;
        int32_t count;
        double radius;
        double position[2];
        double rotation[2];
    } gjk2d_shape_d;

    /* The result: the distance between the two shapes (radii included, 0 when they overlap), the
     * witness points on A and on B in world coordinates, and the iteration count (-1: not known).
     */
    typedef struct gjk2d_result_f
    {
        float distance;
        float point_a[2];
        float point_b[2];
        int32_t iterations;
    } gjk2d_result_f;

    typedef struct gjk2d_result_d
    {
        double distance;
        double point_a[2];
        double point_b[2];
        int32_t iterations;
    } gjk2d_result_d;

    /* `cache` points to cache_bytes bytes, zeroed for a cold start (NULL when cache_bytes is 0).
     * Returns a gjk2d_status. */
    typedef int32_t (*gjk2d_distance_f_fn)(const gjk2d_shape_f* a, const gjk2d_shape_f* b,
                                           void* cache, gjk2d_result_f* out);
    typedef int32_t (*gjk2d_distance_d_fn)(const gjk2d_shape_d* a, const gjk2d_shape_d* b,
                                           void* cache, gjk2d_result_d* out);

    typedef struct gjk2d_implementation
    {
        const char* name;        /* the variant's name: [A-Za-z0-9._+-]{1,64}, unique in the run */
        const char* description; /* one line for the report, may be NULL */
        int32_t scalar;          /* a gjk2d_scalar */
        uint32_t accepts;        /* gjk2d_accepts bits */
        int32_t max_vertices;    /* largest point count of one shape it takes; 0: no limit */
        int32_t cache_bytes;     /* size of its warm-start cache, 0..4096 */
        gjk2d_distance_f_fn distance_f; /* set when scalar is GJK2D_SCALAR_FLOAT, else NULL */
        gjk2d_distance_d_fn distance_d; /* set when scalar is GJK2D_SCALAR_DOUBLE, else NULL */
    } gjk2d_implementation;

    /* What an implementation answers on overlapping shapes (gjk2d_contract.overlap). */
    enum gjk2d_overlap
    {
        /* A distance of 0 and both witness points at one point of both shapes (gjk2d). */
        GJK2D_OVERLAP_COMMON_POINT = 0,
        /* A distance of 0 or below; no witness points promised (FCL without signed distance). */
        GJK2D_OVERLAP_ZERO = 1,
        /* A distance of 0 and both points at one point midway between the shapes' cores: the
         * midpoint of the cores' closest points (Box2D 2.4.1 with radii; a common point of the
         * cores when they overlap). */
        GJK2D_OVERLAP_MIDPOINT = 2,
        /* A negative distance (minus the depth) and a penetration pair: each point on its own
         * shape, ||pA - pB|| = depth (Bullet, FCL with signed distance). */
        GJK2D_OVERLAP_PENETRATION = 3,
        /* A distance of 0; where the cores are apart (rounded shapes overlapping by their radii),
         * each point on its own shape's perimeter along the cores' closest points, so that
         * ||pA - pB|| = rA + rB - (the cores' distance), the exact penetration depth of the two
         * rounded shapes; where the cores meet, one common point (Box2D v3 with radii,
         * src/distance.c: "Keep closest points on perimeter even if overlapped"; Box2D 2.4.1
         * takes the midpoint). */
        GJK2D_OVERLAP_PERIMETER = 4
    };

    /* What an implementation promises, each clause with where the library says so ("source"):
     * its file and line or its documentation, and its version, e.g. "fcl/narrowphase/
     * distance_request.h:63, FCL 0.7.0". A clause the library does not state has a NULL or empty
     * source and says "none stated"; the runner then holds it to gjk2d's own bound for the
     * implementation's scalar type, and says so (docs/peers.md, "What each peer promises (its
     * contract)"). */
    typedef struct gjk2d_contract
    {
        /* The distance on separated shapes is within abs + rel * exact of the exact distance; a
         * claim of overlap on shapes at most that far apart keeps it too. Negative: none stated
         * (both negative: the tolerance is gjk2d's bound for the scalar type). */
        double distance_abs_tolerance;
        double distance_rel_tolerance;
        const char* tolerance_source;
        int32_t overlap; /* a gjk2d_overlap */
        const char* overlap_source;
        /* The skin the library keeps around each shape, as the plugin sets it (0: none); the
         * answers must still be the case's shapes'. */
        double margin;
        const char* margin_source;
    } gjk2d_contract;

    /* The optional depth clause (GJK2D_PLUGIN_DEPTH_ENTRY), one per implementation: on
     * overlapping shapes |depth - exact depth| <= abs + rel * exact depth. Negative: none stated.
     */
    typedef struct gjk2d_depth_contract
    {
        double abs_tolerance;
        double rel_tolerance;
        const char* source; /* file and line or documentation, and version; NULL: none stated */
    } gjk2d_depth_contract;
    typedef const gjk2d_depth_contract* (*gjk2d_plugin_depth_fn)(
        void); /* GJK2D_PLUGIN_DEPTH_ENTRY */

    typedef struct gjk2d_plugin
    {
        int32_t abi_version; /* 1 or 2: GJK2D_PLUGIN_ABI_MIN_VERSION .. GJK2D_PLUGIN_ABI_VERSION */
        int32_t count;       /* implementations, 1..64 */
        const gjk2d_implementation* implementations;
        /* Version 2 only (a version-1 plugin's struct ends above): `count` contracts, one per
         * implementation in the same order; NULL holds every implementation to gjk2d's own
         * contract, as version 1 does. */
        const gjk2d_contract* contracts;
    } gjk2d_plugin;

    typedef const gjk2d_plugin* (*gjk2d_plugin_describe_fn)(void);
    typedef const char* (*gjk2d_plugin_library_fn)(void); /* optional: GJK2D_PLUGIN_LIBRARY_ENTRY */

    /* The optional timing loop (GJK2D_PLUGIN_TIMING_ENTRY). */
    typedef struct gjk2d_timing
    {
        /* Prepares `count` cases for implementation `implementation` (its index in the
         * description): a[i] and b[i] are gjk2d_shape_f when it is a float implementation, else
         * gjk2d_shape_d, valid during this call only (copy what the loop needs). warm = 0: every
         * timed query starts cold; warm = 1: each case's query starts from the cache its previous
         * query of that case left (seeded by one query per case here, before any timing).
         * Returns the prepared state, or NULL when it cannot (for example warm = 1 and no cache).
         */
        void* (*prepare)(int32_t implementation, const void* a, const void* b, int32_t count,
                         int32_t warm);
        /* One timed pass: `reps` loops over all the prepared cases, in order. Returns the
         * nanoseconds they took on the plugin's own monotonic clock (nothing else timed), or a
         * negative number on failure. */
        double (*pass)(void* prepared, int32_t reps);
        void (*release)(void* prepared);
    } gjk2d_timing;
    typedef const gjk2d_timing* (*gjk2d_plugin_timing_fn)(void); /* GJK2D_PLUGIN_TIMING_ENTRY */

    /* What a prepared shape holds (gjk2d_prepared.scope). */
    enum gjk2d_prepared_scope
    {
        /* The shape in its own frame: the transform is given to each query, and the library takes
         * the case's (c, s) and position exactly (Box2D: b2Transform's q.c, q.s). One preparation
         * serves every query of that shape. */
        GJK2D_PREPARED_SHAPE = 0,
        /* The library cannot take the case's transform exactly (libccd turns a non-unit (c, s)
         * into a quaternion and loses its scale; the Bullet adapter bakes world points in), so
         * a prepared shape holds the case's world points: one preparation per case and shape, and
         * the query ignores the transforms it is given. The report says so. */
        GJK2D_PREPARED_CASE = 1
    };

    /* The optional prepared shapes (GJK2D_PLUGIN_PREPARED_ENTRY). `implementation` is the index
     * in the description; shapes are gjk2d_shape_f for a float implementation, else gjk2d_shape_d;
     * results gjk2d_result_f or gjk2d_result_d. */
    typedef struct gjk2d_prepared
    {
        /* GJK2D_PREPARED_SHAPE or GJK2D_PREPARED_CASE, for implementation `implementation`. */
        int32_t (*scope)(int32_t implementation);
        /* Builds the library's shape from `shape` (valid during this call only: copy what the
         * query needs). A GJK2D_PREPARED_SHAPE implementation reads points, count and radius,
         * and is given other = NULL. A GJK2D_PREPARED_CASE one reads the transform too, and is
         * given the case's other shape as `other`, for what the case fixes for both (the prism
         * reduction's common half-height, docs/peers.md). NULL when it cannot (the case is then
         * answered GJK2D_STATUS_ERROR). A shape the library does not take (too many points, a
         * radius it has no shape for) may still be prepared, and the query then answers
         * GJK2D_STATUS_REFUSED, as distance_f/distance_d does. */
        void* (*prepare)(int32_t implementation, const void* shape, const void* other);
        /* One query on two prepared shapes, as distance_f/distance_d answers it: `a` and `b` are
         * the case's shapes (a SCOPE_SHAPE implementation reads their transforms; the runner
         * keeps them valid during the call), `cache` as distance_f's, `out` the result. Returns a
         * gjk2d_status. Its answer must equal distance_f/distance_d's on the same case, bit for
         * bit (the shipped plugins' distance_d is prepare, distance, release). */
        int32_t (*distance)(int32_t implementation, const void* prepared_a, const void* a,
                            const void* prepared_b, const void* b, void* cache, void* out);
        void (*release)(int32_t implementation, void* prepared);
    } gjk2d_prepared;
    typedef const gjk2d_prepared* (*gjk2d_plugin_prepared_fn)(
        void); /* GJK2D_PLUGIN_PREPARED_ENTRY */

#if defined(_WIN32)
#define GJK2D_PLUGIN_EXPORT __declspec(dllexport)
#else
#define GJK2D_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
}
#endif

#endif /* GJK2D_PLUGIN_H */
