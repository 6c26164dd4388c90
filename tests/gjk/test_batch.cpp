// gjk::distanceBatchLanes in SIMD lanes (gjk2d/batch.hpp): bit for bit the single query, on every
// instruction set this CPU runs (SSE2 always on x86-64; AVX2 and AVX-512 when present), cold and
// warm, for lanes of mixed sizes (masked by padding), for the rare paths that leave the lanes and
// for options the lanes do not cover. Expected values: gjk::distance itself, one pair at a time.
#include "gjk2d/batch.hpp"
#include "random_shapes.hpp"

#include <catch2/catch.hpp>

#include <cstring>
#include <random>
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
           x.rescaled == y.rescaled && x.certified == y.certified && sameBits(x.lower, y.lower) &&
           sameBits(x.upper, y.upper);
}

bool sameCache(const SimplexCache& x, const SimplexCache& y)
{
    bool same = x.count == y.count && x.edgeBase == y.edgeBase && x.searchA == y.searchA &&
                x.searchB == y.searchB;
    for (int i = 0; i < 3; ++i)
        same = same && x.indexA[i] == y.indexA[i] && x.indexB[i] == y.indexB[i];
    return same;
}

template <class T> struct Pairs
{
    std::vector<std::vector<Vec2<T>>> points;
    std::vector<DistanceInput<T>> inputs;

    void add(const bench::ShapeData<double>& a, const bench::ShapeData<double>& b, T radiusA = 0,
             T radiusB = 0)
    {
        const auto ca = bench::converted<T>(a), cb = bench::converted<T>(b);
        points.push_back(ca.points);
        points.push_back(cb.points);
        DistanceInput<T> in;
        in.transformA = ca.xf;
        in.transformB = cb.xf;
        in.proxyA.radius = radiusA;
        in.proxyB.radius = radiusB;
        inputs.push_back(in);
    }
    // Polygons point into `points` once it stops growing.
    void bind()
    {
        for (std::size_t i = 0; i < inputs.size(); ++i)
        {
            inputs[i].proxyA.points = points[2 * i].data();
            inputs[i].proxyA.count = int(points[2 * i].size());
            inputs[i].proxyB.points = points[2 * i + 1].data();
            inputs[i].proxyB.count = int(points[2 * i + 1].size());
        }
    }
};

// A shape of n points on a circle (convex order), placed at random.
bench::ShapeData<double> shapeOf(std::mt19937_64& rng, int n)
{
    auto s = bench::randomShape(rng);
    std::uniform_real_distribution<double> angle(0.0, 2 * M_PI);
    const double r = std::sqrt(s.points[0].x * s.points[0].x + s.points[0].y * s.points[0].y);
    std::vector<double> t(n);
    for (auto& x : t)
        x = angle(rng);
    std::sort(t.begin(), t.end());
    s.points.clear();
    for (double x : t)
        s.points.push_back({r * std::cos(x), r * std::sin(x)});
    return s;
}

std::vector<BatchIsa> isasHere()
{
    std::vector<BatchIsa> out{BatchIsa::Scalar};
    for (BatchIsa isa : {BatchIsa::Sse2, BatchIsa::Avx2, BatchIsa::Avx512})
        if (batchIsaSupported(isa))
            out.push_back(isa);
    return out;
}

// Runs the batch cold, then warm from its own caches (twice), on every instruction set here, and
// checks each output and cache against gjk::distance with the same caches. Returns the stats of
// the widest instruction set's cold batch.
template <class T>
BatchStats checkBatch(const std::vector<DistanceInput<T>>& inputs, const Options& options = {})
{
    BatchStats widest;
    for (BatchIsa isa : isasHere())
    {
        INFO("instruction set " << batchIsaName(isa));
        std::vector<SimplexCache> caches(inputs.size()), expectedCaches(inputs.size());
        std::vector<DistanceOutput<T>> outputs(inputs.size());
        for (int pass = 0; pass < 3; ++pass) // cold, then warm twice
        {
            INFO("pass " << pass << " (0: cold)");
            BatchStats stats;
            distanceBatchLanes(std::span<const DistanceInput<T>>(inputs), caches, outputs, options,
                               isa, &stats);
            CHECK(stats.isa == isa);
            CHECK(stats.queries == inputs.size());
            CHECK(stats.laneQueries + stats.scalarQueries + stats.handedBack == inputs.size());
            CHECK(stats.busyLaneSteps <= stats.steps * std::uint64_t(stats.lanes));
            CHECK(stats.usefulPoints <= stats.scannedPoints);
            if (pass == 0)
                widest = stats;
            std::size_t mismatches = 0;
            for (std::size_t i = 0; i < inputs.size(); ++i)
            {
                const DistanceOutput<T> expected = distance(inputs[i], expectedCaches[i], options);
                if (!sameOutput(outputs[i], expected) || !sameCache(caches[i], expectedCaches[i]))
                {
                    if (mismatches++ < 3)
                    {
                        INFO("pair " << i << ": distance " << outputs[i].distance << " vs "
                                     << expected.distance << ", iterations "
                                     << outputs[i].iterations << " vs " << expected.iterations
                                     << ", stop " << stopReasonName(outputs[i].stop) << " vs "
                                     << stopReasonName(expected.stop));
                        CHECK(false);
                    }
                }
            }
            CHECK(mismatches == 0);
        }
    }
    return widest;
}

} // namespace

