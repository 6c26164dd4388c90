// gjk-validate explain: one case in detail (inputs, each variant's result and trace, the exact
// result, the errors), as text, CaseDetail JSON or the iteration viewer page.
#include "report/explain.hpp"
#include "commands/case_choice.hpp"
#include "commands/command_line.hpp"
#include "commands/fault.hpp"
#include "commands/outputs.hpp"
#include "commands/plugin_options.hpp"
#include "common/output.hpp"
#include "evaluate/evaluate.hpp"
#include "implementations/variants.hpp"
#include "inputs/cases.hpp"
#include "inputs/families.hpp"
#include "report/pages.hpp"
#include "report/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

#if defined(GJK2D_HAVE_HTML)
#include "gjk_html/html.hpp"
#endif

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;

struct Options
{
    CaseChoice which;
    std::string exTruth = "filtered";
    std::string exJson, exHtml, exVariants = "all", exRoute = "default";
    PluginOptions plugins;
};

// The variants, the exact route and the outputs, checked before any work (InputError).
EvalContext checkedContext(const Options& o, const std::string& exFile, CLI::App& sub)
{
    EvalContext ctx;
    ctx.variants = selectVariants(o.exVariants, o.plugins, ShippedPlugins::OnlyNamed);
    ctx.pluginTimeoutSeconds = o.plugins.timeoutSeconds;
    ctx.exactOptions.route = parseRouteOrThrow(o.exRoute);
    ctx.exactOptions.filter = parseTruthOrThrow(o.exTruth);
    checkCaseSource(o.which, exFile);
    if (sub.count("--json") > 0)
        checkOutputFile("--json", o.exJson);
    if (sub.count("--html") > 0)
    {
#if !defined(GJK2D_HAVE_HTML)
        throw InputError("--html: this build has no HTML renderer (validation/html/)");
#endif
        checkOutputFile("--html", o.exHtml);
    }
    return ctx;
}

int explainCommand(Options& o, const CommandLine&, CLI::App& sub)
{
    const std::string exFile = caseFileArgument(o.which, "explain");
    const std::uint64_t seedValue = parseSeed(o.which.seed);
    const EvalContext ctx = checkedContext(o, exFile, sub);
    testFault();
    const FoundCase found = findCase(o.which, exFile, seedValue, "explain");
    CaseOutcome outcome = evaluateCase(found.c, ctx);
    const Json detail = caseDetail(found.c, found.family, ctx, outcome, "explain");
    std::fputs(explainText(detail).c_str(), stdout);
    if (!o.exJson.empty())
        writeFileAtomic(o.exJson, detail.dump(1) + "\n");
#if defined(GJK2D_HAVE_HTML)
    if (!o.exHtml.empty())
        writeFileAtomic(o.exHtml, gjk_html::renderCase(forHtmlRenderer(detail)));
#endif
    flushStdout();
    return outcome.rejected.empty() ? kExitPass : kExitInput;
}
} // namespace

Subcommand addExplain(CLI::App& app, const CommandLine& line)
{
    auto o = std::make_shared<Options>();
    auto* ex = app.add_subcommand(
        "explain", "Explain one case: inputs, each variant's result and iteration trace, "
                   "the exact result, the errors. Cases come from FILE, or from --family.");
    ex->footer(exitCodesHelp());
    addCaseChoiceOptions(*ex, o->which);
    ex->add_option("--variants", o->exVariants, "variants to run")->capture_default_str();
    addPluginOptions(*ex, o->plugins, ShippedPlugins::OnlyNamed);
    ex->add_option("--exact-route", o->exRoute, "exact construction")->capture_default_str();
    ex->add_option("--truth", o->exTruth, kTruthHelp)->capture_default_str();
    ex->add_option("--json", o->exJson,
                   "write the CaseDetail JSON (docs/report-schema.md) to this file");
    ex->add_option("--html", o->exHtml, "write the iteration viewer page to this file");
    return {ex, [o, line, ex] { return explainCommand(*o, line, *ex); }};
}

} // namespace gjkval
