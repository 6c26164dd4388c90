// gjk-validate compare: the comparison of two reports (compare.hpp states the tolerance rule); its
// renderings are in compare_render.cpp.
#include "report/compare.hpp"

#include "common/json_text.hpp"
#include "report/report.hpp"
#include "statistics/stats.hpp" // kCountFields

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;

constexpr const char* kSchema = kReportSchema;
constexpr int kMaxReportDepth = 64; // report.json nests about 8 deep; a deeper file is not one
const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string typeName(const Json& j)
{
    return j.type_name();
}

// The report's shape as far as compare reads it; InputError naming `label` otherwise.
void checkShape(const Json& r, const std::string& label)
{
    if (!r.is_object())
        throw InputError(
            fmt::format("{}: the JSON is {}, expected a {} object", label, typeName(r), kSchema));
    if (!r.contains("schema"))
        throw InputError(fmt::format("{}: not a {} report (no \"schema\")", label, kSchema));
    if (!r["schema"].is_string() || r["schema"].get_ref<const std::string&>() != kSchema)
        throw InputError(fmt::format("{}: not a {} report (schema {})", label, kSchema,
                                     excerpt(r["schema"].dump())));
    for (const char* key : {"families", "variants"})
        if (!r.contains(key) || !r[key].is_array())
            throw InputError(fmt::format("{}: \"{}\" is {}, expected an array", label, key,
                                         r.contains(key) ? typeName(r[key]) : "missing"));
    std::size_t i = 0;
    for (const auto& f : r["families"])
    {
        if (!f.is_object() || !f.contains("name") || !f["name"].is_string() ||
            !f.contains("variants") || !f["variants"].is_object())
            throw InputError(fmt::format("{}: families[{}] is not a family (an object with a "
                                         "string \"name\" and an object \"variants\")",
                                         label, i));
        ++i;
    }
    i = 0;
    for (const auto& v : r["variants"])
    {
        if (!v.is_object() || !v.contains("name") || !v["name"].is_string())
            throw InputError(fmt::format("{}: variants[{}] is not a variant (an object with a "
                                         "string \"name\")",
                                         label, i));
        ++i;
    }
}

// One report, and how its messages name it.
struct Side
{
    const Json& report;
    const std::string& label;
};

// parent[key] as a number: NaN when absent or null; a number, "inf"/"-inf"/"nan" (how the report
// writes non-finite values), or true/false as 1/0. Another type: InputError naming the field.
double number(const Json* parent, const std::string& key, const Side& side,
              const std::string& where)
{
    if (parent == nullptr)
        return kNaN;
    const auto it = parent->find(key);
    if (it == parent->end() || it->is_null())
        return kNaN;
    if (it->is_number())
        return it->get<double>();
    if (it->is_boolean())
        return it->get<bool>() ? 1 : 0;
    if (it->is_string())
    {
        const auto& s = it->get_ref<const std::string&>();
        if (s == "inf")
            return std::numeric_limits<double>::infinity();
        if (s == "-inf")
            return -std::numeric_limits<double>::infinity();
        if (s == "nan")
            return kNaN;
    }
    throw InputError(fmt::format("{}: {}.{} is {}, expected a number", side.label, where,
                                 excerpt(key), typeName(*it)));
}

// parent[key] when it is an object; nullptr when absent or null; InputError for another type.
const Json* object(const Json* parent, const std::string& key, const Side& side,
                   const std::string& where)
{
    if (parent == nullptr)
        return nullptr;
    const auto it = parent->find(key);
    if (it == parent->end() || it->is_null())
        return nullptr;
    if (!it->is_object())
        throw InputError(fmt::format("{}: {}.{} is {}, expected an object", side.label, where,
                                     excerpt(key), typeName(*it)));
    return &*it;
}

// The index of each family (by name) of a report.
std::map<std::string, const Json*> familiesByName(const Json& r)
{
    std::map<std::string, const Json*> m;
    for (const auto& f : r["families"])
        m.emplace(f["name"].get<std::string>(), &f);
    return m;
}

