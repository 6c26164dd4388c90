// `gjk-validate search`: an adversarial search for the worst error / bound ratio.
// Starts from families and case files (collectInputs), mutates the best cases it has seen (a vertex
// or a shape moved by ulps or by 2^-k, a scale, a tiny rotation, the gap shifted toward 0, a
// vertex duplicated, collapsed or added near an edge, A and B swapped, everything rounded to
// float) and keeps the K best by the objective: the largest bound_ratio (or witness error / witness
// bound, when larger) over the chosen variants, measured by the campaign's own phases
// (computeTruth, runVariants, checkWitnesses: the same truth, queries, errorBound and
// witnessBound). docs/cli.md, "`search`".
#pragma once

#include "campaign/campaign.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace gjkval
{

struct SearchConfig
{
    std::vector<std::string> families, caseFiles;
    std::uint64_t seed = 1;
    std::vector<const VariantInfo*> variants;
    int threads = 0;               // 0: all cores (the result does not depend on it)
    std::uint64_t evaluations = 0; // budget: case evaluations (start cases included); 0 = none
    double seconds = 0;            // budget: wall time, checked between generations; 0 = none
    int population = 32;           // K: the best cases kept (at most K/4 from one start case)
    int batch = 64;                // candidates per generation (fixed: not the thread count)
    bool progress = false;         // a line on stderr per improvement
    bool truthFilter = true;       // --truth (exact::Options::filter)
    std::string command;
};

// One evaluated case the search keeps: the population's members and the failing cases.
struct SearchCase
{
    Case c;
    double score = 0;            // the objective: max over the variants of answerRatio (search.cpp)
    std::vector<double> ratios;  // per variant (NaN: not counted for that variant)
    std::size_t bestVariant = 0; // the variant of `score`
    std::string origin;          // the start case it descends from
    int mutations = 0;           // mutations applied since that start case
    std::string lastMutation;    // the mutations of its last step ("start" for a start case)
    std::string failure;         // why it fails (empty: it does not)
    // The double truth's witnesses and distance, for the gap-shifting mutation.
    double distance = 0;
    std::array<double, 2> witnessA{}, witnessB{};
};

// What can go wrong per failing evaluation, counted per kind (one case may count in several).
struct SearchFailures
{
    std::uint64_t cases = 0; // evaluations with a failing variant
    std::uint64_t beyondBound = 0, nonfinite = 0, misclassified = 0, iterationLimit = 0,
                  interval = 0;
    std::uint64_t invalid = 0; // an answer outside its contract (negative, witness points)
};

struct SearchResult
{
    std::uint64_t evaluations = 0, startCases = 0, mutated = 0;
    std::uint64_t generations = 0;
    double seconds = 0;
    int threads = 1;
    std::string stoppedBy; // "evaluations", "seconds", "start cases" (budget below the start pool)
    // Evaluations that do not count toward the objective, apart:
    std::uint64_t invalidMutations = 0; // the reader's rules or the exact side reject the case
    std::uint64_t skipped = 0;          // some variant did not run (not representable, n/a)
    std::uint64_t outOfRange = 0;       // some variant's GJK set outOfRange
    std::uint64_t duplicates = 0;       // identical to a member of the population
    std::uint64_t inputRejected = 0;    // start cases rejected by the reader
    // Per variant: the best ratio over the start cases and over the whole search (failing cases
    // included), and its case; bestPassing: the best of a case on which the variant passes (the
    // bound's measured margin, whatever failures were found).
    std::vector<double> startBest, best, bestPassing;
    std::vector<std::string> bestCase;
    std::vector<std::uint64_t> variantFailures;
    SearchFailures failures;
    std::vector<SearchCase> population; // best first; passing cases only
    std::vector<SearchCase> failing;    // the first kMaxFailingKept failing cases, in order found
    Json json;                          // the --json summary (docs/cli.md, `search`)
    int exitCode = kExitPass;
};

inline constexpr std::size_t kMaxFailingKept = 100;

SearchResult runSearch(const SearchConfig& config, const std::vector<FamilyData>& inputs);

// The --json summary (docs/cli.md, `search`), from the result; runSearch puts it in result.json.
Json searchJson(const SearchConfig& config, const SearchResult& result,
                const std::vector<FamilyData>& inputs);
// A bound ratio as the summaries print it: 4 significant digits, "n/a" for NaN.
std::string ratioText(double r);
// The summary printed on stdout.
std::string searchSummary(const SearchConfig& config, const SearchResult& result);
// The --out file: the population (best first) and the failing cases, with a comment per case.
std::string searchCaseFileText(const SearchConfig& config, const SearchResult& result);

} // namespace gjkval
