// Benchmarks of exact::distance for every route (docs/exact.md has the table and the command).
//
//   Pair/<route>/<n>/<transformed>: two random regular-ish convex polygons of n vertices each
//   (points
//     on a circle at jittered angles, so every point is a hull vertex), separated, either
//     untransformed (c = 1, s = 0, no translation: the coordinates are the doubles as given) or
//     with a rotation by a non-trivial angle (c, s from std::cos/std::sin) and a translation.
//     hull-of-differences (O(nm log nm)) stops at 256; minkowski-sum-2 stops at 1024.
//   Small/<route>: the validation runner's workload: a fixed set of 1024 random pairs of 3-8 point
//     shapes (random points, transforms, radii; about 15% overlapping), one case per iteration.
//     Counter "gmp": the share of cases that took the GMP route. Small/edge-merge+gmp is the
//     default route without its filter (Options::filter = false); Small/edge-merge-no-squared
//     leaves the squared rational out (Options::squaredRational = false).
//   Overlap/<options>: the same kind of pairs with centres within 1/2 of each other (about 82%
//     overlapping), with and without Options::penetration (the signed distance and the
//     penetration pair, docs/exact.md "Penetration depth"): "plain" (the default), "penetration",
//     "penetration+gmp" (no filter), "no-squared" and "penetration-no-squared" (the runner's
//     options without --per-case). Counter "depth_gmp": the share whose signed part took GMP.
#include <gjk2d/exact.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{

exact::Shape polygon(std::mt19937_64& rng, int n, double cx, double cy, bool transformed)
{
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    const double pi = std::acos(-1.0);
    exact::Shape s;
    for (int k = 0; k < n; ++k)
    {
        const double t = 2 * pi * (k + jitter(rng)) / n;
        s.points.push_back({std::cos(t), std::sin(t)});
    }
    if (transformed)
    {
        std::uniform_real_distribution<double> angle(0, 2 * pi);
        const double a = angle(rng);
        s.c = std::cos(a);
        s.s = std::sin(a);
        s.px = cx + 0.123456789;
        s.py = cy - 0.987654321;
    }
    else
    {
        for (auto& p : s.points)
        {
            p.x += cx;
            p.y += cy;
        }
    }
    return s;
}

void pair(benchmark::State& state, exact::Route route)
{
    const int n = static_cast<int>(state.range(0));
    const bool transformed = state.range(1) != 0;
    std::mt19937_64 rng(12345 + n);
    const exact::Shape a = polygon(rng, n, 0, 0, transformed);
    const exact::Shape b = polygon(rng, n, 2.5, 0.75, transformed);
    exact::Options o;
    o.route = route;
    for (auto _ : state)
    {
        exact::Result r = exact::distance(a, b, o);
        benchmark::DoNotOptimize(r.distance);
    }
    state.SetLabel(transformed ? "transformed" : "identity");
}

// Offsets in [-spread, spread]: 2.5 gives about 15% overlapping, 0.5 about 82%.
std::vector<std::pair<exact::Shape, exact::Shape>> smallCases(double spread = 2.5)
{
    std::mt19937_64 rng(2024);
    std::uniform_int_distribution<int> count(3, 8);
    std::uniform_real_distribution<double> coord(-1, 1), angle(0, 2 * std::acos(-1.0)),
        offset(-spread, spread), radius(0, 0.3);
    std::vector<std::pair<exact::Shape, exact::Shape>> cases;
    for (int k = 0; k < 1024; ++k)
    {
        exact::Shape s[2];
        for (auto& sh : s)
        {
            const int n = count(rng);
            for (int i = 0; i < n; ++i)
                sh.points.push_back({coord(rng), coord(rng)});
            const double a = angle(rng);
            sh.c = std::cos(a);
            sh.s = std::sin(a);
            sh.px = offset(rng);
            sh.py = offset(rng);
            sh.radius = k % 2 ? radius(rng) : 0.0;
        }
        cases.emplace_back(s[0], s[1]);
    }
    return cases;
}

