// Renderings of report.json: report.md and the terminal summary (both from the JSON only).
#pragma once

#include "common/common.hpp"

#include <string>

namespace gjkval
{

// report.json's format name and version (docs/report-schema.md): written by the campaign, checked
// by compare. report.js and the HTML renderer (validation/html/) spell it again: they are not C++.
inline constexpr const char* kReportSchema = "gjk-report/1";

std::string renderMarkdown(const Json& report);
// The run's summary for the terminal, the report page's first screen in text: the result and what
// was run; one line per variant (cases, failures or contract violations, worst error / bound or
// contract violation, ns/query, verdict); the judged variants' failures per family, failed make-up
// checks and rejected cases; throughput and the truth's fallbacks. `verbose`: also every family x
// variant, and every family x variant that failed or broke its contract.
std::string terminalSummary(const Json& report, bool verbose = false);

// The result in words, from report.json's exit_code: "PASS (exit code 0)", "FAIL (exit code 1):
// 3 judged variant failure(s); make-up checks of 2 family(ies) failed" (either or both causes),
// "INPUT ERROR (exit code 2): 3 case(s) rejected, none judged".
std::string resultText(const Json& report);

// kExitCodeTable (common.hpp) rendered: the --help footer (plain text, lines of at most `width`
// characters) and the Markdown table of docs/cli.md (a test checks the docs hold it).
std::string exitCodesHelp(std::size_t width = 80);
std::string exitCodesMarkdown();

} // namespace gjkval
