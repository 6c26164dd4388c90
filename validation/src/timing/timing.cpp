#include "timing/timing.hpp"

#include "evaluate/evaluate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
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

template <class T> double timePass(const TimingSet<T>& set, const gjk::Options& o, int reps)
{
    const auto t0 = Clock::now();
    double acc = 0;
    const std::size_t n = set.inputs.size();
    if constexpr (std::is_same_v<T, double>)
        if (o.correctlyRounded) // as query(): the undecided queries completed exactly
        {
            for (int r = 0; r < reps; ++r)
                for (std::size_t i = 0; i < n; ++i)
                {
                    gjk::SimplexCache cache = set.caches.empty() ? gjk::SimplexCache{} : set.caches[i];
                    gjk::DistanceOutput<T> out = gjk::distance(set.inputs[i], cache, o);
                    if (out.path == gjk::CorrectPath::NeedsExact) [[unlikely]]
                        completeExactly(set.inputs[i], o, out);
                    acc += double(out.distance);
                }
            const auto t1 = Clock::now();
            g_timingSink = g_timingSink + acc;
            return std::chrono::duration<double, std::nano>(t1 - t0).count();
        }
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

template <class T>
TimingResult timeT(const std::vector<const PreparedCase*>& cases, const gjk::Options& o,
                   const TimingConfig& cfg, bool warm)
{
    TimingResult res;
    res.cases = cases.size();
    res.warm = warm;
    if (cases.empty())
        return res;
    const TimingSet<T> set(cases, o, warm);
    const double first = std::max(1.0, timePass<T>(set, o, 1)); // warm-up and calibration
    const int reps = std::clamp(int(std::ceil(cfg.minPassSeconds * 1e9 / first)), 1, 100000);
    std::vector<double> perQuery;
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    while (int(perQuery.size()) < cfg.maxPasses &&
           (int(perQuery.size()) < cfg.minPasses || elapsed() < cfg.budgetSeconds))
        perQuery.push_back(timePass<T>(set, o, reps) / (double(reps) * double(cases.size())));
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
} // namespace

TimingResult timeQueries(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                         const TimingConfig& cfg)
{
    const bool warm = v.start == Start::Warm || cfg.warm;
    return v.scalar == Scalar::Float ? timeT<float>(cases, v.options, cfg, warm)
                                     : timeT<double>(cases, v.options, cfg, warm);
}

} // namespace gjkval
