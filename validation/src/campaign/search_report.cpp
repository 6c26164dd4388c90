// What `gjk-validate search` writes: the --json summary, the terminal summary and the --out case
// file, from the search's result.
#include "campaign/search.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <set>

namespace gjkval
{

std::string ratioText(double r)
{
    return std::isnan(r) ? std::string("n/a") : fmt::format("{:.4g}", r);
}

namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN(); // a ratio not counted

// The search's context: its inputs (start cases) and their counts, as report.json's.
Json searchContext(const SearchConfig& cfg, const SearchResult& r,
                   const std::vector<FamilyData>& inputs)
{
    Json inputsJson = Json::array();
    std::size_t total = 0, rejected = 0;
    for (const auto& f : inputs)
    {
        inputsJson.push_back(f.input);
        total += f.cases.size();
        for (const auto& why : f.rejected)
            rejected += why.empty() ? 0 : 1;
    }
    Json context = contextJson(isoDateUtc(), gitRevision(), cfg.command, cfg.seed, r.threads,
                               std::move(inputsJson), total, rejected);
    context["elapsed_s"] = {{"total", r.seconds}};
    return context;
}

// Per variant: the best ratios, the best case and the failures.
Json variantsJson(const SearchConfig& cfg, const SearchResult& r)
{
    Json vars = Json::object();
    for (std::size_t k = 0; k < cfg.variants.size(); ++k)
        vars[cfg.variants[k]->name] = {{"start_best_ratio", optNum(r.startBest[k])},
                                       {"best_passing_ratio", optNum(r.bestPassing[k])},
                                       {"best_ratio", optNum(r.best[k])},
                                       {"best_case", r.bestCase[k]},
                                       {"failures", r.variantFailures[k]}};
    return vars;
}

// The population (best first) and the failing cases kept, by name.
Json populationJson(const SearchConfig& cfg, const SearchResult& r)
{
    Json pop = Json::array();
    for (const auto& m : r.population)
        pop.push_back({{"name", m.c.name},
                       {"ratio", num(m.score)},
                       {"variant", cfg.variants[m.bestVariant]->name},
                       {"origin", m.origin},
                       {"mutations", m.mutations}});
    return pop;
}

Json failingJson(const SearchResult& r)
{
    Json failing = Json::array();
    for (const auto& m : r.failing)
        failing.push_back({{"name", m.c.name}, {"failure", m.failure}, {"origin", m.origin}});
    return failing;
}
} // namespace

Json searchJson(const SearchConfig& cfg, const SearchResult& r,
                const std::vector<FamilyData>& inputs)
{
    Json j;
    j["schema"] = "gjk-search/1";
    j["context"] = searchContext(cfg, r, inputs);
    j["budget"] = {{"evaluations", cfg.evaluations > 0 ? Json(cfg.evaluations) : Json(nullptr)},
                   {"seconds", cfg.seconds > 0 ? Json(cfg.seconds) : Json(nullptr)},
                   {"population", cfg.population},
                   {"batch", cfg.batch}};
    j["evaluations"] = r.evaluations;
    j["start_cases"] = r.startCases;
    j["mutated"] = r.mutated;
    j["generations"] = r.generations;
    j["seconds"] = r.seconds;
    j["stopped_by"] = r.stoppedBy;
    j["not_counted"] = {{"invalid_mutations", r.invalidMutations},
                        {"skipped", r.skipped},
                        {"out_of_range", r.outOfRange},
                        {"duplicates", r.duplicates},
                        {"input_rejected", r.inputRejected}};
    j["variants"] = variantsJson(cfg, r);
    j["failures"] = {{"cases", r.failures.cases},
                     {"beyond_bound", r.failures.beyondBound},
                     {"invalid", r.failures.invalid},
                     {"non_finite", r.failures.nonfinite},
                     {"misclassified", r.failures.misclassified},
                     {"iteration_limit", r.failures.iterationLimit},
                     {"interval", r.failures.interval}};
    j["population"] = populationJson(cfg, r);
    j["failing"] = failingJson(r);
    j["exit_code"] = r.exitCode;
    return j;
}

