// Prepared shapes (gjk2d/prepared.hpp): the query on two prepared shapes and their transforms gives
// the plain query's answer and cache, bit for bit, cold and warm, on ordinary cases (where it skips
// the per-step range checks) and on the cases where it must not skip them (huge, tiny and
// non-finite coordinates, large rotations), and for options other than the reference ones.
// Expected values: gjk::distance on the same DistanceInput, one pair at a time. The default
// campaign's families: tests/validation/test_variants.cpp, "prepared shapes".
#include "gjk2d/distance.hpp"
#include "random_shapes.hpp"

#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

using namespace gjk;

namespace
{

template <class T> bool sameBits(T a, T b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class T> bool sameOutput(const DistanceOutput<T>& x, const DistanceOutput<T>& y)
{
    return sameBits(x.distance, y.distance) && sameBits(x.pointA.x, y.pointA.x) &&
           sameBits(x.pointA.y, y.pointA.y) && sameBits(x.pointB.x, y.pointB.x) &&
           sameBits(x.pointB.y, y.pointB.y) && sameBits(x.normal.x, y.normal.x) &&
           sameBits(x.normal.y, y.normal.y) && x.iterations == y.iterations &&
           x.simplexCount == y.simplexCount && x.stop == y.stop && x.outOfRange == y.outOfRange &&
           x.rescaled == y.rescaled && x.certified == y.certified && x.path == y.path &&
           x.expand == y.expand && sameBits(x.lower, y.lower) && sameBits(x.upper, y.upper);
}

bool sameCache(const SimplexCache& x, const SimplexCache& y)
{
    bool same = x.count == y.count && x.edgeBase == y.edgeBase && x.searchA == y.searchA &&
                x.searchB == y.searchB;
    for (int i = 0; i < 3; ++i)
        same = same && x.indexA[i] == y.indexA[i] && x.indexB[i] == y.indexB[i];
    return same;
}

// The prepared query against the plain one: cold, then warm twice from each one's own cache.
// Returns whether the prepared query could skip the range checks (preparedQueryInRange).
template <class T>
bool checkPrepared(const std::vector<Vec2<T>>& a, const std::vector<Vec2<T>>& b,
                   const Transform<T>& xfA, const Transform<T>& xfB, T radiusA, T radiusB,
                   const Options& options = referenceOptions)
{
    const DistanceInput<T> input{
        {a.data(), int(a.size()), radiusA}, {b.data(), int(b.size()), radiusB}, xfA, xfB};
    const PreparedShape<T> pa = prepare(input.proxyA), pb = prepare(input.proxyB);
    SimplexCache plainCache, preparedCache;
    for (int pass = 0; pass < 3; ++pass)
    {
        INFO("pass " << pass << " (0: cold)");
        const DistanceOutput<T> plain = distance(input, plainCache, options);
        const DistanceOutput<T> prepared = distance(pa, xfA, pb, xfB, preparedCache, options);
        CHECK(sameOutput(plain, prepared));
        CHECK(sameCache(plainCache, preparedCache));
    }
    return preparedQueryInRange(pa, pb, invMulTransforms(xfA, xfB));
}

} // namespace

TEMPLATE_TEST_CASE("prepared shapes: bounds and the scan check, by hand", "[gjk][prepared]", float,
                   double)
{
    using T = TestType;
    const std::vector<Vec2<T>> points = {{1, -3}, {-2, 0.5}, {0.25, 2}};
    const PreparedShape<T> s = prepare(Polygon<T>{points.data(), 3, T(0.5)});
    CHECK(s.polygon.points == points.data());
    CHECK(s.polygon.count == 3);
    CHECK(s.polygon.radius == T(0.5));
    CHECK(s.lower == Vec2<T>{-2, -3});
    CHECK(s.upper == Vec2<T>{1, 2});
    CHECK(s.maxAbs == T(3));
    CHECK(s.scanSafe);
    // count * maxAbs just above maxCoordinate: not safe. Non-finite: not safe, NaN bounds.
    const T big = Tolerances<T>::maxCoordinate / T(2);
    const std::vector<Vec2<T>> large = {{big, 0}, {0, big}, {-big, 0}};
    CHECK_FALSE(prepare(Polygon<T>{large.data(), 3, T(0)}).scanSafe);
    CHECK(prepare(Polygon<T>{large.data(), 2, T(0)}).scanSafe);
    const std::vector<Vec2<T>> inf = {{0, 0}, {std::numeric_limits<T>::infinity(), 1}};
    const PreparedShape<T> si = prepare(Polygon<T>{inf.data(), 2, T(0)});
    CHECK_FALSE(si.scanSafe);
    CHECK(std::isnan(si.maxAbs));
}

TEMPLATE_TEST_CASE("prepared shapes: the plain query's answers and caches, bit for bit",
                   "[gjk][prepared]", float, double)
{
    using T = TestType;
    std::mt19937_64 rng(5401);
    int skipped = 0, cases = 0;
    for (int i = 0; i < 800; ++i)
    {
        auto a = bench::randomShape(rng), b = bench::randomShape(rng);
        bool ordinary = false;
        switch (i % 10)
        {
        case 0:
            b.xf.p = a.xf.p; // the same origin: cold start from vertex 0
            break;
        case 1:
            b.xf.p = {a.xf.p.x + 0.1, a.xf.p.y}; // deep overlap: containment
            break;
        case 2: // a tiny shape: the start simplex below minCoordinate (the lower side)
            for (auto* s : {&a, &b})
            {
                for (auto& p : s->points)
                    p = {p.x * 1e-160, p.y * 1e-160};
                s->xf.p = {s->xf.p.x * 1e-160, s->xf.p.y * 1e-160};
            }
            break;
        case 3: // beyond maxCoordinate (float 2.3e18, double 1.7e153): the rescaled retry
            for (auto* s : {&a, &b})
            {
                const double k = std::is_same_v<T, float> ? 1e25 : 1e160;
                for (auto& p : s->points)
                    p = {p.x * k, p.y * k};
                s->xf.p = {s->xf.p.x * k, s->xf.p.y * k};
            }
            break;
        case 4: // a rotation far from unit size: |c| or |s| above 2 in A's frame
            b.xf.q = {b.xf.q.c * 3, b.xf.q.s * 3};
            break;
        case 5: // a float engine's rotation, seen in double (not exactly unit)
            a.xf.q = {double(float(a.xf.q.c)), double(float(a.xf.q.s))};
            ordinary = true;
            break;
        case 6: // one shape a single point, the other a segment
            a.points.resize(1);
            b.points.resize(2);
            ordinary = true;
            break;
        case 7:
            b.points.push_back(b.points[0]); // a repeated point: zero edges
            ordinary = true;
            break;
        default:
            ordinary = true;
            break;
        }
        const auto ca = bench::converted<T>(a), cb = bench::converted<T>(b);
        INFO("case " << i);
        const T ra = T(i % 3 == 0 ? 0.1 : 0), rb = T(i % 4 == 0 ? 0.2 : 0);
        const bool inRange = checkPrepared<T>(ca.points, cb.points, ca.xf, cb.xf, ra, rb);
        ++cases;
        skipped += inRange;
        if (ordinary)
            CHECK(inRange); // these take the prepared path
        if (i % 10 == 3 || i % 10 == 4)
            CHECK_FALSE(inRange);
    }
    INFO(skipped << " of " << cases << " ran without the per-step checks");
    CHECK(skipped >= cases / 2);
}

TEMPLATE_TEST_CASE("prepared shapes: other options run the plain query's code, bit for bit",
                   "[gjk][prepared]", float, double)
{
    using T = TestType;
    std::mt19937_64 rng(5402);
    Options duality, world, closest, binary, certified, limited, signedDistance;
    duality.stopping = StoppingRule::DualityGap;
    world.frame = Frame::World;
    closest.direction = SearchDirection::ClosestPoint;
    binary.support = SupportStrategy::BinarySearch;
    certified.certify = true;
    limited.maxIterations = 2;
    signedDistance.signedDistance = true;
    for (int i = 0; i < 100; ++i)
    {
        const auto a = bench::converted<T>(bench::randomShape(rng));
        const auto b = bench::converted<T>(bench::randomShape(rng));
        for (const Options& o :
             {duality, world, closest, binary, certified, limited, signedDistance})
            checkPrepared<T>(a.points, b.points, a.xf, b.xf, T(0), T(0.05), o);
    }
}