TEMPLATE_TEST_CASE("batch lanes: bit for bit the single query on random pairs of 3 to 8 points",
                   "[gjk][batch]", float, double)
{
    using T = TestType;
    std::mt19937_64 rng(1801);
    Pairs<T> pairs;
    for (int i = 0; i < 3000; ++i)
        pairs.add(bench::randomShape(rng), bench::randomShape(rng));
    pairs.bind();
    const BatchStats stats = checkBatch<T>(pairs.inputs);
    if (stats.isa != BatchIsa::Scalar)
    {
        // Nearly every query ends in the lanes (the rare paths are rare on this family).
        CHECK(stats.laneQueries >= 2990);
        CHECK(stats.scalarQueries == 0);
    }
}

TEMPLATE_TEST_CASE(
    "batch lanes: mixed sizes from 1 to 64 points, and larger ones run the scalar query",
    "[gjk][batch]", float, double)
{
    using T = TestType;
    std::mt19937_64 rng(1802);
    std::uniform_int_distribution<int> small(1, 12), any(1, 64);
    Pairs<T> pairs;
    for (int i = 0; i < 1500; ++i)
    {
        const int nA = i % 7 == 0 ? any(rng) : small(rng), nB = i % 5 == 0 ? any(rng) : small(rng);
        pairs.add(shapeOf(rng, nA), shapeOf(rng, nB), T(i % 3 == 0 ? 0.25 : 0),
                  T(i % 4 == 0 ? 0.5 : 0));
    }
    for (int i = 0; i < 20; ++i) // beyond the lanes' 64 points
        pairs.add(shapeOf(rng, 65 + i), shapeOf(rng, 3 + i));
    pairs.bind();
    const BatchStats stats = checkBatch<T>(pairs.inputs);
    if (stats.isa != BatchIsa::Scalar)
    {
        CHECK(stats.scalarQueries == 20);
        CHECK(stats.scannedPoints > stats.usefulPoints); // padding: lanes of different sizes
    }
}

TEMPLATE_TEST_CASE(
    "batch lanes: overlaps, touching, shared origins, repeated points, tiny edges, huge scales",
    "[gjk][batch]", float, double)
{
    using T = TestType;
    std::mt19937_64 rng(1803);
    Pairs<T> pairs;
    for (int i = 0; i < 400; ++i)
    {
        auto a = bench::randomShape(rng), b = bench::randomShape(rng);
        switch (i % 8)
        {
        case 0:
            b.xf.p = a.xf.p;
            break; // the same origin: cold start from vertex 0
        case 1:
            b.xf.p = {a.xf.p.x + 0.1, a.xf.p.y};
            break; // deep overlap: containment
        case 2:
            b.points.push_back(b.points[0]);
            break; // a repeated point: zero edges
        case 3:    // a tiny shape: edges below minEdgeComponent
            for (auto& p : a.points)
                p = {p.x * 1e-30, p.y * 1e-30};
            break;
        case 4: // far beyond the safe range: the rescaled retry (float overflows there: flagged)
            for (auto* s : {&a, &b})
            {
                for (auto& p : s->points)
                    p = {p.x * 1e25, p.y * 1e25};
                s->xf.p = {s->xf.p.x * 1e25, s->xf.p.y * 1e25};
            }
            break;
        case 5: // a rotation that is not a unit vector (a float engine's, seen in double)
            a.xf.q = {double(float(a.xf.q.c)) * 1.5, double(float(a.xf.q.s)) * 1.5};
            break;
        case 6: // one shape a single point, the other a segment
            a.points.resize(1);
            b.points.resize(2);
            break;
        default:
            break;
        }
        pairs.add(a, b, T(i % 3 == 0 ? 0.1 : 0), T(0));
    }
    pairs.bind();
    const BatchStats stats = checkBatch<T>(pairs.inputs);
    if (stats.isa != BatchIsa::Scalar)
        CHECK(stats.handedBack > 0); // the repeated points and tiny edges leave the lanes
}

