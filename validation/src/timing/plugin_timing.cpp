// The timed loops of other people's implementations: shared libraries in served children
// (prepared shapes, or the per-call ABI, or the plugin's own loop), executable adapters through
// `time` requests, in-process callbacks (timing/plugin_timing.hpp).
#include "timing/plugin_timing.hpp"

#include "implementations/adapter.hpp"
#include "implementations/in_process.hpp"
#include "implementations/plugins.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include <unistd.h>

namespace gjkval
{
namespace
{
using Clock = std::chrono::steady_clock;

volatile double g_pluginTimingSink = 0; // keeps the timed loops from being optimised away

double nsSince(Clock::time_point t0)
{
    return std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
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
// its cache_bytes zeroed (a cold start, as gjk2d's fresh SimplexCache), one call, call(i, cache,
// &result) (through distance_f/distance_d, or the prepared table's distance), the result read. No
// copy of the inputs, no IPC: the served child that runs it reports only the passes' times.
template <class Result, class Call>
double timePassPlugin(std::size_t n, Call call, std::vector<unsigned char>& cache, int cacheBytes,
                      int reps)
{
    void* c = cacheBytes > 0 ? cache.data() : nullptr;
    const auto t0 = Clock::now();
    double acc = 0;
    for (int r = 0; r < reps; ++r)
        for (std::size_t i = 0; i < n; ++i)
        {
            std::memset(cache.data(), 0, std::size_t(cacheBytes));
            Result o{};
            call(i, c, &o);
            acc += double(o.distance);
        }
    const double ns = nsSince(t0);
    g_pluginTimingSink = g_pluginTimingSink + acc;
    return ns;
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

// What a served child sends first, once it has prepared: the preparation per shape (>= 0), none
// to report, or a failed preparation (the loop is lost).
constexpr double kNoPreparation = -1, kPreparationFailed = -2;

// A served child's passes (the child's side of every shared library's loop): after `prepared`
// (kNoPreparation, kPreparationFailed or a figure) is sent, one pass per command (the reps, an
// int32; end of file ends it), each pass's nanoseconds sent back.
void servePasses(double prepared, const std::function<double(int)>& pass, int out, int in)
{
    writeToParent(out, &prepared, sizeof prepared);
    std::int32_t reps = 0;
    while (prepared != kPreparationFailed && readAllBytes(in, &reps, sizeof reps) && reps > 0)
    {
        const double ns = pass(reps);
        if (!writeToParent(out, &ns, sizeof ns))
            break;
    }
}

// The prepared shapes of a timing set (the child's): every case's two, prepared once, released
// when it ends.
template <class T, class Shape> struct PreparedShapes
{
    const PluginImpl& im;
    std::vector<void*> a, b;
    double nsPerShape = kPreparationFailed;

    PreparedShapes(const PluginImpl& plugin, const PluginTimingSet<T, Shape>& set)
        : im(plugin), a(set.a.size(), nullptr), b(set.b.size(), nullptr)
    {
        const gjk2d_prepared& pp = *im.prepared;
        const bool perCase = im.preparation == Preparation::Case;
        bool ok = true;
        const auto t0 = Clock::now();
        for (std::size_t i = 0; i < a.size(); ++i)
        {
            a[i] = pp.prepare(im.index, &set.a[i], perCase ? &set.b[i] : nullptr);
            b[i] = pp.prepare(im.index, &set.b[i], perCase ? &set.a[i] : nullptr);
            ok = ok && a[i] != nullptr && b[i] != nullptr;
        }
        const double ns = nsSince(t0);
        if (ok && !a.empty())
            nsPerShape = ns / double(2 * a.size());
    }
    ~PreparedShapes()
    {
        for (auto* list : {&a, &b})
            for (void* p : *list)
                if (p != nullptr)
                    im.prepared->release(im.index, p);
    }
    PreparedShapes(const PreparedShapes&) = delete;
    PreparedShapes& operator=(const PreparedShapes&) = delete;
};

// The child's side of sharedLibraryLoop(): prepared shapes, or the per-call ABI.
template <class T, class Shape, class Result>
void serveSharedLibrary(const PluginImpl& im, const PluginTimingSet<T, Shape>& set, int out, int in)
{
    const int cacheBytes = im.impl.cache_bytes;
    std::vector<unsigned char> cache(std::size_t(std::max(cacheBytes, 1)));
    if (im.prepared == nullptr)
    {
        const auto fn = [&]
        {
            if constexpr (std::is_same_v<T, float>)
                return im.impl.distance_f;
            else
                return im.impl.distance_d;
        }();
        servePasses(
            kNoPreparation,
            [&](int reps)
            {
                const auto call = [&](std::size_t i, void* c, Result* o)
                { fn(&set.a[i], &set.b[i], c, o); };
                return timePassPlugin<Result>(set.a.size(), call, cache, cacheBytes, reps);
            },
            out, in);
        return;
    }
    const PreparedShapes<T, Shape> shapes(im, set);
    servePasses(
        shapes.nsPerShape,
        [&](int reps)
        {
            // The shapes' preparation is outside the pass: only the table's distance is in it.
            const gjk2d_prepared& pp = *im.prepared;
            const auto call = [&](std::size_t i, void* c, Result* o)
            { pp.distance(im.index, shapes.a[i], &set.a[i], shapes.b[i], &set.b[i], c, o); };
            return timePassPlugin<Result>(set.a.size(), call, cache, cacheBytes, reps);
        },
        out, in);
}

// The parent's side of a served child, and whether it is lost (then every pass answers -1).
struct ServedChild
{
    PluginChild child;
    std::string variant;
    double limitSeconds = 0;
    bool lost = false;

    // One figure from the child: a pass's nanoseconds, or with `preparation` the first one
    // (kNoPreparation accepted). -1 and a line on stderr when it crashed, hung, or answered a
    // negative time or a failed preparation: the loop is lost.
    double receive(const char* what, bool preparation = false)
    {
        double ns = -1;
        std::size_t have = 0;
        long n = 1;
        while (have < sizeof ns && (n = child.read(reinterpret_cast<char*>(&ns) + have,
                                                   sizeof ns - have, limitSeconds)) > 0)
            have += std::size_t(n);
        if (have == sizeof ns && (ns >= 0 || (preparation && ns == kNoPreparation)))
            return ns;
        if (n < 0)
            child.kill();
        else
            child.finish();
        lost = true;
        std::fprintf(stderr, "gjk-validate: plugin variant '%s': %s %s; no ns/query\n",
                     variant.c_str(),
                     have == sizeof ns ? "its timing failed"
                     : n < 0           ? "it hung"
                                       : "it crashed",
                     what);
        return -1;
    }
    double pass(int reps)
    {
        if (lost)
            return -1;
        const std::int32_t r = reps;
        child.send(&r, sizeof r); // when it fails, the child is gone: receive() says so
        return receive("in a timed pass");
    }
    ~ServedChild()
    {
        if (!lost)
            child.finish(); // end of file on its commands: it releases and exits
    }
};

// A served child's TimedLoop: `work` is the child's side (servePasses at its heart).
TimedLoop servedLoop(std::size_t cases, const VariantInfo& v, double limitSeconds,
                     const std::function<void(int out, int in)>& work)
{
    TimedLoop loop;
    loop.cases = cases;
    auto served = std::make_shared<ServedChild>();
    served->variant = v.name;
    served->limitSeconds = limitSeconds;
    served->child = PluginChild::serve(v.plugin, work);
    const double prepared = served->receive("preparing its shapes", true);
    loop.pass = [served](int reps) { return served->pass(reps); };
    if (prepared >= 0)
        loop.prepareNsPerShape = [prepared] { return prepared; };
    return loop;
}

template <class T, class Shape, class Result>
TimedLoop sharedLibraryLoopT(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                             double limitSeconds)
{
    const PluginTimingSet<T, Shape> set(cases); // before the fork: the child times it
    const PluginImpl& im = *v.plugin;
    return servedLoop(cases.size(), v, limitSeconds,
                      [&](int out, int in)
                      { serveSharedLibrary<T, Shape, Result>(im, set, out, in); });
}

template <class T, class Shape>
TimedLoop ownLoopT(const std::vector<const PreparedCase*>& cases, const VariantInfo& v, bool warm,
                   double limitSeconds)
{
    const PluginTimingSet<T, Shape> set(cases); // before the fork: the child only prepares
    const gjk2d_timing& t = *v.plugin->timing;
    const int index = v.plugin->index;
    TimedLoop loop = servedLoop(cases.size(), v, limitSeconds,
                                [&](int out, int in)
                                {
                                    void* prepared =
                                        t.prepare(index, set.a.data(), set.b.data(),
                                                  std::int32_t(set.a.size()), warm ? 1 : 0);
                                    servePasses(
                                        prepared ? kNoPreparation : kPreparationFailed,
                                        [&](int reps) { return t.pass(prepared, reps); }, out, in);
                                    if (prepared)
                                        t.release(prepared);
                                });
    loop.warm = warm;
    return loop;
}
// An executable adapter's timed sample: the cases' request text in chunks of at most
// kAdapterTimeChunkCases, written once, before timing.
// The chunk size: a pass sends every chunk as one `time` request with K = the pass's reps, so the
// adapter repeats a chunk K times where a shared library's pass repeats the whole sample; with
// the sample in one chunk up to this size, the two loops are the same (see
// scripts/adapter_timing_check.py for the bridge's timing against the shared library's). A chunk of
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

// The first kAdapterTimingCases of a sample (an adapter's and an in-process callback's).
std::vector<const PreparedCase*> slowSample(const std::vector<const PreparedCase*>& cases)
{
    return {cases.begin(),
            cases.begin() + std::ptrdiff_t(std::min(cases.size(), kAdapterTimingCases))};
}

// An adapter loop's state: its chunks, and the preparation figures per shape of its passes.
struct AdapterLoopState
{
    AdapterChunks chunks;
    std::size_t cases = 0;
    double limit = 0;
    bool lost = false;
    std::vector<double> prepareNsPerShape;
};
} // namespace

double passLimitSeconds(const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    return pluginTimeoutSeconds + 30 + 4 * cfg.minPassSeconds;
}

TimedLoop sharedLibraryLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                            const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    const double limit = passLimitSeconds(cfg, pluginTimeoutSeconds);
    if (cases.empty())
        return {};
    if (v.plugin->impl.scalar == GJK2D_SCALAR_FLOAT)
        return sharedLibraryLoopT<float, gjk2d_shape_f, gjk2d_result_f>(cases, v, limit);
    return sharedLibraryLoopT<double, gjk2d_shape_d, gjk2d_result_d>(cases, v, limit);
}

TimedLoop ownTimingLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                        bool warm, const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    const double limit = passLimitSeconds(cfg, pluginTimeoutSeconds);
    if (cases.empty())
    {
        TimedLoop loop;
        loop.warm = warm;
        return loop;
    }
    if (v.plugin->impl.scalar == GJK2D_SCALAR_FLOAT)
        return ownLoopT<float, gjk2d_shape_f>(cases, v, warm, limit);
    return ownLoopT<double, gjk2d_shape_d>(cases, v, warm, limit);
}

TimedLoop adapterLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                      const TimingConfig& cfg, double pluginTimeoutSeconds)
{
    const std::vector<const PreparedCase*> sample = slowSample(cases);
    TimedLoop loop;
    loop.cases = sample.size();
    if (sample.empty())
        return loop;
    auto st = std::make_shared<AdapterLoopState>();
    st->chunks = adapterChunks(sample, v);
    st->cases = sample.size();
    st->limit = passLimitSeconds(cfg, pluginTimeoutSeconds);
    // A pass: every chunk's time, K = reps; only the adapter's own timed loops are summed.
    loop.pass = [st, vp = &v](int reps)
    {
        double ns = 0, prepare = 0;
        for (std::size_t k = 0; k < st->chunks.text.size() && !st->lost; ++k)
        {
            const AdapterTime t = adapterTime(*vp, reps, st->chunks.cases[k], st->chunks.text[k],
                                              st->limit, fmt::format("timing chunk {}", k));
            st->lost = t.ns < 0;
            ns += t.ns;
            prepare = prepare >= 0 && t.prepareNs >= 0 ? prepare + t.prepareNs : -1;
        }
        if (st->lost)
            return -1.0;
        if (prepare >= 0)
            st->prepareNsPerShape.push_back(prepare / double(2 * st->cases));
        return ns;
    };
    if (v.plugin->preparation != Preparation::InCall)
        loop.prepareNsPerShape = [st]
        {
            std::vector<double> xs = st->prepareNsPerShape;
            std::sort(xs.begin(), xs.end());
            return medianOfSorted(xs);
        };
    return loop;
}