std::string searchSummary(const SearchConfig& config, const SearchResult& r)
{
    std::string s = fmt::format(
        "search: {} evaluations ({} start cases, {} mutated, {} generations) in {:.1f} s on {} "
        "thread(s), seed {}, stopped by {}\n",
        r.evaluations, r.startCases, r.mutated, r.generations, r.seconds, r.threads, config.seed,
        r.stoppedBy.empty() ? "the end of the start cases" : r.stoppedBy);
    s += fmt::format("{:<22} {:>11} {:>12} {:>11} {:>9}  {}\n", "variant", "start best",
                     "best passing", "best", "failures", "best case");
    for (std::size_t k = 0; k < config.variants.size(); ++k)
        s += fmt::format("{:<22} {:>11} {:>12} {:>11} {:>9}  {}\n", config.variants[k]->name,
                         ratioText(r.startBest[k]), ratioText(r.bestPassing[k]),
                         ratioText(r.best[k]), r.variantFailures[k],
                         r.bestCase[k].empty() ? "-" : r.bestCase[k]);
    s += fmt::format("not counted: {} invalid mutations, {} with a skipped variant, {} out of "
                     "range, {} duplicates\n",
                     r.invalidMutations, r.skipped, r.outOfRange, r.duplicates);
    const SearchFailures& f = r.failures;
    s += fmt::format("failures: {} (beyond the bound {}, invalid {}, non-finite {}, misclassified "
                     "{}, iteration limit {}, interval {})\n",
                     f.cases, f.beyondBound, f.invalid, f.nonfinite, f.misclassified,
                     f.iterationLimit, f.interval);
    s += fmt::format("result: {} (exit code {})\n",
                     r.exitCode == kExitPass   ? "PASS"
                     : r.exitCode == kExitFail ? "FAIL"
                                               : "INPUT ERROR",
                     r.exitCode);
    return s;
}

std::string searchCaseFileText(const SearchConfig& config, const SearchResult& r)
{
    std::vector<std::string> comments = {
        fmt::format("written by `{}` (seed {}) on {}, git {}", config.command, config.seed,
                    isoDateUtc(), gitRevision()),
        fmt::format("adversarial search (docs/cli.md): {} evaluations ({} start cases, {} "
                    "mutated) in {:.1f} s on {} thread(s), stopped by {}",
                    r.evaluations, r.startCases, r.mutated, r.seconds, r.threads,
                    r.stoppedBy.empty() ? "the end of the start cases" : r.stoppedBy)};
    std::string best = "bound_ratio per variant, largest of a passing case / of any case:";
    for (std::size_t k = 0; k < config.variants.size(); ++k)
        best +=
            fmt::format(" {} {} / {} ({});", config.variants[k]->name, ratioText(r.bestPassing[k]),
                        ratioText(r.best[k]), r.bestCase[k].empty() ? "-" : r.bestCase[k]);
    comments.push_back(best);
    comments.push_back(fmt::format("{} failure(s) found; the cases: the final population ({}, "
                                   "best first), then the failing cases kept (at most {})",
                                   r.failures.cases, r.population.size(), kMaxFailingKept));
    std::vector<Case> cases;
    std::set<std::string> names;
    auto add = [&](const SearchCase& m)
    {
        if (!names.insert(m.c.name).second)
            return;
        std::string ratios;
        for (std::size_t k = 0; k < config.variants.size(); ++k)
            ratios += fmt::format("{}{} {}", k ? ", " : "", config.variants[k]->name,
                                  ratioText(k < m.ratios.size() ? m.ratios[k] : kNaN));
        comments.push_back(fmt::format(
            "{}: ratio {} ({}); ratios {}; from {} by {} mutation(s), last {}{}", m.c.name,
            ratioText(m.score), std::isnan(m.score) ? "-" : config.variants[m.bestVariant]->name,
            ratios, m.origin, m.mutations, m.lastMutation,
            m.failure.empty() ? "" : "; FAILS: " + m.failure));
        cases.push_back(m.c);
    };
    for (const auto& m : r.population)
        add(m);
    for (const auto& m : r.failing)
        add(m);
    return caseFileText(comments, cases);
}

} // namespace gjkval