// How a family was made: its case count, seed and source. Two families of the same name compare
// only when these are equal ("" when they are).
std::string inputDifference(const Json& a, const Json& b)
{
    std::string d;
    for (const char* key : {"cases", "seed", "source"})
    {
        const Json none;
        const Json& x = a.contains(key) ? a[key] : none;
        const Json& y = b.contains(key) ? b[key] : none;
        if (x != y)
            d += fmt::format("{}{} {} in OLD, {} in NEW", d.empty() ? "" : ", ", key,
                             excerpt(x.dump()), excerpt(y.dump()));
    }
    return d;
}

// Adds rows, judging each by the tolerance rule.
class Rows
{
  public:
    Rows(const CompareOptions& o, std::vector<CompareRow>& rows) : o_(o), rows_(rows) {}

    void add(CompareRow r, double floor = 0)
    {
        const double a = r.oldValue, b = r.newValue;
        if (std::isnan(a) || std::isnan(b))
        {
            if (!(std::isnan(a) && std::isnan(b)))
            {
                r.change = Change::NotCompared;
                r.note = std::isnan(a) ? "absent or null in OLD" : "absent or null in NEW";
            }
            rows_.push_back(std::move(r));
            return;
        }
        const bool worse = r.higherIsBetter ? b < a : b > a;
        const bool better = r.higherIsBetter ? b > a : b < a;
        switch (r.rule)
        {
        case CompareRule::Count:
        case CompareRule::Presence:
            r.limit = a;
            r.change = worse ? Change::Regressed : better ? Change::Better : Change::Same;
            break;
        case CompareRule::Exact:
        case CompareRule::Percentile:
        {
            const double tol = r.rule == CompareRule::Exact ? o_.relTol : o_.percentileTol;
            r.limit = a * (1 + tol) + floor;
            r.change = b > r.limit ? Change::Regressed
                       : worse     ? Change::Worse
                       : better    ? Change::Better
                                   : Change::Same;
            break;
        }
        case CompareRule::Timing:
        {
            r.limit = a * o_.timingTol;
            const double ratio = b / a;
            r.note = fmt::format("NEW/OLD {:.3f}", ratio);
            r.change = ratio > o_.timingTol       ? Change::Regressed
                       : ratio < 1 / o_.timingTol ? Change::Better
                                                  : Change::Same;
            break;
        }
        }
        rows_.push_back(std::move(r));
    }

  private:
    const CompareOptions& o_;
    std::vector<CompareRow>& rows_;
};

// The rows of one family x variant: each from `base` (family, variant, judged, gates).
struct StatRows
{
    CompareRow base;
    Rows& rows;

    void add(const std::string& statistic, CompareRule rule, double a, double b, double floor = 0,
             bool higherIsBetter = false) const
    {
        CompareRow r = base;
        r.statistic = statistic;
        r.rule = rule;
        r.oldValue = a;
        r.newValue = b;
        r.higherIsBetter = higherIsBetter;
        rows.add(std::move(r), floor);
    }
};

// errors: every histogram either report has, OLD's order first; max and mean by the relative
// tolerance, the percentiles by the percentile one, above the smallest value the bins resolve.
void compareErrors(const Json* oe, const Json* ne, const std::string& where, const Side& os,
                   const Side& ns, const StatRows& out)
{
    std::vector<std::string> metrics;
    for (const Json* e : {oe, ne})
        if (e != nullptr)
            for (const auto& [metric, _] : e->items())
                if (std::find(metrics.begin(), metrics.end(), metric) == metrics.end())
                    metrics.push_back(metric);
    for (const auto& metric : metrics)
    {
        const std::string at = where + ".errors";
        const Json* oh = object(oe, metric, os, at);
        const Json* nh = object(ne, metric, ns, at);
        // The smallest value the bins resolve: values below 10^log10_min share the first bin.
        double lo = number(oh, "log10_min", os, at + "." + metric);
        if (std::isnan(lo))
            lo = number(nh, "log10_min", ns, at + "." + metric);
        const double floor = std::isnan(lo) ? 0 : std::pow(10.0, lo);
        for (const char* s : {"max", "p99", "p999", "mean"})
        {
            const bool percentile = s[0] == 'p';
            out.add(fmt::format("errors.{}.{}", metric, s),
                    percentile ? CompareRule::Percentile : CompareRule::Exact,
                    number(oh, s, os, at + "." + metric), number(nh, s, ns, at + "." + metric),
                    floor);
        }
    }
}

