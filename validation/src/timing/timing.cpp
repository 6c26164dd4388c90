// Timed passes of the variants: the cases in one contiguous array per scalar type, a loop per kind
// of variant (plain, on prepared shapes, correctly rounded, batch, plugin) that keeps the whole
// answer, and the median over the passes.
#include "timing/timing.hpp"

#include "evaluate/evaluate.hpp"
#include "implementations/plugins.hpp"
#include "timing/plugin_timing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <type_traits>

#include <unistd.h>

namespace gjkval
{
namespace
{
using Clock = std::chrono::steady_clock;

double nsBetween(Clock::time_point t0, Clock::time_point t1)
{
    return std::chrono::duration<double, std::nano>(t1 - t0).count();
}

// Whether gjk2d's own variant is timed warm-started, plain or prepared alike.
bool timedWarm(const VariantInfo& v, const TimingConfig& cfg)
{
    return v.start == Start::Warm || cfg.warm;
}

volatile double g_timingSink = 0; // keeps the timed loops from being optimised away

// What a timed loop keeps of an answer: every number of it, summed as a tree (short dependency
// chains), so that the query is timed as a caller gets it. With only the distance kept, the
// compiler, which inlines gjk::distance here, would be free to drop the witness points and the
// normal; GCC 12 did not (the same ns on `random`: docs/speed.md, "Timed loops keep the whole
// answer"), and now no compiler may. A plugin's call is never inlined: its answer is whole.
template <class T> double kept(const gjk::DistanceOutput<T>& o)
{
    const double points =
        (double(o.pointA.x) + double(o.pointA.y)) + (double(o.pointB.x) + double(o.pointB.y));
    const double rest =
        (double(o.normal.x) + double(o.normal.y)) + (double(o.distance) + double(o.iterations));
    return points + rest;
}

// The timed inputs in one scalar type, stored contiguously (points and inputs in case order) so
// that the timing measures GJK rather than scattered memory; with the warm-start caches.
template <class T> struct TimingSet
{
    std::vector<gjk::Vec2<T>> points;
    std::vector<gjk::DistanceInput<T>> inputs;
    std::vector<gjk::SimplexCache> caches; // warm: the cache of a cold query of each case

    TimingSet(const std::vector<const PreparedCase*>& cases, const gjk::Options& o, bool warm)
    {
        std::size_t n = 0;
        for (const PreparedCase* p : cases)
        {
            const auto in = p->input<T>();
            n += std::size_t(in.proxyA.count + in.proxyB.count);
        }
        points.reserve(n); // no reallocation below: the inputs point into it
        for (const PreparedCase* p : cases)
        {
            auto in = p->input<T>();
            for (gjk::Polygon<T>* poly : {&in.proxyA, &in.proxyB})
            {
                const std::size_t at = points.size();
                points.insert(points.end(), poly->points, poly->points + poly->count);
                poly->points = points.data() + at;
            }
            inputs.push_back(in);
        }
        if (warm)
        {
            caches.resize(inputs.size());
            for (std::size_t i = 0; i < inputs.size(); ++i)
                gjk::distance(inputs[i], caches[i], o);
        }
    }
};

// A correctly rounded variant, as query() runs it: the undecided queries completed exactly. Its own
// function, so that the plain loop below keeps its code (and its timing) as it was.
double timePassCorrect(const TimingSet<double>& set, const gjk::Options& o, int reps)
{
    const auto t0 = Clock::now();
    double acc = 0;
    const std::size_t n = set.inputs.size();
    for (int r = 0; r < reps; ++r)
        for (std::size_t i = 0; i < n; ++i)
        {
            gjk::SimplexCache cache = set.caches.empty() ? gjk::SimplexCache{} : set.caches[i];
            gjk::DistanceOutput<double> out = gjk::distance(set.inputs[i], cache, o);
            if (out.path == gjk::CorrectPath::NeedsExact) [[unlikely]]
                completeExactly(set.inputs[i], o, out);
            acc += kept(out);
        }
    const auto t1 = Clock::now();
    g_timingSink = g_timingSink + acc;
    return nsBetween(t0, t1);
}

// The timed loops: `reps` passes over the set, each query cold or from a copy of its case's warm
// cache (as in the accuracy run), answered by query(i, cache). A template on the query, so that
// each loop is compiled with its query inline.
template <class T, class Query> double timeLoops(const TimingSet<T>& set, int reps, Query query)
{
    const auto t0 = Clock::now();
    double acc = 0;
    const std::size_t n = set.inputs.size();
    if (set.caches.empty())
    {
        for (int r = 0; r < reps; ++r)
            for (std::size_t i = 0; i < n; ++i)
            {
                gjk::SimplexCache cache; // cold
                acc += kept(query(i, cache));
            }
    }
    else
    {
        for (int r = 0; r < reps; ++r)
            for (std::size_t i = 0; i < n; ++i)
            {
                gjk::SimplexCache cache = set.caches[i]; // warm: from the case's previous query
                acc += kept(query(i, cache));
            }
    }
    const auto t1 = Clock::now();
    g_timingSink = g_timingSink + acc;
    return nsBetween(t0, t1);
}

template <class T> double timePass(const TimingSet<T>& set, const gjk::Options& o, int reps)
{
    return timeLoops(set, reps,
                     [&](std::size_t i, gjk::SimplexCache& cache)
                     { return gjk::distance(set.inputs[i], cache, o); });
}

// A variant's prepared form (preparedLoop): the TimingSet's shapes prepared once by gjk::prepare,
// the preparation timed here, apart from the passes.
template <class T> struct PreparedTimingSet
{
    TimingSet<T> set;
    std::vector<gjk::PreparedShape<T>> a, b;
    double nsPerShape = -1;

    PreparedTimingSet(const std::vector<const PreparedCase*>& cases, const gjk::Options& o,
                      bool warm)
        : set(cases, o, warm)
    {
        const std::size_t n = set.inputs.size();
        a.reserve(n);
        b.reserve(n);
        const auto t0 = Clock::now();
        for (const gjk::DistanceInput<T>& in : set.inputs)
        {
            a.push_back(gjk::prepare(in.proxyA));
            b.push_back(gjk::prepare(in.proxyB));
        }
        const auto t1 = Clock::now();
        if (n > 0)
            nsPerShape = nsBetween(t0, t1) / double(2 * n);
    }
};

// timePass's loops on prepared shapes: the same queries, cold or from copies of the warm caches,
// through the prepared overload of gjk::distance with the case's transforms.
template <class T>
double timePassPrepared(const PreparedTimingSet<T>& p, const gjk::Options& o, int reps)
{
    return timeLoops(p.set, reps,
                     [&](std::size_t i, gjk::SimplexCache& cache)
                     {
                         const gjk::DistanceInput<T>& in = p.set.inputs[i];
                         return gjk::distance(p.a[i], in.transformA, p.b[i], in.transformB, cache,
                                              o);
                     });
}

template <class T>
TimedLoop preparedLoopT(const std::vector<const PreparedCase*>& cases, const gjk::Options& o,
                        bool warm)
{
    TimedLoop loop;
    loop.cases = cases.size();
    loop.warm = warm;
    if (cases.empty())
        return loop;
    auto state = std::make_shared<PreparedTimingSet<T>>(cases, o, warm);
    loop.pass = [state, o](int reps) { return timePassPrepared<T>(*state, o, reps); };
    loop.prepareNsPerShape = [state] { return state->nsPerShape; };
    return loop;
}

// A batch variant: each rep is one gjk::distanceBatchLanes over all the cases (fresh caches, or
// copies of the warm ones), as an engine's step or a campaign's chunk would call it.
template <class T>
double timePassBatch(const TimingSet<T>& set, const gjk::Options& o, int reps,
                     std::vector<gjk::SimplexCache>& caches,
                     std::vector<gjk::DistanceOutput<T>>& outputs)
{
    const auto t0 = Clock::now();
    double acc = 0;
    for (int r = 0; r < reps; ++r)
    {
        if (set.caches.empty())
            std::fill(caches.begin(), caches.end(), gjk::SimplexCache{});
        else
            std::copy(set.caches.begin(), set.caches.end(), caches.begin());
        gjk::distanceBatchLanes(std::span<const gjk::DistanceInput<T>>(set.inputs), caches, outputs,
                                o);
        for (const auto& out : outputs)
            acc += kept(out);
    }
    const auto t1 = Clock::now();
    g_timingSink = g_timingSink + acc;
    return nsBetween(t0, t1);
}

// The loop's state (the contiguous inputs, a batch's caches and outputs), owned by its pass.
template <class T> struct LoopState
{
    TimingSet<T> set;
    std::vector<gjk::SimplexCache> caches;
    std::vector<gjk::DistanceOutput<T>> outputs;
    LoopState(const std::vector<const PreparedCase*>& cases, const gjk::Options& o, bool warm,
              bool batch)
        : set(cases, o, warm), caches(batch ? set.inputs.size() : 0),
          outputs(batch ? set.inputs.size() : 0)
    {
    }
};

template <class T>
TimedLoop loopT(const std::vector<const PreparedCase*>& cases, const gjk::Options& o, bool warm,
                bool batch)
{
    TimedLoop loop;
    loop.cases = cases.size();
    loop.warm = warm;
    if (cases.empty())
        return loop;
    auto state = std::make_shared<LoopState<T>>(cases, o, warm, batch);
    loop.pass = [state, o, batch](int reps)
    {
        if (batch)
            return timePassBatch<T>(state->set, o, reps, state->caches, state->outputs);
        if constexpr (std::is_same_v<T, double>)
            if (o.correctlyRounded)
                return timePassCorrect(state->set, o, reps);
        return timePass<T>(state->set, o, reps);
    };
    return loop;
}

} // namespace

double medianOfSorted(const std::vector<double>& xs)
{
    const std::size_t n = xs.size();
    if (n == 0)
        return -1;
    return n % 2 ? xs[n / 2] : 0.5 * (xs[n / 2 - 1] + xs[n / 2]);
}

namespace
{
// The median, min and max of a loop's per-query times (sorted in place).
TimingResult summary(std::size_t cases, std::vector<double>& perQuery, int reps)
{
    TimingResult res;
    res.cases = cases;
    std::sort(perQuery.begin(), perQuery.end());
    const std::size_t n = perQuery.size();
    if (n == 0)
        return res;
    res.nsPerQuery = medianOfSorted(perQuery);
    res.nsMin = perQuery.front();
    res.nsMax = perQuery.back();
    res.passes = int(n);
    res.repsPerPass = reps;
    return res;
}

// One calibration pass: the reps that make a pass last cfg.minPassSeconds.
int calibrate(const TimingConfig& cfg, const std::function<double(int)>& pass)
{
    const double once = pass(1);
    if (once < 0) // a plugin's own loop that failed (ownTimingLoop)
        return 0;
    const double first = std::max(1.0, once); // warm-up and calibration
    return std::clamp(int(std::ceil(cfg.minPassSeconds * 1e9 / first)), 1, 100000);
}
} // namespace

TimedLoop variantLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                      const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    if (v.plugin && v.plugin->kind == PluginKind::Executable)
        return adapterLoop(cases, v, cfg, pluginTimeoutSeconds);
    if (v.plugin && v.plugin->kind == PluginKind::InProcess)
        return inProcessLoop(cases, v);
    if (v.plugin)
        return sharedLibraryLoop(cases, v, cfg, pluginTimeoutSeconds);
    const bool warm = timedWarm(v, cfg);
    return v.scalar == Scalar::Float ? loopT<float>(cases, v.options, warm, v.batch)
                                     : loopT<double>(cases, v.options, warm, v.batch);
}

