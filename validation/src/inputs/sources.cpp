// The campaign's inputs as streams: a generated family's cases made in chunks on the threads, a
// case file's entries read in chunks, in case order; and every input of a command line collected
// (for the commands that hold their cases).
#include "inputs/sources.hpp"

#include "inputs/case_binary.hpp"

#include "common/parallel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;

// plan.cases(begin, end), in blocks on up to `threads` threads (parallel.hpp: each block's cases
// stored by position, so the same cases in the same order on any number).
std::vector<Case> makeCases(const FamilyPlan& plan, std::size_t begin, std::size_t end, int threads)
{
    constexpr std::size_t kBlock = 256;
    if (threads <= 1 || end - begin <= kBlock)
        return plan.cases(begin, end);
    std::vector<std::vector<Case>> blocks((end - begin + kBlock - 1) / kBlock);
    Progress none = Progress::silent();
    parallelFor(blocks.size(), threads, none,
                [&](std::size_t b)
                {
                    const std::size_t from = begin + b * kBlock;
                    blocks[b] = plan.cases(from, std::min(end, from + kBlock));
                });
    std::vector<Case> cases;
    cases.reserve(end - begin);
    for (auto& block : blocks)
        std::move(block.begin(), block.end(), std::back_inserter(cases));
    return cases;
}

CampaignInput familyInput(FamilyPlan plan, std::uint64_t campaignSeed)
{
    CampaignInput in;
    in.name = plan.name;
    in.reason = plan.reason;
    in.source = "generated";
    in.seed = plan.seed;
    in.count = plan.count;
    in.input = {{"family", plan.name}, {"count", plan.count}, {"seed", campaignSeed}};
    in.makeup = std::move(plan.makeup);
    in.stream = [plan = std::move(plan)](std::size_t chunkCases,
                                         const std::function<void(CaseChunk&)>& consume,
                                         const CampaignInput::SkipChunk& skip, int threads)
    {
        for (std::size_t first = 0; first < plan.count; first += chunkCases)
        {
            if (skip && skip(first / chunkCases))
                continue; // each case is made from its index alone: nothing to keep in step
            CaseChunk chunk;
            chunk.first = first;
            chunk.cases = makeCases(plan, first, std::min(plan.count, first + chunkCases), threads);
            for (const auto& c : chunk.cases)
                chunk.labels.push_back(c.name);
            chunk.rejected.assign(chunk.cases.size(), {});
            consume(chunk);
        }
    };
    return in;
}

// Entries of a case file in chunks: `read` passes every entry, in order, to its argument.
void chunked(const std::function<void(const std::function<void(CaseEntry&&)>&)>& read,
             std::size_t chunkCases, const std::function<void(CaseChunk&)>& consume)
{
    CaseChunk chunk;
    std::size_t next = 0;
    read(
        [&](CaseEntry&& e)
        {
            if (chunk.cases.empty())
                chunk.first = next;
            ++next;
            chunk.cases.push_back(std::move(e.c));
            chunk.labels.push_back(std::move(e.label));
            chunk.rejected.push_back(std::move(e.rejected));
            if (chunk.size() == chunkCases)
            {
                consume(chunk);
                chunk = CaseChunk();
            }
        });
    if (chunk.size() > 0)
        consume(chunk);
}

// Thrown by the consumer of a check that stops at the first entry.
struct FirstEntryReached
{
};

// True when the JSON file at `path` (a regular file, or a pipe's copy) ends with its closing brace,
// white space after it aside: a file cut short does not.
bool endsWithBrace(const std::string& path)
{
    std::ifstream f(path, std::ios::binary);
    f.seekg(0, std::ios::end);
    const std::streamoff size = f.tellg();
    std::string tail(std::size_t(std::min<std::streamoff>(size, 4096)), '\0');
    f.seekg(size - std::streamoff(tail.size()));
    f.read(tail.data(), std::streamsize(tail.size()));
    const std::size_t last = tail.find_last_not_of(" \t\r\n");
    return f && last != std::string::npos && tail[last] == '}';
}

// Reads the file up to its first entry: InputError when it does not open as a case file. True
// when that read ended the file (no entry): what it found is then the whole file's.
bool readToFirstEntry(const std::string& readPath, const std::string& path,
                      CaseFileSummary& summary)
{
    try
    {
        summary = streamCaseFile(readPath, path, [](CaseEntry&&) { throw FirstEntryReached(); });
        return true;
    }
    catch (const FirstEntryReached&)
    {
        return false;
    }
}

