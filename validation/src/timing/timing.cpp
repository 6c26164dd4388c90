#include "timing/timing.hpp"

#include "evaluate/evaluate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <type_traits>

namespace gjkval
{
namespace
{
using Clock = std::chrono::steady_clock;

volatile double g_timingSink = 0; // keeps the timed loops from being optimised away

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
            acc += out.distance;
        }
    const auto t1 = Clock::now();
    g_timingSink = g_timingSink + acc;
    return std::chrono::duration<double, std::nano>(t1 - t0).count();
}

template <class T> double timePass(const TimingSet<T>& set, const gjk::Options& o, int reps)
{
    const auto t0 = Clock::now();
    double acc = 0;
    const std::size_t n = set.inputs.size();
    if (set.caches.empty())
    {
        for (int r = 0; r < reps; ++r)
            for (std::size_t i = 0; i < n; ++i)
            {
                gjk::SimplexCache cache; // cold, as in the accuracy run
                acc += double(gjk::distance(set.inputs[i], cache, o).distance);
            }
    }
    else
    {
        for (int r = 0; r < reps; ++r)
            for (std::size_t i = 0; i < n; ++i)
            {
                gjk::SimplexCache cache = set.caches[i]; // warm: from the case's previous query
                acc += double(gjk::distance(set.inputs[i], cache, o).distance);
            }
    }
    const auto t1 = Clock::now();
    g_timingSink = g_timingSink + acc;
    return std::chrono::duration<double, std::nano>(t1 - t0).count();
}

// A batch variant: each rep is one gjk::distanceBatch over all the cases (fresh caches, or copies
// of the warm ones), as an engine's step or a campaign's chunk would call it.
template <class T>
double timePassBatch(const TimingSet<T>& set, const gjk::Options& o, int reps, std::vector<gjk::SimplexCache>& caches,
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
        gjk::distanceBatch(std::span<const gjk::DistanceInput<T>>(set.inputs), caches, outputs, o);
        for (const auto& out : outputs)
            acc += double(out.distance);
    }
    const auto t1 = Clock::now();
    g_timingSink = g_timingSink + acc;
    return std::chrono::duration<double, std::nano>(t1 - t0).count();
}

// The loop's state (the contiguous inputs, a batch's caches and outputs), owned by its pass.
template <class T> struct LoopState
{
    TimingSet<T> set;
    std::vector<gjk::SimplexCache> caches;
    std::vector<gjk::DistanceOutput<T>> outputs;
    LoopState(const std::vector<const PreparedCase*>& cases, const gjk::Options& o, bool warm, bool batch)
        : set(cases, o, warm), caches(batch ? set.inputs.size() : 0), outputs(batch ? set.inputs.size() : 0)
    {
    }
};

template <class T>
TimedLoop loopT(const std::vector<const PreparedCase*>& cases, const gjk::Options& o, bool warm, bool batch)
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

// The median, min and max of a loop's per-query times (sorted in place).
TimingResult summary(std::size_t cases, std::vector<double>& perQuery, int reps)
{
    TimingResult res;
    res.cases = cases;
    std::sort(perQuery.begin(), perQuery.end());
    const std::size_t n = perQuery.size();
    if (n == 0)
        return res;
    res.nsPerQuery = n % 2 ? perQuery[n / 2] : 0.5 * (perQuery[n / 2 - 1] + perQuery[n / 2]);
    res.nsMin = perQuery.front();
    res.nsMax = perQuery.back();
    res.passes = int(n);
    res.repsPerPass = reps;
    return res;
}

// One calibration pass: the reps that make a pass last cfg.minPassSeconds.
int calibrate(const TimingConfig& cfg, const std::function<double(int)>& pass)
{
    const double first = std::max(1.0, pass(1)); // warm-up and calibration
    return std::clamp(int(std::ceil(cfg.minPassSeconds * 1e9 / first)), 1, 100000);
}
} // namespace

TimedLoop timedLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v, const TimingConfig& cfg)
{
    const bool warm = v.start == Start::Warm || cfg.warm;
    return v.scalar == Scalar::Float ? loopT<float>(cases, v.options, warm, v.batch)
                                     : loopT<double>(cases, v.options, warm, v.batch);
}

std::vector<TimingResult> medianOfAlternatedPasses(const std::vector<TimedLoop>& loops, const TimingConfig& cfg)
{
    std::vector<int> reps(loops.size(), 0);
    std::vector<std::vector<double>> perQuery(loops.size());
    for (std::size_t k = 0; k < loops.size(); ++k)
        if (loops[k].cases > 0)
            reps[k] = calibrate(cfg, loops[k].pass);
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    for (int p = 0; p < cfg.maxPasses && (p < cfg.minPasses || elapsed() < cfg.budgetSeconds); ++p)
        for (std::size_t k = 0; k < loops.size(); ++k)
            if (loops[k].cases > 0)
                perQuery[k].push_back(loops[k].pass(reps[k]) / (double(reps[k]) * double(loops[k].cases)));
    std::vector<TimingResult> results;
    for (std::size_t k = 0; k < loops.size(); ++k)
    {
        results.push_back(summary(loops[k].cases, perQuery[k], reps[k]));
        results.back().warm = loops[k].warm;
    }
    return results;
}

TimingResult medianOfPasses(std::size_t cases, const TimingConfig& cfg,
                            const std::function<double(int)>& pass)
{
    if (cases == 0)
    {
        TimingResult res;
        res.cases = cases;
        return res;
    }
    const int reps = calibrate(cfg, pass);
    std::vector<double> perQuery;
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    while (int(perQuery.size()) < cfg.maxPasses &&
           (int(perQuery.size()) < cfg.minPasses || elapsed() < cfg.budgetSeconds))
        perQuery.push_back(pass(reps) / (double(reps) * double(cases)));
    return summary(cases, perQuery, reps);
}

TimingResult timeQueries(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                         const TimingConfig& cfg)
{
    const TimedLoop loop = timedLoop(cases, v, cfg);
    TimingResult res;
    if (loop.cases > 0)
        res = medianOfPasses(loop.cases, cfg, loop.pass);
    res.cases = loop.cases;
    res.warm = loop.warm;
    return res;
}

} // namespace gjkval
