// gjk-validate compare: two reports of the same campaign, every statistic that got worse or
// better, exit 1 when one regressed beyond its tolerance (report/compare.hpp states the rule).
#include "report/compare.hpp"
#include "commands/command_line.hpp"
#include "commands/fault.hpp"
#include "commands/outputs.hpp"
#include "common/output.hpp"
#include "report/report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace gjkval
{
namespace
{
struct Options
{
    std::string oldPath, newPath, json, md, html;
    std::string relTol, percentileTol, timingTol;
    bool timing = false, allVariants = false, strict = false, allowDifferentInputs = false;
};

// A tolerance option: a finite decimal number >= lo.
double parseTolerance(const char* option, const std::string& text, double lo)
{
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || v < lo)
        throw InputError(
            fmt::format("{} '{}': expected a number >= {:g}", option, excerpt(text), lo));
    return v;
}

int compareCommand(const Options& o, CLI::App& sub)
{
    CompareOptions c;
    c.relTol = parseTolerance("--rel-tol", o.relTol, 0);
    c.percentileTol = parseTolerance("--percentile-tol", o.percentileTol, 0);
    c.timingTol = parseTolerance("--timing-tol", o.timingTol, 1);
    c.timing = o.timing;
    c.allVariants = o.allVariants;
    c.strict = o.strict;
    c.allowDifferentInputs = o.allowDifferentInputs;
    if (sub.count("--json") > 0)
        checkOutputFile("--json", o.json);
    if (sub.count("--md") > 0)
        checkOutputFile("--md", o.md);
    if (sub.count("--html") > 0)
    {
#if !defined(GJK2D_HAVE_HTML)
        throw InputError("--html: this build has no HTML renderer (validation/html/)");
#endif
        checkOutputFile("--html", o.html);
    }
    testFault();
    const Json oldReport = readReport(o.oldPath);
    const Json newReport = readReport(o.newPath);
    c.oldName = fmt::format("OLD '{}'", shownPath(o.oldPath));
    c.newName = fmt::format("NEW '{}'", shownPath(o.newPath));
    const Comparison result = compareReports(oldReport, newReport, c);
    std::fputs(compareText(result).c_str(), stdout);
    writeOutput("json", o.json, [&] { return compareJson(result).dump(1) + "\n"; });
    writeOutput("markdown", o.md, [&] { return compareMarkdown(result); });
#if defined(GJK2D_HAVE_HTML)
    writeOutput("html", o.html, [&] { return compareHtml(result); });
#endif
    flushStdout();
    return result.exitCode;
}
} // namespace

Subcommand addCompare(CLI::App& app, const CommandLine&)
{
    auto o = std::make_shared<Options>();
    const CompareOptions d;
    o->relTol = fmt::format("{:g}", d.relTol);
    o->percentileTol = fmt::format("{:g}", d.percentileTol);
    o->timingTol = fmt::format("{:g}", d.timingTol);
    auto* cmp = app.add_subcommand(
        "compare", "Compare two reports of the same campaign (OLD, NEW: report directories or "
                   "report.json files): every family x variant statistic that got worse or "
                   "better; exit 1 when one regressed beyond its tolerance (docs/cli.md, "
                   "'compare').");
    cmp->footer(exitCodesHelp());
    cmp->add_option("OLD", o->oldPath, "the report before the change")
        ->required()
        ->type_name("PATH");
    cmp->add_option("NEW", o->newPath, "the report after the change")
        ->required()
        ->type_name("PATH");
    cmp->add_option("--rel-tol", o->relTol,
                    "errors' max and mean regress when NEW > OLD x (1 + this) + floor")
        ->type_name("X")
        ->capture_default_str();
    cmp->add_option("--percentile-tol", o->percentileTol,
                    "errors' p99 and p999 regress when NEW > OLD x (1 + this) + floor (0.3: a "
                    "one-bin move passes, two bins fail)")
        ->type_name("X")
        ->capture_default_str();
    cmp->add_flag("--timing", o->timing, "compare ns_per_query too (as NEW / OLD)");
    cmp->add_option("--timing-tol", o->timingTol,
                    "with --timing: ns_per_query regresses when NEW / OLD > this")
        ->type_name("X")
        ->capture_default_str();
    cmp->add_flag("--all-variants", o->allVariants,
                  "comparison variants' regressions fail too (default: judged variants only)");
    cmp->add_flag("--strict", o->strict,
                  "a family or variant present in one report only fails the comparison");
    cmp->add_flag("--allow-different-inputs", o->allowDifferentInputs,
                  "compare the families both reports ran alike instead of refusing (exit 2)");
    cmp->add_option("--json", o->json, "also write the comparison as JSON (gjk-compare/1)")
        ->type_name("FILE");
    cmp->add_option("--md", o->md, "also write the comparison as Markdown")->type_name("FILE");
    cmp->add_option("--html", o->html, "also write the comparison as an HTML page")
        ->type_name("FILE");
    return {cmp, [o, cmp] { return compareCommand(*o, *cmp); }};
}

} // namespace gjkval
