// report.md and the terminal summary, rendered from report.json alone (the result line, the run's
// context, the variants, one table per family, the truth's fallbacks, the worst cases); and the
// exit codes' text for --help and the docs, from kExitCodeTable.
#include "report/report.hpp"

#include "statistics/stats.hpp" // kPathFields

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace gjkval
{
namespace
{
std::string g(const Json& v, const char* spec = "{:.3g}")
{
    if (v.is_number())
        return fmt::format(fmt::runtime(spec), v.get<double>());
    if (v.is_null())
        return "-";
    if (v.is_string())
        return v.get<std::string>();
    return v.dump();
}

std::string u(const Json& v)
{
    return v.is_number() ? std::to_string(v.get<std::uint64_t>()) : g(v);
}

std::uint64_t count(const Json& st, const char* key)
{
    return st.contains(key) && st[key].is_number() ? st[key].get<std::uint64_t>() : 0;
}

// Words of `text` in lines of at most `width` characters, each line starting with `indent`.
std::string wrap(const std::string& text, const std::string& indent, std::size_t width)
{
    std::string out, line = indent;
    std::size_t i = 0;
    while (i < text.size())
    {
        const std::size_t end = std::min(text.find(' ', i), text.size());
        const std::string word = text.substr(i, end - i);
        if (line.size() > indent.size() && line.size() + 1 + word.size() > width)
        {
            out += line + "\n";
            line = indent;
        }
        line += (line.size() > indent.size() ? " " : "") + word;
        i = end + 1;
    }
    return out + line + "\n";
}

// Variant name -> judged (a report without the field: every variant judged).
std::map<std::string, bool> judgedMap(const Json& r)
{
    std::map<std::string, bool> m;
    for (const auto& v : r["variants"])
        m[v["name"].get<std::string>()] = !v.contains("judged") || v["judged"].get<bool>();
    return m;
}

bool isJudged(const std::map<std::string, bool>& m, const std::string& name)
{
    const auto it = m.find(name);
    return it == m.end() || it->second;
}

// Variant name -> held to gjk2d's own contract (variants[].contract.own; a report without
// contracts: every variant). The others declared theirs: their verdict is said in its words,
// "breaks its contract" and "outside gjk2d's bound", never "fails".
std::map<std::string, bool> ownMap(const Json& r)
{
    std::map<std::string, bool> m;
    for (const auto& v : r["variants"])
        m[v["name"].get<std::string>()] = !v.contains("contract") || !v["contract"].is_object() ||
                                          v["contract"].value("own", true);
    return m;
}

// A family x variant's contract violations (for gjk2d's own contract, its failures; a report
// written before contracts: its failures).
std::uint64_t violations(const Json& st)
{
    if (st.contains("contract_violations") && st["contract_violations"].is_object())
        return st["contract_violations"]["count"].get<std::uint64_t>();
    return st["failures"].get<std::uint64_t>();
}

// Judged answers that keep their contract but are beyond gjk2d's bound (0 before contracts).
std::uint64_t outsideBound(const Json& st)
{
    return st.contains("beyond_bound_keeping_contract")
               ? st["beyond_bound_keeping_contract"].get<std::uint64_t>()
               : 0;
}

// "N (k reason, ...)": the contract violations with their reasons.
std::string violationCounts(const Json& st)
{
    std::string out = std::to_string(violations(st)), reasons;
    if (st.contains("contract_violations") && st["contract_violations"].is_object())
        for (const auto& [reason, n] : st["contract_violations"]["reasons"].items())
            reasons += fmt::format("{}{} {}", reasons.empty() ? "" : ", ", u(n), reason);
    return reasons.empty() ? out : out + " (" + reasons + ")";
}

// Comparison variants' contract violations over all families (gjk2d's own: failures): counted,
// never judged.
std::uint64_t comparisonFailures(const Json& r, const std::map<std::string, bool>& judged)
{
    std::uint64_t n = 0;
    for (const auto& f : r["families"])
        for (const auto& [name, st] : f["variants"].items())
            if (!isJudged(judged, name))
                n += violations(st);
    return n;
}

std::string mdEscape(std::string s)
{
    std::string o;
    for (char c : s)
    {
        if (c == '|')
            o += "\\|";
        else
            o += c;
    }
    return o;
}
// A plugin variant's refusals and incidents, appended to the skipped column: " (3 refused, 1
// crashed)"; empty for gjk2d's variants (older reports have no such keys).
std::string pluginCounts(const Json& st)
{
    std::string out;
    for (const char* key : {"refused", "crashed", "hung", "plugin_errors"})
        if (st.contains(key) && st[key].get<std::uint64_t>() > 0)
            out += fmt::format("{}{} {}", out.empty() ? "" : ", ", st[key].get<std::uint64_t>(),
                               std::string(key) == "plugin_errors" ? "error status" : key);
    return out.empty() ? out : " (" + out + ")";
}

// Invalid answers (docs/judgement.md, "Failures"): "N (k reason, ...)", "0" when none; "-" for a
// report written before the witness judgement.
std::string invalidCounts(const Json& st)
{
    if (!st.contains("invalid"))
        return "-";
    std::string out = u(st["invalid"]), reasons;
    if (st.contains("invalid_reasons"))
        for (const auto& [reason, n] : st["invalid_reasons"].items())
            if (n.get<std::uint64_t>() > 0)
                reasons += fmt::format("{}{} {}", reasons.empty() ? "" : ", ", u(n), reason);
    return reasons.empty() ? out : out + " (" + reasons + ")";
}

// A number of report.json, a non-finite one written as its string ("inf", "-inf", "nan"); NaN for
// null or anything else.
double numberOf(const Json& v)
{
    if (v.is_number())
        return v.get<double>();
    if (v.is_string() && (v == "inf" || v == "-inf"))
        return v == "inf" ? HUGE_VAL : -HUGE_VAL;
    return std::nan("");
}

// One variant over the families, as the terminal's variant table and report.md's timing table
// give it: counts summed; the largest error / bound (or, a variant without a bound, normalised
// error); ns/query (plain and, gjk2d's own, on prepared shapes) and ns/shape to prepare as the
// timed families' figures weighted by their cases (NaN: not measured in any family).
struct VariantTotals
{
    std::uint64_t cases = 0, failures = 0, misclassified = 0, violations = 0, outsideBound = 0;
    double worstBound = std::nan(""), worstNorm = std::nan("");
    double nsPerQuery = std::nan(""), prepareNsPerShape = std::nan("");
    double preparedNsPerQuery = std::nan("");
};

VariantTotals variantTotals(const Json& r, const std::string& name)
{
    VariantTotals t;
    double ns[2] = {0, 0}, prepare[2] = {0, 0}, prepared[2] = {0, 0}; // figure x cases, cases
    for (const auto& f : r["families"])
    {
        if (!f["variants"].contains(name))
            continue;
        const Json& st = f["variants"][name];
        const std::uint64_t n = count(st, "cases");
        t.cases += n;
        t.failures += count(st, "failures");
        t.misclassified += count(st, "false_overlap") + count(st, "false_separation");
        t.violations += violations(st);
        t.outsideBound += outsideBound(st);
        const Json& e = st["errors"];
        if (e.contains("bound_ratio"))
            t.worstBound = std::fmax(t.worstBound, numberOf(e["bound_ratio"]["max"]));
        if (e.contains("normalized"))
            t.worstNorm = std::fmax(t.worstNorm, numberOf(e["normalized"]["max"]));
        for (auto [key, sums] :
             {std::pair{"ns_per_query", ns}, std::pair{"prepare_ns_per_shape", prepare},
              std::pair{"prepared_ns_per_query", prepared}})
            if (st.contains(key) && st[key].is_number() && n > 0)
            {
                sums[0] += st[key].get<double>() * double(n);
                sums[1] += double(n);
            }
    }
    if (ns[1] > 0)
        t.nsPerQuery = ns[0] / ns[1];
    if (prepare[1] > 0)
        t.prepareNsPerShape = prepare[0] / prepare[1];
    if (prepared[1] > 0)
        t.preparedNsPerQuery = prepared[0] / prepared[1];
    return t;
}

// A variant's penetration blocks over the families (families[].variants[].penetration: a
// penetration contract's depths on overlapping shapes): counts summed, each largest error with its
// case and family. `any`: some family has the block.
struct PenetrationTotals
{
    bool any = false;
    std::uint64_t cases = 0, violations = 0, outsideBound = 0;
    struct Largest
    {
        double value = std::nan("");
        std::string caseName;
    } abs, rel, ratio;
};

PenetrationTotals penetrationTotals(const Json& r, const std::string& name)
{
    PenetrationTotals t;
    for (const auto& f : r["families"])
    {
        if (!f["variants"].contains(name) || !f["variants"][name].contains("penetration"))
            continue;
        const Json& p = f["variants"][name]["penetration"];
        t.any = true;
        t.cases += count(p, "cases");
        t.violations += count(p, "contract_violations");
        t.outsideBound += count(p, "beyond_bound_keeping_contract");
        for (auto [key, largest] : {std::pair{"abs", &t.abs}, std::pair{"rel", &t.rel},
                                    std::pair{"bound_ratio", &t.ratio}})
        {
            const Json& h = p[key];
            if (count(h, "count") == 0 ||
                !(numberOf(h["max"]) > largest->value || std::isnan(largest->value)))
                continue;
            largest->value = numberOf(h["max"]);
            largest->caseName = h.value("max_case", "");
        }
    }
    return t;
}

// The penetration verdict in words, first on its line: by gjk2d's own contract "pass" or "FAIL"
// ("fails" for a comparison variant); by a declared one "breaks its contract", "outside gjk2d's
// depth bound" (keeping it) or "keeps its contract".
std::string penetrationVerdict(const PenetrationTotals& t, bool judgedVariant, bool ownContract)
{
    if (ownContract)
        return t.violations > 0 ? (judgedVariant ? "FAIL" : "fails")
                                : (judgedVariant ? "pass" : "passes");
    if (t.violations > 0)
        return judgedVariant ? "FAIL: breaks its contract" : "breaks its contract";
    return t.outsideBound > 0 ? "outside gjk2d's depth bound" : "keeps its contract";
}

// "x (case)", or "-" without one.
std::string largestText(const PenetrationTotals::Largest& l)
{
    return std::isnan(l.value) ? "-" : fmt::format("{:.3g} ({})", l.value, l.caseName);
}

// The terminal's one line under a variant that has the block, verdict first, at most 100 wide: the
// overlapping cases, the answers that broke the contract, those outside gjk2d's depth bound keeping
// it, the worst depth error / depth bound (the table's legend says so).
std::string penetrationLine(const PenetrationTotals& t, bool judgedVariant, bool ownContract)
{
    return fmt::format("    penetration: {}: {} overlapping, {} broke, {} outside, worst {}\n",
                       penetrationVerdict(t, judgedVariant, ownContract), t.cases, t.violations,
                       t.outsideBound,
                       std::isnan(t.ratio.value) ? "-" : fmt::format("{:.3g}", t.ratio.value));
}

// The penetration words of a variant that has the block, verdict first, with each largest error's
// case (report.md).
std::string penetrationWords(const PenetrationTotals& t, bool judgedVariant, bool ownContract)
{
    return fmt::format("penetration: {}: {} overlapping case(s), {} contract violation(s), {} "
                       "outside gjk2d's depth bound keeping it; largest depth error/bound {}, "
                       "error {}, relative error {}",
                       penetrationVerdict(t, judgedVariant, ownContract), t.cases, t.violations,
                       t.outsideBound, largestText(t.ratio), largestText(t.abs),
                       largestText(t.rel));
}

// Whether variants[].timing says gjk2d's own variant: the plain query, nothing prepared for it.
bool ownTiming(const Json& v)
{
    return v["timing"].value("preparation", "") == "none" && !v.contains("plugin");
}

// Whether gjk2d's own variant was timed on prepared shapes too (variants[].timing.prepared.timed).
bool preparedTimed(const Json& v)
{
    const Json& t = v["timing"];
    return t.contains("prepared") && t["prepared"].is_object() &&
           t["prepared"].value("timed", false);
}

// What a variant's ns/query includes (variants[].timing, docs/report-schema.md), in words; "" for a
// report written before the field. gjk2d's own variant: the plain query and, with a prepared form
// (timing.prepared.timed), both figures (`totals`: variantTotals), else why it has none (a report
// written before timing.prepared: that the plain query takes the points as given).
std::string timingWords(const Json& v, const VariantTotals& totals)
{
    if (!v.contains("timing") || !v["timing"].is_object())
        return "";
    const Json& t = v["timing"];
    if (!ownTiming(v))
        return t.value("includes", "") +
               (t.value("timed_by", "") == "adapter" ? "; timed by the adapter" : "");
    if (!t.contains("prepared") || !t["prepared"].is_object())
        return "no preparation: the plain query takes the points as given";
    const Json& p = t["prepared"];
    if (!preparedTimed(v))
        return "the plain query, the points as given; " + p.value("includes", "");
    const auto ns = [](double x) { return std::isnan(x) ? "-" : fmt::format("{:.1f}", x); };
    return fmt::format("plain: {} ns/query, the points as given; prepared: {} ns/query, {}",
                       ns(totals.nsPerQuery), ns(totals.preparedNsPerQuery),
                       p.value("includes", ""));
}

} // namespace

namespace
{
// The result line and the run's context block: date, host, build, seed, elapsed, throughput,
// inputs.
std::string contextMarkdown(const Json& r, const std::map<std::string, bool>& judged)
{
    const Json& c = r["context"];
    std::string s = "# GJK validation report\n\n";
    s += fmt::format("**Result: {}** (judged variants only: comparison variants' "
                     "{} contract violations (gjk2d's own variants': failures) are shown, not "
                     "judged)\n\n",
                     resultText(r), comparisonFailures(r, judged));
    s += "| | |\n|---|---|\n";
    for (const char* k :
         {"date", "host", "compiler", "flags", "build_type", "batch_isa", "git_revision", "command",
          "seed", "threads", "cases_total", "cases_rejected", "exact_route", "truth"})
        if (c.contains(k))
            s += fmt::format("| {} | `{}` |\n", k, mdEscape(g(c[k], "{}")));
    if (c.contains("elapsed_s"))
    {
        std::string e;
        for (const auto& [k, v] : c["elapsed_s"].items())
            e += fmt::format("{} {:.2f} s, ", k, v.get<double>());
        s += fmt::format("| elapsed | {} |\n", e.substr(0, e.size() - 2));
    }
    if (c.contains("throughput"))
    {
        const Json& t = c["throughput"];
        s += fmt::format(
            "| throughput | exact {:.0f} cases/s, GJK evaluation {:.0f} cases/s, witness checks "
            "{:.0f} cases/s, GJK query {} ns (mean of family medians) |\n",
            t["exact_cases_per_s"].get<double>(), t["gjk_cases_per_s"].get<double>(),
            t["witness_cases_per_s"].get<double>(), g(t["gjk_ns_per_query_mean"], "{:.1f}"));
    }
    if (c.contains("plugins")) // every plugin whose variants ran: file, kind, library, variants
        for (const auto& p : c["plugins"])
        {
            std::string names;
            for (const auto& n : p["variants"])
                names += (names.empty() ? "" : ", ") + n.get<std::string>();
            const std::string lib = p["library"].get<std::string>();
            s += fmt::format("| plugin | `{}` ({}{}): {} |\n",
                             mdEscape(p["file"].get<std::string>()),
                             mdEscape(p["kind"].get<std::string>()),
                             lib.empty() ? "" : ", " + mdEscape(lib), mdEscape(names));
        }
    s += "\nInputs: ";
    for (const auto& in : c["inputs"])
        s += in.contains("family")
                 ? fmt::format("`{}` x{}; ", in["family"].get<std::string>(), u(in["count"]))
                 : fmt::format("`{}` x{}; ", in["file"].get<std::string>(), u(in["count"]));
    return s + "\n";
}

// "; given world points rounded to float (SOURCE)" for a variant given its cases' world points
// (variants[].input), else "".
std::string givenWorld(const Json& v)
{
    if (!v.contains("input") || !v["input"].is_object() || v["input"].value("form", "") != "world")
        return "";
    return "; given " + mdEscape(v["input"].value("given", std::string("world points")));
}

// Each implementation with a contract of its own, or given world points: what it promises (its
// overlap answer and tolerance, with their sources), what it is given, what its distance is held
// to, and its worst contract violation (the case to give `gjk-validate explain` or `repro`).
std::string contractsMarkdown(const Json& r)
{
    std::string s;
    for (const auto& v : r["variants"])
    {
        if (!v.contains("contract") || (v["contract"].value("own", true) && givenWorld(v).empty()))
            continue;
        const Json& c = v["contract"];
        const Json& w =
            v.contains("worst_contract_violation") ? v["worst_contract_violation"] : Json(nullptr);
        s += fmt::format("- **{}**: on overlap `{}` ({}){}; judged by {}; worst contract "
                         "violation: {}\n",
                         v["name"].get<std::string>(), c["overlap"].get<std::string>(),
                         mdEscape(c["overlap_source"].get<std::string>()), givenWorld(v),
                         mdEscape(c["judged_by"].get<std::string>()),
                         w.is_object()
                             ? fmt::format("`{}` ({}, {}, excess {})", w["case"].get<std::string>(),
                                           w["family"].get<std::string>(),
                                           w["reason"].get<std::string>(), g(w["excess"]))
                             : "none");
    }
    return s.empty() ? s : "\n### Contracts\n\n" + s;
}

// Each variant whose contract says penetration: its depths over the families, verdict first.
std::string penetrationMarkdown(const Json& r, const std::map<std::string, bool>& judged)
{
    const auto own = ownMap(r);
    std::string s;
    for (const auto& v : r["variants"])
    {
        const std::string name = v["name"].get<std::string>();
        const PenetrationTotals t = penetrationTotals(r, name);
        if (t.any)
            s += fmt::format("- **{}**: {}\n", mdEscape(name),
                             mdEscape(penetrationWords(t, isJudged(judged, name),
                                                       !own.count(name) || own.at(name))));
    }
    return s.empty() ? s
                     : "\n### Penetration\n\nThe depth on overlapping shapes (exact signed "
                       "distance < 0) against the exact signed distance, per variant whose "
                       "contract says `penetration`.\n\n" +
                           s;
}

// What each variant's ns/query includes and who timed it (variants[].timing), and its preparation
// figure where it has one. gjk2d's own variants with a prepared form a row each, with both
// figures; those without one in a row per reason, in the order first met. Nothing for a report
// written before the field.
std::string timingMarkdown(const Json& r)
{
    std::string rows;
    std::vector<std::pair<std::string, std::vector<std::string>>> unprepared; // words, variants
    for (const auto& v : r["variants"])
    {
        const std::string name = v["name"].get<std::string>();
        const VariantTotals t = variantTotals(r, name);
        const std::string words = timingWords(v, t);
        if (words.empty())
            continue;
        if (ownTiming(v) && !preparedTimed(v))
        {
            auto at = std::find_if(unprepared.begin(), unprepared.end(),
                                   [&](const auto& u) { return u.first == words; });
            if (at == unprepared.end())
                at = unprepared.insert(unprepared.end(), {words, {}});
            at->second.push_back(name);
            continue;
        }
        rows += fmt::format(
            "| {} | {} | {} |\n", name, mdEscape(words),
            std::isnan(t.prepareNsPerShape) ? "-" : fmt::format("{:.1f}", t.prepareNsPerShape));
    }
    for (const auto& [words, names] : unprepared)
        rows += fmt::format("| gjk2d's own ({} variant{}: {}) | {} | - |\n", names.size(),
                            names.size() == 1 ? "" : "s", fmt::join(names, ", "), mdEscape(words));
    if (rows.empty())
        return rows;
    return "\n### Timing\n\n| variant | ns/query includes | ns/shape to prepare "
           "|\n|---|---|---|\n" +
           rows +
           "\nns/query and ns/shape to prepare: the families' figures weighted by their cases; "
           "preparing one shape is timed apart from the query (- when there is nothing to prepare "
           "or it was not timed). ns/query per family is in the families' tables; gjk2d's own "
           "variants give both figures, the plain query's (ns_per_query) and the same queries' on "
           "prepared shapes (prepared_ns_per_query).\n";
}

// The variants: judged or comparison, type, options (or the plugin's path) and the bound.
std::string variantsMarkdown(const Json& r, const std::map<std::string, bool>& judged)
{
    std::string s =
        "\n## Variants\n\nJudged variants decide the result; comparison variants (the "
        "alternatives the talk discusses) are run and reported, their failures not judged.\n\n"
        "| variant | judged | type | direction | stopping | frame | support | start | bound |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& v : r["variants"])
    {
        const Json& o = v["options"];
        const std::string name = v["name"].get<std::string>();
        if (v.contains("plugin")) // its own algorithm: only the bound it is compared with is ours
        {
            const std::string held =
                v.contains("contract")
                    ? "; judged by " + v["contract"]["judged_by"].get<std::string>()
                    : "";
            // Its frame: the case's transforms as given, or the world points it is given.
            const std::string frame = givenWorld(v).empty() ? "-" : "world points";
            s += fmt::format("| {} | {} | {} | plugin `{}` | - | {} | - | cold | {}{} |\n", name,
                             isJudged(judged, name) ? "judged (--judge)" : "comparison",
                             v["type"].get<std::string>(),
                             mdEscape(v["plugin"]["path"].get<std::string>()), frame,
                             mdEscape(v["bound"]["formula"].get<std::string>()), mdEscape(held));
            continue;
        }
        s += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", name,
                         isJudged(judged, name) ? "judged" : "comparison",
                         v["type"].get<std::string>(), g(o["direction"]), g(o["stopping"]),
                         g(o["frame"]), g(o["support"]),
                         v.contains("warm") && v["warm"].get<bool>() ? "warm" : "cold",
                         mdEscape(v["bound"]["formula"].get<std::string>()));
    }
    s += "\nErrors: `abs` = |d_gjk - d_exact|; `norm` = abs / (u R); `ulps` = abs / ulp(d_exact); "
         "float variants "
         "are judged against the exact distance of the float-rounded input. p99 values are bin "
         "upper edges.\n";
    s +=
        "\nThree classes of an answer: `breaks contract` counts the answers that break their "
        "implementation's own contract (that implementation's bug; for gjk2d's variants, their "
        "failures), with the reasons; `outside bound` counts the answers that keep their contract "
        "but are outside gjk2d's a-priori bound (a measured accuracy, not a failure); the rest are "
        "within gjk2d's bound. `false ovl`, `false sep`, `undecid.` and `invalid` are gjk2d's own "
        "rules applied to every answer (for an implementation with a contract of its own, a "
        "measure, not its verdict).\n";
    return s + contractsMarkdown(r) + penetrationMarkdown(r, judged) + timingMarkdown(r);
}

// One row of a family's table: one variant's counts, errors, iterations and speed.
std::string statsRow(const std::string& name, const Json& st, bool j)
{
    const Json& e = st["errors"];
    const std::uint64_t na =
        st.contains("not_applicable") ? st["not_applicable"].get<std::uint64_t>() : 0;
    return fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} "
                       "| {} | {} | {} | "
                       "{:.2f}/{} | {} | {} |\n",
                       j ? name : name + " (comparison)", u(st["cases"]),
                       violationCounts(st) + (j || violations(st) == 0 ? "" : " (not judged)"),
                       u(Json(outsideBound(st))), u(st["false_overlap"]), u(st["false_separation"]),
                       u(st["undecidable"]), u(st["nonfinite"]), invalidCounts(st),
                       u(st["iteration_limit"]), u(st["out_of_range"]),
                       u(st["skipped"]) + (na ? fmt::format(" ({} n/a)", na) : "") +
                           pluginCounts(st),
                       g(e["abs"]["max"]), g(e["abs"]["p99"]), g(e["normalized"]["max"]),
                       g(e["normalized"]["p99"]), g(e["ulps"]["p99"]), g(e["witness"]["max"]),
                       st["iterations"]["mean"].get<double>(), st["iterations"]["max"].get<int>(),
                       g(st["ns_per_query"], "{:.1f}"), g(st["ratio_to_baseline"], "{:.2f}"));
}

