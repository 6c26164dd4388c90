// The Bullet 3.24 adapter (a shipped peer, gjk2d/plugin.h, ABI version 2): btGjkPairDetector
// between two prisms, as Bullet's collision pipeline runs it for a pair of convex shapes: a
// btVoronoiSimplexSolver for GJK, a btGjkEpaPenetrationDepthSolver for overlapping cores. One
// source, two modules built against Debian's libbullet-dev: gjk2d-bullet-float.so
// ("bullet-3.24-float", btScalar = float, `pkg-config bullet`) and gjk2d-bullet-double.so
// ("bullet-3.24-double", BT_USE_DOUBLE_PRECISION, `pkg-config bullet-float64`).
// docs/peers/bullet.md.
//
// The 2D case as a 3D one (docs/peers/prisms.md): a shape of points P becomes the
// prism P x [-h, h], the same h for both shapes, chosen per case (prismHalfHeight, below), a
// btConvexHullShape of its 2n vertices (any order: Bullet's support scans them, the shape is their
// hull). The case's radius is the shape's collision margin, setMargin(r), also for r = 0:
// btGjkPairDetector runs GJK on the margin-less hulls and subtracts both margins from the
// distance, so a margin is an exact radius (the prism swept by a ball of radius r). Every case is
// taken: points, segments and polygons, with or without radius.
// - Transforms: the adapter applies the case's transform to the points itself, world = R * local +
//   p in btScalar with R = [[c, -s], [s, c]] from the case's (c, s) as given, and hands Bullet
//   identity transforms (the FCL adapter does the same; one construction for both peers).
// - The simplex solver is built in zeroed storage (Zeroed, below): Bullet reads members its
//   constructor leaves unwritten on degenerate paths, and an answer must not depend on what ran
//   before it in the process.
// - Shapes prepared once (gjk2d_plugin_prepared, scope `case`): a prepared shape is its
//   btConvexHullShape, built from the case's world points with the case's half height; a query
//   is the pair detector on two hulls, as below. distance_f / distance_d is prepare, query,
//   release, so that the two forms answer alike, bit for bit.
// - Defaults kept as Bullet's users run them: the simplex solver's equal-vertex threshold
//   (VORONOI_DEFAULT_EQUAL_VERTEX_THRESHOLD: 1e-4 in float, 1e-12 in double), the pair
//   detector's tolerances, no maximum distance (BT_LARGE_FLOAT).
// - The answer, as Bullet gives it: its btPointCollector holds the distance (negative: the
//   penetration depth, answered by EPA when the cores overlap), the normal on B and the point on
//   B; the point on A is pointOnB + normal * distance (btDiscreteCollisionDetectorInterface.h:
//   "closestPointInA = closestPointInB + m_distance * m_normalOnSurfaceB"). On overlap the two
//   points are EPA's penetration pair: each on its own shape's surface, in 3D apart by the depth
//   Bullet reports (neither lies in both shapes in general; their x, y are apart by less when the
//   pair is tilted in z, test_bullet.cpp). No result at all from Bullet (m_hasResult false) is an
//   error. iterations: the pair detector's m_curIter.
//
// The contract (gjk2d_contract, kContract below; sources: Bullet 3.24's headers, Debian's
// /usr/include/bullet = upstream's src/ at tag 3.24):
// - overlap `penetration`: "give either closest points (distance > 0) or penetration (distance)"
//   (btDiscreteCollisionDetectorInterface.h:53-57; btPointCollector.h:25, "negative means
//   penetration"; btGjkEpaPenetrationDepthSolver.h:22-23, EPA "to calculate the penetration
//   depth");
// - tolerance: none stated. Bullet's thresholds (REL_ERROR2, gGjkEpaPenetrationTolerance in
//   btGjkPairDetector.cpp, the simplex solver's equal-vertex threshold) are stopping rules, which
//   promise no accuracy of the answer;
// - margin 0: the adapter sets each shape's margin to the case's radius, so there is no skin
//   beyond the case's shape; Bullet's default is CONVEX_DISTANCE_MARGIN = 0.04
//   (btCollisionMargin.h:19-22), which the adapter does not use;
// - depth (gjk2d_plugin_depth, kDepth below): none stated. EPA_ACCURACY (btGjkEpa2.cpp:63, 1e-12
//   in double; :67, 1e-4 in float; Bullet 3.24's src/, not installed by Debian) is EPA's stopping
//   rule, tested at :698 (stop when the support along the best face's normal is within it of the
//   face): it bounds the depth only when EPA ends there (AccuraryReached), not when it ends on
//   InvalidHull or OutOfVertices (:716, :728), whose last face is answered all the same (:734);
//   and no header or document of Bullet's promises it to users.
//
// Findings (docs/peers/bullet.md; validation/plugins/bullet/tests/test_bullet.cpp): in double
// every separated random case is within gjk2d's bound. In float the default equal-vertex threshold
// (1e-4) stops GJK early: random/192 is answered 7.8% off.
#include <gjk2d/plugin.h>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <vector>

