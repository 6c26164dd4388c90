// gjk-validate compare's renderings of a Comparison: the terminal table, Markdown, HTML and JSON.
#include "report/compare.hpp"

#if defined(GJK2D_HAVE_HTML)
#include "gjk_html/html.hpp" // styleSheet, escapeHtml
#endif

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace gjkval
{
namespace
{
// What the contract rows count, in the words every verdict uses (never "fails" for an
// implementation with a contract of its own).
constexpr const char* kContractLegend =
    "contract_violations: answers that break their implementation's own contract (gjk2d's own "
    "variants: their failures); beyond_bound_keeping_contract: answers that keep it but are "
    "outside gjk2d's bound (a measured accuracy, not a failure)\n";

// Whether the rows shown hold the contract rows (and the legend says what they count).
bool showsContractRows(const std::vector<const CompareRow*>& shown)
{
    return std::any_of(shown.begin(), shown.end(),
                       [](const CompareRow* r)
                       {
                           return r->statistic == "contract_violations" ||
                                  r->statistic == "beyond_bound_keeping_contract";
                       });
}

std::string formatValue(const CompareRow& r, double v)
{
    if (std::isnan(v))
        return "n/a";
    if (r.rule == CompareRule::Presence)
        return v != 0 ? "present" : "absent";
    if (r.higherIsBetter && r.rule == CompareRule::Count && r.statistic != "interval.contains")
        return v != 0 ? "true" : "false";
    if (r.rule == CompareRule::Count && std::isfinite(v))
        return fmt::format("{:.0f}", v);
    return fmt::format("{:.4g}", v);
}

std::string changeText(const CompareRow& r)
{
    switch (r.change)
    {
    case Change::Regressed:
        return r.gates ? "REGRESSED" : "regressed (comparison variant, not gated)";
    case Change::Worse:
        return "worse, within tolerance";
    case Change::OnlyOld:
    case Change::OnlyNew:
        return std::string(changeName(r.change)) + (r.gates ? " (FAILS: --strict)" : "");
    case Change::NotCompared:
        return "not compared: " + r.note;
    default:
        return changeName(r.change);
    }
}

// Rows shown: not Same, failing ones first, then not-gated regressions, presence and
// not-compared rows, worse within tolerance, better.
std::vector<const CompareRow*> shownRows(const Comparison& c)
{
    auto rank = [](const CompareRow& r)
    {
        if (r.fails())
            return 0;
        switch (r.change)
        {
        case Change::Regressed:
            return 1;
        case Change::OnlyOld:
        case Change::OnlyNew:
        case Change::NotCompared:
            return 2;
        case Change::Worse:
            return 3;
        default:
            return 4;
        }
    };
    std::vector<const CompareRow*> v;
    for (const auto& r : c.rows)
        if (r.change != Change::Same)
            v.push_back(&r);
    std::stable_sort(v.begin(), v.end(),
                     [&](const CompareRow* a, const CompareRow* b) { return rank(*a) < rank(*b); });
    return v;
}

std::string limitText(const CompareRow& r)
{
    if ((r.change != Change::Worse && r.change != Change::Regressed) ||
        r.rule == CompareRule::Presence)
        return "";
    if (r.rule == CompareRule::Timing)
        return fmt::format("{:.4g} ({})", r.limit, r.note);
    return formatValue(r, r.limit);
}

std::string summaryText(const Comparison& c)
{
    std::size_t notGated = 0;
    for (const auto& r : c.rows)
        notGated += r.change == Change::Regressed && !r.gates ? 1 : 0;
    return fmt::format("{} statistic(s) compared: {} regression(s) that fail, {} beyond tolerance "
                       "in comparison variants (not gated), {} worse within tolerance, {} better, "
                       "{} the same",
                       c.rows.size(), c.failing(), notGated, c.count(Change::Worse),
                       c.count(Change::Better), c.count(Change::Same));
}

std::string resultLine(const Comparison& c)
{
    return c.exitCode == kExitPass ? "result: NO REGRESSION (exit code 0)"
                                   : fmt::format("result: REGRESSION (exit code {}): {} "
                                                 "statistic(s) beyond tolerance",
                                                 c.exitCode, c.failing());
}

std::string optionsText(const CompareOptions& o)
{
    std::string s = fmt::format("tolerances: max and mean x(1 + {:g}), p99 and p999 x(1 + {:g}), "
                                "counts none",
                                o.relTol, o.percentileTol);
    if (o.timing)
        s += fmt::format(", ns_per_query x{:g}", o.timingTol);
    s += o.allVariants ? "; every variant gates" : "; judged variants gate";
    if (o.strict)
        s += "; --strict";
    if (o.allowDifferentInputs)
        s += "; --allow-different-inputs";
    return s;
}
} // namespace

std::string compareText(const Comparison& c)
{
    const auto shown = shownRows(c);
    const std::string headers[] = {"family", "variant", "statistic", "OLD",
                                   "NEW",    "limit",   "change"};
    std::vector<std::array<std::string, 7>> table;
    table.push_back(
        {headers[0], headers[1], headers[2], headers[3], headers[4], headers[5], headers[6]});
    for (const CompareRow* r : shown)
        table.push_back({r->family.empty() ? "-" : excerpt(r->family),
                         r->variant.empty() ? "-" : excerpt(r->variant) + (r->judged ? "" : " (c)"),
                         r->statistic, formatValue(*r, r->oldValue), formatValue(*r, r->newValue),
                         limitText(*r), changeText(*r)});
    std::array<std::size_t, 7> width{};
    for (const auto& row : table)
        for (std::size_t i = 0; i < row.size(); ++i)
            width[i] = std::max(width[i], row[i].size());
    std::string s = fmt::format("compare: {}\n     vs: {}\n{}\n", c.options.oldName,
                                c.options.newName, optionsText(c.options));
    if (shown.empty())
        s += "every statistic is the same\n";
    else
    {
        for (const auto& row : table)
        {
            std::string line;
            for (std::size_t i = 0; i < row.size(); ++i)
                line += i + 1 < row.size() ? fmt::format("{:<{}}  ", row[i], width[i]) : row[i];
            s += line + "\n";
        }
        if (std::any_of(shown.begin(), shown.end(), [](const CompareRow* r) { return !r->judged; }))
            s += "(c): a comparison variant (reported; gates only with --all-variants)\n";
        if (showsContractRows(shown))
            s += kContractLegend;
    }
    s += summaryText(c) + "\n" + resultLine(c) + "\n";
    return s;
}

std::string compareMarkdown(const Comparison& c)
{
    auto cell = [](std::string v)
    {
        std::string out;
        for (char ch : v)
            out += ch == '|' ? std::string("\\|") : std::string(1, ch);
        return out;
    };
    std::string s =
        fmt::format("# gjk-validate compare\n\n- {}\n- {}\n- {}\n\n", cell(c.options.oldName),
                    cell(c.options.newName), optionsText(c.options));
    const auto shown = shownRows(c);
    if (shown.empty())
        s += "Every statistic is the same.\n\n";
    else
    {
        s += "| family | variant | statistic | OLD | NEW | limit | change |\n"
             "|---|---|---|---|---|---|---|\n";
        for (const CompareRow* r : shown)
            s += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", cell(excerpt(r->family)),
                             cell(excerpt(r->variant) + (r->judged ? "" : " (comparison)")),
                             cell(r->statistic), formatValue(*r, r->oldValue),
                             formatValue(*r, r->newValue), cell(limitText(*r)),
                             cell(changeText(*r)));
        s += "\n";
        if (showsContractRows(shown))
            s += std::string(kContractLegend) + "\n";
    }
    s += summaryText(c) + ".\n\n**" + resultLine(c) + "**\n";
    return s;
}

