// gjk-validate repro: one case and one shipped peer's variant as a standalone program in that
// peer's own language and API, with no gjk2d in it, for the peer's maintainers (docs/peers.md,
// "Repro programs"). The case is chosen as `explain` chooses it (commands/case_choice.hpp) and
// evaluated as `explain` evaluates it; the program is the peer's template (its folder's peer.txt
// `repro` lines, implementations/peers.hpp) with the case's numbers, the report's answer and the
// exact truth filled in.
//
// A template's placeholders are @NAME@ (capitals, digits, _):
//   VARIANT CASE FAMILY COMMAND FILE STEM SCALAR the variant, the case, the command that wrote it,
//                                                the written file's name and its name without the
//                                                extension, float or double
//   A_COUNT A_POINTS A_PAIRS A_RADIUS A_PX A_PY A_C A_S
//                                                shape A as the variant is given it (B_... for B;
//                                                a variant given world points: its world case's,
//                                                inputs/geometry.hpp, worldCase):
//                                                A_POINTS is "x0, y0, x1, y1, ...", A_PAIRS
//                                                "{x0, y0}, {x1, y1}, ..." (C and C++)
//   REPORT_STATUS REPORT_DISTANCE REPORT_AX REPORT_AY REPORT_BX REPORT_BY REPORT_INVALID
//                                                the variant's answer as gjk-validate reports it
//   EXACT_DISTANCE EXACT_OVERLAP EXACT_SQUARED EXACT_AX EXACT_AY EXACT_BX EXACT_BY
//                                                the exact truth of the inputs the variant is given
//   EXACT_SIGNED EXACT_SIGNED_DISTANCE EXACT_PAX EXACT_PAY EXACT_PBX EXACT_PBY
//                                                its signed distance and penetration pair, for a
//                                                variant whose contract says penetration
//                                                (EXACT_SIGNED true; else false and zeros)
// and the NAME=VALUE pairs of the template's peer.txt line. One name is the command's own:
// WHEN=overlap writes the template only for a case whose shapes overlap (planck's bug report is
// about its overlap answers). An unknown placeholder in a shipped template is our bug
// (std::logic_error, exit 4).
//
// Numbers: the shortest decimal that reads back as the same double (or float, for a float
// variant: the case's doubles rounded to float, as gjk-validate hands them to it). Every reader
// these programs use (a C or C++ compiler, JavaScript's Number, Python's float) rounds a decimal
// correctly to nearest, so the program gets the very bits the adapter got. In C and C++ a float's
// literal has the suffix f: read as a double first, then rounded to float, a decimal could round
// twice.
#include "commands/case_choice.hpp"
#include "commands/command_line.hpp"
#include "commands/fault.hpp"
#include "commands/outputs.hpp"
#include "commands/plugin_options.hpp"
#include "common/output.hpp"
#include "evaluate/evaluate.hpp"
#include "implementations/peers.hpp"
#include "implementations/plugins.hpp"
#include "implementations/prepared.hpp"
#include "implementations/variants.hpp"
#include "inputs/geometry.hpp"
#include "report/report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;

struct Options
{
    CaseChoice which;
    std::string variant, outDir, truth = "filtered", route = "default";
    PluginOptions plugins;
};

// The one plugin variant --variants names, with its templates (InputError otherwise).
struct Chosen
{
    const VariantInfo* v = nullptr;
    std::vector<FoundRepro> templates;
};

Chosen chooseVariant(const Options& o)
{
    if (o.variant.empty() || o.variant.find(',') != std::string::npos || o.variant == "all")
        throw InputError(fmt::format("repro: --variants names one peer variant, got '{}' "
                                     "(gjk-validate list --peers lists them)",
                                     excerpt(o.variant)));
    const auto selected = selectVariants(o.variant, o.plugins, ShippedPlugins::OnlyNamed);
    Chosen c;
    for (const VariantInfo* v : selected)
        if (v->name == o.variant)
            c.v = v;
    if (!c.v || !c.v->plugin)
        throw InputError(fmt::format("repro: '{}' is one of gjk2d's own variants; repro writes "
                                     "a program for a peer's (gjk-validate list --peers)",
                                     excerpt(o.variant)));
    c.templates = reproTemplates(c.v->plugin->path, c.v->name);
    if (c.templates.empty())
        throw InputError(fmt::format(
            "repro: variant '{}' ({}) has no repro template: only the shipped peers have one "
            "(validation/plugins/<folder>/peer.txt, `repro` lines)",
            excerpt(o.variant), shownPath(c.v->plugin->path)));
    return c;
}

