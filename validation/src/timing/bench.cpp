// `gjk-validate bench`: the valid cases prepared once, every variant timed (gjk2d's with their
// passes alternated, plugins in their child processes), the ratios to the baseline and to a peer's
// own loop, the bench report's JSON and its table.
#include "timing/bench.hpp"

#include "timing/plugin_timing.hpp"

#include "implementations/peers.hpp"

#include <fmt/format.h>

#include <chrono>
#include <limits>

namespace gjkval
{
namespace
{
using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

std::string g(const Json& v, const char* spec)
{
    return v.is_number() ? fmt::format(fmt::runtime(spec), v.get<double>()) : std::string("-");
}
} // namespace

namespace
{
// The valid cases, prepared, and what the report says of the inputs and the rejected cases.
struct BenchCases
{
    std::vector<PreparedCase> prepared;
    std::size_t total = 0, rejected = 0;
    Json inputs = Json::array(), rejectedList = Json::array();
};

BenchCases prepareCases(const std::vector<FamilyData>& inputs)
{
    BenchCases b;
    for (const auto& f : inputs)
    {
        b.inputs.push_back(f.input);
        for (std::size_t i = 0; i < f.cases.size(); ++i)
        {
            ++b.total;
            if (!f.rejected[i].empty())
            {
                ++b.rejected;
                b.rejectedList.push_back(
                    {{"name", f.labels[i]}, {"family", f.name}, {"reason", f.rejected[i]}});
                continue;
            }
            b.prepared.push_back(prepare(f.cases[i]));
        }
    }
    return b;
}

// The cases a variant is timed on, and how many it skips (of which not applicable).
struct VariantCases
{
    std::vector<const PreparedCase*> cases;
    std::size_t skipped = 0, notApplicable = 0;
};

VariantCases casesOf(const VariantInfo& v, const std::vector<PreparedCase>& prepared)
{
    VariantCases c;
    for (const auto& p : prepared)
    {
        if (const char* why = skipReason(v, p, p.floatOk))
        {
            ++c.skipped;
            c.notApplicable += why == kSkipNotConvexOrder ? 1 : 0;
            continue;
        }
        if (v.plugin && refusedByDescription(v, p)) // counted as skipped, not applicable
        {
            ++c.skipped;
            ++c.notApplicable;
            continue;
        }
        c.cases.push_back(&p);
    }
    return c;
}

// Every variant timed, their passes alternated (medianOfAlternatedPasses: all their inputs are held
// at once), with --against's own loop, cold and warm.
struct VariantTimings
{
    std::vector<TimingResult> results;
    std::vector<VariantCases> cases;       // only the counts are used once timed
    TimingResult againstCold, againstWarm; // --against: its own loop, cold and warm
    VariantCases againstCases;
};

VariantTimings timeEveryVariant(const BenchConfig& config,
                                const std::vector<PreparedCase>& prepared, const TimingConfig& tc)
{
    VariantTimings t;
    std::vector<TimedLoop> loops;
    for (const VariantInfo* v : config.variants)
    {
        t.cases.push_back(casesOf(*v, prepared));
        loops.push_back(variantLoop(t.cases.back().cases, *v, tc, config.pluginTimeoutSeconds));
    }
    if (config.against) // its own loop, cold and warm, alternated with the others
    {
        t.againstCases = casesOf(*config.against, prepared);
        for (const bool warm : {false, true})
            loops.push_back(ownTimingLoop(t.againstCases.cases, *config.against, warm, tc,
                                          config.pluginTimeoutSeconds));
    }
    std::vector<TimingResult> alternated = medianOfAlternatedPasses(loops, tc);
    const std::size_t nv = config.variants.size();
    t.results.assign(alternated.begin(), alternated.begin() + std::ptrdiff_t(nv));
    if (config.against)
    {
        t.againstCold = alternated[nv];
        t.againstWarm = alternated[nv + 1];
    }
    return t;
}

Json nsJson(double x)
{
    return x > 0 ? Json(x) : Json(nullptr);
}

// x / of, or null when either is missing.
Json ratioJson(double x, double of)
{
    return x > 0 && of > 0 ? Json(x / of) : Json(nullptr);
}

// The bench report's "against": the peer's own loop, cold and warm (null without --against).
Json againstJson(const BenchConfig& config, const VariantTimings& timings)
{
    if (!config.against)
        return nullptr;
    auto timing = [](const TimingResult& t)
    {
        return Json{{"ns_per_query", nsJson(t.nsPerQuery)},
                    {"ns_min", nsJson(t.nsMin)},
                    {"ns_max", nsJson(t.nsMax)},
                    {"passes", t.passes},
                    {"reps_per_pass", t.repsPerPass}};
    };
    const VariantInfo& v = *config.against;
    return {{"name", config.againstName},
            {"variant", v.name},
            {"type", scalarName(v.scalar)},
            {"library", v.plugin->library},
            {"cases", timings.againstCases.cases.size()},
            {"skipped", timings.againstCases.skipped},
            {"cold", timing(timings.againstCold)},
            {"warm", timing(timings.againstWarm)}};
}

// The bench report's "variants": each one's timing, its ratio to `base` when there is one, and
// with --against its ratio to the peer's own loop started alike (cold to cold, warm to warm).
Json variantsJson(const BenchConfig& config, const VariantTimings& timings,
                  const TimingResult* base)
{
    Json vars = Json::object();
    for (std::size_t k = 0; k < config.variants.size(); ++k)
    {
        const VariantInfo& v = *config.variants[k];
        const TimingResult& t = timings.results[k];
        const auto ns = nsJson;
        Json j;
        j["type"] = scalarName(v.scalar);
        j["warm"] = t.warm;
        j["batch"] = v.batch;
        j["options"] = optionsJson(v.options);
        j["cases"] = t.cases;
        j["skipped"] = timings.cases[k].skipped;
        j["not_applicable"] = timings.cases[k].notApplicable;
        j["ns_per_query"] = ns(t.nsPerQuery);
        j["ns_min"] = ns(t.nsMin);
        j["ns_max"] = ns(t.nsMax);
        j["passes"] = t.passes;
        j["reps_per_pass"] = t.repsPerPass;
        j["ratio_to_double"] =
            base && t.nsPerQuery > 0 ? Json(t.nsPerQuery / base->nsPerQuery) : Json(nullptr);
        if (config.against)
            j["ratio_to_against"] = ratioJson(
                t.nsPerQuery, (t.warm ? timings.againstWarm : timings.againstCold).nsPerQuery);
        vars[v.name] = std::move(j);
    }
    return vars;
}

// The bench report's "context", but for elapsed_s.
Json benchContext(const BenchConfig& config, const TimingConfig& tc, BenchCases& cases)
{
    Json context = contextJson(isoDateUtc(), gitRevision(), config.command, config.seed, 1,
                               std::move(cases.inputs), cases.total, cases.rejected);
    context["plugins"] = pluginsJson(config.variants);
    context["timing"] = {
        {"passes", tc.maxPasses},
        {"min_pass_s", tc.minPassSeconds},
        {"warm", config.warm},
        {"note",
         "single thread, pinned to one CPU (cpu; null: not pinned) with the children "
         "it forks; per variant the cases are copied into one contiguous array and "
         "each pass loops over all of them (repeated to last at least min_pass_s); the "
         "passes of gjk2d's variants are alternated (pass k of each before pass k + 1 of "
         "any); plugin variants are timed on their own. "
         "ns_per_query is the median pass, ns_min and ns_max the fastest and slowest. "
         "Warm: each query starts from the SimplexCache of a previous query of the same "
         "case, prepared before timing. A batch variant's pass calls gjk::distanceBatchLanes "
         "on all its cases at once (context.batch_isa: the instruction set of its lanes). "
         "--against: the peer's own loop (gjk2d_plugin_timing) over inputs it prepared once, "
         "cold (a zeroed cache per query) and warm (each case's cache from its previous "
         "query), in a child process, its passes alternated with gjk2d's."}};
    return context;
}
} // namespace

BenchResult runBench(const BenchConfig& config, const std::vector<FamilyData>& inputs)
{
    const auto tStart = Clock::now();
    BenchCases cases = prepareCases(inputs);
    const auto tPrepared = Clock::now();

    TimingConfig tc;
    tc.minPasses = tc.maxPasses = std::max(1, config.passes);
    tc.budgetSeconds = std::numeric_limits<double>::infinity();
    tc.minPassSeconds = config.minPassSeconds;
    tc.warm = config.warm;
    int cpu = -1;
    VariantTimings timings;
    {
        const PinnedToOneCpu pin;
        cpu = pin.cpu();
        timings = timeEveryVariant(config, cases.prepared, tc);
    }
    const auto tTimed = Clock::now();

    const TimingResult* base = nullptr;
    for (std::size_t k = 0; k < config.variants.size(); ++k)
        if (config.variants[k]->name == kBaselineVariant && timings.results[k].nsPerQuery > 0)
            base = &timings.results[k];

    BenchResult out;
    out.exitCode = cases.rejected > 0 ? kExitInput : kExitPass;
    Json context = benchContext(config, tc, cases);
    context["timing"]["cpu"] = cpu >= 0 ? Json(cpu) : Json(nullptr);
    context["elapsed_s"] = {{"prepare", seconds(tStart, tPrepared)},
                            {"timing", seconds(tPrepared, tTimed)},
                            {"total", seconds(tStart, Clock::now())}};
    Json& j = out.json;
    j["schema"] = "gjk-bench/1";
    j["context"] = std::move(context);
    j["baseline_variant"] = base ? Json(kBaselineVariant) : Json(nullptr);
    j["variants"] = variantsJson(config, timings, base);
    j["against"] = againstJson(config, timings);
    j["rejected"] = std::move(cases.rejectedList);
    j["exit_code"] = out.exitCode;
    return out;
}

std::string benchTable(const Json& b)
{
    const Json& c = b["context"];
    std::string s = fmt::format(
        "{} cases ({} rejected), single thread{}, {} passes of >= {:g} s, {} queries; *-batch "
        "variants: "
        "gjk::distanceBatchLanes on {}\n",
        c["cases_total"].get<std::uint64_t>(), c["cases_rejected"].get<std::uint64_t>(),
        c["timing"].value("cpu", Json()).is_number()
            ? fmt::format(" on CPU {}", c["timing"]["cpu"].get<int>())
            : std::string(),
        c["timing"]["passes"].get<int>(), c["timing"]["min_pass_s"].get<double>(),
        c["timing"]["warm"].get<bool>() ? "warm-started" : "cold (warm for *-warm variants)",
        c.contains("batch_isa") ? c["batch_isa"].get<std::string>() : std::string("?"));
    const Json& against = b.contains("against") ? b["against"] : Json(nullptr);
    const std::string vs = against.is_null() ? "" : "x " + against["name"].get<std::string>();
    const auto row = [&](const std::string& name, const std::string& type, bool warm,
                         const Json& cases, const Json& skipped, const Json& t, const Json& ratio,
                         const Json& ratioAgainst)
    {
        s += fmt::format("{:<22} {:<6} {:<5} {:>7} {:>7} {:>10} {:>9} {:>9} {:>8}", name, type,
                         warm ? "warm" : "cold", cases.get<std::uint64_t>(),
                         skipped.get<std::uint64_t>(), g(t["ns_per_query"], "{:.1f}"),
                         g(t["ns_min"], "{:.1f}"), g(t["ns_max"], "{:.1f}"), g(ratio, "{:.2f}"));
        s += vs.empty() ? "\n" : fmt::format(" {:>{}}\n", g(ratioAgainst, "{:.2f}"), vs.size());
    };
    s += fmt::format("{:<22} {:<6} {:<5} {:>7} {:>7} {:>10} {:>9} {:>9} {:>8}", "variant", "type",
                     "start", "cases", "skipped", "ns/query", "min", "max", "x double");
    s += vs.empty() ? "\n" : " " + vs + "\n";
    for (const auto& [name, v] : b["variants"].items())
        row(name, v["type"].get<std::string>(), v["warm"].get<bool>(), v["cases"], v["skipped"], v,
            v["ratio_to_double"], v.contains("ratio_to_against") ? v["ratio_to_against"] : Json());
    if (!against.is_null()) // the peer's own loop: its rows, named as --against named it
        for (const bool warm : {false, true})
            row(against["name"].get<std::string>(), against["type"].get<std::string>(), warm,
                against["cases"], against["skipped"], against[warm ? "warm" : "cold"], Json(),
                Json(1.0));
    if (!against.is_null())
        s += fmt::format("{}: {}'s own timing loop ({})\n", against["name"].get<std::string>(),
                         against["variant"].get<std::string>(),
                         against["library"].get<std::string>());
    s += fmt::format("total {:.1f} s\n", c["elapsed_s"]["total"].get<double>());
    return s;
}

} // namespace gjkval
