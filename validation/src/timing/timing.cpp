#include "timing/timing.hpp"

#include "evaluate/evaluate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
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

template <class T>
TimingResult timeT(const std::vector<const PreparedCase*>& cases, const gjk::Options& o,
                   const TimingConfig& cfg, bool warm, bool batch)
{
    if (cases.empty())
    {
        TimingResult res;
        res.warm = warm;
        return res;
    }
    const TimingSet<T> set(cases, o, warm);
    std::vector<gjk::SimplexCache> caches(batch ? set.inputs.size() : 0);
    std::vector<gjk::DistanceOutput<T>> outputs(batch ? set.inputs.size() : 0);
    auto pass = [&](int reps)
    {
        if (batch)
            return timePassBatch<T>(set, o, reps, caches, outputs);
        if constexpr (std::is_same_v<T, double>)
            if (o.correctlyRounded)
                return timePassCorrect(set, o, reps);
        return timePass<T>(set, o, reps);
    };
    TimingResult res = medianOfPasses(cases.size(), cfg, pass);
    res.warm = warm;
    return res;
}
} // namespace

TimingResult medianOfPasses(std::size_t cases, const TimingConfig& cfg,
                            const std::function<double(int)>& pass)
{
    TimingResult res;
    res.cases = cases;
    if (cases == 0)
        return res;
    const double first = std::max(1.0, pass(1)); // warm-up and calibration
    const int reps = std::clamp(int(std::ceil(cfg.minPassSeconds * 1e9 / first)), 1, 100000);
    std::vector<double> perQuery;
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    while (int(perQuery.size()) < cfg.maxPasses &&
           (int(perQuery.size()) < cfg.minPasses || elapsed() < cfg.budgetSeconds))
        perQuery.push_back(pass(reps) / (double(reps) * double(cases)));
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

TimingResult timeQueries(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                         const TimingConfig& cfg)
{
    const bool warm = v.start == Start::Warm || cfg.warm;
    return v.scalar == Scalar::Float ? timeT<float>(cases, v.options, cfg, warm, v.batch)
                                     : timeT<double>(cases, v.options, cfg, warm, v.batch);
}

} // namespace gjkval
