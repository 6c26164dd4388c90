// gjk-validate: the validation runner (docs/validation.md).
//   run       a campaign: families and case files -> exact truth, GJK variants -> reports
//   generate  write a family's cases to a gjk-cases/1 file
//   explain   one case in detail: inputs, each variant's result and trace, the exact result
//   bench     time the variants on given cases (no exact side)
//   list      the families and variants
#include "bench.hpp"
#include "campaign.hpp"
#include "cases.hpp"
#include "evaluate.hpp"
#include "families.hpp"
#include "report.hpp"
#include "variants.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

#if defined(GJK2D_HAVE_HTML)
#include "gjk_html/html.hpp"
#endif

using namespace gjkval;

namespace
{
const char* kExitCodes =
    "Exit codes:\n"
    "  0  every case is within its judged variant's error bound (run), or success\n"
    "  1  some case failed for a judged variant: error beyond the bound,\n"
    "     misclassification beyond it, non-finite output, iteration limit, a certified\n"
    "     interval missing the truth; or a family make-up check failed (comparison\n"
    "     variants' failures are reported, never judged)\n"
    "  2  usage or input error: bad option, unreadable or invalid case file,\n"
    "     rejected cases (the report is still written), unknown case name";

exact::Route parseRouteOrThrow(const std::string& name)
{
    exact::Route r = exact::Route::Default;
    if (!exact::parseRoute(name, r))
        throw InputError(
            fmt::format("unknown exact route '{}' (hull-of-differences, minkowski-sum-2, "
                        "edge-merge, default)",
                        name));
    return r;
}

std::string joinArgs(int argc, char** argv)
{
    std::string s = "gjk-validate";
    for (int i = 1; i < argc; ++i)
    {
        std::string a = argv[i];
        s += " " + (a.find_first_of(" \t'\"") == std::string::npos ? a : "'" + a + "'");
    }
    return s;
}

void writeText(const std::string& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out)
        throw InputError(fmt::format("{}: cannot write the file", path));
}
} // namespace

