// Checkpoints: the fold's state every checkpointSeconds, so that a run can resume
// (docs/cli.md, "Shards, merge, MPI, resume").
#include "campaign/state.hpp"

#include "common/output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace gjkval
{
namespace
{
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

} // namespace

ChunkPosition resumeFrom(CampaignState& state, const CampaignConfig& config, Shard shard,
                         const EvalContext& ctx)
{
    const std::string path = checkpointFile(config).string();
    if (!std::filesystem::exists(path))
        throw InputError(
            fmt::format("--resume: {}: no checkpoint to resume from", shownPath(path)));
    const Json j = readJsonFile(path, "--resume");
    checkStateSchema(j, kCheckpointSchema, "--resume: " + shownPath(path),
                     "run again without --resume");
    const std::string difference =
        identityDifference(j.at("state").at("campaign"), campaignIdentity(config), "this run");
    if (!difference.empty())
        throw InputError(fmt::format("--resume: {}: the checkpoint is of another campaign: {}",
                                     shownPath(path), difference));
    const Json& sh = j.at("state").at("shard");
    if (sh.at("index").get<std::size_t>() != shard.index ||
        sh.at("count").get<std::size_t>() != shard.count)
        throw InputError(
            fmt::format("--resume: {}: the checkpoint is of another shard", shownPath(path)));
    mergeShard(state, j.at("state"), shard, ctx, std::size_t(std::max(0, config.worstPerFamily)));
    return {j.at("next").at(0).get<std::size_t>(), j.at("next").at(1).get<std::size_t>()};
}

namespace
{
// The test hook of docs/cli.md, "Shards, merge, MPI, resume":
// GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS=K stops a checkpointed run after its K-th chunk, its
// checkpoint written, as an interruption would.
std::size_t testStopAfterChunks()
{
    const char* v = std::getenv("GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS");
    return v ? std::size_t(std::strtoull(v, nullptr, 10)) : 0;
}
} // namespace

std::function<void(ChunkPosition next)> checkpointAfterChunk(const CampaignState& state,
                                                             const CampaignConfig& config,
                                                             Shard shard, int threads)
{
    auto last = Clock::now();
    std::size_t folded = 0;
    const std::size_t stopAfter = testStopAfterChunks();
    return [&state, &config, shard, threads, last, folded, stopAfter](ChunkPosition next) mutable
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

void removeCheckpoint(const CampaignConfig& config)
{
    if (config.checkpointDir.empty())
        return;
    std::error_code ec;
    std::filesystem::remove(checkpointFile(config), ec);
}

} // namespace gjkval