// The number as the program's source holds it (the header comment): `cFamily` for C and C++.
std::string literal(double v, Scalar s, bool cFamily, const char* what)
{
    if (!std::isfinite(v) || (s == Scalar::Float && !std::isfinite(float(v))))
        throw InputError(fmt::format("repro: {} is {} in {}: no program can be given it", what, v,
                                     scalarName(s)));
    std::string t = s == Scalar::Float ? fmt::format("{}", float(v)) : fmt::format("{}", v);
    if (t.find_first_of(".e") == std::string::npos)
        t += ".0"; // "1" -> "1.0" (a float literal in C), "-0" -> "-0.0" (keeps the sign)
    if (s == Scalar::Float && cFamily)
        t += "f";
    return t;
}

// A JSON number of the detail as text: the shortest round-trip double, or nan/inf as written.
std::string shown(const Json& j)
{
    if (j.is_number())
        return fmt::format("{}", j.get<double>());
    return j.is_string() ? j.get<std::string>() : j.dump();
}

using Values = std::map<std::string, std::string>;

// Shape `k` ("A" or "B") as the variant is given it: the case's numbers in its scalar type.
void shapeValues(Values& out, const char* k, const CasePoints<double>& pd,
                 const gjk::Transform<double>& xd, double r, Scalar s, bool cFamily)
{
    const std::string p = k;
    auto lit = [&](double v, const std::string& what)
    { return literal(v, s, cFamily, ("shape " + p + "'s " + what).c_str()); };
    std::string points, pairs;
    for (std::size_t i = 0; i < pd.size(); ++i)
    {
        const std::string x = lit(pd[i].x, fmt::format("x{}", i)),
                          y = lit(pd[i].y, fmt::format("y{}", i));
        points += (i ? ", " : "") + x + ", " + y;
        pairs += (i ? ", {" : "{") + x + ", " + y + "}";
    }
    out[p + "_COUNT"] = std::to_string(pd.size());
    out[p + "_POINTS"] = points;
    out[p + "_PAIRS"] = pairs;
    out[p + "_RADIUS"] = lit(r, "radius");
    out[p + "_PX"] = lit(xd.p.x, "px");
    out[p + "_PY"] = lit(xd.p.y, "py");
    out[p + "_C"] = lit(xd.q.c, "c");
    out[p + "_S"] = lit(xd.q.s, "s");
}