// iterations (max as a count, mean by the relative tolerance) and the certified interval's counts.
void compareIterationsAndInterval(const Json& oldStats, const Json& newStats,
                                  const std::string& where, const Side& os, const Side& ns,
                                  const StatRows& out)
{
    const Json* oi = object(&oldStats, "iterations", os, where);
    const Json* ni = object(&newStats, "iterations", ns, where);
    if (oi != nullptr || ni != nullptr)
    {
        out.add("iterations.max", CompareRule::Count, number(oi, "max", os, where + ".iterations"),
                number(ni, "max", ns, where + ".iterations"));
        out.add("iterations.mean", CompareRule::Exact,
                number(oi, "mean", os, where + ".iterations"),
                number(ni, "mean", ns, where + ".iterations"));
    }
    const Json* ov = object(&oldStats, "interval", os, where);
    const Json* nv = object(&newStats, "interval", ns, where);
    if (ov != nullptr || nv != nullptr)
    {
        const std::string at = where + ".interval";
        out.add("interval.contains", CompareRule::Count, number(ov, "contains", os, at),
                number(nv, "contains", ns, at), 0, true);
        for (const char* key : {"misses", "uncertified"})
            out.add(fmt::format("interval.{}", key), CompareRule::Count, number(ov, key, os, at),
                    number(nv, key, ns, at));
    }
}

// The contract verdict beside beyond_bound: contract_violations (its count: the answers that break
// their implementation's contract) and beyond_bound_keeping_contract (outside gjk2d's bound,
// keeping it); any increase of either is worse. Reports written before contracts have neither.
void compareContract(const Json& oldStats, const Json& newStats, const std::string& where,
                     const Side& os, const Side& ns, const StatRows& out)
{
    const Json* ov = object(&oldStats, "contract_violations", os, where);
    const Json* nv = object(&newStats, "contract_violations", ns, where);
    if (ov != nullptr || nv != nullptr)
        out.add("contract_violations", CompareRule::Count,
                number(ov, "count", os, where + ".contract_violations"),
                number(nv, "count", ns, where + ".contract_violations"));
    const char* kept = "beyond_bound_keeping_contract";
    if (oldStats.contains(kept) || newStats.contains(kept))
        out.add(kept, CompareRule::Count, number(&oldStats, kept, os, where),
                number(&newStats, kept, ns, where));
}

// Every statistic of one family x variant (docs/report-schema.md, Stats).
void compareStats(const Json& oldStats, const Json& newStats, CompareRow base,
                  const CompareOptions& o, const Side& os, const Side& ns, Rows& rows)
{
    const std::string where =
        fmt::format("families['{}'].variants['{}']", excerpt(base.family), excerpt(base.variant));
    const StatRows out{std::move(base), rows};
    // The Stats counts that regress on any increase, in the report's order (statistics/stats.hpp).
    for (const CountField& f : kCountFields)
        if (f.regresses && f.section == Section::Top &&
            (oldStats.contains(f.name) || newStats.contains(f.name)))
            out.add(f.name, CompareRule::Count, number(&oldStats, f.name, os, where),
                    number(&newStats, f.name, ns, where));
    compareContract(oldStats, newStats, where, os, ns, out);
    const Json* oe = object(&oldStats, "errors", os, where);
    const Json* ne = object(&newStats, "errors", ns, where);
    compareErrors(oe, ne, where, os, ns, out);
    compareIterationsAndInterval(oldStats, newStats, where, os, ns, out);
    if (o.timing)
        out.add("ns_per_query", CompareRule::Timing, number(&oldStats, "ns_per_query", os, where),
                number(&newStats, "ns_per_query", ns, where));
}

