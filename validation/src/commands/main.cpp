// gjk-validate: the validation runner (docs/validation.md).
//   run       a campaign: families and case files -> exact truth, GJK variants -> reports
//   generate  write a family's cases to a gjk-cases/1 file
//   explain   one case in detail: inputs, each variant's result and trace, the exact result
//   bench     time the variants on given cases (no exact side)
//   search    mutate cases toward the worst error / bound ratio (adversarial search)
//   list      the families and variants
#include "timing/bench.hpp"
#include "campaign/campaign.hpp"
#include "inputs/cases.hpp"
#include "evaluate/evaluate.hpp"
#include "inputs/families.hpp"
#include "common/output.hpp"
#include "report/report.hpp"
#include "campaign/search.hpp"
#include "evaluate/variants.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <stdexcept>
#include <unistd.h>

#if defined(GJK2D_HAVE_HTML)
#include "gjk_html/html.hpp"
#endif

using namespace gjkval;

namespace
{
namespace fs = std::filesystem;

// Ranges of the numeric options (docs/validation.md).
constexpr int kMaxThreads = 256;
constexpr int kMaxPasses = 1000;
constexpr int kMaxWorst = 1000;
constexpr std::size_t kMaxCommentBytes = 1000;
constexpr int kMaxSearchPopulation = 1000;
constexpr std::uint64_t kMaxSearchEvaluations = 1000000000, kDefaultSearchEvaluations = 10000;

// Memory a command needs per case, measured as peak RSS growth over 5000 .. 40000 `random` cases
// (GCC 12 release build, every variant): run 4.7 KB, run --per-case 24 KB more, generate 1.4 KB,
// bench 1.5 KB. Rounded up; a `hard/many-vertices` case (up to 2 x 4096 points, their exact
// hulls and float copies) is counted as 1 MB. A guard against runs that cannot fit, not a
// prediction: a run is refused when its estimate exceeds the machine's physical memory.
constexpr double kRunBytesPerCase = 5e3, kPerCaseBytesPerCase = 25e3, kGenerateBytesPerCase = 2e3,
                 kLargeCaseBytes = 1e6;

exact::Route parseRouteOrThrow(const std::string& name)
{
    exact::Route r = exact::Route::Default;
    if (!exact::parseRoute(name, r))
        throw InputError(
            fmt::format("unknown exact route '{}' (hull-of-differences, minkowski-sum-2, "
                        "edge-merge, default)",
                        excerpt(name)));
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

// Every argument must be valid UTF-8: paths, names and comments are copied into JSON outputs,
// which hold only UTF-8 (a \xff in --out used to abort the program after the whole campaign).
void checkArgsUtf8(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
        if (!isValidUtf8(argv[i]))
        {
            const std::string prev = i > 1 ? argv[i - 1] : "";
            throw InputError(fmt::format(
                "argument {} ('{}'{}) is not valid UTF-8", i, excerpt(argv[i]),
                !prev.empty() && prev[0] == '-' ? fmt::format(", the value of {}", excerpt(prev))
                                                : std::string()));
        }
}

// A seed: decimal digits only, 0 .. 2^64 - 1 ("-1" used to become 2^64 - 1 silently).
std::uint64_t parseSeed(const std::string& text)
{
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v, 10);
    const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](char c)
                                                     { return c >= '0' && c <= '9'; });
    if (!digits || ec != std::errc() || ptr != end)
        throw InputError(fmt::format("--seed '{}': expected a whole number in 0..{}",
                                     excerpt(text), std::numeric_limits<std::uint64_t>::max()));
    return v;
}

void checkRange(const char* option, int value, int lo, int hi)
{
    if (value < lo || value > hi)
        throw InputError(fmt::format("{} {}: expected {}..{}", option, value, lo, hi));
}

void checkComments(const std::vector<std::string>& comments)
{
    for (const auto& c : comments)
        if (c.size() > kMaxCommentBytes)
            throw InputError(fmt::format("--comment '{}': {} bytes, at most {} allowed",
                                         excerpt(c), c.size(), kMaxCommentBytes));
}

