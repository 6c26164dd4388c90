// gjk-validate compare: two report.json files (OLD, NEW) of the same campaign, every family x
// variant statistic that got worse or better, and whether a change beyond its tolerance fails
// the comparison (docs/cli.md, "`compare`: gate a change on two reports").
//
// The tolerance rule (one home; docs/cli.md states it with the reasons):
//   counts (failures, misclassifications, non-finite, ..., iterations.max, the exit code, and a
//   family's make-up and pass flags read as 1/0) regress on any change for the worse;
//   an error statistic regresses when NEW > OLD * (1 + tol) + floor, tol = relTol for the exact
//   values (max, mean) and percentileTol for the percentiles (upper bin edges, 10 bins per
//   decade), floor = 10^log10_min of its histogram (the smallest value the bins resolve);
//   ns_per_query (with timing only) regresses when NEW / OLD > timingTol.
// Only judged variants (judged in OLD or NEW), the families' make-up and pass, and the exit code
// gate; comparison variants' regressions are reported but gate only with allVariants.
// Improvements are listed as "better" and never fail.
#pragma once

#include "common/common.hpp"

#include <string>
#include <vector>

namespace gjkval
{

struct CompareOptions
{
    double relTol = 0.1;        // max and mean (exact values): 10 %
    double percentileTol = 0.3; // p99, p999: one bin (x 10^0.1 = 1.259) passes, two fail
    bool timing = false;        // compare ns_per_query too
    double timingTol = 1.25;    // NEW / OLD ns_per_query beyond this regresses
    bool allVariants = false;   // comparison variants gate too
    bool strict = false;        // a family or variant in one report only fails the comparison
    bool allowDifferentInputs = false; // compare the families both ran alike instead of refusing
    std::string oldName = "OLD", newName = "NEW"; // how messages name the two reports
};

// How a statistic is judged (the tolerance rule above).
enum class CompareRule
{
    Count,      // any change for the worse regresses
    Exact,      // NEW > OLD * (1 + relTol) + floor
    Percentile, // NEW > OLD * (1 + percentileTol) + floor
    Timing,     // NEW / OLD > timingTol; within [1 / timingTol, timingTol] counts as the same
    Presence,   // a family or variant in one report only
};

enum class Change
{
    Same,
    Better,
    Worse,      // worse, within tolerance
    Regressed,  // worse beyond tolerance (fails the comparison when the row gates)
    OnlyOld,    // the family or variant is in OLD only
    OnlyNew,    // ... in NEW only
    NotCompared // a value missing or not a number on one side, or (families) different inputs
};
const char* changeName(Change c); // "same", "better", "worse", "regressed", "only in OLD", ...

struct CompareRow
{
    std::string family;    // empty for the report's own rows (exit_code)
    std::string variant;   // empty for a family's own rows (makeup_ok, pass, make-up checks)
    bool judged = true;    // the variant is judged in OLD or NEW (true for non-variant rows)
    std::string statistic; // "errors.abs.max", "failures", "makeup: overlapping fraction", ...
    CompareRule rule = CompareRule::Count;
    bool higherIsBetter = false;       // interval.contains, makeup_ok, pass
    double oldValue = 0, newValue = 0; // NaN: absent or null (flags: 1 true, 0 false)
    double limit = 0; // the NEW value beyond which the row regresses (Timing: the ratio)
    Change change = Change::Same;
    bool gates = true; // a Regressed row (or, with strict, OnlyOld/OnlyNew) fails the comparison
    std::string note;  // NotCompared and Presence rows: why
    bool fails() const;
};

struct Comparison
{
    CompareOptions options;
    std::vector<CompareRow> rows; // every statistic compared, in report order
    bool inputsDiffer = false;    // some family ran differently (only with allowDifferentInputs)
    int exitCode = kExitPass;     // kExitFail when some row fails()
    std::size_t count(Change c) const;
    std::size_t failing() const;
};

// Reads a report: PATH is report.json or a report directory holding it. InputError (exit 2), one
// line naming the file: missing, unreadable, not JSON (with line and column), not a kReportSchema
// report.
Json readReport(const std::string& path);

// The comparison, a pure function of the two reports. InputError (naming options.oldName and
// newName) when they cannot be compared: a different schema, a report without families, or
// different inputs (unless allowDifferentInputs).
Comparison compareReports(const Json& oldReport, const Json& newReport,
                          const CompareOptions& options = {});

// Renderings: the terminal table (every row that is not Same, worst first, then the result
// line), the same as Markdown, and JSON (schema gjk-compare/1, every row).
std::string compareText(const Comparison& c);
std::string compareMarkdown(const Comparison& c);
// The same as a self-contained HTML page (no script, no download): the table with regressed rows
// in red and better ones in green, the result first. Only in a build with the HTML renderer
// (validation/html/: its style sheet and its escape); `compare --html` is refused without it.
std::string compareHtml(const Comparison& c);
Json compareJson(const Comparison& c);

} // namespace gjkval
