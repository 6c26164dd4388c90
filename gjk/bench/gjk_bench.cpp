// Google Benchmark programs for the GJK query (docs/speed.md). Cases are generated here with the
// same distribution as the runner's `random` family (3 to 8 vertices on circles of radius 0.5 to
// 2, positions in [-4, 4]^2, random rotations), from a fixed seed, so runs are comparable.
//   build/release/gjk/gjk_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "gjk2d/batch.hpp"
#include "gjk2d/distance.hpp"
#include "random_shapes.hpp"

#include <benchmark/benchmark.h>

#include <random>
#include <utility>
#include <vector>

namespace
{
using gjk::bench::randomShape;
using ShapeData = gjk::bench::ShapeData<double>;

struct Pair
{
    ShapeData a, b;
};

const std::vector<Pair>& randomPairs()
{
    static const std::vector<Pair> pairs = []
    {
        std::mt19937_64 rng(20101);
        std::vector<Pair> p(20000);
        for (auto& x : p)
            x = {randomShape(rng), randomShape(rng)};
        return p;
    }();
    return pairs;
}

template <class T> struct Converted
{
    std::vector<std::vector<gjk::Vec2<T>>> storage;
    std::vector<gjk::DistanceInput<T>> inputs;
};

// FloatRotations: every rotation (c, s) rounded to float, as a float engine stores it (in a double
// query |c^2 + s^2 - 1| is then ~1e-8, never a unit rotation: A's frame divides by |qA|^2).
template <class T, bool FloatRotations = false> const Converted<T>& inputs()
{
    static const Converted<T> c = []
    {
        Converted<T> out;
        const auto& pairs = randomPairs();
        out.storage.reserve(2 * pairs.size());
        for (const auto& p : pairs)
        {
            gjk::DistanceInput<T> in;
            const ShapeData* shapes[2] = {&p.a, &p.b};
            gjk::Polygon<T>* polys[2] = {&in.proxyA, &in.proxyB};
            gjk::Transform<T>* xfs[2] = {&in.transformA, &in.transformB};
            for (int k = 0; k < 2; ++k)
            {
                auto shape = gjk::bench::converted<T>(*shapes[k]);
                auto& pts = out.storage.emplace_back(std::move(shape.points));
                *polys[k] = {pts.data(), int(pts.size()), T(0)};
                *xfs[k] = shape.xf;
                if constexpr (FloatRotations)
                    xfs[k]->q = {T(float(shape.xf.q.c)), T(float(shape.xf.q.s))};
            }
            out.inputs.push_back(in);
        }
        return out;
    }();
    return c;
}

gjk::Options variant(int v)
{
    gjk::Options o;
    if (v == 1)
        o.certify = true;
    return o;
}

// Time per query, as a counter: `queries` queries per benchmark iteration.
void setNsPerQuery(benchmark::State& state, std::size_t queries)
{
    state.counters["ns_per_query"] =
        benchmark::Counter(double(state.iterations()) * double(queries),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// One pass of cold queries: in.size() queries over the first `pairs` inputs, cycling.
template <class T>
void coldPass(const std::vector<gjk::DistanceInput<T>>& in, std::size_t pairs,
              const gjk::Options& o)
{
    for (std::size_t k = 0, j = 0; k < in.size();
         ++k, j = j + 1 == pairs ? 0 : j + 1) // no division
    {
        gjk::SimplexCache cache;
        benchmark::DoNotOptimize(gjk::distance(in[j], cache, o));
    }
}

// Cold query over the whole random set; reports time per query.
template <class T> void BM_Random(benchmark::State& state)
{
    const auto& in = inputs<T>().inputs;
    const gjk::Options o = variant(int(state.range(0)));
    for (auto _ : state)
        coldPass(in, in.size(), o);
    state.SetItemsProcessed(state.iterations() * int64_t(in.size()));
    setNsPerQuery(state, in.size());
}

// The cold query on the overlapping pairs of the random set (unsigned distance 0, about a fifth of
// them), without (signed:0, the reference options) and with Options::signedDistance (signed:1):
// the cost of the expanding polygon (docs/gjk.md, "Signed distance").
template <class T> void BM_RandomOverlapping(benchmark::State& state)
{
    static const std::vector<gjk::DistanceInput<T>> overlapping = []
    {
        std::vector<gjk::DistanceInput<T>> v;
        for (const auto& in : inputs<T>().inputs)
            if (gjk::distance(in).distance == T(0))
                v.push_back(in);
        return v;
    }();
    gjk::Options o;
    o.signedDistance = state.range(0) == 1;
    for (auto _ : state)
        coldPass(overlapping, overlapping.size(), o);
    state.counters["pairs"] = double(overlapping.size());
    setNsPerQuery(state, overlapping.size());
}

// The cold query on a float engine's rotations (transforms as given, docs/gjk.md): against
// BM_Random, the cost of the non-unit path (docs/speed.md, "Transforms as given").
template <class T> void BM_RandomFloatRotations(benchmark::State& state)
{
    const auto& in = inputs<T, true>().inputs;
    for (auto _ : state)
        coldPass(in, in.size(), gjk::referenceOptions);
    setNsPerQuery(state, in.size());
}

// The same cold query, but cycling over only the first `pairs` pairs (20,000 queries per pass, as
// BM_Random). The work per query is the same on average; what changes is that the branch
// predictor can learn a few hundred queries' branch patterns by heart (the data stay in cache in
// both: a 20,000-pair set whose points come from 500 pairs times as BM_Random does, docs/speed.md,
// "Where the time goes"). The difference to BM_Random is therefore the cost of
// mispredicted branches in a cold query (docs/speed.md, "Where the time goes").
template <class T> void BM_RandomLearned(benchmark::State& state)
{
    const auto& in = inputs<T>().inputs;
    const std::size_t pairs = std::size_t(state.range(0));
    for (auto _ : state)
        coldPass(in, pairs, gjk::referenceOptions);
    setNsPerQuery(state, in.size());
}

// The batch entry point over the same pairs (cold), against BM_Random's single-query loop.
template <class T> void BM_RandomBatch(benchmark::State& state)
{
    const auto& in = inputs<T>().inputs;
    std::vector<gjk::SimplexCache> caches(in.size());
    std::vector<gjk::DistanceOutput<T>> out(in.size());
    for (auto _ : state)
    {
        std::fill(caches.begin(), caches.end(), gjk::SimplexCache{});
        gjk::distanceBatch<T>(in, caches, out);
        benchmark::DoNotOptimize(out.data());
    }
    setNsPerQuery(state, in.size());
}

// The batch in SIMD lanes (gjk2d/batch.hpp) over the same pairs, cold, on one instruction set
// (0 scalar, 1 SSE2, 2 AVX2, 3 AVX-512; skipped when this CPU lacks it). Counters: lane
// utilisation (busy lane-iterations / all) and scan utilisation (own points / scanned points).
// FloatRotations: a float engine's rotations in double (not unit ones: each lane's end then runs
// the scalar finishQuery), against BM_RandomFloatRotations.
template <class T, bool FloatRotations = false> void BM_RandomLanes(benchmark::State& state)
{
    const auto isa = gjk::BatchIsa(state.range(0));
    if (!gjk::batchIsaSupported(isa))
    {
        state.SkipWithError("instruction set not supported on this CPU");
        return;
    }
    const auto& in = inputs<T, FloatRotations>().inputs;
    std::vector<gjk::SimplexCache> caches(in.size());
    std::vector<gjk::DistanceOutput<T>> out(in.size());
    gjk::BatchStats stats;
    for (auto _ : state)
    {
        std::fill(caches.begin(), caches.end(), gjk::SimplexCache{});
        gjk::distanceBatchLanes(std::span<const gjk::DistanceInput<T>>(in), caches, out,
                                gjk::referenceOptions, isa, &stats);
        benchmark::DoNotOptimize(out.data());
    }
    setNsPerQuery(state, in.size());
    state.counters["lane_use"] =
        stats.steps ? double(stats.busyLaneSteps) / double(stats.steps * stats.lanes) : 1.0;
    state.counters["scan_use"] =
        stats.scannedPoints ? double(stats.usefulPoints) / double(stats.scannedPoints) : 1.0;
    state.counters["handed_back"] = double(stats.handedBack);
}

// The same, warm: each pair with the cache of its previous query (a batch per step).
template <class T> void BM_RandomLanesWarm(benchmark::State& state)
{
    const auto isa = gjk::BatchIsa(state.range(0));
    if (!gjk::batchIsaSupported(isa))
    {
        state.SkipWithError("instruction set not supported on this CPU");
        return;
    }
    const auto& in = inputs<T>().inputs;
    std::vector<gjk::SimplexCache> caches(in.size());
    std::vector<gjk::DistanceOutput<T>> out(in.size());
    for (size_t i = 0; i < in.size(); ++i)
        gjk::distance(in[i], caches[i]);
    for (auto _ : state)
    {
        gjk::distanceBatchLanes(std::span<const gjk::DistanceInput<T>>(in), caches, out,
                                gjk::referenceOptions, isa);
        benchmark::DoNotOptimize(out.data());
    }
    setNsPerQuery(state, in.size());
}

// Warm-started repeated query: each pair queried with the cache of its previous query.
template <class T> void BM_RandomWarm(benchmark::State& state)
{
    const auto& in = inputs<T>().inputs;
    std::vector<gjk::SimplexCache> caches(in.size());
    for (size_t i = 0; i < in.size(); ++i)
        gjk::distance(in[i], caches[i]);
    for (auto _ : state)
    {
        for (size_t i = 0; i < in.size(); ++i)
            benchmark::DoNotOptimize(gjk::distance(in[i], caches[i]));
    }
    setNsPerQuery(state, in.size());
}

// Two regular n-gons (vertices in counter-clockwise order), a small gap, cold start.
template <class T> void BM_RegularPolygons(benchmark::State& state)
{
    const int n = int(state.range(0));
    std::vector<gjk::Vec2<T>> pts(n);
    for (int i = 0; i < n; ++i)
        pts[i] = {T(std::cos(2 * M_PI * i / n)), T(std::sin(2 * M_PI * i / n))};
    gjk::DistanceInput<T> in;
    in.proxyA = {pts.data(), n, T(0)};
    in.proxyB = {pts.data(), n, T(0)};
    in.transformA = {{T(0), T(0)}, {T(1), T(0)}};
    in.transformB = {{T(2.01), T(0.3)}, {T(std::cos(0.1)), T(std::sin(0.1))}};
    gjk::Options o;
    o.support = gjk::SupportStrategy(state.range(1));
    for (auto _ : state)
    {
        gjk::SimplexCache cache;
        benchmark::DoNotOptimize(gjk::distance(in, cache, o));
    }
}
} // namespace

BENCHMARK_TEMPLATE(BM_Random, double)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("certify")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Random, float)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("certify")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomOverlapping, double)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("signed")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomOverlapping, float)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("signed")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomFloatRotations, double)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomLearned, double)
    ->Arg(500)
    ->ArgName("pairs")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomLearned, float)
    ->Arg(500)
    ->ArgName("pairs")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomBatch, double)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomBatch, float)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomLanes, double)
    ->DenseRange(0, 3)
    ->ArgName("isa")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomLanes, float)
    ->DenseRange(0, 3)
    ->ArgName("isa")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomLanes, double, true)
    ->DenseRange(0, 3)
    ->ArgName("isa")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomLanesWarm, double)
    ->DenseRange(0, 3)
    ->ArgName("isa")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomLanesWarm, float)
    ->DenseRange(0, 3)
    ->ArgName("isa")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomWarm, double)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RandomWarm, float)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_RegularPolygons, double)
    ->ArgsProduct({{8, 64, 512, 4096, 65536}, {0, 1}})
    ->ArgNames({"n", "support"})
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
