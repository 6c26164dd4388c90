// The fold: a campaign's inputs streamed chunk by chunk through truth, variants and witnesses
// (on the threads), then folded in case order into statistics, make-up, worst cases and per-case
// lines; then the timed passes.
#include "campaign/state.hpp"

#include "common/context.hpp"
#include "common/output.hpp"
#include "common/parallel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <future>
#include <ostream>
#include <utility>

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;
std::string g_defaultCaseDir; // setDefaultCaseDir's; empty: beside the program
} // namespace

void setDefaultCaseDir(std::string dir)
{
    g_defaultCaseDir = std::move(dir);
}

std::vector<std::string> defaultFamilies()
{
    return {"random:" + std::to_string(kDefaultRandomCount), "hard", "engine"};
}

std::string defaultFamilyOptions()
{
    std::string options;
    for (const std::string& family : defaultFamilies())
        options += (options.empty() ? "--family " : " --family ") + family;
    return options;
}

std::vector<std::string> defaultCaseFiles()
{
    std::error_code ec;
    fs::path dir = g_defaultCaseDir;
    if (!dir.empty() && !fs::is_directory(dir, ec))
        throw InputError(
            fmt::format("the default campaign's case files are not in {}: give --family or --cases",
                        excerpt(dir.string())));
    if (dir.empty())
    {
        const fs::path exeDir = fs::read_symlink("/proc/self/exe", ec).parent_path();
        const fs::path build = exeDir / "cases", installed = exeDir / ".." / GJK2D_INSTALL_CASE_DIR;
        dir = fs::is_directory(build, ec) ? build : installed;
        if (!fs::is_directory(dir, ec))
            throw InputError(fmt::format("the default campaign's case files are in neither {} nor "
                                         "{}: give --family or --cases",
                                         excerpt(build.string()),
                                         excerpt(installed.lexically_normal().string())));
    }
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file() && e.path().extension() == ".json")
            files.push_back(e.path().lexically_normal().string());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<CampaignInput> campaignInputs(const CampaignConfig& config, FileCheck check)
{
    return campaignInputs(config.families, config.caseFiles, config.seed, check);
}

EvalContext evalContext(const CampaignConfig& config)
{
    EvalContext ctx;
    ctx.variants = config.variants;
    ctx.exactOptions.route = config.route;
    ctx.exactOptions.filter = config.truthFilter;
    // The squared rational is read only by case details (perCaseJson), which ask for it when it
    // was left out: cases.jsonl has every case's, so it is computed at once there.
    ctx.exactOptions.squaredRational = config.perCase;
    ctx.pluginTimeoutSeconds = config.pluginTimeoutSeconds;
    if (ctx.hasPlugins()) // one child a thread, forked on the first chunk, for every chunk
        ctx.pluginServers = std::make_shared<PluginServers>(resolveThreads(config.threads));
    return ctx;
}

FamilyResult emptyResult(const CampaignInput& input, const CampaignConfig& config,
                         const EvalContext& ctx)
{
    return {&input,
            std::vector<Stats>(ctx.variants.size()),
            MakeupFold(input.makeup),
            WorstKeeper(std::size_t(std::max(0, config.worstPerFamily))),
            {}};
}