// A family's own rows: makeup_ok, pass, and each make-up check (by its name) that both have.
void compareFamily(const Json& of, const Json& nf, const std::string& name, const Side& os,
                   const Side& ns, Rows& rows)
{
    const std::string where = fmt::format("families['{}']", excerpt(name));
    auto flag = [&](const std::string& statistic, double a, double b)
    {
        CompareRow r;
        r.family = name;
        r.statistic = statistic;
        r.higherIsBetter = true;
        r.oldValue = a;
        r.newValue = b;
        rows.add(std::move(r));
    };
    flag("makeup_ok", number(&of, "makeup_ok", os, where), number(&nf, "makeup_ok", ns, where));
    flag("pass", number(&of, "pass", os, where), number(&nf, "pass", ns, where));
    if (!of.contains("makeup") || !nf.contains("makeup") || !of["makeup"].is_array() ||
        !nf["makeup"].is_array())
        return;
    for (const auto& oc : of["makeup"])
        for (const auto& nc : nf["makeup"])
            if (oc.is_object() && nc.is_object() && oc.contains("check") &&
                oc["check"].is_string() && nc.contains("check") && oc["check"] == nc["check"])
                flag("makeup: " + excerpt(oc["check"].get<std::string>(), 100),
                     number(&oc, "ok", os, where + ".makeup"),
                     number(&nc, "ok", ns, where + ".makeup"));
}

// Judged in either report (a variant judged in NEW only, or dropped from the judged ones by NEW,
// still gates). A variant neither lists is taken as judged.
bool judgedInEither(const std::string& variant, const Json& a, const Json& b)
{
    bool listed = false;
    for (const Json* r : {&a, &b})
        for (const auto& v : (*r)["variants"])
            if (v["name"] == variant)
            {
                listed = true;
                if (v.contains("judged") && v["judged"].is_boolean() && v["judged"].get<bool>())
                    return true;
            }
    return !listed;
}

} // namespace

const char* changeName(Change c)
{
    switch (c)
    {
    case Change::Same:
        return "same";
    case Change::Better:
        return "better";
    case Change::Worse:
        return "worse";
    case Change::Regressed:
        return "regressed";
    case Change::OnlyOld:
        return "only in OLD";
    case Change::OnlyNew:
        return "only in NEW";
    case Change::NotCompared:
        return "not compared";
    }
    return "?";
}

bool CompareRow::fails() const
{
    return gates &&
           (change == Change::Regressed || change == Change::OnlyOld || change == Change::OnlyNew);
}

std::size_t Comparison::count(Change c) const
{
    return std::size_t(std::count_if(rows.begin(), rows.end(),
                                     [&](const CompareRow& r) { return r.change == c; }));
}

std::size_t Comparison::failing() const
{
    return std::size_t(
        std::count_if(rows.begin(), rows.end(), [](const CompareRow& r) { return r.fails(); }));
}

Json readReport(const std::string& path)
{
    fs::path p = path;
    std::error_code ec;
    if (fs::is_directory(p, ec))
        p /= "report.json";
    const std::string shown = shownPath(p.string());
    const auto st = fs::status(p, ec);
    if (!fs::exists(st))
        throw InputError(fmt::format("compare: {}: no such file", shown));
    if (!fs::is_regular_file(st))
        throw InputError(fmt::format("compare: {}: not a regular file", shown));
    std::ifstream in(p, std::ios::binary);
    if (!in)
        throw InputError(fmt::format("compare: {}: cannot open: {}", shown, std::strerror(errno)));
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad())
        throw InputError(fmt::format("compare: {}: read failed", shown));
    Json report;
    try
    {
        report = Json::parse(text,
                             [&](int depth, Json::parse_event_t, Json&)
                             {
                                 if (depth > kMaxReportDepth)
                                     throw InputError(
                                         fmt::format("compare: {}: not a {} report (JSON nested "
                                                     "more than {} deep)",
                                                     shown, kSchema, kMaxReportDepth));
                                 return true;
                             });
    }
    catch (const Json::parse_error& e)
    {
        // nlohmann: "[json.exception.parse_error.101] parse error at line 1, column 1: syntax
        // error while parsing value - ...": keep what follows the position.
        const std::string what = e.what();
        const std::size_t column = what.find("column");
        const std::size_t colon = column == std::string::npos ? column : what.find(": ", column);
        const std::string reason = colon == std::string::npos ? what : what.substr(colon + 2);
        const auto [line, col] = lineColumn(text, e.byte == 0 ? 0 : e.byte - 1);
        throw InputError(
            fmt::format("compare: {}:{}:{}: not JSON: {}", shown, line, col, excerpt(reason, 120)));
    }
    checkShape(report, "compare: " + shown);
    return report;
}

