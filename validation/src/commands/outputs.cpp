// The subcommands' outputs (commands/outputs.hpp).
#include "commands/outputs.hpp"

#include "campaign/campaign.hpp"
#include "common/output.hpp"
#include "implementations/plugins.hpp"
#include "report/pages.hpp"
#include "report/report.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace gjkval
{
namespace fs = std::filesystem;

void writeOutput(const char* label, const std::string& path,
                 const std::function<std::string()>& text)
{
    if (path.empty())
        return;
    writeFileAtomic(path, text());
    std::printf("%s: %s\n", label, path.c_str());
}

void flushStdout()
{
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
        throw OutputError(fmt::format("standard output: write failed: {}", std::strerror(errno)));
}
void printPluginLogs(const std::vector<PluginLog>& logs, const fs::path& dir)
{
    for (const PluginLog& l : logs)
    {
        const std::string how =
            l.capped
                ? fmt::format("at least {} bytes (the log's cap; the rest was dropped)", l.bytes)
                : fmt::format("{} bytes", l.bytes);
        std::fprintf(stderr,
                     "gjk-validate: plugin %s printed %s on its stdout and stderr: see %s\n",
                     l.plugin.c_str(), how.c_str(), (dir / l.file).c_str());
    }
}

void writeReportAndSummary(const CampaignReport& result, StagedDir& out, bool verbose)
{
    const std::vector<PluginLog> logs = finishPluginLogs(); // into the directory before its commit
    const std::string page = writeReportPages(result, out);
    printPluginLogs(logs, out.dir());
    std::fputs(terminalSummary(result.report, verbose).c_str(), stdout);
    std::printf("report: %s\n", page.c_str());
    flushStdout();
}

void writeJoinedPerCase(const Campaign& camp, std::size_t chunkCases,
                        const std::vector<std::string>& files, StagedDir& out,
                        const std::string& hint)
{
    std::vector<std::ifstream> in(files.size());
    std::vector<std::istream*> inOrder;
    for (std::size_t s = 0; s < files.size(); ++s)
    {
        in[s].open(files[s], std::ios::binary);
        if (!in[s])
            throw InputError(fmt::format("{}: cannot open: {}{}", shownPath(files[s]),
                                         std::strerror(errno), hint));
        inOrder.push_back(&in[s]);
    }
    std::ofstream joined(out.staged("cases.jsonl"), std::ios::binary);
    joinPerCase(camp.report, chunkCases, inOrder, joined);
    joined.close();
    if (!joined)
        throw OutputError(fmt::format("{}/cases.jsonl: write failed: {}",
                                      excerpt(out.dir().string()), std::strerror(errno)));
}

} // namespace gjkval