TimedLoop inProcessLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v)
{
    auto sample = std::make_shared<std::vector<const PreparedCase*>>(slowSample(cases));
    TimedLoop loop;
    loop.cases = sample->size();
    std::shared_ptr<InProcessCalls> calls = v.plugin->calls;
    if (sample->empty() || calls == nullptr)
        return loop;
    auto out = std::make_shared<std::vector<ExternalAnswer>>(sample->size());
    auto lost = std::make_shared<bool>(false);
    loop.pass = [sample, calls, out, lost, name = v.name](int reps)
    {
        if (*lost)
            return -1.0;
        try
        {
            const auto t0 = Clock::now();
            for (int r = 0; r < reps; ++r)
                if (calls->perBatch)
                    calls->perBatch(*sample, *out);
                else
                    for (std::size_t i = 0; i < sample->size(); ++i)
                        calls->perCase(*(*sample)[i], (*out)[i]);
            const double ns = nsSince(t0);
            g_pluginTimingSink = g_pluginTimingSink + (*out)[0].distance;
            return ns;
        }
        catch (const std::exception& e)
        {
            *lost = true;
            std::fprintf(stderr,
                         "gjk-validate: in-process variant '%s' raised while timed: %s; no "
                         "ns/query\n",
                         name.c_str(), e.what());
            return -1.0;
        }
    };
    return loop;
}

} // namespace gjkval
