// A validation campaign: inputs (families, case files) -> exact truths, GJK variants, statistics,
// timings -> report.json (docs/report-schema.md), from which everything else is rendered.
#pragma once

#include "common/context.hpp"
#include "common/output.hpp"
#include "evaluate/evaluate.hpp"
#include "implementations/variants.hpp"
#include "inputs/cases.hpp"
#include "inputs/families.hpp"
#include "inputs/sources.hpp"
#include "report/pages.hpp"
#include "statistics/stats.hpp"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace gjkval
{

// Cases evaluated together: a chunk's cases, outcomes and prepared inputs are all a campaign holds
// per case. Any size gives the same report (tests/validation/test_campaign.cpp). A case holds
// about 3.5 KB while its chunk lives (a CaseOutcome is 2,288 bytes, a PreparedCase 608, a Case
// 224, and 368 a variant). `run --family random:100000 --variants double --no-timing
// --no-default-plugins`, seven alternated rounds on a 2-core AMD EPYC: at 1,024 cases, 15.9 MB
// peak on 1 thread and 21.3 MB on 2, medians 1.12 s and 0.86 s; at 4,096, 31.4 and 53.9 MB,
// 1.24 s and 0.85 s.
inline constexpr std::size_t kDefaultChunkCases = 1024;
// ns per query is timed on at most this many valid cases per family: the first ones.
inline constexpr std::size_t kTimingSampleCases = 50000;
// report.json lists at most this many rejected cases (cases_rejected counts them all).
inline constexpr std::size_t kMaxRejectedListed = 1000;

struct CampaignConfig
{
    std::vector<std::string> families;  // family specs: "random:100", "hard", "hard/sliver:3"
    std::vector<std::string> caseFiles; // gjk-cases/1 files
    std::uint64_t seed = 1;
    std::vector<const VariantInfo*> variants;
    int threads = 0; // 0: all cores
    exact::Route route = exact::Route::Default;
    bool truthFilter = true; // --truth filtered (exact::Options::filter); false: --truth exact
    bool progress = false;   // progress bar on stderr
    bool timing = true;
    int minPasses = 5, maxPasses = 15;
    double timingBudgetSeconds = 0.5; // per family and variant, once minPasses are done
    int worstPerFamily = 3;
    bool perCase = false;
    std::size_t chunkCases = kDefaultChunkCases;
    std::string command; // for the report's context
    // Checkpoints (docs/cli.md, "Shards, merge, MPI, resume"): the fold's state is written to
    // checkpointDir/checkpoint.json at most every checkpointSeconds; `resume` starts from it.
    std::string checkpointDir;
    double checkpointSeconds = 60;
    bool resume = false;
    double pluginTimeoutSeconds =
        kDefaultPluginTimeoutSeconds; // per plugin call (--plugin-timeout)
};

// The default campaign of `gjk-validate run` without inputs: these families and the default case
// files (defaultCaseFiles). Its one home: run's help and `gjk-validate list` (which
// scripts/peers_doc.py reads) show it from here.
std::vector<std::string> defaultFamilies();
// defaultFamilies() as run's options: "--family random:200000 --family hard --family engine".
std::string defaultFamilyOptions();
// Every *.json of the default campaign's case files, sorted: in the directory given to
// setDefaultCaseDir when one was, else found relative to the program: in <dir>/cases (the build
// tree, a link to validation/cases) or <dir>/../<datadir>/gjk2d/cases (an installed prefix).
// InputError, one line naming the places looked in, when none exists.
std::vector<std::string> defaultCaseFiles();
// Where a program that is not gjk-validate keeps the default case files: the Python module, whose
// program is the Python interpreter, gives its package's cases/ (python/gjk2d/__init__.py).
// An empty string goes back to the places beside the program. Set before a campaign runs.
void setDefaultCaseDir(std::string dir);

// The campaign's inputs (inputs/sources.hpp). Throws InputError (exit code 2).
std::vector<CampaignInput> campaignInputs(const CampaignConfig& config,
                                          FileCheck check = FileCheck::Start);

// A campaign's report (report/pages.hpp writes it) and its exit code.
struct Campaign : CampaignReport
{
    int exitCode = kExitPass;
};

// The campaign, one input after the other, chunk by chunk: truth, variants, witnesses (on the
// threads), then statistics, make-up, worst cases and per-case lines folded in case order; then
// timing, judgement and the report. perCase, when given, receives cases.jsonl's lines in case
// order as they are made.
Campaign runCampaign(const CampaignConfig& config, std::vector<CampaignInput> inputs,
                     std::ostream* perCase = nullptr);

// Once the report (or shard.json) is written: the checkpoint is no longer needed.
void removeCheckpoint(const CampaignConfig& config);

// A part of a campaign that one process evaluates: chunk j of input f (its cases j*chunk ..)
// belongs to shard (f + j) mod count. Round robin spreads the costly inputs over the shards, and
// the shift by f gives each shard the first chunk of some inputs (whose cases it times).
struct Shard
{
    std::size_t index = 0, count = 1;
    bool owns(std::size_t input, std::size_t chunk) const
    {
        return (input + chunk) % count == index;
    }
};

// A chunk's place in the campaign: chunk `chunk` of input `input`; ordered as the cases are.
struct ChunkPosition
{
    std::size_t input = 0, chunk = 0;
    bool operator<(const ChunkPosition& o) const
    {
        return input != o.input ? input < o.input : chunk < o.chunk;
    }
};

// The state files: shard.json (`run --shard`, read by `merge`) and checkpoint.json (`run
// --checkpoint`, read by `--resume`), both holding Stats' state (StatsState,
// docs/report-schema.md). A change of that state (a row of Stats' tables added, renamed or removed)
// is a new version of both: bump the number in both names, and add the old version to
// kOldStateVersions.
inline constexpr const char* kShardSchema = "gjk-shard/3";
inline constexpr const char* kCheckpointSchema = "gjk-checkpoint/3";

// The earlier versions of the state files, refused with exit code 2 and a message that names the
// last revision of gjk2d that wrote (and reads) them.
struct OldStateVersion
{
    int version;
    const char* lastRevision; // from `git log`: the last commit before the next version
};
inline constexpr OldStateVersion kOldStateVersions[] = {
    {1, "ff6aac0"}, // Stats' state in an order of its own, with its history's exceptions
    {2, "ff7916d"}, // without the contract verdict (contract_violations and their reasons)
};

// One shard of the campaign, folded and timed: the state that `merge` reads (shard.json,
// docs/cli.md, "Shards, merge, MPI, resume"). Exact: histogram sums are exact, every tie is broken
// by case order, so merging the shards gives the one-process report, timing fields aside.
Json runShard(const CampaignConfig& config, std::vector<CampaignInput> inputs, Shard shard,
              std::ostream* perCase = nullptr);

// The campaign of every shard's state (`names` name them in errors): refuses (InputError) shards
// of different campaigns (inputs, seed, variants, options, revision), a shard given twice or
// missing. `base` gives what the shards do not fix (threads, progress, the command). The case
// files are read again from their paths, for their names and make-up.
// The report's elapsed_s.total is `wallSeconds` when given (mpirun: the whole run), else the
// merge's own time; the phases are the shards' sums.
Campaign mergeShards(const std::vector<Json>& shards, const std::vector<std::string>& names,
                     const CampaignConfig& base, double wallSeconds = -1);

// cases.jsonl of a sharded campaign: `shardLines[s]` streams shard s's lines (its chunks, in
// order); they are written to `out` in case order, following the chunk rule of Shard and the
// inputs' case counts in `report`. InputError when a shard has too few or too many lines.
void joinPerCase(const Json& report, std::size_t chunkCases,
                 const std::vector<std::istream*>& shardLines, std::ostream& out);

// The report without what legitimately changes between runs of the same campaign (timings,
// date, host, thread count): what "identical whatever the number of threads" compares.
Json stripVolatile(Json report);

} // namespace gjkval