namespace
{
using Families = std::map<std::string, const Json*>;

// The inputs: the same families, each with the same cases, seed and source; one line per
// difference (none: the reports ran the same inputs).
std::vector<std::string> inputDifferences(const Json& oldReport, const Json& newReport,
                                          const Families& oldFamilies, const Families& newFamilies)
{
    std::vector<std::string> differences;
    for (const auto& f : oldReport["families"])
    {
        const std::string name = f["name"];
        const auto it = newFamilies.find(name);
        if (it == newFamilies.end())
            differences.push_back(fmt::format("family '{}' is in OLD only", excerpt(name)));
        else if (const std::string d = inputDifference(f, *it->second); !d.empty())
            differences.push_back(fmt::format("family '{}': {}", excerpt(name), d));
    }
    for (const auto& f : newReport["families"])
        if (!oldFamilies.count(f["name"].get<std::string>()))
            differences.push_back(
                fmt::format("family '{}' is in NEW only", excerpt(f["name"].get<std::string>())));
    return differences;
}

std::vector<std::string> variantNames(const Json& r)
{
    std::vector<std::string> v;
    for (const auto& x : r["variants"])
        v.push_back(x["name"]);
    return v;
}

bool has(const std::vector<std::string>& v, const std::string& name)
{
    return std::find(v.begin(), v.end(), name) != v.end();
}

// The rows of one comparison beyond the statistics: a family or variant in one report only (gates
// with --strict), a family whose inputs differ (not compared).
struct Comparing
{
    Comparison& c;
    const CompareOptions& o;

    void presence(std::string family, std::string variant, std::string statistic, bool inOld,
                  std::string note) const
    {
        CompareRow r;
        r.family = std::move(family);
        r.variant = std::move(variant);
        r.statistic = std::move(statistic);
        r.rule = CompareRule::Presence;
        r.oldValue = inOld ? 1 : 0;
        r.newValue = inOld ? 0 : 1;
        r.change = inOld ? Change::OnlyOld : Change::OnlyNew;
        r.gates = o.strict;
        r.note = std::move(note);
        c.rows.push_back(std::move(r));
    }