void small(benchmark::State& state, exact::Options o)
{
    static const auto cases = smallCases();
    std::size_t k = 0, gmp = 0;
    for (auto _ : state)
    {
        const auto& c = cases[k++ % cases.size()];
        exact::Result r = exact::distance(c.first, c.second, o);
        gmp += r.fallbacks.gmp;
        benchmark::DoNotOptimize(r.distance);
    }
    state.counters["gmp"] = k ? double(gmp) / double(k) : 0.0; // share of cases on the GMP route
}

void overlapping(benchmark::State& state, exact::Options o)
{
    static const auto cases = smallCases(0.5);
    std::size_t k = 0, gmp = 0, overlaps = 0;
    for (auto _ : state)
    {
        const auto& c = cases[k++ % cases.size()];
        exact::Result r = exact::distance(c.first, c.second, o);
        gmp += r.fallbacks.depth || r.fallbacks.gmp;
        overlaps += r.overlap;
        benchmark::DoNotOptimize(r.distance);
        benchmark::DoNotOptimize(r.signedDistance);
    }
    state.counters["depth_gmp"] = k ? double(gmp) / double(k) : 0.0;
    state.counters["overlap"] = k ? double(overlaps) / double(k) : 0.0;
}

void bruteForceSmall(benchmark::State& state)
{
    static const auto cases = smallCases();
    std::size_t k = 0;
    for (auto _ : state)
    {
        const auto& c = cases[k++ % cases.size()];
        exact::Result r = exact::bruteForce(c.first, c.second);
        benchmark::DoNotOptimize(r.distance);
    }
}

const int registered = []
{
    for (exact::Route route : exact::kAllRoutes)
    {
        const std::string name = exact::routeName(route);
        exact::Options o;
        o.route = route;
        benchmark::RegisterBenchmark(("Small/" + name).c_str(), small, o)
            ->Unit(benchmark::kMicrosecond);
        auto* b = benchmark::RegisterBenchmark(("Pair/" + name).c_str(), pair, route)
                      ->Unit(benchmark::kMicrosecond);
        std::vector<int64_t> sizes = {4, 8, 64, 256, 1024, 8192};
        if (route == exact::Route::HullOfDifferences)
            sizes = {4, 8, 64, 256};
        if (route == exact::Route::MinkowskiSum2)
            sizes = {4, 8, 64, 256, 1024};
        for (int64_t n : sizes)
            for (int64_t t : {0, 1})
                b->Args({n, t});
    }
    exact::Options witnesses;
    witnesses.exactWitnesses = true;
    benchmark::RegisterBenchmark("Small/edge-merge+exact-witnesses", small, witnesses)
        ->Unit(benchmark::kMicrosecond);
    exact::Options gmp; // the default route without its filter (--truth exact)
    gmp.filter = false;
    benchmark::RegisterBenchmark("Small/edge-merge+gmp", small, gmp)->Unit(benchmark::kMicrosecond);
    exact::Options noSquared; // what the runner asks for without --per-case
    noSquared.squaredRational = false;
    benchmark::RegisterBenchmark("Small/edge-merge-no-squared", small, noSquared)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark("Small/brute-force", bruteForceSmall)
        ->Unit(benchmark::kMicrosecond);
    exact::Options pen;
    pen.penetration = true;
    exact::Options penGmp = pen;
    penGmp.filter = false;
    exact::Options penNoSquared = pen;
    penNoSquared.squaredRational = false;
    for (const auto& [name, o] :
         {std::pair{"plain", exact::Options{}}, std::pair{"penetration", pen},
          std::pair{"penetration+gmp", penGmp}, std::pair{"no-squared", noSquared},
          std::pair{"penetration-no-squared", penNoSquared}})
        benchmark::RegisterBenchmark((std::string("Overlap/") + name).c_str(), overlapping, o)
            ->Unit(benchmark::kMicrosecond);
    return 0;
}();

} // namespace

BENCHMARK_MAIN();
