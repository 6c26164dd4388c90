// What the subcommands write and print at their end: an output file with its line, the report
// with its summary and the plugins' logs, the shards' per-case files joined, and the check that
// standard output took it all.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gjkval
{

// When path is not empty: writes text() there whole (or leaves the file as it was) and prints
// "label: path".
void writeOutput(const char* label, const std::string& path,
                 const std::function<std::string()>& text);
// The last check of a command: what it printed reached standard output.
void flushStdout();
// run's and merge's last step: the report into `out` (committed, with the plugins' logs), then
// the terminal summary (with every family x variant when `verbose`) and the page's path.
struct Campaign;
struct CampaignReport;
class StagedDir;
void writeReportAndSummary(const CampaignReport& result, StagedDir& out, bool verbose);
// One line on stderr per plugin that printed: how much, and its log in `dir`.
struct PluginLog;
void printPluginLogs(const std::vector<PluginLog>& logs, const std::filesystem::path& dir);
// merge's and mpirun's DIR/cases.jsonl: the shards' files (files[s] is shard s's) joined in case
// order (joinPerCase). InputError naming a file that cannot be opened, followed by `hint`.
void writeJoinedPerCase(const Campaign& camp, std::size_t chunkCases,
                        const std::vector<std::string>& files, StagedDir& out,
                        const std::string& hint = {});

} // namespace gjkval
