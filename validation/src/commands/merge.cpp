// gjk-validate merge: the shards of one campaign (`run --shard I/N`, each a shard.json) into the
// campaign's report, the same as the one-process run's, timing fields aside.
#include "campaign/campaign.hpp"
#include "commands/command_line.hpp"
#include "commands/fault.hpp"
#include "commands/outputs.hpp"
#include "common/output.hpp"
#include "inputs/cases.hpp"
#include "report/report.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;

struct Options
{
    std::vector<std::string> shards;
    std::string outDir = "reports/latest/";
    bool verbose = false;
};

// A shard directory's shard.json, or the file itself.
fs::path shardPath(const std::string& path)
{
    fs::path p = path;
    std::error_code ec;
    if (fs::is_directory(p, ec))
        p /= "shard.json";
    return p;
}

int mergeCommand(const Options& o, const CommandLine& line)
{
    checkReportDir(o.outDir);
    testFault();
    std::vector<Json> shards;
    for (const auto& s : o.shards)
        shards.push_back(readJsonFile(shardPath(s).string(), "merge"));
    CampaignConfig base;
    base.command = line.text();
    Campaign camp;
    try
    {
        camp = mergeShards(shards, o.shards, base);
    }
    catch (const Json::exception& e) // a field missing or of the wrong type
    {
        throw InputError(fmt::format("merge: a shard file is not a {} state: {}", kShardSchema,
                                     excerpt(e.what(), 120)));
    }
    StagedDir out(reportDirPath(o.outDir));
    if (shards[0].at("campaign").at("per_case").get<bool>()) // every shard has cases.jsonl
    {
        std::vector<std::string> files(shards.size());
        for (std::size_t i = 0; i < shards.size(); ++i)
            files[shards[i].at("shard").at("index").get<std::size_t>()] =
                (shardPath(o.shards[i]).parent_path() / "cases.jsonl").string();
        writeJoinedPerCase(camp, shards[0].at("campaign").at("chunk_cases").get<std::size_t>(),
                           files, out);
    }
    writeReportAndSummary(camp, out, o.verbose);
    return camp.exitCode;
}
} // namespace

Subcommand addMerge(CLI::App& app, const CommandLine& line)
{
    auto o = std::make_shared<Options>();
    auto* m = app.add_subcommand(
        "merge", "Merge the shards of one campaign (each written by `run --shard I/N --out DIR`) "
                 "into its report: the same report.json as the one-process run, timing aside.");
    m->footer(exitCodesHelp());
    m->add_option("shards", o->shards, "every shard's DIR (or DIR/shard.json), in any order")
        ->required()
        ->type_name("DIR");
    m->add_option("--out", o->outDir,
                  "output directory, replaced as a whole (it may hold only a previous report)")
        ->capture_default_str();
    m->add_flag("--verbose", o->verbose,
                "also print every family x variant to the terminal, and every one that failed or "
                "broke its contract");
    return {m, [o, line] { return mergeCommand(*o, line); }};
}

} // namespace gjkval
