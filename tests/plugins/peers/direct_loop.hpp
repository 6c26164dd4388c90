// What the direct loops of the FCL and Bullet adapters share (validation/plugins/fcl/tests/
// direct_loop.cpp, validation/plugins/bullet/tests/direct_loop.cpp): each builds a case file's
// shapes once in its library's own types and times the library's distance call over them, to set
// beside the adapter's prepared queries (gjk2d/plugin.h, gjk2d_plugin_prepared). Here: reading a
// gjk-cases/1 file, the command line, the timed passes and their median, and the adapter's side
// (its shapes prepared once through the plugin ABI, its queries timed the same way), so that the
// two figures come from one process on one machine, pass for pass alternated.
#pragma once

#include <gjk2d/plugin.h>

#include <nlohmann/json.hpp>

#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace directloop
{

// A case's shape as the file gives it: points (x0, y0, x1, y1, ...), radius, transform.
struct Shape
{
    std::vector<double> points;
    double radius = 0;
    double px = 0, py = 0, c = 1, s = 0;
    int32_t count() const { return int32_t(points.size() / 2); }
};

struct Case
{
    std::string name;
    Shape a, b;
};

// The cases of a gjk-cases/1 file (docs/case-files.md, "Case files"); throws on a file that is not.
inline std::vector<Case> readCases(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
        throw std::runtime_error("cannot open " + path);
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.value("format", "") != "gjk-cases/1")
        throw std::runtime_error(path + ": not a gjk-cases/1 file");
    auto shape = [](const nlohmann::json& s)
    {
        Shape out;
        for (const auto& p : s.at("points"))
        {
            out.points.push_back(p.at(0).get<double>());
            out.points.push_back(p.at(1).get<double>());
        }
        out.radius = s.value("radius", 0.0);
        if (s.contains("transform"))
        {
            const auto& t = s.at("transform");
            if (t.contains("p"))
            {
                out.px = t.at("p").at(0).get<double>();
                out.py = t.at("p").at(1).get<double>();
            }
            if (t.contains("q"))
            {
                out.c = t.at("q").at(0).get<double>();
                out.s = t.at("q").at(1).get<double>();
            }
        }
        return out;
    };
    std::vector<Case> cases;
    for (const auto& c : j.at("cases"))
        cases.push_back(Case{c.value("name", ""), shape(c.at("a")), shape(c.at("b"))});
    return cases;
}

// The command line: CASES [--variant NAME] [--passes N] [--plugin PATH] [--check N]. The variant
// is the adapter's implementation the loop stands beside (defaultVariant when not given).
struct Options
{
    std::string cases;
    int passes = 7;
    double passSeconds =
        0.25; // each timed pass runs whole loops over the cases for about this long
    std::string plugin, variant;
    std::size_t check = 0; // > 0: compare the first `check` cases' distances with the adapter's
};

inline Options parseOptions(int argc, char** argv, const char* usage, const char* defaultVariant)
{
    Options o;
    o.variant = defaultVariant;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string
        {
            if (i + 1 >= argc)
            {
                std::fprintf(stderr, "%s needs a value\n%s", arg.c_str(), usage);
                std::exit(2);
            }
            return argv[++i];
        };
        if (arg == "--passes")
            o.passes = std::max(1, std::atoi(value().c_str()));
        else if (arg == "--plugin")
            o.plugin = value();
        else if (arg == "--variant")
            o.variant = value();
        else if (arg == "--check")
            o.check = std::size_t(std::max(0, std::atoi(value().c_str())));
        else if (!arg.empty() && arg[0] != '-' && o.cases.empty())
            o.cases = arg;
        else
        {
            std::fprintf(stderr, "unknown argument %s\n%s", arg.c_str(), usage);
            std::exit(2);
        }
    }
    if (o.cases.empty() || (o.check > 0 && o.plugin.empty()))
    {
        std::fprintf(stderr, "%s", usage);
        std::exit(2);
    }
    return o;
}

inline double nowNs()
{
    return double(std::chrono::duration_cast<std::chrono::nanoseconds>(
                      std::chrono::steady_clock::now().time_since_epoch())
                      .count());
}

inline double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// An answer: distance, then the witness points on A and on B (x, y).
struct Answer
{
    int32_t status = GJK2D_STATUS_OK;
    double distance = 0, ax = 0, ay = 0, bx = 0, by = 0;
};

