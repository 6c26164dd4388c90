// gjk-validate run: a campaign, from the command line to the report directory.
#include "campaign/campaign.hpp"
#include "commands/command_line.hpp"
#include "commands/fault.hpp"
#include "commands/outputs.hpp"
#include "commands/plugin_options.hpp"
#include "common/output.hpp"
#include "implementations/plugins.hpp"
#include "implementations/variants.hpp"
#include "report/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>
#include <unistd.h>

#if defined(GJK2D_HAVE_MPI)
#include <mpi.h>
#endif

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;

struct RunOptions
{
    CampaignConfig config;
    std::vector<std::string> families, files;
    std::string variants = kDefaultVariants, outDir = "reports/latest/", route = "default",
                seed = "1", truth = "filtered";
    std::size_t chunkCases = kDefaultChunkCases;
    bool noProgress = false, noTiming = false, verbose = false, defaultCases = false;
    std::string shard; // "I/N"
    PluginOptions plugins;
};

// "I/N", 0 <= I < N <= kMaxShards: InputError otherwise.
Shard parseShard(const std::string& text)
{
    unsigned long long i = 0, n = 0;
    char slash = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%llu%c%llu%c", &i, &slash, &n, &extra) != 3 || slash != '/' ||
        n < 1 || n > kMaxShards || i >= n || text.find_first_of("+- ") != std::string::npos)
        throw InputError(fmt::format("--shard {}: expected I/N with 0 <= I < N <= {}",
                                     excerpt(text), kMaxShards));
    return Shard{std::size_t(i), std::size_t(n)};
}

// Every argument is checked here, before any work starts (InputError: exit code 2).
CampaignConfig checkedConfig(RunOptions& o, const CommandLine& line)
{
    CampaignConfig cfg = o.config;
    cfg.seed = parseSeed(o.seed);
    // The default campaign's shipped plugins join the default variant list (an explicit one names
    // them); --peers adds every installed shipped peer.
    cfg.variants = selectVariants(o.variants, o.plugins, ShippedPlugins::JoinDefaultList);
    cfg.pluginTimeoutSeconds = o.plugins.timeoutSeconds;
    cfg.route = parseRouteOrThrow(o.route);
    cfg.truthFilter = parseTruthOrThrow(o.truth);
    checkRange("--threads", cfg.threads, 0, kMaxThreads);
    checkRange("--passes", cfg.maxPasses, 1, kMaxPasses);
    checkRange("--worst", cfg.worstPerFamily, 0, kMaxWorst);
    if (o.chunkCases < 1 || o.chunkCases > kMaxChunkCases)
        throw InputError(fmt::format("--chunk {}: expected 1..{}", o.chunkCases, kMaxChunkCases));
    cfg.chunkCases = o.chunkCases;
    if (cfg.resume && cfg.checkpointDir.empty())
        throw InputError("--resume: needs --checkpoint DIR (where the checkpoint is)");
    if (!cfg.checkpointDir.empty() && cfg.perCase)
        throw InputError("--per-case: not with --checkpoint (cases.jsonl is not resumable)");
    if (!(cfg.checkpointSeconds >= 0))
        throw InputError("--checkpoint-seconds: expected a number >= 0");
    cfg.timing = !o.noTiming;
    cfg.minPasses = std::min(cfg.minPasses, cfg.maxPasses);
    cfg.progress = !o.noProgress && isatty(STDERR_FILENO);
    cfg.command = line.text();
    cfg.families = o.families;
    cfg.caseFiles = o.files;
    if (cfg.families.empty() && cfg.caseFiles.empty() && !o.defaultCases)
        cfg.families = defaultFamilies();
    if ((o.families.empty() && o.files.empty()) || o.defaultCases)
        for (const auto& f : defaultCaseFiles())
            cfg.caseFiles.push_back(f);
    checkFamilies(cfg.families, true);
    checkCaseFiles(cfg.caseFiles);
    checkReportDir(o.outDir);
    return cfg;
}

// DIR/cases.jsonl, staged with the rest of the directory (OutputError when it cannot be written).
std::ofstream openPerCase(StagedDir& out)
{
    std::ofstream f(out.staged("cases.jsonl"), std::ios::binary);
    if (!f)
        throw OutputError(fmt::format("{}/cases.jsonl: cannot create the file: {}",
                                      excerpt(out.dir().string()), std::strerror(errno)));
    return f;
}
void closePerCase(std::ofstream& f, StagedDir& out)
{
    f.close();
    if (!f)
        throw OutputError(fmt::format("{}/cases.jsonl: write failed: {}",
                                      excerpt(out.dir().string()), std::strerror(errno)));
}