namespace
{
// --- Truth, variants, witnesses: one chunk on the campaign's threads ---------------------------

struct EvaluatedChunk
{
    std::vector<CaseOutcome> outcomes;
    std::vector<PreparedCase> prepared;
};

EvaluatedChunk evaluateChunk(const CaseChunk& chunk, const EvalContext& ctx, int threads,
                             Progress& progress, PhaseClock& clock, PhaseSeconds& seconds)
{
    EvaluatedChunk e; // the outcomes' allocation is the exact phase's
    e.outcomes.resize(chunk.size());
    e.prepared.resize(chunk.size());
    for (std::size_t i = 0; i < chunk.size(); ++i)
        e.outcomes[i].rejected = chunk.rejected[i];
    Progress none = Progress::silent();
    parallelFor(chunk.size(), threads, none,
                [&](std::size_t i)
                {
                    if (e.outcomes[i].rejected.empty())
                    {
                        computeTruth(chunk.cases[i], ctx, e.outcomes[i]);
                        if (e.outcomes[i].rejected.empty())
                            e.prepared[i] = prepare(chunk.cases[i]);
                    }
                });
    clock.lap(seconds.exact);
    // Plugin variants, in child processes, between the parallel phases (no worker thread runs).
    answerPluginVariants(chunk.cases.data(), e.prepared.data(), e.outcomes.data(), chunk.size(),
                         ctx);
    parallelFor(chunk.size(), threads, progress,
                [&](std::size_t i)
                {
                    CaseOutcome& o = e.outcomes[i];
                    if (!o.rejected.empty())
                    {
                        o.variants.assign(ctx.variants.size(), {});
                        return;
                    }
                    runVariants(chunk.cases[i], e.prepared[i], ctx, o);
                });
    clock.lap(seconds.gjk);
    parallelFor(chunk.size(), threads, none,
                [&](std::size_t i) { checkWitnesses(chunk.cases[i], ctx, e.outcomes[i]); });
    clock.lap(seconds.witness);
    return e;
}

// --- Statistics, make-up, worst cases, per-case lines: folded in case order --------------------

void foldChunk(FamilyResult& r, std::size_t input, const CaseChunk& chunk, EvaluatedChunk& e,
               const CampaignConfig& config, const EvalContext& ctx,
               std::vector<RejectedCase>& rejected, std::ostream* perCase)
{
    const std::size_t nv = ctx.variants.size();
    for (std::size_t i = 0; i < chunk.size(); ++i)
    {
        const Case& c = chunk.cases[i];
        const CaseOutcome& o = e.outcomes[i];
        ++r.cases;
        if (perCase)
            *perCase << perCaseJson(c, r.input->name, ctx, o).dump() << '\n';
        if (!o.rejected.empty())
        {
            ++r.rejected;
            if (rejected.size() < kMaxRejectedListed)
                rejected.push_back({input,
                                    chunk.first + i,
                                    {{"name", chunk.labels[i]},
                                     {"family", r.input->name},
                                     {"reason", o.rejected}}});
            continue;
        }
        for (std::size_t k = 0; k < nv; ++k)
            r.stats[k].add(o.variants[k], c.name, chunk.first + i, *ctx.variants[k], o);
        r.makeup.add(c, o.exact);
        r.worst.offer(chunk.first + i, c, o);
        if (config.timing && r.timing.cases.size() < kTimingSampleCases)
        {
            std::vector<bool> runs(nv);
            for (std::size_t k = 0; k < nv; ++k)
                runs[k] = !o.variants[k].skipped &&
                          (o.variants[k].plugin == PluginStatus::NotRun ||
                           o.variants[k].plugin == PluginStatus::Ok); // a plugin's crash: untimed
            r.timing.cases.push_back(std::move(e.prepared[i]));
            r.timing.runs.push_back(std::move(runs));
        }
    }
    if (perCase && !*perCase)
        throw OutputError("cases.jsonl: write failed: " + std::string(std::strerror(errno)));
}

// --- The fold beside the next chunk --------------------------------------------------------------

// Runs each chunk's fold (statistics, make-up, worst cases, per-case lines, the checkpoint after
// it) on a thread of its own while the stream makes the next chunk and the campaign's threads
// evaluate it. The fold and the stream are the campaign's serial part: before, a core idled
// through them, 24 % of a 2-thread `run --family random:300000 --variants double,float` (docs/
// speed.md, "Allocations, transforms and the fold"). One fold at a time and in chunk order, so the
// result is the sequential fold's, bit for bit. With one thread (`--threads 1`) each fold runs at
// once on the caller's thread, as before: a run asked to use one core uses one.
class ChunkFolder
{
  public:
    explicit ChunkFolder(bool beside) : beside_(beside) {}
    ChunkFolder(const ChunkFolder&) = delete;
    ChunkFolder& operator=(const ChunkFolder&) = delete;
    // Unwinding from another error: the running fold ends first (it holds references); its own
    // error, if any, is dropped for the first one.
    ~ChunkFolder()
    {
        if (pending_.valid())
            pending_.wait();
    }
    // Starts fold() once the previous fold has ended; that fold's exception is rethrown here.
    template <class F> void submit(F fold)
    {
        finish();
        if (beside_)
            pending_ = std::async(std::launch::async, std::move(fold));
        else
            fold();
    }
    // Waits for the last fold; rethrows its exception.
    void finish()
    {
        if (pending_.valid())
            pending_.get();
    }

