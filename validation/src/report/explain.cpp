// `gjk-validate explain`'s text, from a CaseDetail: both shapes, the exact results, and each
// variant's answer, judgement and iteration trace.
#include "report/explain.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace gjkval
{
namespace
{
std::string fmtPt(const Json& p)
{
    auto f = [](const Json& v)
    { return v.is_number() ? fmt::format("{:.17g}", v.get<double>()) : v.dump(); };
    return p.is_array() && p.size() == 2 ? fmt::format("({}, {})", f(p[0]), f(p[1])) : p.dump();
}

std::string fmtFull(const Json& v)
{
    return v.is_number() ? fmt::format("{:.17g}", v.get<double>()) : v.dump();
}

std::string fmtNum(const Json& v)
{
    if (v.is_number())
        return fmt::format("{:.6g}", v.get<double>());
    return v.is_null() ? "n/a" : v.dump();
}

// Shape `k` ("a" or "b"): its size, radius and transform, and its first 12 points, local and world.
std::string shapeText(const char* k, const Json& sh)
{
    std::string s = fmt::format("  {}: {} points, radius {}, transform p = {}, q = {}\n", k,
                                sh["points"].size(), fmtNum(sh["radius"]),
                                fmtPt(sh["transform"]["p"]), fmtPt(sh["transform"]["q"]));
    const std::size_t shown = std::min<std::size_t>(sh["points"].size(), 12);
    for (std::size_t i = 0; i < shown; ++i)
        s += fmt::format("     [{}] local {}  world {}\n", i, fmtPt(sh["points"][i]),
                         fmtPt(sh["world"][i]));
    if (shown < sh["points"].size())
        s += fmt::format("     ... {} more\n", sh["points"].size() - shown);
    return s;
}

// The exact signed distance where the run judges a penetration depth (CaseDetail exact
// "signed_distance"): on overlap the exact depth and the minimal translation pA -> pB.
std::string signedText(const Json& e)
{
    if (!e.contains("signed_distance"))
        return {};
    const double s = e["signed_distance"].is_number() ? e["signed_distance"].get<double>() : 0;
    std::string t =
        fmt::format("     signed distance {} in [{}, {}]", fmtFull(e["signed_distance"]),
                    fmtFull(e["signed_lower"]), fmtFull(e["signed_upper"]));
    if (s < 0)
        t += fmt::format(": the shapes overlap, exact depth {}\n     penetration pair A {} B {} "
                         "(moving B by A - B brings it to contact)",
                         fmtFull(Json(-s)), fmtPt(e["penetrationA"]), fmtPt(e["penetrationB"]));
    return t + "\n";
}

// An exact result: its distance interval, overlap, squared distance and witness points.
std::string exactText(const char* label, const Json& e)
{
    return signedText(e).insert(
        0, fmt::format("  {}: distance {} in [{}, {}], overlap {}\n", label, fmtFull(e["distance"]),
                       fmtFull(e["lower"]), fmtFull(e["upper"]), e["overlap"].get<bool>()) +
               fmt::format("     squared distance (before radii) {}\n     witnesses A {} B {}\n",
                           e["squared"].get<std::string>(), fmtPt(e["witnessA"]),
                           fmtPt(e["witnessB"])));
}

// A penetration answer's depth on overlapping shapes (CaseDetail variants[].penetration): the
// exact depth, the answer's, the error, and what it was held to.
std::string penetrationText(const Json& v)
{
    if (!v.contains("penetration"))
        return {};
    const Json& p = v["penetration"];
    const double d = p["distance"].is_number() ? p["distance"].get<double>() : 0;
    return fmt::format("     penetration: exact depth {}, its depth {}: error {} (relative {}), "
                       "gjk2d's depth bound {} (ratio {}), held to {}{}\n",
                       fmtFull(Json(-p["exact"].get<double>())),
                       d < 0 ? fmtFull(Json(-d))
                             : fmt::format("none (distance {})", fmtFull(p["distance"])),
                       fmtNum(p["abs"]), fmtNum(p["rel"]), fmtNum(p["bound"]),
                       fmtNum(p["bound_ratio"]), fmtNum(p["tolerance"]),
                       p.value("beyond_bound", false) ? "  ** beyond gjk2d's depth bound **" : "");
}

// The answer's verdict by its implementation's contract (CaseDetail "contract"; older details
// have none): its class in words, the reason and size of a violation, and what the distance and
// the points were held to (judgedBy, implementations/contract.hpp).
std::string contractText(const Json& v)
{
    if (!v.contains("contract") || !v["contract"].is_object())
        return {};
    const Json& c = v["contract"];
    const std::string cls = c["class"].get<std::string>();
    std::string words = cls == "breaks_contract" ? "breaks its contract"
                        : cls == "outside_bound" ? "keeps its contract, outside gjk2d's bound"
                        : cls == "within_bound"  ? "keeps its contract, within gjk2d's bound"
                                                 : cls;
    if (c["violation"].is_string())
        words += fmt::format(" ({}, {} times what it allows)", c["violation"].get<std::string>(),
                             fmtNum(c["excess"]));
    std::string s = fmt::format("     contract: {}\n", words);
    s += fmt::format("     held to: distance within {}, points within {}{}\n",
                     fmtNum(c["tolerance"]), fmtNum(c["witness_tolerance"]),
                     c.contains("judged_by") ? " (" + c["judged_by"].get<std::string>() + ")" : "");
    return s;
}

// The answer's headline verdict: "** FAILED **" for a failure of gjk2d's own contract; for an
// implementation with a contract of its own "** BREAKS ITS CONTRACT **" (never "failed": gjk2d's
// rules are a measure for it, its contract the verdict).
std::string failedWords(const Json& v)
{
    const bool own = !v.contains("contract") || v["contract"].value("own", true);
    if (own)
        return v["failed"].get<bool>() ? "  ** FAILED **" : "";
    return v["contract"]["class"] == "breaks_contract" ? "  ** BREAKS ITS CONTRACT **" : "";
}

// A variant's answer and its judgement: distance, witnesses, errors, validity, certified interval.
std::string answerText(const std::string& name, const Json& v)
{
    std::string s =
        fmt::format("  variant {} ({}): distance {}  iterations {}  stop {}{}\n", name,
                    v["type"].get<std::string>(), fmtFull(v["distance"]),
                    v["iterations"].get<int>(), v["stop"].get<std::string>(), failedWords(v));
    s += fmt::format("     pointA {}  pointB {}  normal {}\n", fmtPt(v["pointA"]),
                     fmtPt(v["pointB"]), fmtPt(v["normal"]));
    const Json& e = v["errors"];
    s += fmt::format("     errors: abs {}  rel {}  ulps {}  normalized {}  bound {} (ratio {})  "
                     "witness {}  witness gap {}  misclassified {}\n",
                     fmtNum(e["abs"]), fmtNum(e["rel"]), fmtNum(e["ulps"]), fmtNum(e["normalized"]),
                     fmtNum(v["bound"]), fmtNum(e["bound_ratio"]), fmtNum(e["witness"]),
                     fmtNum(e["witness_gap"]),
                     v["misclassified"].is_null() ? "no" : v["misclassified"].get<std::string>());
    // Older reports have no witness judgement.
    const bool own = !v.contains("contract") || v["contract"].value("own", true);
    if (v.contains("invalid"))
        s += fmt::format("     {}witness bound {}  invalid answer: {}\n",
                         own ? "" : "by gjk2d's own rules (a measure, not its verdict): ",
                         fmtNum(v["witness_bound"]),
                         v["invalid"].is_null() ? "no" : v["invalid"].get<std::string>());
    if (v.contains("certified") && !v["certified"].get<bool>())
        s += "     certified interval: none (the query did not certify this case)\n";
    else if (v.contains("certified"))
        s += fmt::format("     certified interval [{}, {}], contains the exact distance: {}\n",
                         fmtFull(v["lower"]), fmtFull(v["upper"]),
                         v["interval_contains"].get<bool>() ? "yes" : "NO");
    return s + penetrationText(v) + contractText(v);
}

// A variant's iteration trace, one step per block: simplex, closest point, direction, support.
std::string traceText(const Json& trace)
{
    std::string s;
    int k = 0;
    for (const auto& step : trace)
    {
        s += fmt::format("     step {}: simplex", k++);
        for (const auto& sv : step["simplex"])
            s += fmt::format(" [w {} a {} iA {} iB {}]", fmtPt(sv["w"]), fmtNum(sv["a"]),
                             sv["iA"].get<int>(), sv["iB"].get<int>());
        s += fmt::format("\n            closest {}  direction {}", fmtPt(step["closest"]),
                         fmtPt(step["direction"]));
        if (!step["support"].is_null())
            s += fmt::format("  support w {} (iA {}, iB {})", fmtPt(step["support"]["w"]),
                             step["support"]["iA"].get<int>(), step["support"]["iB"].get<int>());
        s += "\n";
    }
    return s;
}

// One variant on the case: skipped, a plugin's failure status, or its answer and trace.
std::string variantText(const std::string& name, const Json& v)
{
    if (v.contains("skipped"))
        return fmt::format("  variant {}: skipped ({})\n", name, v["skipped"].get<std::string>());
    if (v.contains("plugin_status"))
        return fmt::format("  variant {} ({}): {}: {}\n", name, v["type"].get<std::string>(),
                           v["plugin_status"].get<std::string>(),
                           v["plugin_detail"].get<std::string>()) +
               contractText(v);
    std::string s = answerText(name, v);
    if (v.value("input", "") == "world") // judged on the world case it was given (worldText)
        s += fmt::format("     given the world case in {}: judged on its exact result\n",
                         v["type"].get<std::string>());
    if (!v.contains("trace"))
        return s + "     (no trace: the implementation is a plugin's)\n";
    return s + traceText(v["trace"]);
}
} // namespace

namespace
{
// The world cases variants given world points were given (CaseDetail "world_input", per scalar
// type): their shapes (identity transforms) and exact truth, which those variants are judged on.
std::string worldText(const Json& d)
{
    if (!d.contains("world_input"))
        return {};
    std::string s;
    for (const auto& [scalar, w] : d["world_input"].items())
    {
        s += fmt::format("  world case in {} (what a variant given world points gets: each point "
                         "mapped in double, rounded to {}, identity transforms):\n",
                         scalar, scalar);
        for (const char* k : {"a", "b"})
            if (w.contains(k))
                s += shapeText(k, w[k]);
        const std::string label = fmt::format("exact (world case, {})", scalar);
        s += exactText(label.c_str(), w["exact"]);
        s += fmt::format("     input change |world - exact| {}\n", fmtNum(w["input_rounding"]));
    }
    return s;
}
} // namespace

std::string explainText(const Json& d)
{
    std::string s = fmt::format("case {}  (family {})\n", d["name"].get<std::string>(),
                                d["family"].get<std::string>());
    // A case file's provenance fields (any string: printed as excerpt() quotes it, printable).
    for (const char* k : {"source", "comment"})
        if (d.contains(k))
            s += fmt::format("  {}: {}\n", k, excerpt(d[k].get<std::string>(), 2000));
    for (const char* k : {"a", "b"})
        s += shapeText(k, d[k]);
    if (d.contains("rejected"))
        return s + fmt::format("  REJECTED: {}\n", d["rejected"].get<std::string>());
    s += exactText("exact", d["exact"]);
    if (d.contains("exact_float_input"))
    {
        s += exactText("exact (float-rounded input)", d["exact_float_input"]);
        s += fmt::format("     input rounding error {}\n", fmtNum(d["input_rounding"]));
    }
    s += worldText(d);
    for (const auto& [name, v] : d["variants"].items())
        s += variantText(name, v);
    return s;
}

} // namespace gjkval
