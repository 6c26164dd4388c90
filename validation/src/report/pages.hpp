// The report directory's pages: report.json, report.md, worst-cases.json and index.html, written
// from a campaign's result (its report.json and worst cases), whichever command made it.
#pragma once

#include "common/common.hpp"
#include "common/output.hpp"
#include "inputs/cases.hpp"

#include <string>
#include <vector>

namespace gjkval
{

// What a campaign leaves for its report directory.
struct CampaignReport
{
    Json report;                  // report.json (docs/report-schema.md)
    std::vector<Case> worstCases; // worst-cases.json
    std::vector<std::string> worstComments;
};

// A report (or any of the runner's JSON) as the HTML renderer takes it: nlohmann::json, keys
// sorted, the very value nlohmann::json::parse(j.dump()) gives, without the text between (a
// non-finite double dumps as null, a nonnegative integer parses as unsigned): cheaper than a
// pretty dump and its parse, which the report's size made visible in `run`'s wall time. Throws
// std::logic_error on a binary value, which the runner never makes.
nlohmann::json forHtmlRenderer(const Json& j);

// Up front, before any work: throws InputError when outDir cannot hold a report (empty, not a
// directory, holds files that are not a report's, parent not creatable or not writable).
void checkReportDir(const std::string& outDir);

// Writes report.json, report.md, worst-cases.json and index.html (when the HTML renderer is built
// in) into `out`, staged beside the report directory (cases.jsonl is streamed there during the
// run), then swaps it in: the directory holds this run or the previous one, never a mix. Throws
// OutputError (exit code 5) when a write fails. Returns the absolute path of the page to open
// (index.html, or report.md without the renderer).
std::string writeReportPages(const CampaignReport& result, StagedDir& out);

} // namespace gjkval