// `run --shard I/N`: the shard's state into DIR/shard.json; `merge` makes the report.
int shardCommand(RunOptions& o, const CampaignConfig& cfg)
{
    const Shard shard = parseShard(o.shard);
    std::vector<CampaignInput> inputs = campaignInputs(cfg);
    StagedDir out(reportDirPath(o.outDir));
    setPluginLogDirectory(out.staging().string()); // plugin-*.log beside shard.json
    std::ofstream perCase; // the shard's chunks; merge joins the shards' files in case order
    if (cfg.perCase)
        perCase = openPerCase(out);
    const Json state = runShard(cfg, std::move(inputs), shard, cfg.perCase ? &perCase : nullptr);
    if (cfg.perCase)
        closePerCase(perCase, out);
    out.write("shard.json", state.dump() + "\n");
    const std::vector<PluginLog> logs = finishPluginLogs();
    out.commit();
    printPluginLogs(logs, out.dir());
    removeCheckpoint(cfg);
    std::size_t cases = 0;
    for (const auto& f : state.at("families"))
        cases += f.at("cases").get<std::size_t>();
    std::printf("shard %zu/%zu: %zu cases of %zu inputs; merge the shards with `gjk-validate "
                "merge`\nshard: %s\n",
                shard.index, shard.count, cases, state.at("families").size(),
                (out.dir() / "shard.json").c_str());
    flushStdout();
    return kExitPass;
}

// The number of processes a launcher started this one among (mpirun sets OMPI_COMM_WORLD_SIZE,
// Slurm's and MPICH's PMI PMI_SIZE), and how many of them share this node; 1 without a launcher.
std::size_t launcherSize(const char* variable)
{
    const char* v = std::getenv(variable);
    const long n = v ? std::strtol(v, nullptr, 10) : 1;
    return n > 1 ? std::size_t(n) : 1;
}
std::size_t worldSize()
{
    return std::max(launcherSize("OMPI_COMM_WORLD_SIZE"), launcherSize("PMI_SIZE"));
}

#if defined(GJK2D_HAVE_MPI)
// --per-case under mpirun: each rank writes its chunks' lines beside DIR (a file system every rank
// shares), rank 0 joins them into DIR/cases.jsonl in case order and removes them.
fs::path rankLinesPath(const std::string& outDir, int rank)
{
    return fs::path(reportDirPath(outDir).string() + fmt::format(".rank-{}.cases.jsonl", rank));
}

// The rank's configuration: the node's cores shared among its ranks (unless --threads), the
// progress bar on rank 0 only, a checkpoint directory of its own.
CampaignConfig rankConfig(CampaignConfig cfg, int rank)
{
    if (cfg.threads == 0)
        cfg.threads = int(std::max<std::size_t>(
            1, std::thread::hardware_concurrency() /
                   std::max<std::size_t>(1, launcherSize("OMPI_COMM_WORLD_LOCAL_SIZE"))));
    cfg.progress = cfg.progress && rank == 0;
    if (!cfg.checkpointDir.empty())
        cfg.checkpointDir = (fs::path(cfg.checkpointDir) / fmt::format("rank-{}", rank)).string();
    return cfg;
}

// Shard rank/size of the campaign, its per-case lines into rankLinesPath: the shard's state.
std::string runRankShard(const RunOptions& o, const CampaignConfig& cfg, int rank, int size)
{
    const fs::path lines = rankLinesPath(o.outDir, rank);
    std::ofstream perCase;
    if (cfg.perCase)
    {
        perCase.open(lines, std::ios::binary);
        if (!perCase)
            throw OutputError(fmt::format("{}: cannot create the file: {}", excerpt(lines.string()),
                                          std::strerror(errno)));
    }
    std::string state =
        runShard(cfg, campaignInputs(cfg), Shard{std::size_t(rank), std::size_t(size)},
                 cfg.perCase ? &perCase : nullptr)
            .dump();
    if (cfg.perCase)
    {
        perCase.close();
        if (!perCase)
            throw OutputError(
                fmt::format("{}: write failed: {}", excerpt(lines.string()), std::strerror(errno)));
    }
    return state;
}

// Every rank's state gathered on rank 0, in rank order (empty on the other ranks).
std::vector<std::string> gatherStates(const std::string& state, int rank, int size)
{
    const int length = int(state.size());
    std::vector<int> lengths(static_cast<std::size_t>(size)), offsets(lengths.size());
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::string all;
    if (rank == 0)
    {
        for (int r = 1; r < size; ++r)
            offsets[std::size_t(r)] = offsets[std::size_t(r) - 1] + lengths[std::size_t(r) - 1];
        all.resize(std::size_t(offsets.back() + lengths.back()));
    }
    MPI_Gatherv(state.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                MPI_CHAR, 0, MPI_COMM_WORLD);
    std::vector<std::string> states;
    if (rank == 0)
        for (std::size_t r = 0; r < lengths.size(); ++r)
            states.push_back(all.substr(std::size_t(offsets[r]), std::size_t(lengths[r])));
    return states;
}