// The adapter's side: its shapes of the same cases prepared once through gjk2d_plugin_prepared,
// then its queries. Scalar T is the implementation's (float: the case's numbers rounded).
class PluginSide
{
  public:
    PluginSide(const std::string& path, const std::string& variant)
    {
        handle_ = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle_)
            throw std::runtime_error("cannot load " + path + ": " + ::dlerror());
        auto describe =
            reinterpret_cast<gjk2d_plugin_describe_fn>(::dlsym(handle_, GJK2D_PLUGIN_ENTRY_POINT));
        auto prepared = reinterpret_cast<gjk2d_plugin_prepared_fn>(
            ::dlsym(handle_, GJK2D_PLUGIN_PREPARED_ENTRY));
        if (!describe || !prepared)
            throw std::runtime_error(path + " does not export " GJK2D_PLUGIN_PREPARED_ENTRY);
        const gjk2d_plugin* d = describe();
        for (int32_t i = 0; i < d->count; ++i)
            if (variant == d->implementations[i].name)
                index_ = i, impl_ = &d->implementations[i];
        if (!impl_)
            throw std::runtime_error(path + " has no implementation " + variant);
        table_ = prepared();
        isFloat_ = impl_->scalar == GJK2D_SCALAR_FLOAT;
    }
    PluginSide(const PluginSide&) = delete;
    PluginSide& operator=(const PluginSide&) = delete;
    ~PluginSide()
    {
        for (void* p : prepared_)
            table_->release(index_, p);
        ::dlclose(handle_);
    }

    // Prepares both shapes of every case (each case's other shape given to a `case` scope).
    void prepare(const std::vector<const Case*>& cases)
    {
        const bool caseScope = table_->scope(index_) == GJK2D_PREPARED_CASE;
        held_.reserve(cases.size()); // the shapes point into their own vectors: no reallocation
        for (const Case* c : cases)
        {
            Held& h = held_.emplace_back();
            hold(c->a, h.a);
            hold(c->b, h.b);
            const void* a = shapePtr(h.a);
            const void* b = shapePtr(h.b);
            h.pa = table_->prepare(index_, a, caseScope ? b : nullptr);
            h.pb = table_->prepare(index_, b, caseScope ? a : nullptr);
            if (!h.pa || !h.pb)
                throw std::runtime_error("the adapter's prepare failed");
            prepared_.push_back(h.pa);
            prepared_.push_back(h.pb);
        }
    }

    // One query of case k through the ABI, as the runner makes it (cold: no cache to reset here
    // for FCL and Bullet, whose cache_bytes are 0).
    Answer answer(std::size_t k)
    {
        Held& h = held_[k];
        Answer out;
        if (isFloat_)
        {
            gjk2d_result_f r{};
            out.status = table_->distance(index_, h.pa, &h.a.f, h.pb, &h.b.f, nullptr, &r);
            out.distance = r.distance, out.ax = r.point_a[0], out.ay = r.point_a[1];
            out.bx = r.point_b[0], out.by = r.point_b[1];
        }
        else
        {
            gjk2d_result_d r{};
            out.status = table_->distance(index_, h.pa, &h.a.d, h.pb, &h.b.d, nullptr, &r);
            out.distance = r.distance, out.ax = r.point_a[0], out.ay = r.point_a[1];
            out.bx = r.point_b[0], out.by = r.point_b[1];
        }
        return out;
    }

    // One timed pass: `reps` loops over every case; returns the nanoseconds.
    double pass(int reps)
    {
        double sum = 0;
        const double t0 = nowNs();
        for (int r = 0; r < reps; ++r)
            for (std::size_t k = 0; k < held_.size(); ++k)
            {
                const Answer a = answer(k);
                sum += a.distance + a.ax;
            }
        const double t1 = nowNs();
        sink_ = sink_ + sum;
        return t1 - t0;
    }

  private:
    struct HeldShape
    {
        std::vector<float> pf;
        std::vector<double> pd;
        gjk2d_shape_f f{};
        gjk2d_shape_d d{};
    };
    struct Held
    {
        HeldShape a, b;
        void* pa = nullptr;
        void* pb = nullptr;
    };
    // The case's shape in both scalar types (float: each number rounded, as the runner gives it).
    static void hold(const Shape& s, HeldShape& h)
    {
        h.pd = s.points;
        h.pf.assign(s.points.begin(), s.points.end());
        h.d = gjk2d_shape_d{h.pd.data(), s.count(), s.radius, {s.px, s.py}, {s.c, s.s}};
        h.f = gjk2d_shape_f{h.pf.data(),
                            s.count(),
                            float(s.radius),
                            {float(s.px), float(s.py)},
                            {float(s.c), float(s.s)}};
    }
    const void* shapePtr(HeldShape& h) const
    {
        return isFloat_ ? static_cast<const void*>(&h.f) : &h.d;
    }

    void* handle_ = nullptr;
    int32_t index_ = -1;
    const gjk2d_implementation* impl_ = nullptr;
    const gjk2d_prepared* table_ = nullptr;
    bool isFloat_ = false;
    std::vector<Held> held_;
    std::vector<void*> prepared_;
    volatile double sink_ = 0;
};