  private:
    bool beside_;
    std::future<void> pending_;
};

void addSeconds(PhaseSeconds& to, const PhaseSeconds& s)
{
    to.setup += s.setup;
    to.inputs += s.inputs;
    to.exact += s.exact;
    to.gjk += s.gjk;
    to.witness += s.witness;
    to.fold += s.fold;
    to.timing += s.timing;
    to.report += s.report;
}

// One input (state.families[inputIndex]), streamed: its cases are generated or read chunk by
// chunk, and the plan's chunks are evaluated, then folded by `folder`. state.seconds is the
// folder's: the phases' seconds lapped here (on state.clock) go to it with each fold (`unsent`
// holds those not sent yet: skipped chunks', the stream's end), so no two threads write it.
void runInput(std::size_t inputIndex, const CampaignConfig& config, const FoldPlan& plan,
              const EvalContext& ctx, int threads, Progress& progress, CampaignState& state,
              ChunkFolder& folder, PhaseSeconds& unsent, std::ostream* perCase)
{
    PhaseClock& clock = state.clock;
    FamilyResult& r = state.families[inputIndex];
    const std::size_t chunkCases = std::max<std::size_t>(1, config.chunkCases);
    const auto skip = [&](std::size_t chunk)
    {
        const ChunkPosition at{inputIndex, chunk};
        return !plan.shard.owns(at.input, at.chunk) || at < plan.resumeAt;
    };
    std::size_t seen = 0; // cases up to the end of the last chunk passed on (for the progress)
    r.input->stream(
        chunkCases,
        [&](CaseChunk& chunk)
        {
            clock.lap(unsent.inputs);
            const std::size_t j = chunk.first / chunkCases;
            if (!r.input->counted) // a case file counted as it is read
                progress.grow(chunk.size());
            progress.add(chunk.first - seen); // the chunks left out before it
            seen = chunk.first + chunk.size();
            if (skip(j)) // a case file passes every chunk
                progress.add(chunk.size());
            else
            {
                EvaluatedChunk e = evaluateChunk(chunk, ctx, threads, progress, clock, unsent);
                // Everything by value or bound to objects that outlive the folder: the fold may
                // still run after this input's stream has returned.
                folder.submit(
                    [&st = state, &res = r, &cfg = config, &cx = ctx, &pl = plan, perCase,
                     inputIndex, j, seconds = unsent, chunk = std::move(chunk),
                     e = std::move(e)]() mutable
                    {
                        addSeconds(st.seconds, seconds);
                        foldChunk(res, inputIndex, chunk, e, cfg, cx, st.rejected, perCase);
                        if (pl.afterChunk)
                            pl.afterChunk({inputIndex, j + 1});
                    });
                unsent = {};
                clock.lap(unsent.fold); // the next fold adds it
            }
        },
        skip, threads);
    CampaignInput& in = state.inputs[inputIndex];
    if (!in.counted) // its end reached: its count and comments known
    {
        settleFileInput(in);
        in.counted = true;
    }
    progress.add(in.count - std::min(seen, in.count));
    clock.lap(unsent.inputs);
}

// --- Timing: single-threaded, apart from everything else ---------------------------------------

void timeVariants(CampaignState& state, const CampaignConfig& config, const EvalContext& ctx)
{
    TimingConfig tc;
    tc.minPasses = config.minPasses;
    tc.maxPasses = config.maxPasses;
    tc.budgetSeconds = config.timingBudgetSeconds;
    const std::size_t nv = ctx.variants.size();
    Progress p(config.progress, "timing", state.families.size());
    for (auto& f : state.families) // per family, every variant's passes alternated
    {
        std::vector<std::vector<const PreparedCase*>> cases(nv);
        for (std::size_t k = 0; k < nv; ++k)
            for (std::size_t i = 0; i < f.timing.cases.size(); ++i)
                if (f.timing.runs[i][k])
                    cases[k].push_back(&f.timing.cases[i]);
        const std::vector<TimingResult> t =
            timeAlternated(cases, ctx.variants, tc, ctx.pluginTimeoutSeconds);
        for (std::size_t k = 0; k < nv; ++k)
        {
            Stats& s = f.stats[k];
            s.nsPerQuery = t[k].nsPerQuery;
            s.nsMin = t[k].nsMin;
            s.nsMax = t[k].nsMax;
            s.timingPasses = t[k].passes;
            s.prepareNsPerShape = t[k].prepareNsPerShape;
            s.preparedNsPerQuery = t[k].preparedNsPerQuery;
        }
        p.add(1);
    }
    for (auto& f : state.families) // the samples are no longer needed
        f.timing = {};
}
} // namespace