// The HTML page takes the report page's style sheet and escape (validation/html/).
#if defined(GJK2D_HAVE_HTML)
// A row's class in report.css: a failing regression, a change for the worse, for the better.
static const char* rowClass(const CompareRow& r)
{
    switch (r.change)
    {
    case Change::Regressed:
        return r.fails() ? "regressed" : "worse";
    case Change::Worse:
        return "worse";
    case Change::Better:
        return "better";
    default:
        return "other";
    }
}

std::string compareHtml(const Comparison& c)
{
    const auto esc = [](const std::string& text) { return gjk_html::escapeHtml(text); };
    // The palette and the row classes are report.css's (the report page's), inlined.
    const std::string_view css = gjk_html::styleSheet();
    std::string s = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>gjk-validate "
        "compare</title>\n<style>\n{}\nbody{{padding:2em}}</style></head><body>\n"
        "<h1>gjk-validate compare</h1>\n<p class=\"result {}\">{}</p>\n"
        "<ul><li>{}</li><li>{}</li><li>{}</li></ul>\n<p>{}.</p>\n",
        css, c.exitCode != kExitPass ? "fail" : "pass", esc(resultLine(c)), esc(c.options.oldName),
        esc(c.options.newName), esc(optionsText(c.options)), esc(summaryText(c)));
    const auto shown = shownRows(c);
    if (shown.empty())
        s += "<p>Every statistic is the same.</p>\n";
    else
    {
        s += "<table class=\"data "
             "compact\"><tr><th>family</th><th>variant</th><th>statistic</th><th>OLD</th>"
             "<th>NEW</th><th>limit</th><th>change</th></tr>\n";
        for (const CompareRow* r : shown)
            s += fmt::format("<tr class=\"{}\"><td>{}</td><td>{}</td><td>{}</td><td class=\"num\">"
                             "{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td>{}</td>"
                             "</tr>\n",
                             rowClass(*r), esc(excerpt(r->family)),
                             esc(excerpt(r->variant) + (r->judged ? "" : " (comparison)")),
                             esc(r->statistic), esc(formatValue(*r, r->oldValue)),
                             esc(formatValue(*r, r->newValue)), esc(limitText(*r)),
                             esc(changeText(*r)));
        s += "</table>\n";
    }
    return s + "</body></html>\n";
}
#endif