inline bool sameBits(double x, double y)
{
    return std::memcmp(&x, &y, sizeof x) == 0;
}

// The loop: `query(k)` is the library's call on case k's shapes, built once. With --check, the
// first cases' distances are compared with the adapter's, bit for bit (not the points: FCL leaves
// them unwritten on overlap, where the adapter sets NaN first);
// else passes of whole loops over the cases are timed, the adapter's prepared queries alternated
// with them when --plugin is given (after, then before: neither side always runs first), and the
// medians printed in ns/query.
template <class Query>
int run(const Options& o, const std::vector<const Case*>& cases, Query&& query)
{
    if (cases.empty())
    {
        std::fprintf(stderr, "no case to time\n");
        return 2;
    }
    if (o.check > 0)
    {
        const std::size_t n = std::min(o.check, cases.size());
        const std::vector<const Case*> first(cases.begin(), cases.begin() + std::ptrdiff_t(n));
        PluginSide adapter(o.plugin, o.variant);
        adapter.prepare(first);
        int differ = 0;
        for (std::size_t k = 0; k < n; ++k)
        {
            const Answer d = query(k), a = adapter.answer(k);
            if ((a.status != GJK2D_STATUS_OK || !sameBits(d.distance, a.distance)) &&
                ++differ <= 10)
                std::printf("%s: direct %.17g (%.17g, %.17g) (%.17g, %.17g), adapter status %d "
                            "%.17g (%.17g, %.17g) (%.17g, %.17g)\n",
                            cases[k]->name.c_str(), d.distance, d.ax, d.ay, d.bx, d.by, a.status,
                            a.distance, a.ax, a.ay, a.bx, a.by);
        }
        std::printf("%s: %zu cases, %d answers differ from the adapter's\n", o.variant.c_str(), n,
                    differ);
        return differ == 0 ? 0 : 1;
    }

    volatile double sink = 0;
    auto directPass = [&](int reps)
    {
        double sum = 0;
        const double t0 = nowNs();
        for (int r = 0; r < reps; ++r)
            for (std::size_t k = 0; k < cases.size(); ++k)
            {
                const Answer a = query(k);
                sum += a.distance + a.ax;
            }
        const double t1 = nowNs();
        sink = sink + sum;
        return t1 - t0;
    };
    std::unique_ptr<PluginSide> adapter;
    if (!o.plugin.empty())
    {
        adapter = std::make_unique<PluginSide>(o.plugin, o.variant);
        adapter->prepare(cases);
    }
    const double once = directPass(1); // also warms the caches
    const int reps = std::max(1, int(std::ceil(o.passSeconds * 1e9 / std::max(once, 1.0))));
    const double queries = double(reps) * double(cases.size());
    std::vector<double> direct, viaAdapter;
    for (int p = 0; p < o.passes; ++p) // the adapter's pass after the direct one, then before it
    {
        if (adapter && p % 2 == 1)
            viaAdapter.push_back(adapter->pass(reps) / queries);
        direct.push_back(directPass(reps) / queries);
        if (adapter && p % 2 == 0)
            viaAdapter.push_back(adapter->pass(reps) / queries);
    }
    std::printf("%s, %zu cases, %d passes of %d loops:\n", o.variant.c_str(), cases.size(),
                o.passes, reps);
    std::printf("  direct:  median %.1f ns/query (min %.1f, max %.1f)\n", median(direct),
                *std::min_element(direct.begin(), direct.end()),
                *std::max_element(direct.begin(), direct.end()));
    if (adapter)
    {
        std::printf("  adapter: median %.1f ns/query (min %.1f, max %.1f), prepared shapes "
                    "through the plugin ABI\n",
                    median(viaAdapter), *std::min_element(viaAdapter.begin(), viaAdapter.end()),
                    *std::max_element(viaAdapter.begin(), viaAdapter.end()));
        std::printf("  adapter / direct: %.3f\n", median(viaAdapter) / median(direct));
    }
    return 0;
}

} // namespace directloop