// Every placeholder's value for template `t` (the header comment).
Values valuesFor(const FoundRepro& t, const VariantInfo& v, const Case& c, const Json& detail,
                 const std::string& file, const CommandLine& line)
{
    const std::string tpl = t.line->path;
    const bool cFamily = tpl.ends_with(".c.in") || tpl.ends_with(".cpp.in");
    Values out;
    out["VARIANT"] = v.name;
    out["CASE"] = c.name;
    out["FAMILY"] = detail["family"].get<std::string>();
    out["COMMAND"] = line.text();
    out["FILE"] = file;
    out["STEM"] = fs::path(file).stem().string();
    out["SCALAR"] = scalarName(v.scalar);
    // The inputs, as the host hands them to the plugin (implementations/servers.cpp: the prepared
    // case's double or float copies; adapter.cpp, adapterCaseText: a variant given world points
    // gets the world case). The float copies are the doubles rounded; literal() rounds.
    const bool world = contractOf(v).input == InputForm::World;
    const std::optional<Case> w = world ? worldCase(c, v.scalar == Scalar::Float) : std::nullopt;
    if (world && !w) // the variant was not skipped (reproCommand): its world case fits
        throw std::logic_error("repro: the world case of a case the variant ran on does not fit");
    const PreparedCase p = prepare(world ? *w : c);
    shapeValues(out, "A", p.ad, p.xad, p.rad, v.scalar, cFamily);
    shapeValues(out, "B", p.bd, p.xbd, p.rbd, v.scalar, cFamily);
    const Json& a = detail["variants"][v.name];
    out["REPORT_STATUS"] = a.contains("skipped") ? "skipped: " + a["skipped"].get<std::string>()
                           : a.contains("plugin_status") ? a["plugin_status"].get<std::string>()
                                                         : "ok";
    const bool answered = out["REPORT_STATUS"] == "ok";
    out["REPORT_DISTANCE"] = answered ? shown(a["distance"]) : "none";
    for (const auto& [key, field, i] : {std::tuple{"REPORT_AX", "pointA", 0},
                                        {"REPORT_AY", "pointA", 1},
                                        {"REPORT_BX", "pointB", 0},
                                        {"REPORT_BY", "pointB", 1}})
        out[key] = answered ? shown(a[field][i]) : "none";
    out["REPORT_INVALID"] =
        answered && a["invalid"].is_string() ? a["invalid"].get<std::string>() : "none";
    const Json& e = world ? detail["world_input"][scalarName(v.scalar)]["exact"]
                          : detail[v.scalar == Scalar::Float && detail.contains("exact_float_input")
                                       ? "exact_float_input"
                                       : "exact"];
    out["EXACT_DISTANCE"] = shown(e["distance"]);
    out["EXACT_OVERLAP"] = e["overlap"].get<bool>() ? "true" : "false";
    out["EXACT_SQUARED"] = e["squared"].get<std::string>();
    out["EXACT_AX"] = shown(e["witnessA"][0]);
    out["EXACT_AY"] = shown(e["witnessA"][1]);
    out["EXACT_BX"] = shown(e["witnessB"][0]);
    out["EXACT_BY"] = shown(e["witnessB"][1]);
    // The exact signed distance and penetration pair, where the detail has them (a
    // variant whose contract says penetration): EXACT_SIGNED "false" and zeros otherwise.
    const bool hasSigned = e.contains("signed_distance") && e["signed_distance"].is_number();
    out["EXACT_SIGNED"] = hasSigned ? "true" : "false";
    out["EXACT_SIGNED_DISTANCE"] = hasSigned ? shown(e["signed_distance"]) : "0";
    for (const auto& [key, field, i] : {std::tuple{"EXACT_PAX", "penetrationA", 0},
                                        {"EXACT_PAY", "penetrationA", 1},
                                        {"EXACT_PBX", "penetrationB", 0},
                                        {"EXACT_PBY", "penetrationB", 1}})
        out[key] = hasSigned && e.contains(field) ? shown(e[field][i]) : "0";
    std::istringstream extra(t.line->values);
    for (std::string pair; extra >> pair;)
        out[pair.substr(0, pair.find('='))] = pair.substr(pair.find('=') + 1);
    return out;
}

std::string readTemplate(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    if (!in)
        throw InputError(fmt::format("repro: cannot read the template {}", shownPath(path)));
    return s.str();
}

// The template with every @NAME@ replaced.
std::string fill(const std::string& text, const Values& values, const std::string& path)
{
    static const std::regex placeholder("@([A-Z][A-Z0-9_]*)@");
    std::string out;
    auto last = text.cbegin();
    for (std::sregex_iterator it(text.begin(), text.end(), placeholder), end; it != end; ++it)
    {
        const auto found = values.find((*it)[1].str());
        if (found == values.end())
            throw std::logic_error(fmt::format("the repro template {} has the unknown placeholder "
                                               "@{}@",
                                               path, (*it)[1].str()));
        out.append(last, (*it)[0].first);
        out += found->second;
        last = (*it)[0].second;
    }
    out.append(last, text.cend());
    return out;
}

// "planck-1.5.0-random-1": the variant and the case, every other character a '-'.
std::string fileStem(const std::string& variant, const std::string& caseName)
{
    std::string s = variant + "-" + caseName;
    for (char& ch : s)
        if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '_' || ch == '-'))
            ch = '-';
    return s;
}

