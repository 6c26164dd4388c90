// gjk-validate bench: the variants timed on given cases (no exact side, but for --overlapping's
// choice of cases, made before any timing).
#include "timing/bench.hpp"
#include "campaign/campaign.hpp"
#include "commands/command_line.hpp"
#include "commands/fault.hpp"
#include "commands/outputs.hpp"
#include "commands/plugin_options.hpp"
#include "common/output.hpp"
#include "implementations/peers.hpp"
#include "implementations/plugins.hpp"
#include "implementations/variants.hpp"
#include "inputs/cases.hpp"
#include "report/report.hpp"

#include <gjk2d/exact.hpp>

#include <fmt/format.h>

#include <cstdio>
#include <memory>

namespace gjkval
{
namespace
{
struct Options
{
    BenchConfig bcfg;
    std::vector<std::string> benchFamilies, benchFiles;
    std::string benchVariants = "all", benchJson, benchSeed = "1", against;
    bool overlapping = false;
    PluginOptions plugins;
};

// --overlapping: each input keeps the cases whose shapes overlap or touch, as the exact side says
// (exact::distance on the case's numbers as given: the exact distance, radii included, is 0), and
// its rejected entries (still reported as such). Decided before any timing, never timed; a case
// the exact side cannot take (it throws on it) is left out. For `double-signed` against a peer's
// penetration depth (docs/speed.md, "Signed distance against Bullet's EPA").
void keepOverlapping(std::vector<FamilyData>& inputs)
{
    for (FamilyData& f : inputs)
    {
        const bool labelled = f.labels.size() == f.cases.size();
        FamilyData kept = f;
        kept.cases.clear(), kept.labels.clear(), kept.rejected.clear();
        for (std::size_t i = 0; i < f.cases.size(); ++i)
        {
            bool keep = !f.rejected[i].empty();
            if (!keep)
                try
                {
                    keep = exact::distance(toExact(f.cases[i].a), toExact(f.cases[i].b)).upper == 0;
                }
                catch (const std::exception&)
                {
                    keep = false;
                }
            if (!keep)
                continue;
            kept.cases.push_back(f.cases[i]);
            kept.rejected.push_back(f.rejected[i]);
            if (labelled)
                kept.labels.push_back(f.labels[i]);
        }
        f = std::move(kept);
    }
}

// --against NAME: a shipped peer's name for it (ShippedPeer::againstName), loaded here whatever
// --no-default-plugins says, or a loaded plugin variant's name; its plugin must have its own
// timing loop. InputError (exit 2) otherwise, naming what is missing.
const VariantInfo* againstVariant(const std::string& name, double timeoutSeconds)
{
    for (const ShippedPeer& peer : shippedPeers())
        if (peer.againstName && name == peer.againstName)
        {
            const std::string path = shippedPeerPath(peer);
            if (path.empty())
                throw InputError(fmt::format("--against {}: its adapter {} is not built (it needs "
                                             "{}; `gjk-validate list`)",
                                             name, peer.file, peer.needs));
            return loadPlugin(path, timeoutSeconds).front();
        }
    const VariantInfo* v = findPluginVariant(name);
    if (v == nullptr)
        throw InputError(fmt::format("--against {}: neither a shipped peer's name (box2d-v3) nor "
                                     "a loaded plugin's implementation",
                                     excerpt(name)));
    if (v->plugin->timing == nullptr)
        throw InputError(fmt::format("--against {}: its plugin {} has no timing loop of its own "
                                     "(gjk2d_plugin_timing, gjk2d/plugin.h)",
                                     name, v->plugin->path));
    return v;
}

int benchCommand(Options& o, const CommandLine& line, CLI::App& sub)
{
    o.bcfg.seed = parseSeed(o.benchSeed);
    if (!o.against.empty() && sub.count("--variants") == 0)
        o.benchVariants = kAgainstVariants;
    o.bcfg.variants = selectVariants(o.benchVariants, o.plugins, ShippedPlugins::OnlyNamed);
    if (!o.against.empty())
    {
        o.bcfg.against = againstVariant(o.against, o.plugins.timeoutSeconds);
        o.bcfg.againstName = o.against;
    }
    o.bcfg.pluginTimeoutSeconds = o.plugins.timeoutSeconds;
    o.bcfg.command = line.text();
    if (o.benchFamilies.empty() && o.benchFiles.empty())
        throw InputError("bench: which cases? give --cases FILE and/or --family F");
    checkRange("--passes", o.bcfg.passes, 1, kMaxPasses);
    checkFamilies(o.benchFamilies, false);
    checkCaseFiles(o.benchFiles);
    if (!o.benchJson.empty() || sub.count("--json") > 0)
        checkOutputFile("--json", o.benchJson);
    testFault();
    o.bcfg.families = o.benchFamilies;
    o.bcfg.caseFiles = o.benchFiles;
    std::vector<FamilyData> inputs = collectInputs(o.benchFamilies, o.benchFiles, o.bcfg.seed);
    if (o.overlapping)
        keepOverlapping(inputs);
    const BenchResult res = runBench(o.bcfg, inputs);
    std::fputs(benchTable(res.json).c_str(), stdout);
    for (const auto& r : res.json["rejected"])
        std::fprintf(stderr, "gjk-validate: rejected %s: %s\n",
                     r["name"].get<std::string>().c_str(), r["reason"].get<std::string>().c_str());
    writeOutput("json", o.benchJson, [&] { return res.json.dump(1) + "\n"; });
    flushStdout();
    return res.exitCode;
}
} // namespace

Subcommand addBench(CLI::App& app, const CommandLine& line)
{
    auto o = std::make_shared<Options>();
    auto* bench = app.add_subcommand(
        "bench", "Time GJK variants on your cases (no exact side): per variant, repeated "
                 "single-threaded passes over all cases; prints the median ns per query, its "
                 "spread (fastest, slowest pass) and the ratio to `double`.");
    bench->footer(exitCodesHelp());
    bench->add_option("--cases", o->benchFiles, "a gjk-cases/1 file; repeatable")
        ->allow_extra_args(false);
    bench->add_option("--family", o->benchFamilies, "case family as for run; repeatable")
        ->allow_extra_args(false);
    bench->add_option("--seed", o->benchSeed, "campaign seed for --family, 0..2^64-1")
        ->capture_default_str();
    bench
        ->add_option("--variants", o->benchVariants,
                     "comma-separated variant names, or all (see `list`)")
        ->capture_default_str();
    bench->add_flag("--warm", o->bcfg.warm,
                    "time warm-started queries: each starts from the SimplexCache of a previous "
                    "query of the same case");
    bench->add_option("--against", o->against,
                      "also time this peer by its adapter's own loop, cold and warm, its passes "
                      "alternated with the variants', and give every variant's ratio to it: "
                      "box2d-v3 (the shipped Box2D v3 adapter), or a loaded plugin's "
                      "implementation whose plugin has a timing loop (gjk2d_plugin_timing); "
                      "without --variants, the variants are " +
                          std::string(kAgainstVariants));
    addPluginOptions(*bench, o->plugins, ShippedPlugins::OnlyNamed, Judging::RefusesJudge);
    bench->add_flag("--overlapping", o->overlapping,
                    "time only the cases whose shapes overlap or touch, as the exact side says "
                    "(decided before timing): signed distance and penetration depths");
    bench->add_option("--passes", o->bcfg.passes, "timed passes per variant, 1..1000")
        ->capture_default_str();
    bench->add_option("--json", o->benchJson, "write the timings as JSON to this file");
    return {bench, [o, line, bench] { return benchCommand(*o, line, *bench); }};
}

} // namespace gjkval