// A correctly rounded variant: the share of the queries each path decided.
std::string correctPathsLine(const std::string& name, const Json& st)
{
    const Json& p = st["correct"]["paths"];
    const double n = std::max(1.0, double(st["cases"].get<std::uint64_t>()));
    std::vector<std::string> shares;
    for (const PathField& f : kPathFields)
    {
        const char* k = gjk::correctPathName(f.path);
        // A path newer than the report is missing from it: 0.
        const std::uint64_t c = p.contains(k) ? p[k].get<std::uint64_t>() : 0;
        shares.push_back(fmt::format("{} {} ({:.4g} %)", k, u(Json(c)), 100.0 * double(c) / n));
    }
    return fmt::format("\n{}: paths {}; {} bit mismatches with the exact side.\n", name,
                       fmt::join(shares, ", "), u(st["correct"]["bit_mismatches"]));
}

// The truth's fallbacks (Stats' Truth rows, docs/exact.md "The filter") summed over `families`,
// read from the first variant of each type: every variant of a type is judged against the same
// truths (of the input as given, or rounded to float). Reports from before the rows have none.
std::string truthLines(const Json& r, const std::vector<const Json*>& families)
{
    std::string s;
    std::set<std::string> types;
    for (const auto& v : r["variants"])
    {
        const std::string type = v["type"].get<std::string>(), name = v["name"].get<std::string>();
        if (!types.insert(type).second)
            continue;
        std::map<std::string, std::uint64_t> sum;
        std::uint64_t cases = 0;
        for (const Json* f : families)
        {
            const Json& vs = (*f)["variants"];
            if (!vs.contains(name) || !vs[name].contains("truth"))
                continue;
            cases += vs[name]["cases"].get<std::uint64_t>();
            for (const auto& [k, n] : vs[name]["truth"].items())
                sum[k] += n.get<std::uint64_t>();
        }
        if (cases == 0)
            continue;
        std::vector<std::string> parts;
        for (const CountField& f : kCountFields)
            if (f.section == Section::Truth && f.member != &Stats::truthGmp)
                parts.push_back(fmt::format("{} {}", f.name, sum[f.name]));
        s +=
            fmt::format("truth of the {} input: GMP route on {} of {} cases ({:.3g} %); cases with "
                        "an exact decision: {}\n",
                        type, sum["gmp_route"], cases,
                        100.0 * double(sum["gmp_route"]) / double(cases), fmt::join(parts, ", "));
    }
    return s;
}