// "fcl/repro.cpp.in" -> ".cpp": the template's own extension, without ".in".
std::string extensionOf(const std::string& templatePath)
{
    std::string name = fs::path(templatePath).filename().string();
    name.resize(name.size() - 3);
    const auto dot = name.find('.');
    return dot == std::string::npos ? std::string() : name.substr(dot);
}

// DIR exists as a directory or can be made (InputError).
void checkOutDir(const std::string& dir)
{
    if (dir.empty())
        throw InputError("--out: the output directory is empty");
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir, ec))
        throw InputError(fmt::format("--out {}: not a directory that can be written in{}",
                                     excerpt(dir), ec ? ": " + ec.message() : std::string()));
}

int reproCommand(Options& o, const CommandLine& line)
{
    const std::string file = caseFileArgument(o.which, "repro");
    const std::uint64_t seed = parseSeed(o.which.seed);
    const Chosen chosen = chooseVariant(o);
    EvalContext ctx;
    ctx.variants = {chosen.v};
    ctx.pluginTimeoutSeconds = o.plugins.timeoutSeconds;
    ctx.exactOptions.route = parseRouteOrThrow(o.route);
    ctx.exactOptions.filter = parseTruthOrThrow(o.truth);
    checkCaseSource(o.which, file);
    checkOutDir(o.outDir);
    testFault();
    const FoundCase found = findCase(o.which, file, seed, "repro");
    const CaseOutcome outcome = evaluateCase(found.c, ctx);
    if (!outcome.rejected.empty())
        throw InputError(fmt::format("repro: case '{}' is rejected: {}", excerpt(found.c.name),
                                     outcome.rejected));
    const Json detail = caseDetail(found.c, found.family, ctx, outcome, "repro");
    // A case the variant does not take (a refusal, or inputs its scalar type cannot hold) has no
    // answer to reproduce; a crash, a hang or an error status has one worth a program.
    if (const Json& a = detail["variants"][chosen.v->name]; a.contains("skipped"))
        throw InputError(fmt::format("repro: {} does not take case '{}' ({}): nothing to reproduce",
                                     chosen.v->name, excerpt(found.c.name),
                                     a["skipped"].get<std::string>()));
    const std::string stem = fileStem(chosen.v->name, found.c.name);
    // Every file filled before any is written: a bad template writes nothing.
    std::vector<std::pair<std::string, std::string>> files;
    for (const FoundRepro& t : chosen.templates)
    {
        const std::string name = stem + extensionOf(t.line->path);
        const Values values = valuesFor(t, *chosen.v, found.c, detail, name, line);
        if (const auto when = values.find("WHEN"); when != values.end() &&
                                                   when->second == "overlap" &&
                                                   values.at("EXACT_OVERLAP") != "true")
        {
            std::printf("repro: %s is written for overlapping cases only: not for this one\n",
                        name.c_str());
            continue;
        }
        files.emplace_back(name, fill(readTemplate(t.path), values, t.line->path));
    }
    for (const auto& [name, text] : files)
        writeOutput("repro", (fs::path(o.outDir) / name).string(), [&text] { return text; });
    flushStdout();
    return kExitPass;
}
} // namespace

Subcommand addRepro(CLI::App& app, const CommandLine& line)
{
    auto o = std::make_shared<Options>();
    auto* sub = app.add_subcommand(
        "repro", "Write one case as a standalone program for one peer (its own language and API, "
                 "no gjk2d), which prints the peer's answer beside the exact one. The case as "
                 "explain takes it, from FILE or from --family.");
    sub->footer(exitCodesHelp());
    addCaseChoiceOptions(*sub, o->which);
    sub->add_option("--variants", o->variant,
                    "the one peer variant (gjk-validate list --peers), e.g. planck-1.5.0")
        ->required();
    addPluginOptions(*sub, o->plugins, ShippedPlugins::OnlyNamed);
    sub->add_option("--exact-route", o->route, "exact construction")->capture_default_str();
    sub->add_option("--truth", o->truth, kTruthHelp)->capture_default_str();
    sub->add_option("--out", o->outDir,
                    "the directory the program (and, for planck, its bug report) is written "
                    "into; made when missing, other files in it left alone")
        ->required();
    return {sub, [o, line] { return reproCommand(*o, line); }};
}

} // namespace gjkval
