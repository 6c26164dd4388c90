// Timed passes of the variants: the cases in one contiguous array per scalar type, a loop per kind
// of variant (plain, correctly rounded, batch, plugin) that keeps the whole answer, and the median
// over the passes.
#include "timing/timing.hpp"

#include "evaluate/evaluate.hpp"
#include "implementations/adapter.hpp"
#include "implementations/in_process.hpp"
#include "implementations/plugins.hpp"

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
                acc += kept(gjk::distance(set.inputs[i], cache, o));
            }
    }
    else
    {
        for (int r = 0; r < reps; ++r)
            for (std::size_t i = 0; i < n; ++i)
            {
                gjk::SimplexCache cache = set.caches[i]; // warm: from the case's previous query
                acc += kept(gjk::distance(set.inputs[i], cache, o));
            }
    }
    const auto t1 = Clock::now();
    g_timingSink = g_timingSink + acc;
    return std::chrono::duration<double, std::nano>(t1 - t0).count();
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
    return std::chrono::duration<double, std::nano>(t1 - t0).count();
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

// A plugin variant's timed inputs: each case's two shapes in the ABI's struct (gjk2d/plugin.h), in
// the implementation's scalar type, their points in one contiguous array: built once, before
// timing, as TimingSet builds gjk2d's. Built per call from each case's own vectors (allocated
// chunk by chunk by the campaign's worker threads, scattered over the heap), `run` read the plugin
// 1.7x slower than `bench` (which prepares its cases in one sequence), while `double` (timed from
// a TimingSet) agreed.
template <class T, class Shape> struct PluginTimingSet
{
    std::vector<T> coords;
    std::vector<Shape> a, b;

    explicit PluginTimingSet(const std::vector<const PreparedCase*>& cases)
    {
        std::size_t n = 0;
        for (const PreparedCase* p : cases)
        {
            const auto in = p->input<T>();
            n += 2 * std::size_t(in.proxyA.count + in.proxyB.count);
        }
        coords.reserve(n); // no reallocation below: the shapes point into it
        for (const PreparedCase* p : cases)
        {
            const auto in = p->input<T>();
            a.push_back(shape(in.proxyA, in.transformA));
            b.push_back(shape(in.proxyB, in.transformB));
        }
    }

    Shape shape(const gjk::Polygon<T>& poly, const gjk::Transform<T>& xf)
    {
        const std::size_t at = coords.size();
        for (int i = 0; i < poly.count; ++i)
        {
            coords.push_back(poly.points[i].x);
            coords.push_back(poly.points[i].y);
        }
        Shape s{};
        s.points = coords.data() + at;
        s.count = std::int32_t(poly.count);
        s.radius = poly.radius;
        s.position[0] = xf.p.x;
        s.position[1] = xf.p.y;
        s.rotation[0] = xf.q.c;
        s.rotation[1] = xf.q.s;
        return s;
    }
};

// A plugin's pass: what an engine's call of it costs, the ABI call and nothing else. Per query:
// its cache_bytes zeroed (a cold start, as gjk2d's fresh SimplexCache), one call through the
// function pointer, the result read. No copy of the inputs, no IPC: the child process that runs
// it (timeContained) reports only the passes' times, after timing.
template <class T, class Shape, class Result, class Fn>
double timePassPlugin(const PluginTimingSet<T, Shape>& set, Fn fn,
                      std::vector<unsigned char>& cache, int cacheBytes, int reps)
{
    void* c = cacheBytes > 0 ? cache.data() : nullptr;
    const std::size_t n = set.a.size();
    const auto t0 = Clock::now();
    double acc = 0;
    for (int r = 0; r < reps; ++r)
        for (std::size_t i = 0; i < n; ++i)
        {
            std::memset(cache.data(), 0, std::size_t(cacheBytes));
            Result o{};
            fn(&set.a[i], &set.b[i], c, &o);
            acc += double(o.distance);
        }
    const auto t1 = Clock::now();
    g_timingSink = g_timingSink + acc;
    return std::chrono::duration<double, std::nano>(t1 - t0).count();
}

template <class T, class Shape, class Result, class Fn>
TimedLoop pluginLoopT(const std::vector<const PreparedCase*>& cases, Fn fn, int cacheBytes)
{
    TimedLoop loop;
    loop.cases = cases.size();
    if (cases.empty())
        return loop;
    auto set = std::make_shared<PluginTimingSet<T, Shape>>(cases);
    auto cache = std::make_shared<std::vector<unsigned char>>(std::size_t(std::max(cacheBytes, 1)));
    loop.pass = [set, cache, fn, cacheBytes](int reps)
    { return timePassPlugin<T, Shape, Result>(*set, fn, *cache, cacheBytes, reps); };
    return loop;
}