// One family: verdict, reason, make-up checks, the table of variants and the correct paths' shares.
std::string familyMarkdown(const Json& r, const Json& f, const std::map<std::string, bool>& judged)
{
    std::string s = fmt::format(
        "\n### {} — {} ({} cases{})\n\n", f["name"].get<std::string>(),
        f["pass"].get<bool>() ? "pass" : "**FAIL**", u(f["cases"]),
        f["rejected"].get<std::uint64_t>() ? fmt::format(", {} rejected", u(f["rejected"])) : "");
    s += mdEscape(f["reason"].get<std::string>()) + "\n\n";
    if (!f["makeup"].empty())
    {
        s += "Make-up: ";
        for (const auto& m : f["makeup"])
            s += fmt::format("{} = {} in [{}, {}] {}; ", m["check"].get<std::string>(),
                             g(m["value"]), g(m["min"]), g(m["max"]),
                             m.contains("skipped") ? "(not judged)"
                                                   : (m["ok"].get<bool>() ? "ok" : "**FAILED**"));
        s += "\n\n";
    }
    s += "| variant | cases | breaks contract | outside bound | false ovl | false sep | undecid. | "
         "nonfinite | invalid | iter lim | out of range | "
         "skipped | max abs | p99 abs | max norm | p99 norm | p99 ulps | max witness | iters "
         "mean/max | "
         "ns/query | x base |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& [name, st] : f["variants"].items())
        s += statsRow(name, st, isJudged(judged, name));
    for (const auto& [name, st] : f["variants"].items())
        if (st.contains("correct"))
            s += correctPathsLine(name, st);
    const std::string truth = truthLines(r, {&f});
    if (!truth.empty())
        s += "\n" + truth;
    return s;
}

