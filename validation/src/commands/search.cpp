// gjk-validate search: cases mutated toward the worst error / bound ratio (adversarial search).
#include "campaign/search.hpp"
#include "campaign/campaign.hpp"
#include "commands/command_line.hpp"
#include "commands/fault.hpp"
#include "commands/outputs.hpp"
#include "common/output.hpp"
#include "implementations/variants.hpp"
#include "report/report.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <unistd.h>

namespace gjkval
{
namespace
{
struct Options
{
    SearchConfig scfg;
    std::vector<std::string> searchFamilies, searchFiles;
    std::string searchVariants = "double,float", searchSeed = "1", searchOut, searchJson;
    std::string searchTruth = "filtered";
    std::uint64_t searchEvaluations = 0;
    double searchSeconds = 0;
    bool searchVerbose = false, searchNoProgress = false;
};

int searchCommand(Options& o, const CommandLine& line, CLI::App& sub)
{
    o.scfg.seed = parseSeed(o.searchSeed);
    o.scfg.truthFilter = parseTruthOrThrow(o.searchTruth);
    o.scfg.variants = parseVariants(o.searchVariants);
    o.scfg.command = line.text();
    if (o.searchFamilies.empty() && o.searchFiles.empty())
        throw InputError("search: which cases to start from? give --family F and/or --cases "
                         "FILE");
    checkRange("--threads", o.scfg.threads, 0, kMaxThreads);
    checkRange("--population", o.scfg.population, 1, kMaxSearchPopulation);
    if (sub.count("--evaluations") > 0 &&
        (o.searchEvaluations < 1 || o.searchEvaluations > kMaxSearchEvaluations))
        throw InputError(fmt::format("--evaluations {}: expected 1..{}", o.searchEvaluations,
                                     kMaxSearchEvaluations));
    if (sub.count("--seconds") > 0 && !(o.searchSeconds > 0 && o.searchSeconds <= 1e7))
        throw InputError(
            fmt::format("--seconds {}: expected a number in (0, 1e7]", o.searchSeconds));
    o.scfg.evaluations = o.searchEvaluations;
    o.scfg.seconds = o.searchSeconds;
    if (o.scfg.evaluations == 0 && o.scfg.seconds == 0)
        o.scfg.evaluations = kDefaultSearchEvaluations;
    o.scfg.progress = o.searchVerbose || (!o.searchNoProgress && isatty(STDERR_FILENO));
    checkFamilies(o.searchFamilies, false);
    checkCaseFiles(o.searchFiles);
    if (sub.count("--out") > 0)
        checkOutputFile("--out", o.searchOut);
    if (sub.count("--json") > 0)
        checkOutputFile("--json", o.searchJson);
    testFault();
    o.scfg.families = o.searchFamilies;
    o.scfg.caseFiles = o.searchFiles;
    const SearchResult res =
        runSearch(o.scfg, collectInputs(o.searchFamilies, o.searchFiles, o.scfg.seed));
    std::fputs(searchSummary(o.scfg, res).c_str(), stdout);
    writeOutput("cases", o.searchOut, [&] { return searchCaseFileText(o.scfg, res); });
    writeOutput("json", o.searchJson, [&] { return res.json.dump(1) + "\n"; });
    flushStdout();
    return res.exitCode;
}
} // namespace

Subcommand addSearch(CLI::App& app, const CommandLine& line)
{
    auto o = std::make_shared<Options>();
    auto* search = app.add_subcommand(
        "search", "Adversarial search: mutate the cases of families and case files toward the "
                  "largest error / bound ratio of the chosen variants, within a budget of "
                  "evaluations and/or seconds. Every chosen variant is judged: a failure found "
                  "gives exit code 1. Without a budget: --evaluations 10000.");
    search->footer(exitCodesHelp());
    search->add_option("--family", o->searchFamilies, "start family as for run; repeatable")
        ->allow_extra_args(false);
    search->add_option("--cases", o->searchFiles, "start cases from a gjk-cases/1 file; repeatable")
        ->allow_extra_args(false);
    search
        ->add_option("--variants", o->searchVariants,
                     "comma-separated variant names, or all (see `list`)")
        ->capture_default_str();
    search->add_option("--seed", o->searchSeed, "seed of the families and the mutations, 0..2^64-1")
        ->capture_default_str();
    search
        ->add_option("--threads", o->scfg.threads,
                     "worker threads, 0..256 (0: all cores; the result does not depend on it)")
        ->capture_default_str();
    search->add_option("--evaluations", o->searchEvaluations,
                       "budget: case evaluations (start cases included), 1..1e9");
    search->add_option("--seconds", o->searchSeconds,
                       "budget: wall time in seconds, checked between generations, > 0");
    search->add_option("--truth", o->searchTruth, kTruthHelp)->capture_default_str();
    search->add_option("--population", o->scfg.population, "best cases kept, 1..1000")
        ->capture_default_str();
    search->add_option("--out", o->searchOut,
                       "write the final population (best first) and the failing cases as a "
                       "gjk-cases/1 file");
    search->add_option("--json", o->searchJson, "write a JSON summary to this file");
    search->add_flag("--verbose", o->searchVerbose,
                     "a line on stderr per improvement, also when stderr is not a terminal");
    search->add_flag("--no-progress", o->searchNoProgress,
                     "no improvement lines (shown only when stderr is a terminal)");
    return {search, [o, line, search] { return searchCommand(*o, line, *search); }};
}

} // namespace gjkval