// Rank 0: the ranks' states merged into the report, their per-case lines joined; the campaign's
// exit code.
int writeMergedReport(const RunOptions& o, const CampaignConfig& cfg,
                      const std::vector<std::string>& states, double wallSeconds)
{
    std::vector<Json> shards;
    std::vector<std::string> names;
    for (std::size_t r = 0; r < states.size(); ++r)
    {
        shards.push_back(Json::parse(states[r]));
        names.push_back(fmt::format("rank {}", r));
    }
    const Campaign camp = mergeShards(shards, names, cfg, wallSeconds);
    StagedDir out(reportDirPath(o.outDir));
    if (cfg.perCase)
    {
        std::vector<std::string> files;
        for (std::size_t r = 0; r < states.size(); ++r)
            files.push_back(rankLinesPath(o.outDir, int(r)).string());
        writeJoinedPerCase(camp, cfg.chunkCases, files, out,
                           " (is the directory on a file system every rank shares?)");
        for (const auto& f : files)
            fs::remove(f);
    }
    writeReportAndSummary(camp, out, o.verbose);
    return camp.exitCode;
}

// Under mpirun: rank r of n runs shard r/n; rank 0 gathers the shard states, merges them and
// writes the report (the one-process report, timing fields aside; each rank times the inputs
// whose first chunk it holds, while the other ranks work). Every rank returns the campaign's
// exit code: rank 0's error, if any, is broadcast as its exit code and rethrown there.
int mpiCommand(const RunOptions& o, const CampaignConfig& config)
{
    if (!o.shard.empty())
        throw InputError("--shard: not under mpirun, where every rank is a shard");
    MPI_Init(nullptr, nullptr);
    const double start = MPI_Wtime();
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const CampaignConfig cfg = rankConfig(config, rank);
    const std::vector<std::string> states =
        gatherStates(runRankShard(o, cfg, rank, size), rank, size);
    int code = kExitPass;
    std::exception_ptr error;
    if (rank == 0)
        try
        {
            code = writeMergedReport(o, cfg, states, MPI_Wtime() - start);
        }
        catch (const InputError&)
        {
            error = std::current_exception();
            code = kExitInput;
        }
        catch (const OutputError&)
        {
            error = std::current_exception();
            code = kExitResources;
        }
        catch (...)
        {
            error = std::current_exception();
            code = kExitInternal;
        }
    MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
    MPI_Finalize();
    if (error)
        std::rethrow_exception(error); // main() reports it, with the same exit code
    return code;
}
#endif

// The whole campaign in this process: its report into DIR.
int wholeCampaignCommand(const RunOptions& o, const CampaignConfig& cfg)
{
    std::vector<CampaignInput> inputs = campaignInputs(cfg);
    // Staged beside DIR and swapped in at the end: DIR holds this run or the previous one.
    StagedDir out(reportDirPath(o.outDir));
    setPluginLogDirectory(out.staging().string()); // what plugins print: DIR/plugin-*.log
    std::ofstream perCase;
    if (cfg.perCase)
        perCase = openPerCase(out);
    const Campaign camp = runCampaign(cfg, std::move(inputs), cfg.perCase ? &perCase : nullptr);
    if (cfg.perCase)
        closePerCase(perCase, out);
    writeReportAndSummary(camp, out, o.verbose);
    removeCheckpoint(cfg);
    return camp.exitCode;
}

// The campaign the way it was launched: under mpirun (a shard per rank), as one shard
// (--shard), or whole in this process.
int runAsLaunched(RunOptions& o, const CommandLine& line)
{
    const CampaignConfig cfg = checkedConfig(o, line);
    testFault();
    if (worldSize() > 1)
    {
#if defined(GJK2D_HAVE_MPI)
        return mpiCommand(o, cfg);
#else
        throw InputError(fmt::format(
            "started as one of {} processes (mpirun?), but this gjk-validate is built without "
            "MPI (GJK2D_WITH_MPI, docs/cli.md): each would run the whole campaign",
            worldSize()));
#endif
    }
    if (!o.shard.empty())
        return shardCommand(o, cfg);
    return wholeCampaignCommand(o, cfg);
}

