// The Bullet 3.24 adapter (a shipped peer, gjk2d/plugin.h): btGjkPairDetector between two prisms,
// as Bullet's collision pipeline runs it for a pair of convex shapes: a btVoronoiSimplexSolver for
// GJK, a btGjkEpaPenetrationDepthSolver for overlapping cores. One source, two modules built
// against Debian's libbullet-dev: gjk2d-bullet-float.so ("bullet-3.24-float", btScalar = float,
// `pkg-config bullet`) and gjk2d-bullet-double.so ("bullet-3.24-double", BT_USE_DOUBLE_PRECISION,
// `pkg-config bullet-float64`). docs/peers.md, "## Bullet".
//
// The 2D case as a 3D one (docs/peers.md, "The prism reduction"): a shape of points P becomes the
// prism P x [-h, h] with h = kHalfHeight, the same for both shapes, a btConvexHullShape of its 2n
// vertices (any order: Bullet's support scans them, the shape is their hull). The case's radius
// is the shape's collision margin, setMargin(r), also for r = 0 (Bullet's default margin is 0.04):
// btGjkPairDetector runs GJK on the margin-less hulls and subtracts both margins from the
// distance, so a margin is an exact radius (the prism swept by a ball of radius r). Every case is
// taken: points, segments and polygons, with or without radius.
// - Transforms: the adapter applies the case's transform to the points itself, world = R * local +
//   p in btScalar with R = [[c, -s], [s, c]] from the case's (c, s) as given, and hands Bullet
//   identity transforms (the FCL adapter does the same; one construction for both peers).
// - The simplex solver is built in zeroed storage (Zeroed, below): Bullet reads members its
//   constructor leaves unwritten on degenerate paths, and an answer must not depend on what ran
//   before it in the process.
// - Defaults kept as Bullet's users run them: the simplex solver's equal-vertex threshold
//   (VORONOI_DEFAULT_EQUAL_VERTEX_THRESHOLD: 1e-4 in float, 1e-12 in double), the pair
//   detector's tolerances, no maximum distance (BT_LARGE_FLOAT).
// - The answer: Bullet's btPointCollector holds the distance, the normal on B and the point on B;
//   the point on A is pointOnB + normal * distance (Bullet's own convention, btManifoldResult).
//   A negative distance (cores overlapping, answered by EPA, or margins overlapping) is reported
//   as distance 0, as plugin.h asks for overlapping shapes, with the two points as Bullet gives
//   them (each lies in the other shape when Bullet is right). No result at all from Bullet
//   (m_hasResult false) is an error. iterations: the pair detector's m_curIter.
//
// Findings (docs/peers.md, "## Bullet"; validation/plugins/bullet/tests/test_bullet.cpp): in double
// every separated random case is within gjk2d's bound; on overlap Bullet's two points are apart by
// the penetration depth, which gjk-validate's witness-gap check counts as invalid. In float the
// default equal-vertex threshold (1e-4) stops GJK early: random/192 is answered 7.8% off, and
// near-touching shapes are called touching.
#include <gjk2d/plugin.h>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

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

// The prisms' half height: 1, a fixed number rather than the shapes' scale. The distance and the
// nearest points' x, y do not depend on it (docs/peers.md); it only has to be positive.
constexpr btScalar kHalfHeight = 1;

// The prism P x [-h, h] of the shape's points in the world frame, margin = the case's radius.
void buildPrism(const Shape& s, btConvexHullShape& hull)
{
    const btScalar c = s.rotation[0], sn = s.rotation[1];
    for (int32_t i = 0; i < s.count; ++i)
    {
        const btScalar x = s.points[2 * i], y = s.points[2 * i + 1];
        const btScalar wx = c * x - sn * y + s.position[0];
        const btScalar wy = sn * x + c * y + s.position[1];
        hull.addPoint(btVector3(wx, wy, -kHalfHeight), false);
        hull.addPoint(btVector3(wx, wy, kHalfHeight), false);
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

int32_t bulletDistance(const Shape* a, const Shape* b, void*, Result* out)
{
    if (a->count < 1 || b->count < 1)
        return GJK2D_STATUS_REFUSED;
    btConvexHullShape hullA, hullB;
    buildPrism(*a, hullA);
    buildPrism(*b, hullB);
    Zeroed<btVoronoiSimplexSolver> simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector detector(&hullA, &hullB, simplex.get(), &epa);
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA.setIdentity();
    input.m_transformB.setIdentity();
    btPointCollector result;
    detector.getClosestPoints(input, result, nullptr);
    if (!result.m_hasResult)
        return GJK2D_STATUS_ERROR;
    const btVector3 onB = result.m_pointInWorld;
    const btVector3 onA = onB + result.m_normalOnBInWorld * result.m_distance;
    out->distance = result.m_distance < 0 ? btScalar(0) : result.m_distance;
    out->point_a[0] = onA.x();
    out->point_a[1] = onA.y();
    out->point_b[0] = onB.x();
    out->point_b[1] = onB.y();
    out->iterations = detector.m_curIter;
    return GJK2D_STATUS_OK;
}

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

const gjk2d_plugin kPlugin = {GJK2D_PLUGIN_ABI_VERSION, 1, kImplementations};

} // namespace

extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
{
    return &kPlugin;
}

extern "C" GJK2D_PLUGIN_EXPORT const char* gjk2d_plugin_library(void)
{
    return "Bullet " GJK2D_BULLET_VERSION " (Debian libbullet-dev)";
}