// One worst case's cell for variant `n`: normalised error, stop reason, invalid, failed.
std::string worstCell(const Json& w, const std::string& n)
{
    if (!w.contains("variants") || !w["variants"].contains(n) ||
        w["variants"][n].contains("skipped"))
        return " - |";
    const Json& x = w["variants"][n];
    if (x.contains("plugin_status")) // a plugin's error status, crash or hang
        return fmt::format(" **{}** |", x["plugin_status"].get<std::string>());
    const bool invalid = x.contains("invalid") && x["invalid"].is_string();
    return fmt::format(" {}, {}{}{} |", g(x["errors"]["normalized"]), x["stop"].get<std::string>(),
                       invalid ? ", invalid: " + x["invalid"].get<std::string>() : "",
                       x["failed"].get<bool>() ? " **FAIL**" : "");
}

// The worst cases: how to replay them, and one row per case with a column per variant.
std::string worstMarkdown(const Json& r)
{
    std::string s = fmt::format(
        "\n## Worst cases\n\nReplay them with `gjk-validate run --cases {}`; inspect one with "
        "`gjk-validate explain {} NAME`.\n\n| family | case | exact distance |",
        r["worst_cases_file"].get<std::string>(), r["worst_cases_file"].get<std::string>());
    for (const auto& v : r["variants"])
        s += fmt::format(" {} (norm err, stop) |", v["name"].get<std::string>());
    s += "\n|---|---|---|";
    for (std::size_t i = 0; i < r["variants"].size(); ++i)
        s += "---|";
    s += "\n";
    for (const auto& w : r["worst"])
    {
        s += fmt::format("| {} | `{}` | {} |", w["family"].get<std::string>(),
                         w["name"].get<std::string>(),
                         w.contains("exact") ? g(w["exact"]["distance"], "{:.17g}") : "-");
        for (const auto& v : r["variants"])
            s += worstCell(w, v["name"].get<std::string>());
        s += "\n";
    }
    return s;
}
} // namespace