CampaignState foldCampaign(const CampaignConfig& config, std::vector<CampaignInput> inputs,
                           Shard shard, const EvalContext& ctx, int threads, std::ostream* perCase)
{
    CampaignState state;
    state.inputs = std::move(inputs); // not resized below: families point into it
    std::size_t total = 0;
    for (const auto& in : state.inputs)
    {
        total += in.count;
        state.families.push_back(emptyResult(in, config, ctx));
    }
    FoldPlan plan{shard, {}, {}};
    if (config.resume)
        plan.resumeAt = resumeFrom(state, config, shard, ctx);
    if (!config.checkpointDir.empty())
        plan.afterChunk = checkpointAfterChunk(state, config, shard, threads);
    PhaseSeconds unsent;
    {
        Progress progress(config.progress, "cases", total);
        ChunkFolder folder(threads >= 2);
        state.clock.last = commandStart();
        state.clock.lap(unsent.setup);
        for (std::size_t i = 0; i < state.inputs.size(); ++i)
            runInput(i, config, plan, ctx, threads, progress, state, folder, unsent, perCase);
        folder.finish();
    }
    state.clock.lap(unsent.fold);
    addSeconds(state.seconds, unsent);
    // A shard times only the inputs whose first chunk it holds: the merge takes those.
    for (std::size_t i = 0; i < state.families.size(); ++i)
        if (!shard.owns(i, 0))
            state.families[i].timing = {};
    if (config.timing) // untimed, the phase stays 0 (the report page reads it so)
    {
        timeVariants(state, config, ctx);
        state.clock.lap(state.seconds.timing);
    }
    return state;
}

Campaign runCampaign(const CampaignConfig& config, std::vector<CampaignInput> inputs,
                     std::ostream* perCase)
{
    const int threads = resolveThreads(config.threads);
    const EvalContext ctx = evalContext(config);
    CampaignState state = foldCampaign(config, std::move(inputs), Shard{}, ctx, threads, perCase);
    return finishCampaign(state, config, ctx, threads, kSinceCommandStart);
}

Json runShard(const CampaignConfig& config, std::vector<CampaignInput> inputs, Shard shard,
              std::ostream* perCase)
{
    const int threads = resolveThreads(config.threads);
    const EvalContext ctx = evalContext(config);
    const CampaignState state =
        foldCampaign(config, std::move(inputs), shard, ctx, threads, perCase);
    return shardState(state, config, shard, threads);
}

} // namespace gjkval
