// HTML rendering of validation results. Both functions return a complete, self-contained
// HTML page: no network access, no external script, style sheet or font; opening the file is
// enough. The page's HTML, CSS and JavaScript live in validation/html/assets/ and are embedded at
// build time; the C++ side only inlines the JSON data, and the page's JavaScript draws everything
// (tables, SVG plots, the GJK iteration viewer) in the browser. See docs/report.md.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace gjk_html
{

// The full index.html for a report.json (docs/report-schema.md): context, summary table,
// speed-against-error plot, per-family histograms, and an iteration viewer for each of the report's
// worst cases. Missing optional fields are tolerated. `schema`: the report format the page is made
// for (gjkval::kReportSchema); the page warns when the data names another.
std::string renderReport(const nlohmann::json& report, std::string_view schema);

// A page with the iteration viewer for one CaseDetail (for `gjk-validate explain CASE --html`).
std::string renderCase(const nlohmann::json& caseDetail);

// The page's style sheet (assets/report.css), the one home of the pass/fail palette: other pages
// (gjk-validate compare --html) inline it and use its classes.
std::string_view styleSheet();

// Text as HTML: every '<', '>', '&' and '"' written as its entity, so that it is safe as element
// content and as a double-quoted attribute value. The one escape of the pages gjk2d writes (this
// renderer's and `gjk-validate compare --html`'s).
std::string escapeHtml(std::string_view text);

// The JSON text as inlined into the page's <script type="application/json" id="report-data">
// block: compact, invalid UTF-8 replaced by U+FFFD, and every '<', '>' and '&' written as a
// \u escape, so no "</script>" or "<!--" can end or disturb the block. The text is valid JSON and
// parses back to the same value. Exposed for tests.
std::string embedJson(const nlohmann::json& data);

} // namespace gjk_html