std::string renderMarkdown(const Json& r)
{
    const auto judged = judgedMap(r);
    std::string s = contextMarkdown(r, judged) + variantsMarkdown(r, judged);
    s += "\n## Families\n";
    for (const auto& f : r["families"])
        s += familyMarkdown(r, f, judged);
    if (!r["rejected"].empty())
    {
        s += "\n## Rejected cases\n\n";
        for (const auto& j : r["rejected"])
            s += fmt::format("- {}: {}\n", mdEscape(j["name"].get<std::string>()),
                             mdEscape(j["reason"].get<std::string>()));
    }
    return s + worstMarkdown(r);
}

namespace
{
bool isOwn(const std::map<std::string, bool>& m, const std::string& name)
{
    const auto it = m.find(name);
    return it == m.end() || it->second;
}

// A family x variant's verdict in words: FAIL (a judged variant broke its contract); for a
// comparison variant held to gjk2d's own contract "fails (not judged)", for one with a contract
// of its own "breaks its contract" or "outside gjk2d's bound" (keeping it), never "fails".
std::string verdictWords(const Json& st, bool judgedVariant, bool ownContract)
{
    if (violations(st) > 0)
        return judgedVariant
                   ? "  FAIL"
                   : (ownContract ? "  fails (not judged)" : "  breaks its contract (not judged)");
    return !ownContract && outsideBound(st) > 0 ? "  outside gjk2d's bound" : "";
}

// Every family x variant, a line each (run --verbose).
std::string terminalTable(const Json& r)
{
    // The columns: broke, the answers that break their implementation's contract (gjk2d's own
    // variants: failures); beyond, the answers that keep it but are beyond gjk2d's bound.
    std::string s;
    const auto judged = judgedMap(r), own = ownMap(r);
    s += fmt::format("{:<28} {:<21} {:>7} {:>5} {:>6} {:>5} {:>9} {:>9} {:>9} {:>9} {:>5} {:>8} "
                     "{:>6}\n",
                     "family", "variant", "cases", "broke", "beyond", "undec", "max abs",
                     "max norm", "p99 norm", "p99 ulps", "iters", "ns/query", "x base");
    for (const auto& f : r["families"])
    {
        bool first = true;
        for (const auto& [name, st] : f["variants"].items())
        {
            const Json& e = st["errors"];
            std::string fam = first ? f["name"].get<std::string>() : "";
            if (fam.size() > 28)
                fam = fam.substr(0, 25) + "...";
            s += fmt::format(
                "{:<28} {:<21} {:>7} {:>5} {:>6} {:>5} {:>9} {:>9} {:>9} {:>9} {:>5} {:>8} "
                "{:>6}{}\n",
                fam, name, u(st["cases"]), violations(st), outsideBound(st), u(st["undecidable"]),
                g(e["abs"]["max"], "{:.2g}"), g(e["normalized"]["max"], "{:.3g}"),
                g(e["normalized"]["p99"], "{:.2g}"), g(e["ulps"]["p99"], "{:.2g}"),
                st["iterations"]["max"].get<int>(), g(st["ns_per_query"], "{:.1f}"),
                g(st["ratio_to_baseline"], "{:.2f}"),
                verdictWords(st, isJudged(judged, name), isOwn(own, name)));
            first = false;
            const auto oor = st["out_of_range"].get<std::uint64_t>(),
                       skipped = st["skipped"].get<std::uint64_t>();
            const auto na =
                st.contains("not_applicable") ? st["not_applicable"].get<std::uint64_t>() : 0;
            if (oor || skipped)
                s += fmt::format("{:<28}   {} case(s) flagged out of range by GJK (not judged), {} "
                                 "skipped (input not representable in float: {}, not applicable: "
                                 "{})\n",
                                 "", oor, skipped, skipped - na, na);
        }
    }
    return s;
}

// One line for a family x variant with a contract of its own that breaks it or is outside gjk2d's
// bound: its violations with their reasons, the answers outside the bound that keep it, the
// penetration depths not judged yet.
std::string contractLine(const std::string& family, const std::string& name, const Json& st,
                         bool judgedVariant)
{
    const std::uint64_t broken = violations(st);
    const std::string what = broken == 0     ? "outside gjk2d's bound"
                             : judgedVariant ? "FAIL: breaks its contract"
                                             : "breaks its contract";
    std::string detail = fmt::format("{} contract violation(s)", violationCounts(st));
    detail += fmt::format(", {} outside gjk2d's bound keeping its contract", outsideBound(st));
    std::string fam = family.size() > 28 ? family.substr(0, 25) + "..." : family;
    return fmt::format("  {:<28} {:<21} {:<19} {}\n", fam, name, what, detail);
}

// One line for a family x variant that failed or gave a wrong overlap answer: what and how much.
std::string problemLine(const std::string& family, const std::string& name, const Json& st,
                        bool judgedVariant)
{
    const std::uint64_t fails = count(st, "failures");
    std::string what =
        fails == 0 ? "misclassified" : (judgedVariant ? "FAIL" : "fails (not judged)");
    std::string detail = fmt::format("{} failure(s)", fails);
    for (const auto& [key, label] :
         {std::pair{"false_overlap", "false overlap"},
          std::pair{"false_separation", "false separation"}, std::pair{"nonfinite", "non-finite"},
          std::pair{"iteration_limit", "iteration limit"}, std::pair{"crashed", "crashed"},
          std::pair{"hung", "hung"}, std::pair{"plugin_errors", "error status"},
          std::pair{"refused", "refused"}})
        if (count(st, key) > 0)
            detail += fmt::format(", {} {}", count(st, key), label);
    if (count(st, "invalid") > 0)
        detail += ", invalid " + invalidCounts(st);
    const Json& e = st["errors"];
    if (e.contains("bound_ratio"))
        detail += ", max error/bound " + g(e["bound_ratio"]["max"]);
    else
        detail += ", max norm " + g(e["normalized"]["max"]);
    std::string fam = family.size() > 28 ? family.substr(0, 25) + "..." : family;
    return fmt::format("  {:<28} {:<21} {:<19} {}\n", fam, name, what, detail);
}

// The witness checks' GMP fallbacks over every family and variant (nothing for a report written
// before the witness filter): the points neither the witness filter nor exact::
// pointToShapeDistance's own floating-point filter decided.
std::string witnessFallbackLine(const Json& r)
{
    std::uint64_t points = 0, exact = 0;
    for (const auto& f : r["families"])
        for (const auto& [name, st] : f["variants"].items())
        {
            points += count(st, "witness_points");
            exact += count(st, "witness_exact");
        }
    if (points == 0)
        return {};
    return fmt::format("witness points: {} measured, {} by the GMP route ({:.2f} %), the rest "
                       "decided in floating point\n",
                       points, exact, 100.0 * double(exact) / double(points));
}
} // namespace