TimedLoop pluginLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v)
{
    const gjk2d_implementation& im = v.plugin->impl;
    if (im.scalar == GJK2D_SCALAR_FLOAT)
        return pluginLoopT<float, gjk2d_shape_f, gjk2d_result_f>(cases, im.distance_f,
                                                                 im.cache_bytes);
    return pluginLoopT<double, gjk2d_shape_d, gjk2d_result_d>(cases, im.distance_d, im.cache_bytes);
}

// Reads n bytes from fd, waiting as long as it takes: false at end of file or on an error.
bool readAllBytes(int fd, void* data, std::size_t n)
{
    auto* p = static_cast<char*>(data);
    while (n > 0)
    {
        const ssize_t got = ::read(fd, p, n);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            return false;
        p += got;
        n -= std::size_t(got);
    }
    return true;
}

// The child's side of ownTimingLoop(): prepare once, then one pass per command (the reps, an
// int32; end of file ends it), each pass's nanoseconds sent back; a failed prepare() sends -1.
void serveOwnTiming(const gjk2d_timing& t, int index, const void* a, const void* b,
                    std::size_t count, bool warm, int out, int in)
{
    void* prepared = t.prepare(index, a, b, std::int32_t(count), warm ? 1 : 0);
    double ns = prepared ? 0.0 : -1.0;
    writeToParent(out, &ns, sizeof ns);
    std::int32_t reps = 0;
    while (prepared && readAllBytes(in, &reps, sizeof reps) && reps > 0)
    {
        ns = t.pass(prepared, reps);
        if (!writeToParent(out, &ns, sizeof ns))
            break;
    }
    if (prepared)
        t.release(prepared);
}

// The parent's side: the child, and whether it is lost (then every pass answers -1).
struct OwnTimingChild
{
    PluginChild child;
    std::string variant;
    double limitSeconds = 0;
    bool lost = false;

    double receive(const char* what)
    {
        double ns = -1;
        std::size_t have = 0;
        long n = 1;
        while (have < sizeof ns && (n = child.read(reinterpret_cast<char*>(&ns) + have,
                                                   sizeof ns - have, limitSeconds)) > 0)
            have += std::size_t(n);
        if (have == sizeof ns && ns >= 0)
            return ns;
        if (n < 0)
            child.kill();
        else
            child.finish();
        lost = true;
        std::fprintf(stderr,
                     "gjk-validate: plugin variant '%s': its timing loop %s %s; no "
                     "ns/query\n",
                     variant.c_str(),
                     have == sizeof ns ? "failed"
                     : n < 0           ? "hung"
                                       : "crashed",
                     what);
        return -1;
    }
    double pass(int reps)
    {
        if (lost)
            return -1;
        const std::int32_t r = reps;
        child.send(&r, sizeof r); // when it fails, the child is gone: receive() says so
        return receive("in a pass");
    }
    ~OwnTimingChild()
    {
        if (!lost)
            child.finish(); // end of file on its commands: it releases and exits
    }
};

template <class T, class Shape>
TimedLoop ownLoopT(const std::vector<const PreparedCase*>& cases, const VariantInfo& v, bool warm,
                   double limitSeconds)
{
    TimedLoop loop;
    loop.cases = cases.size();
    loop.warm = warm;
    if (cases.empty())
        return loop;
    const PluginTimingSet<T, Shape> set(cases); // before the fork: the child only prepares
    const PluginImpl& im = *v.plugin;
    auto own = std::make_shared<OwnTimingChild>();
    own->variant = v.name;
    own->limitSeconds = limitSeconds;
    own->child = PluginChild::serve(&im,
                                    [&](int out, int in) {
                                        serveOwnTiming(*im.timing, im.index, set.a.data(),
                                                       set.b.data(), set.a.size(), warm, out, in);
                                    });
    own->receive("in prepare()");
    loop.pass = [own](int reps) { return own->pass(reps); };
    return loop;
}

// How long a plugin's pass (or an adapter's `time` request, a part of one) may take before it
// counts as hung: a pass lasts at most min_pass_s plus one loop over the cases, and the limit
// allows a loop of 50,000 cases (kTimingSampleCases) at 600 us a query, or one call that hangs.
double passLimitSeconds(const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    return pluginTimeoutSeconds + 30 + 4 * cfg.minPassSeconds;
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
    const double once = pass(1);
    if (once < 0) // a plugin's own loop that failed (ownTimingLoop)
        return 0;
    const double first = std::max(1.0, once); // warm-up and calibration
    return std::clamp(int(std::ceil(cfg.minPassSeconds * 1e9 / first)), 1, 100000);
}
} // namespace

