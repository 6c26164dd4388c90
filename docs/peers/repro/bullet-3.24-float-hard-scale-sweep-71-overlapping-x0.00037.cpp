// Bullet's btGjkPairDetector on one case: a standalone reproduction, with nothing of gjk2d in it.
// Written by gjk2d's `gjk-validate repro` (docs/peers.md, "Repro programs"):
//   gjk-validate repro --family hard/scale-sweep:172 --seed 1 hard/scale-sweep/71-overlapping-x0.00037 --variants bullet-3.24-float --no-default-plugins --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-float.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-double.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-fcl.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-geos --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-jolt --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-planck --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-rapier --out /work/wt-issue55-runner/docs/peers/repro
// Build and run it against Debian's libbullet-dev (Bullet 3.24, btScalar = float: pkg-config
// bullet; -O3 -ffp-contract=off as gjk2d builds its adapter, so that no a*b+c is fused here):
//   g++ bullet-3.24-float-hard-scale-sweep-71-overlapping-x0.00037.cpp $(pkg-config --cflags --libs bullet) -std=c++17 -O3 -ffp-contract=off -o bullet-3.24-float-hard-scale-sweep-71-overlapping-x0.00037 && ./bullet-3.24-float-hard-scale-sweep-71-overlapping-x0.00037
//
// The case: hard/scale-sweep/71-overlapping-x0.00037 (family hard/scale-sweep), variant bullet-3.24-float. gjk-validate hands Bullet the case's
// numbers in btScalar (float: a float variant gets the case's doubles rounded to the nearest
// float). Each number below is the shortest decimal that reads back as that float (a float's with
// the suffix f, so that it is rounded once): the compiler reads it correctly rounded, so Bullet
// gets the very bits gjk-validate gave it.
//
// The call, as gjk2d's adapter (validation/plugins/bullet/bullet.cpp) makes it, as Bullet's
// collision pipeline runs a convex pair: each 2D shape (points in its local frame, a radius,
// world = R * local + p with R = [[c, -s], [s, c]]) becomes the prism P x [-h, h], a
// btConvexHullShape of its 2n vertices placed in the world frame here in btScalar, with the case's
// radius as its collision margin (setMargin, also for 0); identity transforms. h = k * (eA + eB),
// k = 2^14 in double, 2^4 in float, e = radius + max_i (|x_i| + |y_i|) over the shape's local
// points, computed in double and then rounded to btScalar (1 when it is 0): far taller than any
// depth of the case, so that a minimal translation never runs along z, and EPA's faces are tilted
// little in z (the adapter's rule, bullet.cpp: prismHalfHeight). Then btGjkPairDetector with a btVoronoiSimplexSolver
// (built in zeroed storage: Bullet reads members its constructor leaves unwritten on degenerate
// paths) and a btGjkEpaPenetrationDepthSolver, into a btPointCollector. gjk-validate reports
// distance m_distance (negative: minus the penetration depth), the point on B m_pointInWorld and
// the point on A
// m_pointInWorld + m_normalOnBInWorld * m_distance (Bullet's convention, btManifoldResult).
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <new>
#include <vector>

struct Shape
{
    std::vector<btScalar> points; // x0, y0, x1, y1, ...
    btScalar radius, px, py, c, s;
};

const Shape A = {{0.00017695814f, 0.00032493973f, -5.8431477e-05f, 0.00036535703f, -0.00024427503f, 0.00027790235f, -0.00020610305f, -0.00030728086f, 0.0001649124f, -0.0003312158f}, 0.0f, -0.001155792f, -0.0005958382f, 0.46768293f, -0.8838963f};
const Shape B = {{0.0f, 0.0f, 0.000296f, -0.000111f, 0.000185f, 0.000259f}, 0.0f, -0.000568551f, -0.00029210167f, -0.56453055f, -0.82541215f};

// The exact answer for these inputs (gjk2d's CGAL/GMP ground truth), correctly rounded to double.
// On overlap the shapes share points: no pair of nearest points is unique, and the exact side's
// witness is one common point.
const double exactDistance = 0;
const bool exactOverlap = true;
const double exactA[2] = {-0.0008272727282685323, -0.0004737608142937863}, exactB[2] = {-0.0008272727282685323, -0.0004737608142937863};
// The exact signed distance (minus the penetration depth on overlap) and penetration pair, where
// gjk-validate computed them (a variant whose contract says penetration).
const bool exactSigned = true;
const double exactSignedDistance = -9.80174978771787e-11;
const double exactPA[2] = {-0.0008272727188467579, -0.00047376075710322185}, exactPB[2] = {-0.000827272811992066, -0.00047376078762176484};