TimedLoop preparedLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                       const TimingConfig& cfg)
{
    if (!hasPreparedForm(v))
        return {};
    const bool warm = timedWarm(v, cfg);
    return v.scalar == Scalar::Float ? preparedLoopT<float>(cases, v.options, warm)
                                     : preparedLoopT<double>(cases, v.options, warm);
}

PinnedToOneCpu::PinnedToOneCpu()
{
    CPU_ZERO(&previous_);
    const int cpu = ::sched_getcpu();
    if (cpu < 0 || cpu >= CPU_SETSIZE || ::sched_getaffinity(0, sizeof previous_, &previous_) != 0)
        return;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu, &one);
    if (::sched_setaffinity(0, sizeof one, &one) == 0)
        cpu_ = cpu;
}

PinnedToOneCpu::~PinnedToOneCpu()
{
    if (cpu_ >= 0)
        ::sched_setaffinity(0, sizeof previous_, &previous_);
}

std::vector<TimingResult> medianOfAlternatedPasses(const std::vector<TimedLoop>& loops,
                                                   const TimingConfig& cfg)
{
    const std::size_t n = loops.size();
    std::vector<int> reps(n, 0); // 0: no cases, or lost (a negative time)
    std::vector<std::vector<double>> perQuery(n);
    for (std::size_t k = 0; k < n; ++k)
        if (loops[k].cases > 0)
            reps[k] = calibrate(cfg, loops[k].pass);
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    // The budget is per loop, as a loop timed alone has it; round p starts at loop p mod n, so
    // that no loop always runs first (or last) in a round.
    const double budget = cfg.budgetSeconds * double(std::max<std::size_t>(n, 1));
    for (int p = 0; p < cfg.maxPasses && (p < cfg.minPasses || elapsed() < budget); ++p)
        for (std::size_t j = 0; j < n; ++j)
        {
            const std::size_t k = (std::size_t(p) + j) % n;
            if (reps[k] == 0)
                continue;
            const double ns = loops[k].pass(reps[k]);
            if (ns < 0)
                reps[k] = 0;
            else
                perQuery[k].push_back(ns / (double(reps[k]) * double(loops[k].cases)));
        }
    std::vector<TimingResult> results;
    for (std::size_t k = 0; k < n; ++k)
    {
        if (reps[k] == 0)
            perQuery[k].clear();
        results.push_back(summary(loops[k].cases, perQuery[k], reps[k]));
        results.back().warm = loops[k].warm;
        if (reps[k] > 0 && loops[k].prepareNsPerShape)
            results.back().prepareNsPerShape = loops[k].prepareNsPerShape();
    }
    return results;
}

std::vector<TimingResult> timeAlternated(const std::vector<std::vector<const PreparedCase*>>& cases,
                                         const std::vector<const VariantInfo*>& variants,
                                         const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    const std::size_t n = variants.size();
    std::vector<TimedLoop> loops;
    for (std::size_t k = 0; k < n; ++k)
        loops.push_back(variantLoop(cases[k], *variants[k], cfg, pluginTimeoutSeconds));
    std::vector<std::size_t> prepared(n, 0); // the index of variant k's prepared loop; 0: none
    for (std::size_t k = 0; k < n; ++k)
        if (hasPreparedForm(*variants[k]) && !cases[k].empty())
        {
            prepared[k] = loops.size();
            loops.push_back(preparedLoop(cases[k], *variants[k], cfg));
        }
    std::vector<TimingResult> results = medianOfAlternatedPasses(loops, cfg);
    for (std::size_t k = 0; k < n; ++k)
    {
        results[k].cases = loops[k].cases;
        if (prepared[k] > 0)
        {
            results[k].preparedNsPerQuery = results[prepared[k]].nsPerQuery;
            results[k].prepareNsPerShape = results[prepared[k]].prepareNsPerShape;
        }
    }
    results.resize(n);
    return results;
}

} // namespace gjkval