Json compareJson(const Comparison& c)
{
    const CompareOptions& o = c.options;
    Json j;
    j["schema"] = "gjk-compare/1";
    j["old"] = o.oldName;
    j["new"] = o.newName;
    j["options"] = {{"rel_tol", o.relTol},
                    {"percentile_tol", o.percentileTol},
                    {"timing", o.timing},
                    {"timing_tol", o.timingTol},
                    {"all_variants", o.allVariants},
                    {"strict", o.strict},
                    {"allow_different_inputs", o.allowDifferentInputs}};
    j["inputs_differ"] = c.inputsDiffer;
    j["compared"] = c.rows.size();
    j["same"] = c.count(Change::Same);
    Json rows = Json::array();
    for (const CompareRow* r : shownRows(c))
    {
        static constexpr const char* kRules[] = {"count", "exact", "percentile", "timing",
                                                 "presence"};
        rows.push_back({{"family", r->family},
                        {"variant", r->variant},
                        {"judged", r->judged},
                        {"statistic", r->statistic},
                        {"rule", kRules[int(r->rule)]},
                        {"old", optNum(r->oldValue)},
                        {"new", optNum(r->newValue)},
                        {"limit", limitText(*r).empty() ? Json(nullptr) : num(r->limit)},
                        {"change", changeName(r->change)},
                        {"gates", r->gates},
                        {"fails", r->fails()},
                        {"note", r->note}});
    }
    j["rows"] = std::move(rows); // every row that is not "same", failing ones first
    j["regressions"] = c.failing();
    j["exit_code"] = c.exitCode;
    return j;
}

} // namespace gjkval
