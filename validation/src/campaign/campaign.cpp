#include "campaign/campaign.hpp"

#include "common/output.hpp"
#include "common/parallel.hpp"
#include "report/report.hpp"
#include "statistics/makeup.hpp"
#include "statistics/worst.hpp"
#include "timing/timing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <exception>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <set>
#include <unistd.h>

#if defined(GJK2D_HAVE_HTML)
#include "gjk_html/html.hpp"
#endif

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double elapsed(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

} // namespace

std::vector<std::string> defaultFamilies()
{
    return {"random:" + std::to_string(kDefaultRandomCount), "hard", "engine"};
}

std::vector<std::string> defaultCaseFiles()
{
    std::error_code ec;
    const fs::path exeDir = fs::read_symlink("/proc/self/exe", ec).parent_path();
    const fs::path build = exeDir / "cases", installed = exeDir / ".." / GJK2D_INSTALL_CASE_DIR;
    const fs::path dir = fs::is_directory(build, ec) ? build : installed;
    if (!fs::is_directory(dir, ec))
        throw InputError(fmt::format(
            "the default campaign's case files are in neither {} nor {}: give --family or --cases",
            excerpt(build.string()), excerpt(installed.lexically_normal().string())));
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file() && e.path().extension() == ".json")
            files.push_back(e.path().lexically_normal().string());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<CampaignInput> campaignInputs(const CampaignConfig& config)
{
    return campaignInputs(config.families, config.caseFiles, config.seed);
}

std::vector<FamilyData> loadInputs(const CampaignConfig& config)
{
    return collectInputs(config.families, config.caseFiles, config.seed);
}