// hold: the caller keeps every case anyway (collectInputs), so the file is read once, whole.
CampaignInput fileInput(const std::string& path, std::string name, bool hold, FileCheck check)
{
    CampaignInput in;
    in.name = std::move(name);
    in.source = "file";
    in.read = std::make_shared<CaseFileSummary>();
    in.input = {{"file", path}, {"count", 0}};
    std::shared_ptr<CaseFile> whole;
    std::shared_ptr<PipeCopy> copy; // a pipe cannot be read twice: its copy is
    std::error_code ec;
    if (hold)
    {
        whole = std::make_shared<CaseFile>(readCaseFile(path));
        in.read->comments = whole->comments;
        in.read->entries = whole->entries.size();
    }
    else
    {
        const bool pipe = fs::status(path, ec).type() == fs::file_type::fifo;
        if (pipe)
            copy = std::make_shared<PipeCopy>(path);
        const std::string readPath = copy ? copy->path() : path;
        const bool cutShort = !isBinaryCaseFile(readPath) && !endsWithBrace(readPath);
        const bool readWhole = check == FileCheck::Whole || cutShort; // cut short: for its message
        if (readWhole)
            *in.read = streamCaseFile(readPath, path, [](CaseEntry&&) {});
        in.counted = readWhole || readToFirstEntry(readPath, path, *in.read);
    }
    settleFileInput(in);
    in.stream = [path, whole, copy, read = in.read](std::size_t chunkCases,
                                                    const std::function<void(CaseChunk&)>& consume,
                                                    const CampaignInput::SkipChunk&,
                                                    int) // in order, on one thread
    {
        chunked(
            [&](const std::function<void(CaseEntry &&)>& each)
            {
                if (whole)
                    for (auto e : whole->entries)
                        each(std::move(e));
                else
                    *read = streamCaseFile(copy ? copy->path() : path, path, each);
            },
            chunkCases, consume);
    };
    return in;
}

std::vector<CampaignInput> inputsOf(const std::vector<std::string>& familySpecs,
                                    const std::vector<std::string>& caseFiles, std::uint64_t seed,
                                    bool holdFiles, FileCheck check)
{
    std::vector<CampaignInput> out;
    std::set<std::string> names;
    for (const auto& spec : familySpecs)
        for (auto& plan : planFamilies(spec, seed))
        {
            if (!names.insert(plan.name).second)
                throw InputError(fmt::format("family '{}' is given twice", plan.name));
            out.push_back(familyInput(std::move(plan), seed));
        }
    for (const auto& path : caseFiles)
    {
        std::string name = "file:" + fs::path(path).filename().string();
        if (!names.insert(name).second)
        {
            name = "file:" + path;
            if (!names.insert(name).second)
                throw InputError(fmt::format("case file '{}' is given twice", path));
        }
        out.push_back(fileInput(path, std::move(name), holdFiles, check));
    }
    return out;
}
} // namespace

std::vector<CampaignInput> campaignInputs(const std::vector<std::string>& familySpecs,
                                          const std::vector<std::string>& caseFiles,
                                          std::uint64_t seed, FileCheck check)
{
    return inputsOf(familySpecs, caseFiles, seed, false, check);
}

void settleFileInput(CampaignInput& in)
{
    const std::string path = in.input.at("file").get<std::string>();
    in.count = in.read->entries;
    in.reason = in.read->comments.empty() ? "cases from " + path : in.read->comments.front();
    in.input["count"] = in.count;
}

std::vector<FamilyData> collectInputs(const std::vector<std::string>& familySpecs,
                                      const std::vector<std::string>& caseFiles, std::uint64_t seed)
{
    std::vector<FamilyData> out;
    for (auto& in : inputsOf(familySpecs, caseFiles, seed, true, FileCheck::Whole))
    {
        FamilyData f{in.name, in.reason, in.source, in.input, {}, {}, {}, in.makeup, in.seed};
        in.stream(
            std::max<std::size_t>(1, in.count),
            [&](CaseChunk& chunk)
            {
                for (std::size_t i = 0; i < chunk.size(); ++i)
                {
                    f.cases.push_back(std::move(chunk.cases[i]));
                    f.labels.push_back(std::move(chunk.labels[i]));
                    f.rejected.push_back(std::move(chunk.rejected[i]));
                }
            },
            {}, 1);
        out.push_back(std::move(f));
    }
    return out;
}

} // namespace gjkval