TimedLoop timedLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                    const TimingConfig& cfg)
{
    if (v.plugin)
        return pluginLoop(cases, v);
    const bool warm = v.start == Start::Warm || cfg.warm;
    return v.scalar == Scalar::Float ? loopT<float>(cases, v.options, warm, v.batch)
                                     : loopT<double>(cases, v.options, warm, v.batch);
}

TimedLoop ownTimingLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                        bool warm, const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    const double limit = passLimitSeconds(cfg, pluginTimeoutSeconds);
    if (v.plugin->impl.scalar == GJK2D_SCALAR_FLOAT)
        return ownLoopT<float, gjk2d_shape_f>(cases, v, warm, limit);
    return ownLoopT<double, gjk2d_shape_d>(cases, v, warm, limit);
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
    std::vector<int> reps(loops.size(), 0); // 0: no cases, or lost (a negative time)
    std::vector<std::vector<double>> perQuery(loops.size());
    for (std::size_t k = 0; k < loops.size(); ++k)
        if (loops[k].cases > 0)
            reps[k] = calibrate(cfg, loops[k].pass);
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    for (int p = 0; p < cfg.maxPasses && (p < cfg.minPasses || elapsed() < cfg.budgetSeconds); ++p)
        for (std::size_t k = 0; k < loops.size(); ++k)
            if (reps[k] > 0)
            {
                const double ns = loops[k].pass(reps[k]);
                if (ns < 0)
                    reps[k] = 0;
                else
                    perQuery[k].push_back(ns / (double(reps[k]) * double(loops[k].cases)));
            }
    std::vector<TimingResult> results;
    for (std::size_t k = 0; k < loops.size(); ++k)
    {
        if (reps[k] == 0)
            perQuery[k].clear();
        results.push_back(summary(loops[k].cases, perQuery[k], reps[k]));
        results.back().warm = loops[k].warm;
    }
    return results;
}

TimingResult medianOfPasses(std::size_t cases, const TimingConfig& cfg,
                            const std::function<double(int)>& pass,
                            const std::function<void()>& afterPass)
{
    if (cases == 0)
    {
        TimingResult res;
        res.cases = cases;
        return res;
    }
    const int reps = calibrate(cfg, pass);
    if (reps == 0)
    {
        TimingResult res;
        res.cases = cases;
        return res;
    }
    std::vector<double> perQuery;
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    while (int(perQuery.size()) < cfg.maxPasses &&
           (int(perQuery.size()) < cfg.minPasses || elapsed() < cfg.budgetSeconds))
    {
        if (afterPass)
            afterPass();
        perQuery.push_back(pass(reps) / (double(reps) * double(cases)));
    }
    return summary(cases, perQuery, reps);
}

namespace
{
// An executable adapter's timed sample: the cases' request text in chunks of at most
// kAdapterTimeChunkCases, written once, before timing.
// The chunk size: a pass sends every chunk as one `time` request with K = the pass's reps, so the
// adapter repeats a chunk K times where a shared library's pass repeats the whole sample; with
// the sample in one chunk up to this size, the two loops are the same (see
// docs/validate-your-gjk.md for the bridge's timing against the shared library's). A chunk of
// 2,048 cases of 8 points is a line of about 1.5 MB.
constexpr std::size_t kAdapterTimeChunkCases = 2048;

struct AdapterChunks
{
    std::vector<std::string> text; // each: its cases' "A ... B ..." joined by spaces
    std::vector<std::size_t> cases;
};

AdapterChunks adapterChunks(const std::vector<const PreparedCase*>& cases, const VariantInfo& v)
{
    AdapterChunks c;
    for (std::size_t i = 0; i < cases.size(); ++i)
    {
        if (i % kAdapterTimeChunkCases == 0)
        {
            c.text.emplace_back();
            c.cases.push_back(0);
        }
        c.text.back() += (c.cases.back() == 0 ? "" : " ") + adapterCaseText(v, *cases[i]);
        ++c.cases.back();
    }
    return c;
}

struct AdapterLost // a `time` request without its answer: the variant gets no ns/query
{
};
} // namespace