// Case files: each readable, none given twice (also not under two paths).
void checkCaseFiles(const std::vector<std::string>& files)
{
    for (std::size_t i = 0; i < files.size(); ++i)
    {
        if (files[i].empty())
            throw InputError("--cases: the file name is empty");
        std::ifstream in(files[i], std::ios::binary);
        if (!in)
            throw InputError(fmt::format("{}: cannot open the file: {}", excerpt(files[i]),
                                         std::strerror(errno)));
        for (std::size_t j = 0; j < i; ++j)
        {
            std::error_code ec;
            if (fs::equivalent(files[i], files[j], ec))
                throw InputError(fmt::format("--cases: '{}' and '{}' are the same file",
                                             excerpt(files[j]), excerpt(files[i])));
        }
    }
}

// Parses every family spec (InputError on a bad one) and refuses a command whose estimated memory
// exceeds the machine's physical memory.
void checkFamilies(const std::vector<std::string>& specs, double bytesPerCase)
{
    double need = 0;
    std::string biggest;
    double biggestBytes = -1;
    for (const auto& spec : specs)
    {
        double bytes = 0;
        for (const auto& [name, count] : familyCaseCounts(parseFamilySpec(spec)))
            bytes += double(count) *
                     (name == "hard/many-vertices" ? kLargeCaseBytes + bytesPerCase : bytesPerCase);
        need += bytes;
        if (bytes > biggestBytes)
            biggestBytes = bytes, biggest = spec;
    }
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0)
        return; // unknown: bad_alloc, if it comes, still ends the run with exit code 5
    const double have = double(pages) * double(pageSize);
    if (need > have)
        throw InputError(fmt::format(
            "--family {}: this command needs about {:.3g} GB of memory (about {:.2g} KB per case), "
            "more than this machine's {:.3g} GB; give fewer cases",
            excerpt(biggest), need / 1e9, bytesPerCase / 1e3, have / 1e9));
}

// Test-only: GJK2D_VALIDATE_TEST_FAULT=logic_error|bad_alloc|unknown makes the program throw that
// once its arguments are checked, so that tests reach the top-level handlers (exit codes 4, 5).
void testFault()
{
    const char* f = std::getenv("GJK2D_VALIDATE_TEST_FAULT");
    if (f == nullptr)
        return;
    const std::string fault = f;
    if (fault == "logic_error")
        throw std::logic_error("test fault: a broken invariant");
    if (fault == "bad_alloc")
        throw std::bad_alloc();
    if (fault == "unknown")
        throw 42;
}

// The last check of a command: what it printed reached standard output.
void flushStdout()
{
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
        throw OutputError(fmt::format("standard output: write failed: {}", std::strerror(errno)));
}
} // namespace