namespace
{
// --- The pipeline's state ---------------------------------------------------------------------

// Seconds spent in each phase (the report's context.elapsed_s; volatile).
struct PhaseSeconds
{
    double inputs = 0, exact = 0, gjk = 0, witness = 0, timing = 0;
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
};

// --- Truth, variants, witnesses: one chunk on the campaign's threads ---------------------------

struct EvaluatedChunk
{
    std::vector<CaseOutcome> outcomes;
    std::vector<PreparedCase> prepared;
};

EvaluatedChunk evaluateChunk(const CaseChunk& chunk, const EvalContext& ctx, int threads,
                             Progress& progress, PhaseSeconds& seconds)
{
    EvaluatedChunk e;
    e.outcomes.resize(chunk.size());
    e.prepared.resize(chunk.size());
    for (std::size_t i = 0; i < chunk.size(); ++i)
        e.outcomes[i].rejected = chunk.rejected[i];
    Progress none(false, "", 0);
    auto t0 = Clock::now();
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
    auto t1 = Clock::now();
    // Plugin variants, in child processes, between the parallel phases (no worker thread runs).
    answerPluginVariants(chunk.cases.data(), e.prepared.data(), e.outcomes.data(), chunk.size(), ctx);
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
    auto t2 = Clock::now();
    parallelFor(chunk.size(), threads, none,
                [&](std::size_t i) { checkWitnesses(chunk.cases[i], ctx, e.outcomes[i]); });
    auto t3 = Clock::now();
    seconds.exact += elapsed(t0, t1);
    seconds.gjk += elapsed(t1, t2);
    seconds.witness += elapsed(t2, t3);
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
                rejected.push_back({input, chunk.first + i,
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
}

// One input, streamed: its cases are generated or read chunk by chunk, and the shard's chunks
// are evaluated and folded.
// Which chunks a fold evaluates (the shard's, from where a checkpoint left off), and what it does
// after each (write a checkpoint).
struct FoldPlan
{
    Shard shard;
    ChunkPosition resumeAt;                               // chunks before it are folded already
    std::function<void(ChunkPosition next)> afterChunk; // may be empty
};

FamilyResult emptyResult(const CampaignInput& input, const CampaignConfig& config,
                         const EvalContext& ctx)
{
    return {&input, std::vector<Stats>(ctx.variants.size()), MakeupFold(input.makeup),
            WorstKeeper(std::size_t(std::max(0, config.worstPerFamily))), {}};
}

// One input (state.families[inputIndex]), streamed: its cases are generated or read chunk by
// chunk, and the plan's chunks are evaluated and folded.
void runInput(std::size_t inputIndex, const CampaignConfig& config, const FoldPlan& plan,
              const EvalContext& ctx, int threads, Progress& progress, CampaignState& state,
              std::ostream* perCase)
{
    FamilyResult& r = state.families[inputIndex];
    const std::size_t chunkCases = std::max<std::size_t>(1, config.chunkCases);
    const auto skip = [&](std::size_t chunk)
    {
        const ChunkPosition at{inputIndex, chunk};
        return !plan.shard.owns(at.input, at.chunk) || at < plan.resumeAt;
    };
    auto t = Clock::now();
    std::size_t seen = 0; // cases up to the end of the last chunk passed on (for the progress)
    r.input->stream(chunkCases,
                    [&](CaseChunk& chunk)
                    {
                        state.seconds.inputs += elapsed(t, Clock::now());
                        const std::size_t j = chunk.first / chunkCases;
                        progress.add(chunk.first - seen); // the chunks left out before it
                        seen = chunk.first + chunk.size();
                        if (skip(j)) // a case file passes every chunk
                            progress.add(chunk.size());
                        else
                        {
                            EvaluatedChunk e =
                                evaluateChunk(chunk, ctx, threads, progress, state.seconds);
                            foldChunk(r, inputIndex, chunk, e, config, ctx, state.rejected,
                                      perCase);
                            if (plan.afterChunk)
                                plan.afterChunk({inputIndex, j + 1});
                        }
                        t = Clock::now();
                    },
                    skip);
    progress.add(r.input->count - std::min(seen, r.input->count));
    state.seconds.inputs += elapsed(t, Clock::now());
    if (perCase && !*perCase)
        throw OutputError("cases.jsonl: write failed: " + std::string(std::strerror(errno)));
}

// --- Timing: single-threaded, apart from everything else ---------------------------------------

void timeVariants(CampaignState& state, const CampaignConfig& config, const EvalContext& ctx)
{
    TimingConfig tc;
    tc.minPasses = config.minPasses;
    tc.maxPasses = config.maxPasses;
    tc.budgetSeconds = config.timingBudgetSeconds;
    const std::size_t nv = ctx.variants.size();
    Progress p(config.progress, "timing", state.families.size() * nv);
    for (auto& f : state.families)
        for (std::size_t k = 0; k < nv; ++k)
        {
            std::vector<const PreparedCase*> cases;
            for (std::size_t i = 0; i < f.timing.cases.size(); ++i)
                if (f.timing.runs[i][k])
                    cases.push_back(&f.timing.cases[i]);
            const VariantInfo& v = *ctx.variants[k];
            const TimingResult t = timeQueries(cases, v, tc, ctx.pluginTimeoutSeconds);
            Stats& s = f.stats[k];
            s.nsPerQuery = t.nsPerQuery;
            s.nsMin = t.nsMin;
            s.nsMax = t.nsMax;
            s.timingPasses = t.passes;
            p.add(1);
        }
    for (auto& f : state.families) // the samples are no longer needed
        f.timing = {};
}

// Index of the variant timing ratios are given against: kBaselineVariant when selected, else the
// first.
std::size_t baselineIndex(const EvalContext& ctx)
{
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
        if (ctx.variants[k]->name == kBaselineVariant)
            return k;
    return 0;
}

void setTimingRatios(CampaignState& state, std::size_t baseline)
{
    for (auto& f : state.families)
        for (auto& s : f.stats)
            if (s.nsPerQuery > 0 && f.stats[baseline].nsPerQuery > 0)
                s.ratioToBaseline = s.nsPerQuery / f.stats[baseline].nsPerQuery;
}

// --- Judgement ---------------------------------------------------------------------------------

// A family passes when its make-up checks hold and no judged variant failed a case; comparison
// variants are reported, never failed.
struct Verdict
{
    bool makeupOk = true, variantsOk = true;
    bool pass() const { return makeupOk && variantsOk; }
};

Verdict judgeFamily(const std::vector<MakeupResult>& makeup, const std::vector<Stats>& stats,
                    const EvalContext& ctx)
{
    Verdict v;
    for (const auto& m : makeup)
        v.makeupOk = v.makeupOk && m.ok;
    for (std::size_t k = 0; k < stats.size(); ++k)
        if (ctx.variants[k]->judged)
            v.variantsOk = v.variantsOk && stats[k].failures == 0;
    return v;
}

// Any failing family fails the campaign (1); else any rejected case makes it an input error (2).
int campaignExitCode(bool anyFamilyFailed, std::size_t rejected)
{
    return anyFamilyFailed ? kExitFail : (rejected > 0 ? kExitInput : kExitPass);
}

// --- The report --------------------------------------------------------------------------------

Json makeupJson(const std::vector<MakeupResult>& m)
{
    Json a = Json::array();
    for (const auto& r : m)
    {
        Json j;
        j["check"] = r.check;
        j["value"] = num(r.value);
        j["min"] = num(r.min);
        j["max"] = num(r.max);
        j["ok"] = r.ok;
        if (r.skipped)
            j["skipped"] = r.note;
        else if (!r.note.empty())
            j["scaled"] = r.note; // min and max are the range judged at this count
        a.push_back(std::move(j));
    }
    return a;
}

Json familyJson(const FamilyResult& f, const std::vector<MakeupResult>& makeup,
                const Verdict& verdict, const EvalContext& ctx)
{
    const CampaignInput& in = *f.input;
    Json j;
    j["name"] = in.name;
    j["source"] = in.source;
    j["reason"] = in.reason;
    if (in.source == "generated")
        j["seed"] = in.seed;
    j["cases"] = f.cases;
    j["rejected"] = f.rejected;
    j["makeup"] = makeupJson(makeup);
    j["makeup_ok"] = verdict.makeupOk;
    j["pass"] = verdict.pass();
    Json vs = Json::object();
    for (std::size_t k = 0; k < f.stats.size(); ++k)
        vs[ctx.variants[k]->name] = f.stats[k].toJson();
    j["variants"] = std::move(vs);
    return j;
}

Json variantsJson(const EvalContext& ctx)
{
    Json out = Json::array();
    for (auto* v : ctx.variants)
    {
        Json j;
        j["name"] = v->name;
        j["type"] = scalarName(v->scalar);
        j["description"] = v->description;
        j["judged"] = v->judged;
        j["warm"] = v->start == Start::Warm;
        j["batch"] = v->batch;
        j["options"] = optionsJson(v->options);
        if (v->plugin) // the options name the bound it is compared with; the answer is the plugin's
        {
            j["plugin"] = {{"path", v->plugin->path},
                           {"accepts_radius", (v->plugin->impl.accepts & GJK2D_ACCEPTS_RADIUS) != 0},
                           {"accepts_warm_start",
                            (v->plugin->impl.accepts & GJK2D_ACCEPTS_WARM_START) != 0},
                           {"max_vertices", v->plugin->impl.max_vertices}};
        }
        j["bound"] = {{"formula", boundFormula(*v)}, {"unit_roundoff", unitRoundoff(v->scalar)}};
        j["witness_bound"] = {{"formula", witnessBoundFormula(*v)}};
        out.push_back(std::move(j));
    }
    return out;
}

// worst-cases.json (every family's kept cases, names made unique) and the report's "worst" (each
// family's worst case in detail).
Json worstCases(const CampaignState& state, const CampaignConfig& config, const EvalContext& ctx,
                const std::string& date, const std::string& revision, Campaign& camp)
{
    Json detail = Json::array();
    std::set<std::string> names;
    camp.worstComments.push_back(
        fmt::format("Worst cases of `{}` ({}), git {}, seed {}: per family the {} "
                    "cases with the largest normalised error over the variants.",
                    config.command, date, revision, config.seed, config.worstPerFamily));
    for (const auto& f : state.families)
        for (const auto& w : f.worst.cases())
        {
            Case c = w.c;
            for (int k = 2; !names.insert(c.name).second; ++k)
                c.name = fmt::format("{}#{}", w.c.name, k);
            const std::size_t wk = w.outcome.worstVariant();
            camp.worstComments.push_back(
                fmt::format("{}: family {}, normalised error {:.3g} ({}), exact distance {:.17g}",
                            c.name, f.input->name, worstKey(w.outcome.variants[wk]),
                            ctx.variants[wk]->name, w.outcome.exact.distance));
            if (&w == &f.worst.cases().front())
                detail.push_back(caseDetail(w.c, f.input->name, ctx, w.outcome, "normalized"));
            camp.worstCases.push_back(std::move(c));
        }
    return detail;
}

Json contextOf(const CampaignState& state, const CampaignConfig& config, int threads,
               const std::string& date, const std::string& revision, double totalSeconds)
{
    Json inputs = Json::array();
    std::size_t cases = 0, rejected = 0;
    double queries = 0, queryNs = 0;
    for (const auto& f : state.families)
    {
        inputs.push_back(f.input->input);
        cases += f.cases;
        rejected += f.rejected;
        for (const auto& s : f.stats)
            if (s.nsPerQuery > 0)
            {
                queries += double(s.cases);
                queryNs += s.nsPerQuery * double(s.cases);
            }
    }
    const PhaseSeconds& t = state.seconds;
    const double valid = double(cases - rejected);
    const auto perSecond = [&](double s) { return s > 0 ? valid / s : 0.0; };
    Json context = contextJson(date, revision, config.command, config.seed, threads,
                               std::move(inputs), cases, rejected);
    context["exact_route"] = exact::routeName(config.route);
    context["elapsed_s"] = {{"generate", t.inputs}, {"exact", t.exact},   {"gjk", t.gjk},
                            {"witness", t.witness}, {"timing", t.timing}, {"total", totalSeconds}};
    context["throughput"] = {
        {"exact_cases_per_s", perSecond(t.exact)},
        {"gjk_cases_per_s", perSecond(t.gjk)},
        {"witness_cases_per_s", perSecond(t.witness)},
        {"gjk_ns_per_query_mean", queries > 0 ? Json(queryNs / queries) : Json(nullptr)},
        {"note",
         "exact: truths (double input, plus float-rounded input when a float variant runs); "
         "gjk: every variant's query and its error metrics; witness: exact point-to-shape "
         "checks; all on `threads` threads. generate: making or reading the cases. ns per query: "
         "single-threaded timed passes over each family's first cases."}};
    return context;
}
} // namespace

namespace
{
// --- The campaign: fold (one process or one shard), then judge and report ----------------------

EvalContext evalContext(const CampaignConfig& config)
{
    EvalContext ctx;
    ctx.variants = config.variants;
    ctx.exactOptions.route = config.route;
    ctx.pluginTimeoutSeconds = config.pluginTimeoutSeconds;
    return ctx;
}

// Inputs -> truth -> variants -> statistics, input by input, chunk by chunk (the shard's chunks
// only); then the timed passes over the cases kept for them.
Json shardState(const CampaignState& state, const CampaignConfig& config, Shard shard,
                int threads);
Json campaignIdentity(const CampaignConfig& config);
std::string identityDifference(const Json& other, const Json& identity, const std::string& theirs);
void mergeShard(CampaignState& state, const Json& j, Shard shard, const EvalContext& ctx,
                std::size_t worstPerFamily);

// --- Checkpoints: the fold's state every checkpointSeconds, so that a run can resume ------------

std::filesystem::path checkpointFile(const CampaignConfig& config)
{
    return std::filesystem::path(config.checkpointDir) / "checkpoint.json";
}

void writeCheckpoint(const CampaignState& state, const CampaignConfig& config, Shard shard,
                     int threads, ChunkPosition next)
{
    std::error_code ec;
    std::filesystem::create_directories(config.checkpointDir, ec);
    const Json j{{"schema", kCheckpointSchema},
                 {"next", {next.input, next.chunk}},
                 {"state", shardState(state, config, shard, threads)}};
    writeFileAtomic(checkpointFile(config).string(), j.dump() + "\n");
}

// The checkpoint's state merged into the empty `state`; returns where the fold goes on.
// InputError when there is none, or it is another campaign's (another command line).
ChunkPosition resumeFrom(CampaignState& state, const CampaignConfig& config, Shard shard,
                         const EvalContext& ctx)
{
    const std::string path = checkpointFile(config).string();
    if (!std::filesystem::exists(path))
        throw InputError(fmt::format("--resume: {}: no checkpoint to resume from",
                                     shownPath(path)));
    const Json j = readJsonFile(path, "--resume");
    if (!j.is_object() || j.value("schema", "") != kCheckpointSchema)
        throw InputError(
            fmt::format("--resume: {}: not a {} file", shownPath(path), kCheckpointSchema));
    const std::string difference =
        identityDifference(j.at("state").at("campaign"), campaignIdentity(config), "this run");
    if (!difference.empty())
        throw InputError(fmt::format("--resume: {}: the checkpoint is of another campaign: {}",
                                     shownPath(path), difference));
    const Json& sh = j.at("state").at("shard");
    if (sh.at("index").get<std::size_t>() != shard.index ||
        sh.at("count").get<std::size_t>() != shard.count)
        throw InputError(fmt::format("--resume: {}: the checkpoint is of another shard",
                                     shownPath(path)));
    mergeShard(state, j.at("state"), shard, ctx, std::size_t(std::max(0, config.worstPerFamily)));
    return {j.at("next").at(0).get<std::size_t>(), j.at("next").at(1).get<std::size_t>()};
}

// The test hook of docs/validation.md, "Resume": GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS=K stops a
// checkpointed run after its K-th chunk, its checkpoint written, as an interruption would.
std::size_t testStopAfterChunks()
{
    const char* v = std::getenv("GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS");
    return v ? std::size_t(std::strtoull(v, nullptr, 10)) : 0;
}

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
    {
        auto last = Clock::now();
        std::size_t folded = 0;
        const std::size_t stopAfter = testStopAfterChunks();
        plan.afterChunk = [&, last, folded, stopAfter](ChunkPosition next) mutable
        {
            ++folded;
            const bool stop = stopAfter > 0 && folded >= stopAfter;
            if (stop || elapsed(last, Clock::now()) >= config.checkpointSeconds)
            {
                writeCheckpoint(state, config, shard, threads, next);
                last = Clock::now();
            }
            if (stop)
                throw std::runtime_error(
                    fmt::format("test: stopped after {} chunks (a checkpoint is written)", folded));
        };
    }
    {
        Progress progress(config.progress, "cases", total);
        for (std::size_t i = 0; i < state.inputs.size(); ++i)
            runInput(i, config, plan, ctx, threads, progress, state, perCase);
    }
    // A shard times only the inputs whose first chunk it holds: the merge takes those.
    for (std::size_t i = 0; i < state.families.size(); ++i)
        if (!shard.owns(i, 0))
            state.families[i].timing = {};
    const auto tTiming = Clock::now();
    if (config.timing)
        timeVariants(state, config, ctx);
    state.seconds.timing = elapsed(tTiming, Clock::now());
    return state;
}

// Judgement and the report, from the folded (or merged) state.
Campaign finishCampaign(CampaignState& state, const CampaignConfig& config, const EvalContext& ctx,
                        int threads, double seconds)
{
    const std::size_t baseline = baselineIndex(ctx);
    setTimingRatios(state, baseline);

    Campaign camp;
    Json families = Json::array();
    bool anyFailed = false;
    std::size_t rejected = 0;
    for (const auto& f : state.families)
    {
        const std::vector<MakeupResult> makeup = f.makeup.results();
        const Verdict verdict = judgeFamily(makeup, f.stats, ctx);
        anyFailed = anyFailed || !verdict.pass();
        rejected += f.rejected;
        families.push_back(familyJson(f, makeup, verdict, ctx));
    }
    camp.exitCode = campaignExitCode(anyFailed, rejected);

    const std::string date = isoDateUtc(), revision = gitRevision();
    Json worst = worstCases(state, config, ctx, date, revision, camp);
    Json rejectedList = Json::array();
    for (const auto& r : state.rejected)
        rejectedList.push_back(r.entry);
    Json report;
    report["schema"] = kReportSchema;
    report["context"] = contextOf(state, config, threads, date, revision, seconds);
    report["variants"] = variantsJson(ctx);
    report["baseline_variant"] = ctx.variants[baseline]->name;
    report["families"] = std::move(families);
    report["rejected"] = std::move(rejectedList);
    report["worst_cases_file"] = "worst-cases.json";
    report["worst"] = std::move(worst);
    report["exit_code"] = camp.exitCode;
    report["passed"] = camp.exitCode == kExitPass;
    camp.report = std::move(report);
    return camp;
}

// --- A shard's state: what `run --shard` writes and `merge` reads ------------------------------

// What makes two shards parts of one campaign: everything that changes a case, its evaluation
// or the report, plus the code's revision.
Json campaignIdentity(const CampaignConfig& config)
{
    Json variants = Json::array();
    for (const auto* v : config.variants)
        variants.push_back(v->name);
    return Json{{"families", config.families},
                {"case_files", config.caseFiles},
                {"seed", config.seed},
                {"variants", std::move(variants)},
                {"exact_route", exact::routeName(config.route)},
                {"worst_per_family", config.worstPerFamily},
                {"timing", config.timing},
                {"chunk_cases", config.chunkCases},
                {"per_case", config.perCase},
                {"git_revision", gitRevision()}};
}

Json shardState(const CampaignState& state, const CampaignConfig& config, Shard shard,
                int threads)
{
    Json families = Json::array();
    for (const auto& f : state.families)
    {
        Json stats = Json::array(), timing = Json::array();
        for (const auto& s : f.stats)
        {
            stats.push_back(s.state());
            timing.push_back({s.nsPerQuery, s.nsMin, s.nsMax, s.timingPasses});
        }
        std::vector<Case> worst;
        Json worstAt = Json::array();
        for (const auto& w : f.worst.cases())
        {
            worst.push_back(w.c);
            worstAt.push_back(w.index);
        }
        families.push_back({{"name", f.input->name},
                            {"cases", f.cases},
                            {"rejected", f.rejected},
                            {"stats", std::move(stats)},
                            {"timing", std::move(timing)},
                            {"makeup", f.makeup.state()},
                            {"worst_index", std::move(worstAt)},
                            {"worst", caseFileText({}, worst)}});
    }
    Json rejected = Json::array();
    for (const auto& r : state.rejected)
        rejected.push_back({{"input", r.input}, {"index", r.index}, {"entry", r.entry}});
    const PhaseSeconds& t = state.seconds;
    return Json{{"schema", kShardSchema},
                {"campaign", campaignIdentity(config)},
                {"shard", {{"index", shard.index}, {"count", shard.count}}},
                {"command", config.command},
                {"threads", threads},
                {"elapsed_s",
                 {t.inputs, t.exact, t.gjk, t.witness, t.timing}},
                {"families", std::move(families)},
                {"rejected", std::move(rejected)}};
}

// The first field of `identity` (campaignIdentity) that `other` holds differently, as the message
// "its KEY is OTHER, THEIRS's is VALUE"; empty when they are the same campaign.
std::string identityDifference(const Json& other, const Json& identity, const std::string& theirs)
{
    for (const auto& [key, value] : identity.items())
        if (other.value(key, Json()) != value)
            return fmt::format("its {} is {}, {}'s is {}", key,
                               excerpt(other.value(key, Json()).dump()), theirs,
                               excerpt(value.dump()));
    return {};
}

// The shard states' campaign configuration (the command line of `merge` gives the rest).
CampaignConfig configOf(const Json& identity, const CampaignConfig& base)
{
    CampaignConfig c = base;
    c.families = identity.at("families").get<std::vector<std::string>>();
    c.caseFiles = identity.at("case_files").get<std::vector<std::string>>();
    c.seed = identity.at("seed").get<std::uint64_t>();
    c.variants.clear();
    for (const auto& n : identity.at("variants"))
    {
        const std::string name = n.get<std::string>();
        const VariantInfo* v = findVariant(name);
        if (!v) // a shipped plugin's variant (run loads them by default): load them and look again
            for (const auto& path : shippedPluginPaths())
                loadPlugin(path);
        v = findVariant(name);
        if (!v)
            throw InputError(fmt::format("merge: the shards ran variant '{}', which is neither "
                                         "gjk2d's nor a shipped plugin's",
                                         name));
        c.variants.push_back(v);
    }
    if (!exact::parseRoute(identity.at("exact_route").get<std::string>(), c.route))
        throw InputError("merge: an unknown exact route");
    c.worstPerFamily = identity.at("worst_per_family").get<int>();
    c.timing = identity.at("timing").get<bool>();
    c.chunkCases = identity.at("chunk_cases").get<std::size_t>();
    c.perCase = identity.at("per_case").get<bool>();
    return c;
}

// One shard's state folded into `state` (whose inputs are the campaign's): statistics, make-up,
// the rejected cases, the worst cases (evaluated again here: the same code gives the same
// outcome), and the timing of the inputs whose first chunk the shard held.
void mergeShard(CampaignState& state, const Json& j, Shard shard, const EvalContext& ctx,
                std::size_t worstPerFamily)
{
    const Json& families = j.at("families");
    if (families.size() != state.families.size())
        throw InputError("merge: the shards hold different inputs");
    for (std::size_t i = 0; i < state.families.size(); ++i)
    {
        FamilyResult& f = state.families[i];
        const Json& s = families[i];
        if (s.at("name").get<std::string>() != f.input->name)
            throw InputError(fmt::format("merge: input {} is '{}' in a shard, '{}' here", i,
                                         excerpt(s.at("name").get<std::string>()),
                                         excerpt(f.input->name)));
        f.cases += s.at("cases").get<std::size_t>();
        f.rejected += s.at("rejected").get<std::size_t>();
        const Json& stats = s.at("stats");
        if (stats.size() != f.stats.size())
            throw InputError("merge: the shards ran different variants");
        const bool timedFirstChunk = shard.owns(i, 0);
        for (std::size_t k = 0; k < f.stats.size(); ++k)
        {
            f.stats[k].merge(Stats::fromState(stats[k]));
            if (timedFirstChunk)
            {
                const Json& t = s.at("timing")[k];
                f.stats[k].nsPerQuery = t[0].get<double>();
                f.stats[k].nsMin = t[1].get<double>();
                f.stats[k].nsMax = t[2].get<double>();
                f.stats[k].timingPasses = t[3].get<int>();
            }
        }
        f.makeup.merge(MakeupFold::fromState(f.input->makeup, s.at("makeup")));
        const CaseFile worst = parseCaseFile(s.at("worst").get<std::string>(), "shard worst");
        const Json& at = s.at("worst_index");
        for (std::size_t w = 0; w < worst.entries.size() && w < worstPerFamily; ++w)
        {
            const Case& c = worst.entries[w].c;
            f.worst.offer(at.at(w).get<std::size_t>(), c, evaluateCase(c, ctx));
        }
    }
    for (const auto& r : j.at("rejected"))
        state.rejected.push_back({r.at("input").get<std::size_t>(),
                                  r.at("index").get<std::size_t>(), r.at("entry")});
    const Json& e = j.at("elapsed_s");
    state.seconds.inputs += e[0].get<double>();
    state.seconds.exact += e[1].get<double>();
    state.seconds.gjk += e[2].get<double>();
    state.seconds.witness += e[3].get<double>();
    state.seconds.timing += e[4].get<double>();
}
} // namespace

void removeCheckpoint(const CampaignConfig& config)
{
    if (config.checkpointDir.empty())
        return;
    std::error_code ec;
    std::filesystem::remove(checkpointFile(config), ec);
}

Campaign runCampaign(const CampaignConfig& config, std::vector<CampaignInput> inputs,
                     std::ostream* perCase)
{
    const auto tStart = Clock::now();
    const int threads = resolveThreads(config.threads);
    const EvalContext ctx = evalContext(config);
    CampaignState state = foldCampaign(config, std::move(inputs), Shard{}, ctx, threads, perCase);
    return finishCampaign(state, config, ctx, threads, elapsed(tStart, Clock::now()));
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

Campaign mergeShards(const std::vector<Json>& shards, const std::vector<std::string>& names,
                     const CampaignConfig& base, double wallSeconds)
{
    const auto tStart = Clock::now();
    if (shards.empty())
        throw InputError("merge: no shard given");
    // Every shard of one campaign, each once.
    const auto identityOf = [&](std::size_t i) -> const Json&
    {
        const Json& j = shards[i];
        if (!j.is_object() || j.value("schema", "") != kShardSchema)
            throw InputError(fmt::format("{}: not a {} file", shownPath(names[i]), kShardSchema));
        return j.at("campaign");
    };
    const Json& identity = identityOf(0);
    const std::size_t count = shards[0].at("shard").at("count").get<std::size_t>();
    std::vector<bool> seen(count, false);
    for (std::size_t i = 0; i < shards.size(); ++i)
    {
        const std::string difference =
            identityDifference(identityOf(i), identity, shownPath(names[0]));
        if (!difference.empty())
            throw InputError(fmt::format("{}: a shard of another campaign: {}",
                                         shownPath(names[i]), difference));
        const Json& sh = shards[i].at("shard");
        const auto index = sh.at("index").get<std::size_t>();
        if (sh.at("count").get<std::size_t>() != count || index >= count)
            throw InputError(fmt::format("{}: shard {}/{} is not one of {} shards",
                                         shownPath(names[i]), index,
                                         sh.at("count").get<std::size_t>(), count));
        if (seen[index])
            throw InputError(
                fmt::format("{}: shard {}/{} is given twice", shownPath(names[i]), index, count));
        seen[index] = true;
    }
    for (std::size_t i = 0; i < count; ++i)
        if (!seen[i])
            throw InputError(fmt::format("merge: shard {}/{} is missing", i, count));

    CampaignConfig config = configOf(identity, base);
    const EvalContext ctx = evalContext(config);
    CampaignState state;
    state.inputs = campaignInputs(config);
    for (const auto& in : state.inputs)
        state.families.push_back({&in, std::vector<Stats>(ctx.variants.size()),
                                  MakeupFold(in.makeup),
                                  WorstKeeper(std::size_t(std::max(0, config.worstPerFamily))),
                                  {}});
    for (std::size_t i = 0; i < shards.size(); ++i)
        mergeShard(state, shards[i],
                   Shard{shards[i].at("shard").at("index").get<std::size_t>(), count}, ctx,
                   std::size_t(std::max(0, config.worstPerFamily)));
    std::sort(state.rejected.begin(), state.rejected.end(),
              [](const RejectedCase& a, const RejectedCase& b)
              { return a.input != b.input ? a.input < b.input : a.index < b.index; });
    if (state.rejected.size() > kMaxRejectedListed)
        state.rejected.resize(kMaxRejectedListed);
    int threads = 0;
    for (const auto& j : shards)
        threads += j.at("threads").get<int>();
    return finishCampaign(state, config, ctx, threads,
                          wallSeconds >= 0 ? wallSeconds : elapsed(tStart, Clock::now()));
}

void joinPerCase(const Json& report, std::size_t chunkCases,
                 const std::vector<std::istream*>& shardLines, std::ostream& out)
{
    const Shard rule{0, shardLines.size()};
    std::string line;
    const Json& families = report.at("families");
    for (std::size_t f = 0; f < families.size(); ++f)
    {
        const auto cases = families[f].at("cases").get<std::size_t>();
        for (std::size_t first = 0, j = 0; first < cases; first += chunkCases, ++j)
        {
            const std::size_t s = (f + j) % rule.count; // Shard::owns
            for (std::size_t i = first; i < std::min(cases, first + chunkCases); ++i)
            {
                if (!std::getline(*shardLines[s], line))
                    throw InputError(fmt::format("merge: shard {}'s cases.jsonl ends before "
                                                 "case {} of {}",
                                                 s, i, excerpt(families[f].at("name").dump())));
                out << line << '\n';
            }
        }
    }
    for (std::size_t s = 0; s < shardLines.size(); ++s)
        if (std::getline(*shardLines[s], line))
            throw InputError(fmt::format("merge: shard {}'s cases.jsonl has more lines than its "
                                         "cases",
                                         s));
}

namespace
{
// Every file a report directory holds, besides the plugins' logs (plugin-*.log, evaluate/plugins.hpp);
// writeCampaign replaces the directory as a whole.
const char* const kReportFiles[] = {"report.json", "report.md",  "worst-cases.json",
                                    "cases.jsonl", "index.html", "shard.json"};
} // namespace

void checkReportDir(const std::string& outDir)
{
    if (outDir.empty())
        throw InputError("--out: the output directory is empty");
    const fs::path dir = reportDirPath(outDir);
    std::error_code ec;
    const auto st = fs::status(dir, ec);
    if (fs::exists(st))
    {
        if (!fs::is_directory(st))
            throw InputError(
                fmt::format("--out {}: exists and is not a directory", excerpt(outDir)));
        // The whole directory is replaced: refuse one that holds anything else than a report.
        for (const auto& e : fs::directory_iterator(dir, ec))
        {
            const std::string name = e.path().filename().string();
            const bool pluginLog = name.rfind("plugin-", 0) == 0 && name.size() > 11 &&
                                   name.compare(name.size() - 4, 4, ".log") == 0;
            if (!pluginLog && std::find(std::begin(kReportFiles), std::end(kReportFiles), name) ==
                                  std::end(kReportFiles))
                throw InputError(fmt::format(
                    "--out {}: holds '{}', which is not part of a report (the directory is "
                    "replaced as a whole: give a new or a report directory)",
                    excerpt(outDir), excerpt(name)));
        }
        if (ec)
            throw InputError(fmt::format("--out {}: cannot read the directory: {}", excerpt(outDir),
                                         ec.message()));
    }
    // The parent must exist or be creatable, and be writable: the report is staged beside DIR.
    fs::path parent = dir.parent_path();
    while (!fs::exists(parent, ec) && parent.has_relative_path())
        parent = parent.parent_path();
    if (!fs::is_directory(parent, ec))
        throw InputError(fmt::format("--out {}: {} is not a directory", excerpt(outDir),
                                     excerpt(parent.string())));
    if (::access(parent.c_str(), W_OK | X_OK) != 0)
        throw InputError(fmt::format("--out {}: cannot write in {}: {}", excerpt(outDir),
                                     excerpt(parent.string()), std::strerror(errno)));
}

std::string writeCampaign(const Campaign& camp, StagedDir& out)
{
    out.write("report.json", camp.report.dump(1) + "\n"); // first: the rest is rendered from it
    out.write("report.md", renderMarkdown(camp.report));
    out.write("worst-cases.json", caseFileText(camp.worstComments, camp.worstCases));
#if defined(GJK2D_HAVE_HTML)
    out.write("index.html", gjk_html::renderReport(nlohmann::json::parse(camp.report.dump()), kReportSchema));
    const std::string page = "index.html";
#else
    const std::string page = "report.md";
#endif
    out.commit();
    return (out.dir() / page).string();
}

Json stripVolatile(Json r)
{
    Json& c = r["context"];
    for (const char* k : {"date", "host", "threads", "elapsed_s", "throughput", "command"})
        c.erase(k);
    for (auto& f : r["families"])
        for (auto& [name, s] : f["variants"].items())
            for (const char* k :
                 {"ns_per_query", "ns_spread", "ratio_to_baseline", "timing_passes"})
                s.erase(k);
    return r;
}

} // namespace gjkval