int main(int argc, char** argv)
{
    CLI::App app{"gjk-validate: checks the GJK distance library against an exact ground truth.\n"
                 "Runs case families and case files through the GJK variants and the exact\n"
                 "(CGAL/GMP) distance, and reports correctness, accuracy and speed."};
    app.require_subcommand(1);
    app.footer(kExitCodes);
    app.set_help_all_flag("--help-all", "help for every subcommand");

    // --- run ---
    CampaignConfig cfg;
    std::vector<std::string> families, files;
    std::string variants = kDefaultVariants, outDir = "reports/latest/", route = "default";
    bool noProgress = false, noTiming = false;
    auto* run = app.add_subcommand(
        "run", "Run a campaign and write DIR/report.json, report.md, worst-cases.json "
               "(and cases.jsonl, index.html). Without --family and --cases: the "
               "default campaign, --family random:200000 --family hard plus every "
               "validation/cases/*.json.");
    run->footer(kExitCodes);
    run->add_option("--family", families,
                    "case family with optional count: random[:N] (default N 200000), hard[:N] (all "
                    "sub-families, N "
                    "each, default their built-in counts), hard/<sub>[:N]; repeatable (see `list`)")
        ->allow_extra_args(false);
    run->add_option("--cases", files, "a gjk-cases/1 file; repeatable")->allow_extra_args(false);
    run->add_option("--seed", cfg.seed, "campaign seed (each family derives its own from it)")
        ->capture_default_str();
    run->add_option("--variants", variants, "comma-separated variant names, or all (see `list`)")
        ->capture_default_str();
    run->add_option("--threads", cfg.threads, "worker threads (0: all cores)")
        ->capture_default_str();
    run->add_option("--out", outDir, "output directory")->capture_default_str();
    run->add_flag("--per-case", cfg.perCase,
                  "also write DIR/cases.jsonl, one JSON object per case");
    run->add_option("--worst", cfg.worstPerFamily,
                    "worst cases kept per family in worst-cases.json")
        ->capture_default_str();
    run->add_option("--exact-route", route,
                    "exact construction: edge-merge, hull-of-differences, minkowski-sum-2")
        ->capture_default_str();
    run->add_option("--passes", cfg.maxPasses,
                    "maximum timed passes per family and variant (at least 5 are run "
                    "unless fewer are asked)")
        ->capture_default_str();
    run->add_flag("--no-timing", noTiming, "skip the timed passes (ns_per_query is null)");
    run->add_flag("--no-progress", noProgress,
                  "no progress bar (it is shown only when stderr is a terminal)");

    // --- generate ---
    std::vector<std::string> genFamilies, genComments;
    std::uint64_t genSeed = 1;
    std::string genOut;
    auto* gen = app.add_subcommand(
        "generate", "Write the cases of one or more families to a gjk-cases/1 file, to "
                    "replay with `run --cases FILE` or to share.");
    gen->footer(kExitCodes);
    gen->add_option("--family", genFamilies, "family spec as for run; repeatable")
        ->required()
        ->allow_extra_args(false);
    gen->add_option("--seed", genSeed, "campaign seed")->capture_default_str();
    gen->add_option("-o,--out", genOut, "output file ('-' for stdout)")->required();
    gen->add_option("--comment", genComments, "extra provenance comment; repeatable")
        ->allow_extra_args(false);

    // --- explain ---
    std::string exFile, exName, exFamily, exJson, exHtml, exVariants = "all", exRoute = "default";
    std::uint64_t exSeed = 1;
    auto* ex = app.add_subcommand(
        "explain", "Explain one case: inputs, each variant's result and iteration trace, "
                   "the exact result, the errors. Cases come from FILE, or from --family.");
    ex->footer(kExitCodes);
    std::string exPosName;
    ex->add_option("file", exFile, "gjk-cases/1 file holding the case (omit with --family)");
    ex->add_option("name", exPosName, "the case's name (or --name)");
    ex->add_option("--name,-n", exName, "the case's name");
    ex->add_option("--family", exFamily,
                   "take the case from this generated family instead of a file");
    ex->add_option("--seed", exSeed, "seed for --family")->capture_default_str();
    ex->add_option("--variants", exVariants, "variants to run")->capture_default_str();
    ex->add_option("--exact-route", exRoute, "exact construction")->capture_default_str();
    ex->add_option("--json", exJson,
                   "write the CaseDetail JSON (docs/report-schema.md) to this file");
    ex->add_option("--html", exHtml, "write the iteration viewer page to this file");

    // --- bench ---
    BenchConfig bcfg;
    std::vector<std::string> benchFamilies, benchFiles;
    std::string benchVariants = "all", benchJson;
    auto* bench = app.add_subcommand(
        "bench", "Time GJK variants on your cases (no exact side): per variant, repeated "
                 "single-threaded passes over all cases; prints the median ns per query, its "
                 "spread (fastest, slowest pass) and the ratio to `double`.");
    bench->footer(kExitCodes);
    bench->add_option("--cases", benchFiles, "a gjk-cases/1 file; repeatable")
        ->allow_extra_args(false);
    bench->add_option("--family", benchFamilies, "case family as for run; repeatable")
        ->allow_extra_args(false);
    bench->add_option("--seed", bcfg.seed, "campaign seed for --family")->capture_default_str();
    bench
        ->add_option("--variants", benchVariants,
                     "comma-separated variant names, or all (see `list`)")
        ->capture_default_str();
    bench->add_flag("--warm", bcfg.warm,
                    "time warm-started queries: each starts from the SimplexCache of a previous "
                    "query of the same case");
    bench->add_option("--passes", bcfg.passes, "timed passes per variant")->capture_default_str();
    bench->add_option("--json", benchJson, "write the timings as JSON to this file");

    // --- list ---
    auto* list =
        app.add_subcommand("list", "List the families (with their reasons) and the variants.");

    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::ParseError& e)
    {
        const int code = app.exit(e);
        return code == 0 ? kExitPass : kExitInput;
    }

    try
    {
        if (*run)
        {
            cfg.variants = parseVariants(variants);
            cfg.route = parseRouteOrThrow(route);
            cfg.timing = !noTiming;
            cfg.minPasses = std::min(cfg.minPasses, std::max(1, cfg.maxPasses));
            cfg.progress = !noProgress && isatty(STDERR_FILENO);
            cfg.command = joinArgs(argc, argv);
            if (cfg.threads < 0)
                throw InputError("--threads must be 0 (all cores) or more");
            if (families.empty() && files.empty())
            {
                families = defaultFamilies();
                files = defaultCaseFiles();
            }
            cfg.families = families;
            cfg.caseFiles = files;
            auto inputs = loadInputs(cfg);
            Campaign camp = runCampaign(cfg, std::move(inputs));
            const std::string page = writeCampaign(camp, outDir);
            std::fputs(terminalSummary(camp.report).c_str(), stdout);
            std::printf("report: %s\n", page.c_str());
            return camp.exitCode;
        }
        if (*bench)
        {
            bcfg.variants = parseVariants(benchVariants);
            bcfg.command = joinArgs(argc, argv);
            if (benchFamilies.empty() && benchFiles.empty())
                throw InputError("bench: which cases? give --cases FILE and/or --family F");
            if (bcfg.passes < 1)
                throw InputError("--passes must be at least 1");
            CampaignConfig in;
            in.families = bcfg.families = benchFamilies;
            in.caseFiles = bcfg.caseFiles = benchFiles;
            in.seed = bcfg.seed;
            const BenchResult res = runBench(bcfg, loadInputs(in));
            std::fputs(benchTable(res.json).c_str(), stdout);
            for (const auto& r : res.json["rejected"])
                std::fprintf(stderr, "gjk-validate: rejected %s: %s\n",
                             r["name"].get<std::string>().c_str(),
                             r["reason"].get<std::string>().c_str());
            if (!benchJson.empty())
            {
                writeText(benchJson, res.json.dump(1) + "\n");
                std::printf("json: %s\n", benchJson.c_str());
            }
            return res.exitCode;
        }
        if (*gen)
        {
            std::vector<Case> cases;
            std::vector<std::string> comments = {
                fmt::format("generated by `{}` (seed {}) on {}, git {}", joinArgs(argc, argv),
                            genSeed, isoDateUtc(), gitRevision())};
            for (const auto& spec : genFamilies)
                for (auto& f : generateFamilies(spec, genSeed))
                {
                    comments.push_back(fmt::format("{} ({} cases, family seed {}): {}", f.name,
                                                   f.cases.size(), f.seed, f.reason));
                    for (auto& c : f.cases)
                        cases.push_back(std::move(c));
                }
            for (const auto& c : genComments)
                comments.push_back(c);
            if (genOut == "-")
                std::fputs(caseFileText(comments, cases).c_str(), stdout);
            else
            {
                writeCaseFile(genOut, comments, cases);
                std::fprintf(stderr, "wrote %zu cases to %s\n", cases.size(), genOut.c_str());
            }
            return kExitPass;
        }
        if (*ex)
        {
            // `explain FILE NAME`, `explain FILE --name NAME`, `explain --family F NAME`.
            if (exName.empty())
                exName = exPosName;
            if (exName.empty() && !exFamily.empty())
                std::swap(exName, exFile);
            if (exName.empty())
                throw InputError("explain: which case? give its name (explain FILE NAME)");
            EvalContext ctx;
            ctx.variants = parseVariants(exVariants);
            ctx.exactOptions.route = parseRouteOrThrow(exRoute);
            Case found;
            std::string family;
            bool ok = false;
            std::string rejected;
            if (!exFamily.empty())
            {
                for (auto& f : generateFamilies(exFamily, exSeed))
                    for (auto& c : f.cases)
                        if (!ok && c.name == exName)
                        {
                            found = c;
                            family = f.name;
                            ok = true;
                        }
            }
            else
            {
                if (exFile.empty())
                    throw InputError("explain: give a case FILE or --family");
                CaseFile file = readCaseFile(exFile);
                family = "file:" + std::filesystem::path(exFile).filename().string();
                for (auto& e : file.entries)
                    if (!ok && e.c.name == exName)
                    {
                        found = e.c;
                        rejected = e.rejected;
                        ok = true;
                    }
            }
            if (!ok)
                throw InputError(fmt::format("explain: no case named '{}'", exName));
            if (!rejected.empty())
                throw InputError(
                    fmt::format("explain: case '{}' is rejected: {}", exName, rejected));
            CaseOutcome o = evaluateCase(found, ctx);
            const Json detail = caseDetail(found, family, ctx, o, "explain");
            std::fputs(explainText(detail).c_str(), stdout);
            if (!exJson.empty())
                writeText(exJson, detail.dump(1) + "\n");
            if (!exHtml.empty())
            {
#if defined(GJK2D_HAVE_HTML)
                writeText(exHtml, gjk_html::renderCase(nlohmann::json::parse(detail.dump())));
#else
                throw InputError("--html: this build has no HTML renderer (validation/html/)");
#endif
            }
            return o.rejected.empty() ? kExitPass : kExitInput;
        }
        if (*list)
        {
            std::printf("families:\n  random  (default count %d)\n", kDefaultRandomCount);
            for (const auto& h : hardSubFamilies())
                std::printf("  hard/%-20s %4d cases  %s\n", h.name.c_str(), h.count,
                            h.reason.c_str());
            std::printf("variants (default %s; judged decide the exit code, comparison are "
                        "reported only):\n",
                        kDefaultVariants);
            for (const auto& v : variantTable())
                std::printf("  %-22s %-6s %-10s %s\n", v.name.c_str(), scalarName(v.scalar),
                            v.judged ? "judged" : "comparison", v.description.c_str());
            return kExitPass;
        }
    }
    catch (const InputError& e)
    {
        std::fprintf(stderr, "gjk-validate: error: %s\n", e.what());
        return kExitInput;
    }
    return kExitInput;
}
