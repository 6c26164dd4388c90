// The campaign's pipeline state, shared by its roles: the fold (fold.cpp), the verdict and
// report.json (verdict.cpp), checkpoints (checkpoint.cpp) and shards (shards.cpp). Internal to
// campaign/; campaign.hpp is the interface.
#pragma once

#include "campaign/campaign.hpp"
#include "statistics/makeup.hpp"
#include "statistics/worst.hpp"
#include "timing/timing.hpp"

#include <chrono>
#include <functional>

namespace gjkval
{

using Clock = std::chrono::steady_clock;

inline double elapsed(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

// --- The pipeline's state ---------------------------------------------------------------------

// Seconds spent in each phase (the report's context.elapsed_s; volatile), wall time of the thread
// that drives the campaign: together they are the command's time up to the report
// (docs/report-schema.md, "context"). setup: from the command's start to the first case (the
// command line, the case files' first read, the variants); inputs: making or reading the cases;
// fold: folding each chunk's outcomes into the statistics (or waiting for the fold beside);
// report: the verdict and the report up to elapsed_s.
struct PhaseSeconds
{
    double setup = 0, inputs = 0, exact = 0, gjk = 0, witness = 0, fold = 0, timing = 0, report = 0;
};

// The driving thread's wall time cut into phases with no gap between them: each lap gives one
// phase the time since the lap before, so the phases add up to the time from the first `last` to
// the last lap by construction (tests/validation/test_cli.cpp, "elapsed_s phases add up").
struct PhaseClock
{
    Clock::time_point last;
    void lap(double& phase)
    {
        const auto now = Clock::now();
        phase += elapsed(last, now);
        last = now;
    }
};

// The valid cases of a family kept for the timed passes (the first kTimingSampleCases), and which
// variants run on each.
struct TimingSample
{
    std::vector<PreparedCase> cases;
    std::vector<std::vector<bool>> runs; // runs[i][k]: variant k runs on case i
};

// Everything a campaign keeps of one input once its cases have streamed by.
struct FamilyResult
{
    const CampaignInput* input;
    std::vector<Stats> stats; // per variant
    MakeupFold makeup;
    WorstKeeper worst;
    TimingSample timing;
    std::size_t cases = 0, rejected = 0;
};

// A rejected case, and where it stands in the campaign's case order (input, then case).
struct RejectedCase
{
    std::size_t input = 0, index = 0;
    Json entry; // report.json's {"name", "family", "reason"}
};

struct CampaignState
{
    std::vector<CampaignInput> inputs; // families[i].input points here
    std::vector<FamilyResult> families;
    std::vector<RejectedCase> rejected; // the first kMaxRejectedListed in case order
    PhaseSeconds seconds;
    PhaseClock clock; // a fold's: its last lap is where the report phase begins
};

// Which chunks a fold evaluates (the shard's, from where a checkpoint left off), and what it does
// after each (write a checkpoint).
struct FoldPlan
{
    Shard shard;
    ChunkPosition resumeAt;                             // chunks before it are folded already
    std::function<void(ChunkPosition next)> afterChunk; // may be empty
};

// --- The fold (fold.cpp) ----------------------------------------------------------------------

EvalContext evalContext(const CampaignConfig& config);
// An input's result before any of its cases is folded.
FamilyResult emptyResult(const CampaignInput& input, const CampaignConfig& config,
                         const EvalContext& ctx);
// Inputs -> truth -> variants -> statistics, input by input, chunk by chunk (the shard's chunks
// only, from a checkpoint when config.resume); then the timed passes over the cases kept for them.
CampaignState foldCampaign(const CampaignConfig& config, std::vector<CampaignInput> inputs,
                           Shard shard, const EvalContext& ctx, int threads, std::ostream* perCase);

// --- The verdict and report.json (verdict.cpp) ------------------------------------------------

// Judgement and the report, from the folded (or merged) state. `seconds`: the campaign's wall
// time (a merge's), or kSinceCommandStart: from commandStart() to the report, with the time
// finishCampaign takes as the phase "report".
inline constexpr double kSinceCommandStart = -1;
Campaign finishCampaign(CampaignState& state, const CampaignConfig& config, const EvalContext& ctx,
                        int threads, double seconds);

// --- Checkpoints (checkpoint.cpp) -------------------------------------------------------------

// The checkpoint's state merged into the empty `state`; returns where the fold goes on.
// InputError when there is none, or it is another campaign's (another command line).
ChunkPosition resumeFrom(CampaignState& state, const CampaignConfig& config, Shard shard,
                         const EvalContext& ctx);
// FoldPlan::afterChunk of a checkpointed run: writes `state` at most every checkpointSeconds.
std::function<void(ChunkPosition next)> checkpointAfterChunk(const CampaignState& state,
                                                             const CampaignConfig& config,
                                                             Shard shard, int threads);

// --- Shard states (shards.cpp) ----------------------------------------------------------------

// InputError unless `j` is a `schema` file (kShardSchema or kCheckpointSchema): "FILE: not a
// SCHEMA file", or, for an earlier version (kOldStateVersions), one line naming the revision that
// reads it and `redo`, what to do with this one instead.
void checkStateSchema(const Json& j, const char* schema, const std::string& file, const char* redo);
// What `run --shard` writes and `merge` (and a checkpoint) reads.
Json shardState(const CampaignState& state, const CampaignConfig& config, Shard shard, int threads);
// What makes two shards parts of one campaign: everything that changes a case, its evaluation
// or the report, plus the code's revision.
Json campaignIdentity(const CampaignConfig& config);
// The first field of `identity` (campaignIdentity) that `other` holds differently, as the message
// "its KEY is OTHER, THEIRS's is VALUE"; empty when they are the same campaign.
std::string identityDifference(const Json& other, const Json& identity, const std::string& theirs);
// One shard's state folded into `state` (whose inputs are the campaign's).
void mergeShard(CampaignState& state, const Json& j, Shard shard, const EvalContext& ctx,
                std::size_t worstPerFamily);

} // namespace gjkval
