// A validation campaign: inputs (families, case files) -> exact truths, GJK variants, statistics,
// timings -> report.json (docs/report-schema.md), from which everything else is rendered.
#pragma once

#include "inputs/cases.hpp"
#include "evaluate/evaluate.hpp"
#include "inputs/families.hpp"
#include "statistics/stats.hpp"
#include "evaluate/variants.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace gjkval
{

struct CampaignConfig
{
    std::vector<std::string> families;  // family specs: "random:100", "hard", "hard/sliver:3"
    std::vector<std::string> caseFiles; // gjk-cases/1 files
    std::uint64_t seed = 1;
    std::vector<const VariantInfo*> variants;
    int threads = 0; // 0: all cores
    exact::Route route = exact::Route::Default;
    bool progress = false; // progress bar on stderr
    bool timing = true;
    int minPasses = 5, maxPasses = 15;
    double timingBudgetSeconds = 0.5; // per family and variant, once minPasses are done
    int worstPerFamily = 3;
    bool perCase = false;
    std::string command; // for the report's context
};

// `git rev-parse` of the source tree ("abc123 (dirty)"), "unknown" when git fails.
std::string gitRevision();
std::string isoDateUtc();

// report.json's context block up to "cases_rejected" (date, host, compiler, flags, build_type,
// gjk_checked, git_revision, command, seed, threads, inputs, cases_total, cases_rejected); `bench`
// writes the same block.
Json contextJson(const std::string& date, const std::string& revision, const std::string& command,
                 std::uint64_t seed, int threads, Json inputs, std::size_t casesTotal,
                 std::size_t casesRejected);

// The default campaign of `gjk-validate run` without inputs.
std::vector<std::string> defaultFamilies();
std::vector<std::string> defaultCaseFiles(); // every *.json in <source>/validation/cases, sorted

struct FamilyData
{
    std::string name; // "random", "hard/sliver", "file:talk.json"
    std::string reason;
    std::string source; // "generated" or "file"
    Json input;         // its entry in context.inputs
    std::vector<Case> cases;
    std::vector<std::string> labels;   // how a rejected entry is named ("file.json#3 (case 'x')")
    std::vector<std::string> rejected; // per case: reason from reading the file, or empty
    std::vector<MakeupSpec> makeup;
    std::uint64_t seed = 0;
};

// Generates the families and reads the files. Throws InputError (exit code 2).
std::vector<FamilyData> loadInputs(const CampaignConfig& config);

struct Campaign
{
    Json report;                  // report.json
    std::vector<Case> worstCases; // worst-cases.json
    std::vector<std::string> worstComments;
    std::vector<std::string> perCaseLines; // cases.jsonl (when config.perCase)
    int exitCode = kExitPass;
};

Campaign runCampaign(const CampaignConfig& config, std::vector<FamilyData> families);

// Up front, before any work: throws InputError when outDir cannot hold a report (empty, not a
// directory, holds files that are not a report's, parent not creatable or not writable).
void checkReportDir(const std::string& outDir);

// Writes report.json, report.md, worst-cases.json, cases.jsonl (if any) and index.html (when the
// HTML renderer is built in) into a directory beside outDir, then swaps it in: outDir holds this
// run or the previous one, never a mix. Throws OutputError (exit code 5) when a write fails.
// Returns the absolute path of the page to open (index.html, or report.md without the renderer).
std::string writeCampaign(const Campaign& campaign, const std::string& outDir);

// The report without what legitimately changes between runs of the same campaign (timings,
// date, host, thread count): what "identical whatever the number of threads" compares.
Json stripVolatile(Json report);

} // namespace gjkval