// The shape's reach from its own origin, in double: radius + the largest |x| + |y| of its points.
double reach(const Shape& s)
{
    double m = 0;
    for (std::size_t i = 0; i < s.points.size(); i += 2)
    {
        const double x = s.points[i], y = s.points[i + 1];
        m = std::max(m, std::abs(x) + std::abs(y));
    }
    return double(s.radius) + m;
}

void buildPrism(const Shape& s, btScalar h, btConvexHullShape& hull)
{
    for (std::size_t i = 0; i < s.points.size(); i += 2)
    {
        const btScalar x = s.points[i], y = s.points[i + 1];
        const btScalar wx = s.c * x - s.s * y + s.px;
        const btScalar wy = s.s * x + s.c * y + s.py;
        hull.addPoint(btVector3(wx, wy, -h), false);
        hull.addPoint(btVector3(wx, wy, h), false);
    }
    hull.recalcLocalAabb();
    hull.setMargin(s.radius);
}

int main()
{
    double hd = (sizeof(btScalar) == sizeof(double) ? 16384 : 16) * (reach(A) + reach(B));
    if (hd == 0)
        hd = 1;
    hd = std::min(hd, double(std::numeric_limits<btScalar>::max()) / 8);
    const btScalar h = btScalar(hd);
    btConvexHullShape hullA, hullB;
    buildPrism(A, h, hullA);
    buildPrism(B, h, hullB);
    alignas(btVoronoiSimplexSolver) unsigned char storage[sizeof(btVoronoiSimplexSolver)] = {};
    btVoronoiSimplexSolver* simplex = new (storage) btVoronoiSimplexSolver;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector detector(&hullA, &hullB, simplex, &epa);
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA.setIdentity();
    input.m_transformB.setIdentity();
    btPointCollector result;
    detector.getClosestPoints(input, result, nullptr);
    if (!result.m_hasResult)
    {
        std::printf("Bullet gave no result (m_hasResult false)\n");
        return 1;
    }
    const btVector3 onB = result.m_pointInWorld;
    const btVector3 onA = onB + result.m_normalOnBInWorld * result.m_distance;
    std::printf("Bullet btGjkPairDetector (btScalar %s) on hard/scale-sweep/71-overlapping-x0.00037, half-height h = %.17g, "
                "%d iterations:\n", sizeof(btScalar) == 4 ? "float" : "double", double(h),
                detector.m_curIter);
    std::printf("bullet m_distance %.17g  m_normalOnBInWorld (%.17g, %.17g, %.17g)\n",
                double(result.m_distance), double(result.m_normalOnBInWorld.x()),
                double(result.m_normalOnBInWorld.y()), double(result.m_normalOnBInWorld.z()));
    // As gjk-validate reports it: m_distance as it is (negative: minus the penetration depth), the
    // points' x and y.
    const double d = double(result.m_distance);
    const double ax = onA.x(), ay = onA.y(), bx = onB.x(), by = onB.y();
    std::printf("answer distance %.17g %a\n", d, d);
    std::printf("answer pointA %.17g %.17g %a %a\n", ax, ay, ax, ay);
    std::printf("answer pointB %.17g %.17g %a %a\n", bx, by, bx, by);
    std::printf("exact distance %.17g%s\n", exactDistance, exactOverlap ? " (the shapes overlap)" : "");
    std::printf("exact pointA %.17g %.17g%s\n", exactA[0], exactA[1], exactOverlap ? " (a common point)" : "");
    std::printf("exact pointB %.17g %.17g\n", exactB[0], exactB[1]);
    if (exactSigned && exactSignedDistance < 0)
        std::printf("exact signed distance %.17g (minus the depth), penetration pair (%.17g, "
                    "%.17g) (%.17g, %.17g)\n",
                    exactSignedDistance, exactPA[0], exactPA[1], exactPB[0], exactPB[1]);
    simplex->~btVoronoiSimplexSolver();
    return 0;
}