TEMPLATE_TEST_CASE(
    "batch lanes: options the lanes do not cover run the scalar query, with the same results",
    "[gjk][batch]", float, double)
{
    using T = TestType;
    std::mt19937_64 rng(1804);
    Pairs<T> pairs;
    for (int i = 0; i < 300; ++i)
        pairs.add(bench::randomShape(rng), shapeOf(rng, 3 + i % 30));
    pairs.bind();
    Options duality, world, closest, binary, certified, limited;
    duality.stopping = StoppingRule::DualityGap;
    world.frame = Frame::World;
    closest.direction = SearchDirection::ClosestPoint;
    binary.support = SupportStrategy::BinarySearch;
    certified.certify = true;
    limited.maxIterations = 2;
    for (const Options& o : {duality, world, closest})
        CHECK(checkBatch<T>(pairs.inputs, o).laneQueries == 0);
    // In the lanes: the binary search on shapes of at most 16 points (it is the linear scan there),
    // the certified interval (made at the end, by the scalar code), an iteration limit.
    for (const Options& o : {binary, certified, limited})
    {
        const BatchStats stats = checkBatch<T>(pairs.inputs, o);
        if (stats.isa != BatchIsa::Scalar)
            CHECK(stats.laneQueries > 0);
    }
}

TEST_CASE("batch lanes: the instruction sets", "[gjk][batch]")
{
    CHECK(batchIsaSupported(BatchIsa::Scalar));
    CHECK(batchIsaSupported(bestBatchIsa()));
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
    CHECK(batchIsaSupported(BatchIsa::Sse2));
    CHECK(bestBatchIsa() >= BatchIsa::Sse2);
#endif
    // An empty batch.
    std::vector<DistanceInput<double>> none;
    std::vector<SimplexCache> caches;
    std::vector<DistanceOutput<double>> outputs;
    BatchStats stats;
    distanceBatchLanes(std::span<const DistanceInput<double>>(none), caches, outputs,
                       referenceOptions, BatchIsa::Best, &stats);
    CHECK(stats.queries == 0);
}

namespace
{
// The default batch (BatchIsa::Best) on `inputs`: every output and cache bit for bit
// gjk::distance's, and the lanes' too (the widest instruction set asked for by name). Returns the
// instruction set the default chose.
template <class T> BatchIsa checkDefaultChoice(const std::vector<DistanceInput<T>>& inputs)
{
    std::vector<SimplexCache> caches(inputs.size()), laneCaches(inputs.size());
    std::vector<DistanceOutput<T>> outputs(inputs.size()), laneOutputs(inputs.size());
    BatchStats stats;
    distanceBatchLanes(std::span<const DistanceInput<T>>(inputs), caches, outputs, referenceOptions,
                       BatchIsa::Best, &stats);
    distanceBatchLanes(std::span<const DistanceInput<T>>(inputs), laneCaches, laneOutputs,
                       referenceOptions, bestBatchIsa());
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < inputs.size(); ++i)
    {
        SimplexCache cache;
        const DistanceOutput<T> expected = distance(inputs[i], cache, referenceOptions);
        const bool same = sameOutput(outputs[i], expected) && sameCache(caches[i], cache) &&
                          sameOutput(laneOutputs[i], expected) && sameCache(laneCaches[i], cache);
        mismatches += same ? 0 : 1;
    }
    CHECK(mismatches == 0);
    return stats.isa;
}
} // namespace

// The choice between lanes and the scalar loop, once per batch from its point counts
// (gjk/src/batch.cpp, lanesPay): double pairs of 8 points (mean 8 > 3.75) run the scalar loop,
// pairs of 3 and 4 points (mean 3.5 <= 3.75) the lanes; float always the lanes. Both paths give
// gjk::distance's bits.
TEMPLATE_TEST_CASE("batch lanes: the default chooses lanes or the scalar loop by point counts",
                   "[gjk][batch]", float, double)
{
    using T = TestType;
    std::mt19937_64 rng(3301);
    Pairs<T> large, small;
    for (int i = 0; i < 500; ++i)
    {
        large.add(shapeOf(rng, 8), shapeOf(rng, 8));
        small.add(shapeOf(rng, 3), shapeOf(rng, 4));
    }
    large.bind();
    small.bind();
    const BatchIsa lanes = bestBatchIsa(); // Scalar where no lanes are compiled
    const BatchIsa largeIsa = std::is_same_v<T, double> ? BatchIsa::Scalar : lanes;
    CHECK(checkDefaultChoice<T>(small.inputs) == lanes);
    CHECK(checkDefaultChoice<T>(large.inputs) == largeIsa);
    // bestBatchIsaFor() tells the same choice beforehand, also for one pair of each kind (the
    // every-start variants ask it for one case's input).
    CHECK(bestBatchIsaFor(std::span<const DistanceInput<T>>(small.inputs)) == lanes);
    CHECK(bestBatchIsaFor(std::span<const DistanceInput<T>>(large.inputs)) == largeIsa);
    CHECK(bestBatchIsaFor(std::span<const DistanceInput<T>>(small.inputs.data(), 1)) == lanes);
    CHECK(bestBatchIsaFor(std::span<const DistanceInput<T>>(large.inputs.data(), 1)) == largeIsa);
}