namespace
{
// A line per family x variant that failed or misclassified (gjk2d's own contract), or breaks its
// declared contract or is outside gjk2d's bound keeping it, and per failed make-up check; with
// `judgedOnly`, only the judged variants' failures and the failed make-up checks (what fails the
// run). `pairs` counts the family x variant pairs.
std::string problemLines(const Json& r, bool judgedOnly, std::size_t& pairs)
{
    const auto judged = judgedMap(r), own = ownMap(r);
    std::string problems;
    for (const auto& f : r["families"])
    {
        const std::string family = f["name"].get<std::string>();
        for (const auto& [name, st] : f["variants"].items())
        {
            ++pairs;
            const bool j = isJudged(judged, name);
            if (judgedOnly && (!j || violations(st) == 0))
                continue;
            if (!isOwn(own, name))
            {
                if (violations(st) > 0 || outsideBound(st) > 0)
                    problems += contractLine(family, name, st, j);
            }
            else if (count(st, "failures") > 0 || count(st, "false_overlap") > 0 ||
                     count(st, "false_separation") > 0)
                problems += problemLine(family, name, st, j);
        }
        for (const auto& m : f["makeup"])
            if (!m["ok"].get<bool>())
                problems += fmt::format("  {:<28} make-up check failed: {} = {} not in [{}, {}]\n",
                                        family, m["check"].get<std::string>(), g(m["value"]),
                                        g(m["min"]), g(m["max"]));
    }
    return problems;
}

// The run's short lines, wrapped at 100 characters: its phases' rates and times, the witness
// checks' and the truths' GMP fallbacks.
std::string runLines(const Json& r)
{
    const Json& c = r["context"];
    const Json& t = c["throughput"];
    const Json& e = c["elapsed_s"];
    std::string s = fmt::format(
        "{} cases on {} threads in {:.1f} s: exact {:.0f} cases/s ({:.1f} s), GJK {:.0f} cases/s "
        "({:.2f} s, {} variants), witness checks {:.0f} cases/s ({:.1f} s), timing {:.1f} s\n",
        u(c["cases_total"]), c["threads"].get<int>(), e["total"].get<double>(),
        t["exact_cases_per_s"].get<double>(), e["exact"].get<double>(),
        t["gjk_cases_per_s"].get<double>(), e["gjk"].get<double>(), r["variants"].size(),
        t["witness_cases_per_s"].get<double>(), e["witness"].get<double>(),
        e["timing"].get<double>());
    // The other phases (docs/report-schema.md, "context"), when the report has them.
    if (e.contains("setup"))
        s += fmt::format("and setup {:.1f} s, cases made or read {:.1f} s, fold {:.1f} s, report "
                         "{:.1f} s\n",
                         e["setup"].get<double>(), e["generate"].get<double>(),
                         e["fold"].get<double>(), e["report"].get<double>());
    s += witnessFallbackLine(r);
    std::vector<const Json*> families;
    for (const auto& f : r["families"])
        families.push_back(&f);
    s += truthLines(r, families);
    std::string wrapped; // each line in lines of at most 100 characters, the rest indented
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);)
        wrapped += wrap(line, "  ", 100).substr(2);
    return wrapped;
}