TimingResult timeAdapter(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                         const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    const std::vector<const PreparedCase*> sample(
        cases.begin(), cases.begin() + std::ptrdiff_t(std::min(cases.size(), kAdapterTimingCases)));
    TimingResult res;
    res.cases = sample.size();
    if (sample.empty())
        return res;
    const AdapterChunks chunks = adapterChunks(sample, v);
    const double limit = passLimitSeconds(cfg, pluginTimeoutSeconds);
    // A pass: every chunk's time, K = reps; only the adapter's own timed loops are summed.
    const auto pass = [&](int reps)
    {
        double ns = 0;
        for (std::size_t k = 0; k < chunks.text.size(); ++k)
        {
            const double t = adapterTime(v, reps, chunks.cases[k], chunks.text[k], limit,
                                         fmt::format("timing chunk {}", k))
                                 .ns;
            if (t < 0)
                throw AdapterLost{};
            ns += t;
        }
        return ns;
    };
    try
    {
        return medianOfPasses(sample.size(), cfg, pass);
    }
    catch (const AdapterLost&)
    {
        return res;
    }
}

TimingResult timeInProcess(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                           const TimingConfig& cfg)
{
    const std::vector<const PreparedCase*> sample(
        cases.begin(), cases.begin() + std::ptrdiff_t(std::min(cases.size(), kAdapterTimingCases)));
    TimingResult res;
    res.cases = sample.size();
    const InProcessCalls* calls = v.plugin->calls.get();
    if (sample.empty() || calls == nullptr)
        return res;
    std::vector<ExternalAnswer> out(sample.size());
    const auto pass = [&](int reps)
    {
        const auto t0 = Clock::now();
        for (int r = 0; r < reps; ++r)
            if (calls->perBatch)
                calls->perBatch(sample, out);
            else
                for (std::size_t i = 0; i < sample.size(); ++i)
                    calls->perCase(*sample[i], out[i]);
        const auto t1 = Clock::now();
        g_timingSink = g_timingSink + out[0].distance;
        return std::chrono::duration<double, std::nano>(t1 - t0).count();
    };
    try
    {
        return medianOfPasses(sample.size(), cfg, pass);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr,
                     "gjk-validate: in-process variant '%s' raised while timed: %s; no "
                     "ns/query\n",
                     v.name.c_str(), e.what());
        return res;
    }
}

TimingResult timeContained(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                           const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    TimingResult res;
    res.cases = cases.size();
    const TimedLoop loop = timedLoop(cases, v, cfg); // before the fork: the child only times
    if (loop.cases == 0)
        return res;
    // The child sends '.' before each pass (the calibration's included), then 'R' and the result.
    PluginChild child =
        PluginChild::start(v.plugin,
                           [&](int fd)
                           {
                               const auto tick = [fd] { writeToParent(fd, ".", 1); };
                               tick();
                               const TimingResult t =
                                   medianOfPasses(loop.cases, cfg, loop.pass, tick);
                               writeToParent(fd, "R", 1);
                               writeToParent(fd, &t, sizeof t);
                           });
    const double limit = passLimitSeconds(cfg, pluginTimeoutSeconds);
    char mark = 0;
    long n = 0;
    while ((n = child.read(&mark, 1, limit)) > 0 && mark == '.')
    {
    }
    TimingResult got;
    std::size_t have = 0;
    while (n > 0 && mark == 'R' && have < sizeof got &&
           (n = child.read(reinterpret_cast<char*>(&got) + have, sizeof got - have, limit)) > 0)
        have += std::size_t(n);
    if (have < sizeof got)
    {
        if (n < 0)
            child.kill();
        else
            child.finish();
        std::fprintf(stderr, "gjk-validate: plugin variant '%s' %s while timed; no ns/query\n",
                     v.name.c_str(), n < 0 ? "hung" : "crashed");
        return res;
    }
    child.finish();
    got.cases = cases.size();
    return got;
}

TimingResult timeQueries(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                         const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    if (v.plugin && v.plugin->kind == PluginKind::Executable)
        return timeAdapter(cases, v, cfg, pluginTimeoutSeconds);
    if (v.plugin && v.plugin->kind == PluginKind::InProcess)
        return timeInProcess(cases, v, cfg);
    if (v.plugin)
        return timeContained(cases, v, cfg, pluginTimeoutSeconds);
    const TimedLoop loop = timedLoop(cases, v, cfg);
    TimingResult res;
    if (loop.cases > 0)
        res = medianOfPasses(loop.cases, cfg, loop.pass);
    res.cases = loop.cases;
    res.warm = loop.warm;
    return res;
}

} // namespace gjkval
