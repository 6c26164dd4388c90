// The prisms' half height on penetrating cases (validation/plugins/bullet/bullet.cpp,
// prismHalfHeight; docs/peers/prisms.md): Bullet in double called directly, with
// the adapter's construction (world points, prisms of btConvexHullShape, margin 0, a zeroed
// btVoronoiSimplexSolver, btGjkEpaPenetrationDepthSolver), once with h = 1 and once with the
// adapter's h = 2 (eA + eB); then the adapter itself (gjk2d-bullet-double.so) on the same case.
//
// A = [0, 10]^2 (eA = max |x| + |y| = 20). Two hand-derived cases (depths derived in
// test_bullet.cpp):
// - B the segment (6, -5)-(6, 15): depth 4 along x; eB = 21, h = 2^14 (eA + eB) = 671744;
// - B the diamond (12, 5), (7, 10), (2, 5), (7, 0): depth 8 along x; eB = 17, h = 606208.
// With h = 1 the prisms are also separated by 2 along z, less than either depth: Bullet answers
// -2, both points at one x, y (the translation runs along z). With the adapter's h it answers the
// 2D depth, its points' x, y apart by it; and the adapter answers bit for bit what the direct
// call with that h answers (the rule is the adapter's, and `gjk-validate repro`'s programs use it).
#include "peer_plugin.hpp"

#include "within.hpp"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

static_assert(sizeof(btScalar) == sizeof(double), "built against bullet-float64");

namespace
{

// The case's shapes have identity transforms: their points are world points.
double extent(const std::vector<double>& p)
{
    double m = 0;
    for (std::size_t i = 0; i + 1 < p.size(); i += 2)
        m = std::max(m, std::abs(p[i]) + std::abs(p[i + 1]));
    return m;
}

// Bullet's answer on the prisms P x [-h, h], Q x [-h, h] (radius 0), as the adapter builds them.
peers::Answer direct(const std::vector<double>& p, const std::vector<double>& q, double h)
{
    btConvexHullShape a, b;
    for (std::size_t i = 0; i + 1 < p.size(); i += 2)
    {
        a.addPoint(btVector3(p[i], p[i + 1], -h), false);
        a.addPoint(btVector3(p[i], p[i + 1], h), false);
    }
    for (std::size_t i = 0; i + 1 < q.size(); i += 2)
    {
        b.addPoint(btVector3(q[i], q[i + 1], -h), false);
        b.addPoint(btVector3(q[i], q[i + 1], h), false);
    }
    a.recalcLocalAabb();
    b.recalcLocalAabb();
    a.setMargin(0);
    b.setMargin(0);
    alignas(btVoronoiSimplexSolver) unsigned char storage[sizeof(btVoronoiSimplexSolver)] = {};
    btVoronoiSimplexSolver* simplex = new (storage) btVoronoiSimplexSolver;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector detector(&a, &b, simplex, &epa);
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA.setIdentity();
    input.m_transformB.setIdentity();
    btPointCollector result;
    detector.getClosestPoints(input, result, nullptr);
    simplex->~btVoronoiSimplexSolver();
    peers::Answer out;
    out.status = result.m_hasResult ? GJK2D_STATUS_OK : GJK2D_STATUS_ERROR;
    const btVector3 onB = result.m_pointInWorld;
    const btVector3 onA = onB + result.m_normalOnBInWorld * result.m_distance;
    out.distance = result.m_distance;
    out.ax = onA.x();
    out.ay = onA.y();
    out.bx = onB.x();
    out.by = onB.y();
    return out;
}

const peers::Plugin& bulletDouble()
{
    static const peers::Plugin p(GJK2D_BULLET_DOUBLE_PLUGIN, "bullet-3.24-double");
    return p;
}

} // namespace

TEST_CASE("penetrating cases: half height 1 answers the z translation 2, the adapter's h the 2D "
          "depth")
{
    constexpr double tol = 1e-12; // measured: every answer below is within it
    const std::vector<double> square{0, 0, 10, 0, 10, 10, 0, 10};
    struct Case
    {
        const char* name;
        std::vector<double> b;
        double depth;
    };
    for (const Case& c :
         {Case{"segment", {6, -5, 6, 15}, 4}, Case{"diamond", {12, 5, 7, 10, 2, 5, 7, 0}, 8}})
    {
        INFO(c.name);
        const peers::Answer low = direct(square, c.b, 1);
        REQUIRE(low.status == GJK2D_STATUS_OK);
        CHECK(low.distance == within(-2, tol));
        CHECK(std::hypot(low.ax - low.bx, low.ay - low.by) == within(0, tol));

        const double h = 16384 * (extent(square) + extent(c.b)); // bullet.cpp, kHeightFactor
        const peers::Answer tall = direct(square, c.b, h);
        REQUIRE(tall.status == GJK2D_STATUS_OK);
        CHECK(tall.distance == within(-c.depth, tol));
        CHECK(std::hypot(tall.ax - tall.bx, tall.ay - tall.by) == within(c.depth, tol));

        const peers::Answer adapter =
            bulletDouble().distance(peers::Shape{square, 0}, peers::Shape{c.b, 0});
        REQUIRE(adapter.status == GJK2D_STATUS_OK);
        CHECK(adapter.distance == tall.distance);
        CHECK(adapter.ax == tall.ax);
        CHECK(adapter.ay == tall.ay);
        CHECK(adapter.bx == tall.bx);
        CHECK(adapter.by == tall.by);
    }
}
