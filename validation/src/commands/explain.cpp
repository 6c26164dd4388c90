// gjk-validate explain: one case in detail (inputs, each variant's result and trace, the exact
// result, the errors), as text, CaseDetail JSON or the iteration viewer page.
#include "report/explain.hpp"
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
// "3 case(s): 'a', 'b', 'c'": at most kNamesListed names, then "and N more".
std::string someNames(const std::vector<std::string>& names)
{
    constexpr std::size_t kNamesListed = 8;
    std::string s = fmt::format("{} case(s)", names.size());
    for (std::size_t i = 0; i < std::min(names.size(), kNamesListed); ++i)
        s += fmt::format("{}'{}'", i == 0 ? ": " : ", ", excerpt(names[i]));
    if (names.size() > kNamesListed)
        s += fmt::format(" and {} more", names.size() - kNamesListed);
    return s;
}

namespace fs = std::filesystem;

struct Options
{
    std::vector<std::string> exPositional;
    std::string exTruth = "filtered";
    std::string exName, exFamily, exJson, exHtml, exVariants = "all", exRoute = "default",
                                                  exSeed = "1";
    PluginOptions plugins;
};

// `explain FILE NAME`, `explain FILE --name NAME`, `explain --family F NAME`,
// `explain --family F --name NAME`: anything more is refused. Returns FILE (empty with --family)
// and sets o.exName.
std::string caseFileArgument(Options& o)
{
    std::string exFile;
    const std::size_t wanted = (o.exFamily.empty() ? 1 : 0) + (o.exName.empty() ? 1 : 0);
    if (o.exPositional.size() > wanted)
        throw InputError(fmt::format("explain: unexpected argument '{}' (give FILE NAME, or "
                                     "--family F NAME)",
                                     excerpt(o.exPositional[wanted])));
    std::size_t next = 0;
    if (o.exFamily.empty() && next < o.exPositional.size())
        exFile = o.exPositional[next++];
    if (o.exName.empty() && next < o.exPositional.size())
        o.exName = o.exPositional[next++];
    if (o.exFamily.empty() && exFile.empty())
        throw InputError("explain: give a case FILE or --family");
    if (o.exName.empty())
        throw InputError("explain: which case? give its name (explain FILE NAME)");
    return exFile;
}

// The variants, the exact route and the outputs, checked before any work (InputError).
EvalContext checkedContext(const Options& o, const std::string& exFile, CLI::App& sub)
{
    EvalContext ctx;
    ctx.variants = selectVariants(o.exVariants, o.plugins, ShippedPlugins::OnlyNamed);
    ctx.pluginTimeoutSeconds = o.plugins.timeoutSeconds;
    ctx.exactOptions.route = parseRouteOrThrow(o.exRoute);
    ctx.exactOptions.filter = parseTruthOrThrow(o.exTruth);
    if (!o.exFamily.empty())
        checkFamilies({o.exFamily}, false);
    else
        checkCaseFiles({exFile});
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

// The case named o.exName, from --family or the case file.
struct FoundCase
{
    Case c;
    std::string family, rejected; // rejected: the case file's reason, if it holds one
    bool ok = false;
};

FoundCase findInFamily(const Options& o, std::uint64_t seed, std::vector<std::string>& names)
{
    FoundCase found;
    for (auto& f : generateFamilies(o.exFamily, seed))
        for (auto& c : f.cases)
        {
            names.push_back(c.name);
            if (!found.ok && c.name == o.exName)
                found = {c, f.name, {}, true};
        }
    return found;
}

FoundCase findInFile(const Options& o, const std::string& exFile, std::vector<std::string>& names)
{
    FoundCase found;
    CaseFile file = readCaseFile(exFile);
    found.family = "file:" + fs::path(exFile).filename().string();
    for (auto& e : file.entries)
    {
        names.push_back(e.c.name);
        if (!found.ok && e.c.name == o.exName)
        {
            found.c = e.c;
            found.rejected = e.rejected;
            found.ok = true;
        }
    }
    return found;
}

// InputError when no case has the name (listing some that do exist) or the case is rejected.
FoundCase findCase(const Options& o, const std::string& exFile, std::uint64_t seed)
{
    std::vector<std::string> names; // every name looked at, for the error when none matches
    FoundCase found =
        o.exFamily.empty() ? findInFile(o, exFile, names) : findInFamily(o, seed, names);
    if (!found.ok)
        throw InputError(fmt::format(
            "explain: no case named '{}' in {}; it has {}", excerpt(o.exName),
            o.exFamily.empty() ? shownPath(exFile) : "--family " + o.exFamily, someNames(names)));
    if (!found.rejected.empty())
        throw InputError(
            fmt::format("explain: case '{}' is rejected: {}", excerpt(o.exName), found.rejected));
    return found;
}

int explainCommand(Options& o, const CommandLine&, CLI::App& sub)
{
    const std::string exFile = caseFileArgument(o);
    const std::uint64_t seedValue = parseSeed(o.exSeed);
    const EvalContext ctx = checkedContext(o, exFile, sub);
    testFault();
    const FoundCase found = findCase(o, exFile, seedValue);
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
    ex->add_option("args", o->exPositional,
                   "FILE NAME (the gjk-cases/1 file and the case's name), or NAME alone with "
                   "--family; NAME may be given as --name instead");
    ex->add_option("--name,-n", o->exName, "the case's name");
    ex->add_option("--family", o->exFamily,
                   "take the case from this generated family instead of a file");
    ex->add_option("--seed", o->exSeed, "seed for --family, 0..2^64-1")->capture_default_str();
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