// --family, --cases, --default-cases, --seed, --variants: the campaign's cases and variants.
void addInputOptions(CLI::App* run, RunOptions& o)
{
    run->add_option("--family", o.families,
                    "case family with optional count: random[:N] (default N 200000), hard[:N] (all "
                    "sub-families, N each, default their built-in counts), hard/<sub>[:N], "
                    "engine[:N] (all engine families, N each, default 2000), "
                    "engine/<scene>-<kind>[:N]; N in 1..1e8 (engine families are held in memory: "
                    "within it); repeatable (see `list`)")
        ->allow_extra_args(false);
    run->add_option("--cases", o.files, "a gjk-cases/1 file; repeatable")->allow_extra_args(false);
    run->add_flag("--default-cases", o.defaultCases,
                  "also run the default campaign's case files (validation/cases/*.json, installed "
                  "in <prefix>/share/gjk2d/cases: found beside the program)");
    run->add_option("--seed", o.seed, "campaign seed, 0..2^64-1 (each family derives its own)")
        ->capture_default_str();
    run->add_option("--variants", o.variants, "comma-separated variant names, or all (see `list`)")
        ->capture_default_str();
}

// --threads, --out, --per-case, --worst, --exact-route, --passes, --chunk, --no-timing: how the
// campaign runs and what it writes.
void addEvaluationOptions(CLI::App* run, RunOptions& o)
{
    CampaignConfig& cfg = o.config;
    run->add_option("--threads", cfg.threads, "worker threads, 0..256 (0: all cores)")
        ->capture_default_str();
    run->add_option("--out", o.outDir,
                    "output directory, replaced as a whole (it may hold only a previous report)")
        ->capture_default_str();
    run->add_flag("--per-case", cfg.perCase,
                  "also write DIR/cases.jsonl, one JSON object per case");
    run->add_option("--worst", cfg.worstPerFamily,
                    "worst cases kept per family in worst-cases.json, 0..1000")
        ->capture_default_str();
    run->add_option("--exact-route", o.route,
                    "exact construction: edge-merge, hull-of-differences, minkowski-sum-2")
        ->capture_default_str();
    run->add_option("--truth", o.truth, kTruthHelp)->capture_default_str();
    run->add_option("--passes", cfg.maxPasses,
                    "maximum timed passes per family and variant, 1..1000 (at least 5 are run "
                    "unless fewer are asked)")
        ->capture_default_str();
    run->add_option("--chunk", o.chunkCases,
                    "cases evaluated together, 1..1e6: memory follows it, the report does not")
        ->capture_default_str();
    run->add_flag("--no-timing", o.noTiming, "skip the timed passes (ns_per_query is null)");
}

// --checkpoint, --checkpoint-seconds, --resume, --shard: a campaign in parts.
void addPartOptions(CLI::App* run, RunOptions& o)
{
    CampaignConfig& cfg = o.config;
    run->add_option("--checkpoint", cfg.checkpointDir,
                    "write the campaign's state to DIR/checkpoint.json as it goes (removed once "
                    "the report is written)")
        ->type_name("DIR");
    run->add_option("--checkpoint-seconds", cfg.checkpointSeconds,
                    "at most this often (0: after every chunk)")
        ->capture_default_str();
    run->add_flag("--resume", cfg.resume,
                  "start from --checkpoint DIR's state (the same command line otherwise); the "
                  "report is the uninterrupted run's, timing aside");
    run->add_option(
           "--shard", o.shard,
           "I/N: evaluate only shard I of N (chunks round robin) and write DIR/shard.json; "
           "`gjk-validate merge` makes the report of all N")
        ->type_name("I/N");
}
} // namespace

Subcommand addRun(CLI::App& app, const CommandLine& line)
{
    auto o = std::make_shared<RunOptions>();
    auto* run = app.add_subcommand(
        "run", "Run a campaign and write DIR/report.json, report.md, worst-cases.json "
               "(and cases.jsonl, index.html). Without --family and --cases: the "
               "default campaign, " +
                   defaultFamilyOptions() + " plus every validation/cases/*.json.");
    run->footer(exitCodesHelp());
    addInputOptions(run, *o);
    addEvaluationOptions(run, *o);
    addPartOptions(run, *o);
    run->add_flag("--verbose", o->verbose,
                  "also print every family x variant to the terminal, and every one that failed "
                  "or broke its contract (the summary has a line per variant and, per family, "
                  "only the judged variants' failures; report.md has the full table)");
    addPluginOptions(*run, o->plugins, ShippedPlugins::JoinDefaultList);
    run->add_flag("--no-progress", o->noProgress,
                  "no progress bar (it is shown only when stderr is a terminal)");
    return {run, [o, line] { return runAsLaunched(*o, line); }};
}

} // namespace gjkval