    void notCompared(const std::string& family, const std::string& statistic, double a, double b,
                     std::string note) const
    {
        CompareRow r;
        r.family = family;
        r.statistic = statistic;
        r.change = Change::NotCompared;
        r.oldValue = a;
        r.newValue = b;
        r.gates = false;
        r.note = std::move(note);
        c.rows.push_back(std::move(r));
    }
};

// A variant one report ran and the other did not: one row, not one per family.
void compareVariantSets(const std::vector<std::string>& oldVariants,
                        const std::vector<std::string>& newVariants, const Comparing& cmp)
{
    for (const auto& v : oldVariants)
        if (!has(newVariants, v))
            cmp.presence("", v, "variant", true, "the variant is in OLD only");
    for (const auto& v : newVariants)
        if (!has(oldVariants, v))
            cmp.presence("", v, "variant", false, "the variant is in NEW only");
}

// One family both reports ran alike: its own rows, then each variant's statistics.
void compareFamilyVariants(const Json& of, const Json& nf, const std::string& name,
                           const std::vector<std::string>& oldVariants,
                           const std::vector<std::string>& newVariants, const Side& os,
                           const Side& ns, const Comparing& cmp, Rows& rows)
{
    const CompareOptions& o = cmp.o;
    compareFamily(of, nf, name, os, ns, rows);
    for (const auto& [variant, oldStats] : of["variants"].items())
    {
        const Json* newStats =
            nf["variants"].contains(variant) ? &nf["variants"][variant] : nullptr;
        if (newStats == nullptr)
        {
            if (has(newVariants, variant))
                cmp.presence(name, variant, "variant", true, "absent from the family in NEW");
            continue;
        }
        CompareRow base;
        base.family = name;
        base.variant = variant;
        base.judged = judgedInEither(variant, os.report, ns.report);
        base.gates = base.judged || o.allVariants;
        const std::string where = fmt::format("families['{}'].variants", excerpt(name));
        if (!oldStats.is_object())
            throw InputError(fmt::format("{}: {}['{}'] is {}, expected an object", o.oldName, where,
                                         excerpt(variant), typeName(oldStats)));
        if (!newStats->is_object())
            throw InputError(fmt::format("{}: {}['{}'] is {}, expected an object", o.newName, where,
                                         excerpt(variant), typeName(*newStats)));
        compareStats(oldStats, *newStats, base, o, os, ns, rows);
    }
    for (const auto& [variant, _] : nf["variants"].items())
        if (!of["variants"].contains(variant) && has(oldVariants, variant))
            cmp.presence(name, variant, "variant", false, "absent from the family in OLD");
}
} // namespace

Comparison compareReports(const Json& oldReport, const Json& newReport, const CompareOptions& o)
{
    checkShape(oldReport, o.oldName);
    checkShape(newReport, o.newName);
    const Side os{oldReport, o.oldName}, ns{newReport, o.newName};
    Comparison c;
    c.options = o;
    Rows rows(o, c.rows);
    const Comparing cmp{c, o};

    const auto oldFamilies = familiesByName(oldReport), newFamilies = familiesByName(newReport);
    const auto differences = inputDifferences(oldReport, newReport, oldFamilies, newFamilies);
    c.inputsDiffer = !differences.empty();
    if (c.inputsDiffer && !o.allowDifferentInputs)
        throw InputError(
            fmt::format("compare: {} and {} ran different inputs: {}{} (give "
                        "--allow-different-inputs to compare the families both ran "
                        "alike)",
                        o.oldName, o.newName, differences.front(),
                        differences.size() > 1
                            ? fmt::format(" and {} more difference(s)", differences.size() - 1)
                            : ""));

    // The variants each report ran (a variant in one only: one row, not one per family).
    const auto oldVariants = variantNames(oldReport), newVariants = variantNames(newReport);
    compareVariantSets(oldVariants, newVariants, cmp);

    for (const auto& of : oldReport["families"])
    {
        const std::string name = of["name"];
        const auto it = newFamilies.find(name);
        if (it == newFamilies.end())
            cmp.presence(name, "", "family", true, "the family is in OLD only");
        else if (const std::string d = inputDifference(of, *it->second); !d.empty())
            cmp.notCompared(name, "inputs", kNaN, kNaN, d);
        else
            compareFamilyVariants(of, *it->second, name, oldVariants, newVariants, os, ns, cmp,
                                  rows);
    }
    for (const auto& nf : newReport["families"])
        if (!oldFamilies.count(nf["name"].get<std::string>()))
            cmp.presence(nf["name"], "", "family", false, "the family is in NEW only");

    // The overall exit code: meaningful only when both ran the same inputs.
    const double oldExit = number(&oldReport, "exit_code", os, "report");
    const double newExit = number(&newReport, "exit_code", ns, "report");
    if (c.inputsDiffer)
        cmp.notCompared("", "exit_code", oldExit, newExit, "the reports ran different inputs");
    else
    {
        CompareRow exit;
        exit.statistic = "exit_code";
        exit.oldValue = oldExit;
        exit.newValue = newExit;
        rows.add(std::move(exit));
    }
    c.exitCode = c.failing() > 0 ? kExitFail : kExitPass;
    return c;
}

} // namespace gjkval
