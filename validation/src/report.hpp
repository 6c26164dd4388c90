// Renderings of report.json: report.md and the terminal summary (both from the JSON only).
#pragma once

#include "common.hpp"

#include <string>

namespace gjkval
{

std::string renderMarkdown(const Json& report);
std::string terminalSummary(const Json& report);

} // namespace gjkval