#ifndef GJK2D_BULLET_VERSION
#define GJK2D_BULLET_VERSION "unknown"
#endif

namespace
{

#ifdef BT_USE_DOUBLE_PRECISION
using Shape = gjk2d_shape_d;
using Result = gjk2d_result_d;
#define GJK2D_BULLET_NAME "bullet-3.24-double"
#define GJK2D_BULLET_SCALAR GJK2D_SCALAR_DOUBLE
#else
using Shape = gjk2d_shape_f;
using Result = gjk2d_result_f;
#define GJK2D_BULLET_NAME "bullet-3.24-float"
#define GJK2D_BULLET_SCALAR GJK2D_SCALAR_FLOAT
#endif
static_assert(sizeof(*Shape{}.points) == sizeof(btScalar), "the case's scalar is btScalar");

// A shape's extent about its local origin: e = radius + max_i (|x_i| + |y_i|) over its local
// points, in double from the case's numbers (floats in the float module, exact in double): at
// least each point's distance to the origin, and finite wherever the numbers are.
double extent(const Shape& s)
{
    double m = 0;
    for (int32_t i = 0; i < s.count; ++i)
    {
        const double x = s.points[2 * i], y = s.points[2 * i + 1];
        m = std::max(m, std::abs(x) + std::abs(y));
    }
    return double(s.radius) + m;
}

// The prisms' half height h, one per case: h = k (eA + eB) in double, then rounded to btScalar
// (k = kHeightFactor below); 1 when it is 0 (two bare points at their local origins). The distance
// and the nearest points' x, y do not depend on h (docs/peers/prisms.md), but a
// penetration does, twice:
// - Exactly: two prisms of the same [-h, h] are also separated by a translation of 2h along z, so
//   the 3D minimal translation is min(2D depth, 2h) (+ the radii). Every point of a shape, radius
//   included, lies within e of its position (for a unit (c, s)), so its width is at most 2e, and
//   the 2D depth, at most the smaller shape's width, is at most 2 min(eA, eB) <= eA + eB: any
//   k >= 1 keeps the z translation out, by at least (2k - 1) times the depth (with h = 1, a segment
//   crossing a 10 x 10 square 4 deep is answered depth 2, along z: test_prism_height.cpp).
// - As Bullet computes it: its EPA (btGjkEpa2.cpp) often ends on InvalidHull (the prisms' side
//   faces are flat, four coplanar vertices each) and answers its last face, which spans the prisms'
//   height and is tilted in z by about (the shapes' width) / h: the depth comes out short by a
//   factor cos(tilt), falling as 1 / k^2. Taller is better until btScalar's rounding of the tall
//   faces makes EPA fail outright (depth 0) more often: from about k = 2^8 in float and 2^18 in
//   double on random:2000 (seed 1). kHeightFactor sits 16 times below that, 2^4 in float and 2^14
//   in double (the figures at both heights: docs/peers/prisms.md;
//   tests/bullet_depth_height_{float,double} measures them).
// The same rule in the programs of `gjk-validate repro` and in the direct loop, so that they answer
// as this adapter. At most the largest btScalar / 8, so that h, 2h and the prisms' vertices stay
// finite in btScalar (beyond it the shapes themselves are near btScalar's range).
constexpr double kHeightFactor = sizeof(btScalar) == sizeof(double) ? 16384 : 16;
btScalar prismHalfHeight(const Shape& a, const Shape& b)
{
    const double h = kHeightFactor * (extent(a) + extent(b));
    const double most = double(std::numeric_limits<btScalar>::max()) / 8;
    return btScalar(h == 0 ? 1.0 : std::min(h, most));
}

// The prism P x [-h, h] of the shape's points in the world frame, margin = the case's radius.
void buildPrism(const Shape& s, btScalar h, btConvexHullShape& hull)
{
    const btScalar c = s.rotation[0], sn = s.rotation[1];
    for (int32_t i = 0; i < s.count; ++i)
    {
        const btScalar x = s.points[2 * i], y = s.points[2 * i + 1];
        const btScalar wx = c * x - sn * y + s.position[0];
        const btScalar wy = sn * x + c * y + s.position[1];
        hull.addPoint(btVector3(wx, wy, -h), false);
        hull.addPoint(btVector3(wx, wy, h), false);
    }
    hull.recalcLocalAabb();
    hull.setMargin(s.radius);
}

// An object constructed in zeroed storage. btVoronoiSimplexSolver's constructor leaves members
// unwritten that btGjkPairDetector reads on its degenerate paths (valgrind: on
// hard/extreme-scale/217-random-1e40 the answer's points come from them): built on the stack, the
// answer would depend on what ran before in the process. Zeroed, it is the same in every run.
template <class T> class Zeroed
{
  public:
    Zeroed() : object_(new (storage_) T) {}
    Zeroed(const Zeroed&) = delete;
    Zeroed& operator=(const Zeroed&) = delete;
    ~Zeroed() { object_->~T(); }
    T* get() { return object_; }

  private:
    alignas(T) unsigned char storage_[sizeof(T)] = {};
    T* object_;
};

// A prepared shape (gjk2d_prepared, scope GJK2D_PREPARED_CASE): the btConvexHullShape a user keeps,
// built once from the case's world points with the case's half height (buildPrism), which depends
// on both shapes: hence the `other` shape. The scope is the case's because the world points are
// baked in (see the header comment: the adapter applies the case's (c, s) itself and hands Bullet
// identity transforms). A shape without a point is kept as refused, which the query answers as
// distance_f / distance_d does.
struct Prepared
{
    btConvexHullShape hull;
    bool refused = false;
};

void* prepare(int32_t implementation, const void* shape, const void* other)
{
    if (implementation != 0 || other == nullptr)
        return nullptr;
    const Shape& s = *static_cast<const Shape*>(shape);
    const Shape& o = *static_cast<const Shape*>(other);
    auto* p = new (std::nothrow) Prepared;
    if (p == nullptr)
        return nullptr;
    p->refused = s.count < 1 || o.count < 1;
    if (!p->refused)
        buildPrism(s, prismHalfHeight(s, o), p->hull);
    return p;
}

void release(int32_t /*implementation*/, void* prepared)
{
    delete static_cast<Prepared*>(prepared);
}

// The query, what Bullet's own pipeline pays for one pair of kept shapes (btConvexConvexAlgorithm
// builds a btGjkPairDetector per call): the simplex solver (zeroed, see Zeroed), the EPA solver,
// the pair detector, getClosestPoints with identity transforms, the answer copied out. The case's
// shapes are not read (their transforms are in the hulls' points).
int32_t distance(int32_t /*implementation*/, const void* preparedA, const void* /*a*/,
                 const void* preparedB, const void* /*b*/, void* /*cache*/, void* answer)
{
    const auto& pa = *static_cast<const Prepared*>(preparedA);
    const auto& pb = *static_cast<const Prepared*>(preparedB);
    if (pa.refused || pb.refused)
        return GJK2D_STATUS_REFUSED;
    Zeroed<btVoronoiSimplexSolver> simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector detector(&pa.hull, &pb.hull, simplex.get(), &epa);
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA.setIdentity();
    input.m_transformB.setIdentity();
    btPointCollector result;
    detector.getClosestPoints(input, result, nullptr);
    if (!result.m_hasResult)
        return GJK2D_STATUS_ERROR;
    const btVector3 onB = result.m_pointInWorld;
    const btVector3 onA = onB + result.m_normalOnBInWorld * result.m_distance;
    auto* out = static_cast<Result*>(answer);
    out->distance = result.m_distance; // negative: minus the penetration depth (`penetration`)
    out->point_a[0] = onA.x();
    out->point_a[1] = onA.y();
    out->point_b[0] = onB.x();
    out->point_b[1] = onB.y();
    out->iterations = detector.m_curIter;
    return GJK2D_STATUS_OK;
}

int32_t scope(int32_t /*implementation*/)
{
    return GJK2D_PREPARED_CASE;
}

// distance_f / distance_d is the prepared form on one case: prepare both shapes, query, release.
int32_t bulletDistance(const Shape* a, const Shape* b, void*, Result* out)
{
    void* pa = prepare(0, a, b);
    void* pb = prepare(0, b, a);
    const int32_t status = pa && pb ? distance(0, pa, a, pb, b, nullptr, out) : GJK2D_STATUS_ERROR;
    release(0, pa);
    release(0, pb);
    return status;
}

const gjk2d_prepared kPrepared = {&scope, &prepare, &distance, &release};

#ifdef BT_USE_DOUBLE_PRECISION
constexpr gjk2d_distance_f_fn kFloat = nullptr;
constexpr gjk2d_distance_d_fn kDouble = &bulletDistance;
#else
constexpr gjk2d_distance_f_fn kFloat = &bulletDistance;
constexpr gjk2d_distance_d_fn kDouble = nullptr;
#endif

const gjk2d_implementation kImplementations[] = {
    {GJK2D_BULLET_NAME,
     "Bullet " GJK2D_BULLET_VERSION " btGjkPairDetector (Voronoi simplex, GJK-EPA), prisms of "
     "btConvexHullShape, margin = radius",
     GJK2D_BULLET_SCALAR, GJK2D_ACCEPTS_RADIUS, 0, 0, kFloat, kDouble},
};

// The sources: Bullet 3.24's headers (Debian's /usr/include/bullet = upstream's src/ at tag 3.24),
// as read for this contract; a new Bullet needs them read again.
const gjk2d_contract kContract = {
    -1,
    -1,
    "",
    GJK2D_OVERLAP_PENETRATION,
    "BulletCollision/NarrowPhaseCollision/btDiscreteCollisionDetectorInterface.h:53-57 (\"give "
    "either closest points (distance > 0) or penetration (distance)\"), btPointCollector.h:25 "
    "(\"negative means penetration\"), btGjkEpaPenetrationDepthSolver.h:22-23, Bullet 3.24",
    0,
    "the adapter sets each margin to the case's radius (setMargin): no skin beyond the case's "
    "shape; Bullet's default, not used: CONVEX_DISTANCE_MARGIN 0.04, "
    "BulletCollision/CollisionShapes/btCollisionMargin.h:19-22, Bullet 3.24"};

// The depth clause: none stated (the header comment), the constant cited for the report's reader.
#ifdef BT_USE_DOUBLE_PRECISION
#define GJK2D_BULLET_EPA_ACCURACY "btGjkEpa2.cpp:63, EPA_ACCURACY 1e-12 (double)"
#else
#define GJK2D_BULLET_EPA_ACCURACY "btGjkEpa2.cpp:67, EPA_ACCURACY 1e-4 (float)"
#endif
const gjk2d_depth_contract kDepth = {
    -1, -1,
    "none: " GJK2D_BULLET_EPA_ACCURACY " is EPA's stopping rule (btGjkEpa2.cpp:698), not a "
    "promise: EPA also ends on InvalidHull or OutOfVertices (btGjkEpa2.cpp:716, 728) "
    "and answers its last face; src/BulletCollision/NarrowPhaseCollision/, Bullet 3.24"};

const gjk2d_plugin kPlugin = {GJK2D_PLUGIN_ABI_VERSION, 1, kImplementations, &kContract};

} // namespace

extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
{
    return &kPlugin;
}

extern "C" GJK2D_PLUGIN_EXPORT const char* gjk2d_plugin_library(void)
{
    return "Bullet " GJK2D_BULLET_VERSION " (Debian libbullet-dev)";
}

// The depth clause (the optional export of gjk2d/plugin.h): none stated, EPA's constant cited.
extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_depth_contract* gjk2d_plugin_depth(void)
{
    return &kDepth;
}

// Shapes prepared once (the optional export of gjk2d/plugin.h): each case's btConvexHullShapes.
extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_prepared* gjk2d_plugin_prepared(void)
{
    return &kPrepared;
}