// The verdict and one line of what was run.
std::string verdictLines(const Json& r)
{
    const auto judged = judgedMap(r);
    std::size_t judgedCount = 0;
    for (const auto& v : r["variants"])
        judgedCount += isJudged(judged, v["name"].get<std::string>()) ? 1 : 0;
    const Json& c = r["context"];
    return fmt::format("result: {}\nran {} cases ({} rejected), {} families, {} variants: {} "
                       "judged, {} comparison (not judged)\n",
                       resultText(r), u(c["cases_total"]), u(c["cases_rejected"]),
                       r["families"].size(), r["variants"].size(), judgedCount,
                       r["variants"].size() - judgedCount);
}

// A variant's verdict over the families, in the words of its contract (verdictWords').
std::string variantVerdict(const VariantTotals& t, bool judgedVariant, bool ownContract)
{
    if (ownContract)
        return t.violations > 0 ? (judgedVariant ? "FAIL" : "fails")
                                : (judgedVariant ? "pass" : "passes");
    if (t.violations > 0)
        return judgedVariant ? "FAIL: breaks its contract" : "breaks its contract";
    return t.outsideBound > 0 ? "outside gjk2d's bound" : "keeps its contract";
}

// The worst column: the largest error / gjk2d's bound (a variant without one: "norm" and its
// largest normalised error); for a contract broken, its worst violation's excess and reason.
std::string worstText(const Json& v, const VariantTotals& t, bool ownContract)
{
    const Json& w =
        v.contains("worst_contract_violation") ? v["worst_contract_violation"] : Json(nullptr);
    if (!ownContract && t.violations > 0 && w.is_object())
    {
        const double excess = numberOf(w["excess"]);
        std::string reason = w["reason"].get<std::string>();
        std::replace(reason.begin(), reason.end(), '_', ' ');
        return std::isfinite(excess) ? fmt::format("{:.2g} {}", excess, reason) : reason;
    }
    if (!std::isnan(t.worstBound))
        return fmt::format("{:.3g}", t.worstBound);
    return std::isnan(t.worstNorm) ? "-" : fmt::format("norm {:.3g}", t.worstNorm);
}