namespace
{
int runMain(int argc, char** argv)
{
    checkArgsUtf8(argc, argv);
    const std::string exitCodes = exitCodesHelp();
    CLI::App app{"gjk-validate: checks the GJK distance library against an exact ground truth.\n"
                 "Runs case families and case files through the GJK variants and the exact\n"
                 "(CGAL/GMP) distance, and reports correctness, accuracy and speed."};
    app.require_subcommand(1);
    app.footer(exitCodes);
    app.set_help_all_flag("--help-all", "help for every subcommand");

    // --- run ---
    CampaignConfig cfg;
    std::vector<std::string> families, files;
    std::string variants = kDefaultVariants, outDir = "reports/latest/", route = "default",
                seed = "1";
    bool noProgress = false, noTiming = false;
    auto* run = app.add_subcommand(
        "run", "Run a campaign and write DIR/report.json, report.md, worst-cases.json "
               "(and cases.jsonl, index.html). Without --family and --cases: the "
               "default campaign, --family random:200000 --family hard --family engine plus every "
               "validation/cases/*.json.");
    run->footer(exitCodes);
    run->add_option("--family", families,
                    "case family with optional count: random[:N] (default N 200000), hard[:N] (all "
                    "sub-families, N each, default their built-in counts), hard/<sub>[:N], "
                    "engine[:N] (all engine families, N each, default 2000), "
                    "engine/<scene>-<kind>[:N]; N in 1..1e8 and within memory; repeatable (see "
                    "`list`)")
        ->allow_extra_args(false);
    run->add_option("--cases", files, "a gjk-cases/1 file; repeatable")->allow_extra_args(false);
    run->add_option("--seed", seed, "campaign seed, 0..2^64-1 (each family derives its own)")
        ->capture_default_str();
    run->add_option("--variants", variants, "comma-separated variant names, or all (see `list`)")
        ->capture_default_str();
    run->add_option("--threads", cfg.threads, "worker threads, 0..256 (0: all cores)")
        ->capture_default_str();
    run->add_option("--out", outDir,
                    "output directory, replaced as a whole (it may hold only a previous report)")
        ->capture_default_str();
    run->add_flag("--per-case", cfg.perCase,
                  "also write DIR/cases.jsonl, one JSON object per case");
    run->add_option("--worst", cfg.worstPerFamily,
                    "worst cases kept per family in worst-cases.json, 0..1000")
        ->capture_default_str();
    run->add_option("--exact-route", route,
                    "exact construction: edge-merge, hull-of-differences, minkowski-sum-2")
        ->capture_default_str();
    run->add_option("--passes", cfg.maxPasses,
                    "maximum timed passes per family and variant, 1..1000 (at least 5 are run "
                    "unless fewer are asked)")
        ->capture_default_str();
    run->add_flag("--no-timing", noTiming, "skip the timed passes (ns_per_query is null)");
    run->add_flag("--no-progress", noProgress,
                  "no progress bar (it is shown only when stderr is a terminal)");

    // --- generate ---
    std::vector<std::string> genFamilies, genComments;
    std::string genSeed = "1";
    std::string genOut;
    auto* gen = app.add_subcommand(
        "generate", "Write the cases of one or more families to a gjk-cases/1 file, to "
                    "replay with `run --cases FILE` or to share.");
    gen->footer(exitCodes);
    gen->add_option("--family", genFamilies, "family spec as for run; repeatable")
        ->required()
        ->allow_extra_args(false);
    gen->add_option("--seed", genSeed, "campaign seed, 0..2^64-1")->capture_default_str();
    gen->add_option("-o,--out", genOut,
                    "output file ('-' for stdout), replaced whole or left as it was")
        ->required();
    gen->add_option("--comment", genComments,
                    "extra provenance comment (at most 1000 bytes); repeatable")
        ->allow_extra_args(false);

    // --- explain ---
    std::vector<std::string> exPositional;
    std::string exName, exFamily, exJson, exHtml, exVariants = "all", exRoute = "default",
                                                  exSeed = "1";
    auto* ex = app.add_subcommand(
        "explain", "Explain one case: inputs, each variant's result and iteration trace, "
                   "the exact result, the errors. Cases come from FILE, or from --family.");
    ex->footer(exitCodes);
    ex->add_option("args", exPositional,
                   "FILE NAME (the gjk-cases/1 file and the case's name), or NAME alone with "
                   "--family; NAME may be given as --name instead");
    ex->add_option("--name,-n", exName, "the case's name");
    ex->add_option("--family", exFamily,
                   "take the case from this generated family instead of a file");
    ex->add_option("--seed", exSeed, "seed for --family, 0..2^64-1")->capture_default_str();
    ex->add_option("--variants", exVariants, "variants to run")->capture_default_str();
    ex->add_option("--exact-route", exRoute, "exact construction")->capture_default_str();
    ex->add_option("--json", exJson,
                   "write the CaseDetail JSON (docs/report-schema.md) to this file");
    ex->add_option("--html", exHtml, "write the iteration viewer page to this file");

    // --- bench ---
    BenchConfig bcfg;
    std::vector<std::string> benchFamilies, benchFiles;
    std::string benchVariants = "all", benchJson, benchSeed = "1";
    auto* bench = app.add_subcommand(
        "bench", "Time GJK variants on your cases (no exact side): per variant, repeated "
                 "single-threaded passes over all cases; prints the median ns per query, its "
                 "spread (fastest, slowest pass) and the ratio to `double`.");
    bench->footer(exitCodes);
    bench->add_option("--cases", benchFiles, "a gjk-cases/1 file; repeatable")
        ->allow_extra_args(false);
    bench->add_option("--family", benchFamilies, "case family as for run; repeatable")
        ->allow_extra_args(false);
    bench->add_option("--seed", benchSeed, "campaign seed for --family, 0..2^64-1")
        ->capture_default_str();
    bench
        ->add_option("--variants", benchVariants,
                     "comma-separated variant names, or all (see `list`)")
        ->capture_default_str();
    bench->add_flag("--warm", bcfg.warm,
                    "time warm-started queries: each starts from the SimplexCache of a previous "
                    "query of the same case");
    bench->add_option("--passes", bcfg.passes, "timed passes per variant, 1..1000")
        ->capture_default_str();
    bench->add_option("--json", benchJson, "write the timings as JSON to this file");

    // --- search ---
    SearchConfig scfg;
    std::vector<std::string> searchFamilies, searchFiles;
    std::string searchVariants = "double,float", searchSeed = "1", searchOut, searchJson;
    std::uint64_t searchEvaluations = 0;
    double searchSeconds = 0;
    bool searchVerbose = false, searchNoProgress = false;
    auto* search = app.add_subcommand(
        "search", "Adversarial search: mutate the cases of families and case files toward the "
                  "largest error / bound ratio of the chosen variants, within a budget of "
                  "evaluations and/or seconds. Every chosen variant is judged: a failure found "
                  "gives exit code 1. Without a budget: --evaluations 10000.");
    search->footer(exitCodes);
    search->add_option("--family", searchFamilies, "start family as for run; repeatable")
        ->allow_extra_args(false);
    search->add_option("--cases", searchFiles, "start cases from a gjk-cases/1 file; repeatable")
        ->allow_extra_args(false);
    search->add_option("--variants", searchVariants,
                       "comma-separated variant names, or all (see `list`)")
        ->capture_default_str();
    search->add_option("--seed", searchSeed, "seed of the families and the mutations, 0..2^64-1")
        ->capture_default_str();
    search->add_option("--threads", scfg.threads,
                       "worker threads, 0..256 (0: all cores; the result does not depend on it)")
        ->capture_default_str();
    search->add_option("--evaluations", searchEvaluations,
                       "budget: case evaluations (start cases included), 1..1e9");
    search->add_option("--seconds", searchSeconds,
                       "budget: wall time in seconds, checked between generations, > 0");
    search->add_option("--population", scfg.population, "best cases kept, 1..1000")
        ->capture_default_str();
    search->add_option("--out", searchOut,
                       "write the final population (best first) and the failing cases as a "
                       "gjk-cases/1 file");
    search->add_option("--json", searchJson, "write a JSON summary to this file");
    search->add_flag("--verbose", searchVerbose,
                     "a line on stderr per improvement, also when stderr is not a terminal");
    search->add_flag("--no-progress", searchNoProgress,
                     "no improvement lines (shown only when stderr is a terminal)");

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

    // Every argument is checked here, before any work starts (InputError: exit code 2).
    if (*run)
    {
        cfg.seed = parseSeed(seed);
        cfg.variants = parseVariants(variants);
        cfg.route = parseRouteOrThrow(route);
        checkRange("--threads", cfg.threads, 0, kMaxThreads);
        checkRange("--passes", cfg.maxPasses, 1, kMaxPasses);
        checkRange("--worst", cfg.worstPerFamily, 0, kMaxWorst);
        cfg.timing = !noTiming;
        cfg.minPasses = std::min(cfg.minPasses, cfg.maxPasses);
        cfg.progress = !noProgress && isatty(STDERR_FILENO);
        cfg.command = joinArgs(argc, argv);
        if (families.empty() && files.empty())
        {
            families = defaultFamilies();
            files = defaultCaseFiles();
        }
        checkFamilies(families, kRunBytesPerCase + (cfg.perCase ? kPerCaseBytesPerCase : 0));
        checkCaseFiles(files);
        checkReportDir(outDir);
        testFault();
        cfg.families = families;
        cfg.caseFiles = files;
        auto inputs = loadInputs(cfg);
        Campaign camp = runCampaign(cfg, std::move(inputs));
        const std::string page = writeCampaign(camp, outDir);
        std::fputs(terminalSummary(camp.report).c_str(), stdout);
        std::printf("report: %s\n", page.c_str());
        flushStdout();
        return camp.exitCode;
    }
    if (*bench)
    {
        bcfg.seed = parseSeed(benchSeed);
        bcfg.variants = parseVariants(benchVariants);
        bcfg.command = joinArgs(argc, argv);
        if (benchFamilies.empty() && benchFiles.empty())
            throw InputError("bench: which cases? give --cases FILE and/or --family F");
        checkRange("--passes", bcfg.passes, 1, kMaxPasses);
        checkFamilies(benchFamilies, kGenerateBytesPerCase);
        checkCaseFiles(benchFiles);
        if (!benchJson.empty() || bench->count("--json") > 0)
            checkOutputFile("--json", benchJson);
        testFault();
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
            writeFileAtomic(benchJson, res.json.dump(1) + "\n");
            std::printf("json: %s\n", benchJson.c_str());
        }
        flushStdout();
        return res.exitCode;
    }
    if (*search)
    {
        scfg.seed = parseSeed(searchSeed);
        scfg.variants = parseVariants(searchVariants);
        scfg.command = joinArgs(argc, argv);
        if (searchFamilies.empty() && searchFiles.empty())
            throw InputError("search: which cases to start from? give --family F and/or --cases "
                             "FILE");
        checkRange("--threads", scfg.threads, 0, kMaxThreads);
        checkRange("--population", scfg.population, 1, kMaxSearchPopulation);
        if (search->count("--evaluations") > 0 &&
            (searchEvaluations < 1 || searchEvaluations > kMaxSearchEvaluations))
            throw InputError(fmt::format("--evaluations {}: expected 1..{}", searchEvaluations,
                                         kMaxSearchEvaluations));
        if (search->count("--seconds") > 0 && !(searchSeconds > 0 && searchSeconds <= 1e7))
            throw InputError(fmt::format("--seconds {}: expected a number in (0, 1e7]",
                                         searchSeconds));
        scfg.evaluations = searchEvaluations;
        scfg.seconds = searchSeconds;
        if (scfg.evaluations == 0 && scfg.seconds == 0)
            scfg.evaluations = kDefaultSearchEvaluations;
        scfg.progress = searchVerbose || (!searchNoProgress && isatty(STDERR_FILENO));
        checkFamilies(searchFamilies, kRunBytesPerCase);
        checkCaseFiles(searchFiles);
        if (search->count("--out") > 0)
            checkOutputFile("--out", searchOut);
        if (search->count("--json") > 0)
            checkOutputFile("--json", searchJson);
        testFault();
        CampaignConfig in;
        in.families = scfg.families = searchFamilies;
        in.caseFiles = scfg.caseFiles = searchFiles;
        in.seed = scfg.seed;
        const SearchResult res = runSearch(scfg, loadInputs(in));
        std::fputs(searchSummary(scfg, res).c_str(), stdout);
        if (!searchOut.empty())
        {
            writeFileAtomic(searchOut, searchCaseFileText(scfg, res));
            std::printf("cases: %s\n", searchOut.c_str());
        }
        if (!searchJson.empty())
        {
            writeFileAtomic(searchJson, res.json.dump(1) + "\n");
            std::printf("json: %s\n", searchJson.c_str());
        }
        flushStdout();
        return res.exitCode;
    }
    if (*gen)
    {
        const std::uint64_t genSeedValue = parseSeed(genSeed);
        checkComments(genComments);
        checkFamilies(genFamilies, kGenerateBytesPerCase);
        checkOutputFile("--out", genOut);
        testFault();
        std::vector<Case> cases;
        std::vector<std::string> comments = {
            fmt::format("generated by `{}` (seed {}) on {}, git {}", joinArgs(argc, argv),
                        genSeedValue, isoDateUtc(), gitRevision())};
        for (const auto& spec : genFamilies)
            for (auto& f : generateFamilies(spec, genSeedValue))
            {
                comments.push_back(fmt::format("{} ({} cases, family seed {}): {}", f.name,
                                               f.cases.size(), f.seed, f.reason));
                for (auto& c : f.cases)
                    cases.push_back(std::move(c));
            }
        for (const auto& c : genComments)
            comments.push_back(c);
        writeFileAtomic(genOut, caseFileText(comments, cases));
        if (genOut != "-")
            std::fprintf(stderr, "wrote %zu cases to %s\n", cases.size(), genOut.c_str());
        return kExitPass;
    }
    if (*ex)
    {
        // `explain FILE NAME`, `explain FILE --name NAME`, `explain --family F NAME`,
        // `explain --family F --name NAME`: anything more is refused.
        std::string exFile;
        const std::size_t wanted = (exFamily.empty() ? 1 : 0) + (exName.empty() ? 1 : 0);
        if (exPositional.size() > wanted)
            throw InputError(fmt::format("explain: unexpected argument '{}' (give FILE NAME, or "
                                         "--family F NAME)",
                                         excerpt(exPositional[wanted])));
        std::size_t next = 0;
        if (exFamily.empty() && next < exPositional.size())
            exFile = exPositional[next++];
        if (exName.empty() && next < exPositional.size())
            exName = exPositional[next++];
        if (exFamily.empty() && exFile.empty())
            throw InputError("explain: give a case FILE or --family");
        if (exName.empty())
            throw InputError("explain: which case? give its name (explain FILE NAME)");
        const std::uint64_t seedValue = parseSeed(exSeed);
        EvalContext ctx;
        ctx.variants = parseVariants(exVariants);
        ctx.exactOptions.route = parseRouteOrThrow(exRoute);
        if (!exFamily.empty())
            checkFamilies({exFamily}, kGenerateBytesPerCase);
        else
            checkCaseFiles({exFile});
        if (ex->count("--json") > 0)
            checkOutputFile("--json", exJson);
        if (ex->count("--html") > 0)
        {
#if !defined(GJK2D_HAVE_HTML)
            throw InputError("--html: this build has no HTML renderer (validation/html/)");
#endif
            checkOutputFile("--html", exHtml);
        }
        testFault();
        Case found;
        std::string family;
        bool ok = false;
        std::string rejected;
        if (!exFamily.empty())
        {
            for (auto& f : generateFamilies(exFamily, seedValue))
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
            CaseFile file = readCaseFile(exFile);
            family = "file:" + fs::path(exFile).filename().string();
            for (auto& e : file.entries)
                if (!ok && e.c.name == exName)
                {
                    found = e.c;
                    rejected = e.rejected;
                    ok = true;
                }
        }
        if (!ok)
            throw InputError(fmt::format("explain: no case named '{}'", excerpt(exName)));
        if (!rejected.empty())
            throw InputError(
                fmt::format("explain: case '{}' is rejected: {}", excerpt(exName), rejected));
        CaseOutcome o = evaluateCase(found, ctx);
        const Json detail = caseDetail(found, family, ctx, o, "explain");
        std::fputs(explainText(detail).c_str(), stdout);
        if (!exJson.empty())
            writeFileAtomic(exJson, detail.dump(1) + "\n");
#if defined(GJK2D_HAVE_HTML)
        if (!exHtml.empty())
            writeFileAtomic(exHtml, gjk_html::renderCase(nlohmann::json::parse(detail.dump())));
#endif
        flushStdout();
        return o.rejected.empty() ? kExitPass : kExitInput;
    }
    if (*list)
    {
        std::printf("families:\n  random  (default count %d)\n", kDefaultRandomCount);
        for (const auto& h : hardSubFamilies())
            std::printf("  hard/%-20s %4d cases  %s\n", h.name.c_str(), h.count, h.reason.c_str());
        for (const auto& e : engineSubFamilies())
            std::printf("  engine/%-19s %4d cases  %s\n", e.name.c_str(), e.count,
                        e.reason.c_str());
        std::printf("variants (default %s; judged decide the exit code, comparison are "
                    "reported only):\n",
                    kDefaultVariants);
        for (const auto& v : variantTable())
            std::printf("  %-22s %-6s %-10s %s\n", v.name.c_str(), scalarName(v.scalar),
                        v.judged ? "judged" : "comparison", v.description.c_str());
        flushStdout();
        return kExitPass;
    }
    throw std::logic_error("no subcommand ran although CLI11 requires one");
}
} // namespace

// Every failure ends here with its documented exit code (kExitCodeTable) and one line on stderr.
int main(int argc, char** argv)
{
    // A file size limit (ulimit -f) makes a write fail with EFBIG, handled as any failed write,
    // instead of killing the program with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    try
    {
        return runMain(argc, argv);
    }
    catch (const InputError& e)
    {
        std::fprintf(stderr, "gjk-validate: error: %s\n", e.what());
        return kExitInput;
    }
    catch (const OutputError& e)
    {
        std::fprintf(stderr, "gjk-validate: error: %s (the previous output is left in place)\n",
                     e.what());
        return kExitResources;
    }
    catch (const std::bad_alloc&)
    {
        std::fputs("gjk-validate: error: out of memory (no output was written; give fewer "
                   "cases)\n",
                   stderr);
        return kExitResources;
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "gjk-validate: internal error: %s (a bug in gjk2d, not in the "
                             "input: please report it)\n",
                     excerpt(e.what(), 300).c_str());
        return kExitInternal;
    }
    catch (...)
    {
        std::fputs("gjk-validate: internal error: an unknown exception (a bug in gjk2d, not in "
                   "the input: please report it)\n",
                   stderr);
        return kExitInternal;
    }
}
