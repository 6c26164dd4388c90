// Bullet called directly, beside the Bullet adapter (validation/plugins/bullet/bullet.cpp): each
// case's two shapes built once as Bullet's users build them, btConvexHullShapes of the adapter's
// prisms (docs/peers/prisms.md) with margin = radius, then passes of the pair
// detector as its users call it on two convex shapes: a btVoronoiSimplexSolver and a
// btGjkEpaPenetrationDepthSolver on the stack, a btGjkPairDetector over the two shapes,
// getClosestPoints with identity transforms into a btPointCollector. Prints the median ns/query;
// with --plugin, the adapter's prepared queries of the same cases (gjk2d_plugin_prepared), timed
// the same way in alternate passes, and their ratio. Not a test: a speed figure belongs to a quiet
// machine, not to CTest. Its CTest (--check 50) checks that it runs and that its distances are the
// adapter's. Built twice, as the adapter: bullet_direct_loop_float (btScalar float, the case's
// numbers rounded to float) and bullet_direct_loop_double (BT_USE_DOUBLE_PRECISION).
//
//     cd build/release
//     validation/gjk-validate generate --family random:20000 --seed 1 --out /tmp/r.json
//     P=validation/plugins
//     tests/plugins/bullet_direct_loop_double /tmp/r.json --plugin $P/gjk2d-bullet-double.so
//
// (likewise _float with gjk2d-bullet-float.so.)
#include "direct_loop.hpp"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <limits>
#include <memory>

namespace
{

#ifdef BT_USE_DOUBLE_PRECISION
const char* const kVariant = "bullet-3.24-double";
#else
const char* const kVariant = "bullet-3.24-float";
#endif

const char* const kUsage = "usage: bullet_direct_loop_{float,double} CASES.json [--passes N]\n"
                           "                                        [--plugin "
                           "gjk2d-bullet-{float,double}.so] [--check N]\n";

// The case's shape in btScalar (float: each number rounded, as the adapter receives it).
struct ScalarShape
{
    std::vector<btScalar> points;
    btScalar radius, px, py, c, s;
};

ScalarShape scalarShape(const directloop::Shape& s)
{
    return ScalarShape{std::vector<btScalar>(s.points.begin(), s.points.end()),
                       btScalar(s.radius),
                       btScalar(s.px),
                       btScalar(s.py),
                       btScalar(s.c),
                       btScalar(s.s)};
}

// The adapter's prism reduction (bullet.cpp: extent, prismHalfHeight with its kHeightFactor,
// buildPrism), the same rule, so that both sides query the same shapes.
double extent(const ScalarShape& s)
{
    double m = 0;
    for (std::size_t i = 0; i + 1 < s.points.size(); i += 2)
        m = std::max(m, std::abs(double(s.points[i])) + std::abs(double(s.points[i + 1])));
    return double(s.radius) + m;
}

btScalar prismHalfHeight(const ScalarShape& a, const ScalarShape& b)
{
    const double h = (sizeof(btScalar) == sizeof(double) ? 16384 : 16) * (extent(a) + extent(b));
    const double most = double(std::numeric_limits<btScalar>::max()) / 8;
    return btScalar(h == 0 ? 1.0 : std::min(h, most));
}

void buildPrism(const ScalarShape& s, btScalar h, btConvexHullShape& hull)
{
    for (std::size_t i = 0; i + 1 < s.points.size(); i += 2)
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

} // namespace

int main(int argc, char** argv)
{
    const directloop::Options o = directloop::parseOptions(argc, argv, kUsage, kVariant);
    const std::vector<directloop::Case> all = directloop::readCases(o.cases);
    std::vector<const directloop::Case*> cases;
    std::vector<std::unique_ptr<btConvexHullShape>> hulls; // A, B of each case
    for (const directloop::Case& c : all)
    {
        if (c.a.count() < 1 || c.b.count() < 1)
            continue;
        const ScalarShape a = scalarShape(c.a), b = scalarShape(c.b);
        const btScalar h = prismHalfHeight(a, b);
        for (const ScalarShape* s : {&a, &b})
        {
            hulls.push_back(std::make_unique<btConvexHullShape>());
            buildPrism(*s, h, *hulls.back());
        }
        cases.push_back(&c);
    }
    btTransform identity;
    identity.setIdentity();
    return directloop::run(
        o, cases,
        [&](std::size_t k)
        {
            btVoronoiSimplexSolver simplex;
            btGjkEpaPenetrationDepthSolver epa;
            btGjkPairDetector detector(hulls[2 * k].get(), hulls[2 * k + 1].get(), &simplex, &epa);
            btGjkPairDetector::ClosestPointInput input;
            input.m_transformA = identity;
            input.m_transformB = identity;
            btPointCollector result;
            detector.getClosestPoints(input, result, nullptr);
            const btVector3 onB = result.m_pointInWorld;
            const btVector3 onA = onB + result.m_normalOnBInWorld * result.m_distance;
            return directloop::Answer{GJK2D_STATUS_OK, double(result.m_distance), double(onA.x()),
                                      double(onA.y()), double(onB.x()),           double(onB.y())};
        });
}