// The ns/query column, ten characters: the figure and its marks, a (timed by the adapter) and +
// (the shapes' set-up included: no preparation step).
std::string nsCell(const Json& v, const VariantTotals& t)
{
    std::string marks;
    if (v.contains("timing") && v["timing"].is_object())
    {
        marks += v["timing"].value("timed_by", "") == "adapter" ? "a" : "";
        marks += v["timing"].value("preparation", "") == "in-call" ? "+" : "";
    }
    return fmt::format("{:>8}{:<2}",
                       std::isnan(t.nsPerQuery) ? "-" : fmt::format("{:.1f}", t.nsPerQuery),
                       std::isnan(t.nsPerQuery) ? "" : marks);
}

// One line per variant, judged ones first (a heading per group), and the legend.
std::string variantTable(const Json& r)
{
    const auto judged = judgedMap(r), own = ownMap(r);
    constexpr const char* row = "{:<21} {:>7} {:>12} {:<24} {:>10}  {}\n"; // at most 100 wide
    std::string s = fmt::format(fmt::runtime(row), "variant", "cases", "failures",
                                "worst err/bound", "mean ns/q", "verdict");
    for (const bool group : {true, false})
    {
        std::string rows;
        for (const auto& v : r["variants"])
        {
            const std::string name = v["name"].get<std::string>();
            if (isJudged(judged, name) != group)
                continue;
            const VariantTotals t = variantTotals(r, name);
            const bool o = isOwn(own, name);
            std::string fails = std::to_string(o ? t.failures : t.violations);
            if (o && t.misclassified > 0)
                fails += fmt::format(" ({} ovl)", t.misclassified);
            rows += fmt::format(
                fmt::runtime(row), name.size() > 21 ? name.substr(0, 18) + "..." : name, t.cases,
                fails, worstText(v, t, o), nsCell(v, t), variantVerdict(t, group, o));
            const PenetrationTotals p = penetrationTotals(r, name);
            if (p.any)
                rows += penetrationLine(p, group, o);
        }
        if (!rows.empty())
            s += (group ? "judged (they decide the result):\n"
                        : "comparison (shown, not judged):\n") +
                 rows;
    }
    return s + wrap("failures: failed cases (wrong overlap answers); a contract of its own: its "
                    "violations. worst: the largest error / gjk2d's bound, or a broken contract's "
                    "worst excess and why. mean ns/q: the timed families' figures weighted by "
                    "their cases; a: timed by the adapter; +: includes the shapes' set-up. "
                    "penetration (a contract whose overlap answer is minus the depth): its "
                    "verdict, the overlapping cases, the answers that broke the contract and "
                    "those outside gjk2d's depth bound keeping it, the worst depth error / depth "
                    "bound (report.md: with their cases).",
                    "", 100);
}
} // namespace

std::string terminalSummary(const Json& r, bool verbose)
{
    std::string s = verdictLines(r) + variantTable(r);
    if (verbose)
        s += terminalTable(r);
    std::size_t pairs = 0;
    const std::string problems = problemLines(r, !verbose, pairs);
    if (!problems.empty())
        s +=
            wrap(verbose ? fmt::format("failed or misclassified (false overlap or separation), or, "
                                       "for an implementation with a contract of its own, breaks "
                                       "its contract or is outside gjk2d's bound, family x "
                                       "variant ({} pairs in all):",
                                       pairs)
                         : "what failed the run, per family (--verbose: every family x variant "
                           "that failed):",
                 "", 100) +
            problems;
    if (r["context"]["cases_rejected"].get<std::uint64_t>() > 0)
        s += fmt::format("{} case(s) rejected (see report.md, 'Rejected cases'):\n",
                         u(r["context"]["cases_rejected"]));
    std::size_t shown = 0;
    for (const auto& j : r["rejected"])
        if (shown++ < 10)
            s += fmt::format("  {}: {}\n", j["name"].get<std::string>(),
                             j["reason"].get<std::string>());
    return s + runLines(r);
}

namespace
{
// What made a run fail: the judged variants' failures (cases, summed over families and variants)
// and the families whose make-up checks failed.
std::string failureCauses(const Json& r)
{
    const auto judged = judgedMap(r);
    std::uint64_t failures = 0, makeup = 0;
    for (const auto& f : r["families"])
    {
        for (const auto& [name, st] : f["variants"].items())
            if (isJudged(judged, name))
                failures += violations(st); // gjk2d's own: its failures
        makeup += f.contains("makeup_ok") && !f["makeup_ok"].get<bool>() ? 1 : 0;
    }
    std::string s = failures > 0 ? fmt::format("{} judged variant failure(s)", failures) : "";
    if (makeup > 0)
        s +=
            fmt::format("{}make-up checks of {} family(ies) failed", s.empty() ? "" : "; ", makeup);
    return s.empty() ? "no judged variant failure and no failed make-up check in the report" : s;
}
} // namespace

std::string resultText(const Json& r)
{
    const int code = r["exit_code"].get<int>();
    if (code == kExitPass)
        return "PASS (exit code 0)";
    if (code == kExitInput)
    {
        const Json& c = r["context"];
        const auto rejected = c["cases_rejected"].get<std::uint64_t>(),
                   total = c["cases_total"].get<std::uint64_t>();
        if (rejected >= total)
            return fmt::format("INPUT ERROR (exit code 2): {} case(s) rejected, none judged",
                               rejected);
        return fmt::format("INPUT ERROR (exit code 2): {} case(s) rejected; the {} judged "
                           "case(s) pass",
                           rejected, total - rejected);
    }
    return fmt::format("FAIL (exit code {}): {}", code, failureCauses(r));
}

std::string exitCodesHelp(std::size_t width)
{
    std::string s = "Exit codes:\n";
    for (const auto& e : kExitCodeTable)
    {
        std::string w = wrap(e.meaning, "     ", width);
        s += fmt::format("  {}  {}", e.code, w.substr(5));
    }
    s.pop_back(); // CLI11 ends the footer with its own newline
    return s;
}

std::string exitCodesMarkdown()
{
    std::string s = "| code | meaning |\n|---|---|\n";
    for (const auto& e : kExitCodeTable)
        s += fmt::format("| {} | {} |\n", e.code, e.meaning);
    return s;
}

} // namespace gjkval
