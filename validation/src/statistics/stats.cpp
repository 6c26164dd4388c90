#include "statistics/stats.hpp"

#include "gjk/distance.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gjkval
{

std::size_t Hist::binOf(double v) const
{
    const double x = std::floor((std::log10(v) - log10Min) * binsPerDecade);
    if (!(x > 0))
        return 0;
    return std::min(std::size_t(x), binCount() - 1);
}

double Hist::upperEdge(std::size_t bin) const
{
    return std::pow(10.0, log10Min + double(bin + 1) / binsPerDecade);
}

void Hist::add(double v, const std::string& caseName, std::uint64_t index)
{
    if (!(v >= 0) || !std::isfinite(v))
        return;
    ++count;
    total.add(v);
    if (count == 1 || v > max || (v == max && index < maxIndex)) // ties: the earlier case
    {
        max = v;
        maxCase = caseName;
        maxIndex = index;
    }
    if (v == 0)
    {
        ++zeros;
        return;
    }
    if (counts.empty())
        counts.assign(binCount(), 0);
    ++counts[binOf(v)];
}

void Hist::merge(const Hist& o)
{
    if (o.count == 0)
        return;
    if (count == 0)
    {
        *this = o;
        return;
    }
    if (o.max > max || (o.max == max && o.maxIndex < maxIndex))
    {
        max = o.max;
        maxCase = o.maxCase;
        maxIndex = o.maxIndex;
    }
    count += o.count;
    zeros += o.zeros;
    total.merge(o.total);
    if (!o.counts.empty())
    {
        if (counts.empty())
            counts.assign(binCount(), 0);
        for (std::size_t i = 0; i < counts.size(); ++i)
            counts[i] += o.counts[i];
    }
}

double Hist::percentile(std::uint64_t num, std::uint64_t den) const
{
    if (count == 0)
        return 0;
    std::uint64_t rank = (count * num + den - 1) / den;
    rank = std::max<std::uint64_t>(rank, 1);
    std::uint64_t cum = zeros;
    if (cum >= rank)
        return 0;
    for (std::size_t i = 0; i < counts.size(); ++i)
    {
        cum += counts[i];
        if (cum >= rank)
            return upperEdge(i);
    }
    return max;
}

Json Hist::toJson() const
{
    Json j;
    j["count"] = count;
    j["zeros"] = zeros;
    j["max"] = num(max);
    j["mean"] = num(mean());
    j["sum"] = num(sum());
    j["p50"] = num(percentile(500, 1000));
    j["p99"] = num(percentile(990, 1000));
    j["p999"] = num(percentile(999, 1000));
    j["log10_min"] = log10Min;
    j["bins_per_decade"] = binsPerDecade;
    // Trailing empty bins are left out: counts[i] for i >= size() are 0.
    std::size_t last = counts.size();
    while (last > 0 && counts[last - 1] == 0)
        --last;
    j["counts"] = std::vector<std::uint64_t>(counts.begin(), counts.begin() + std::ptrdiff_t(last));
    j["max_case"] = maxCase;
    return j;
}

Json Hist::state() const
{
    return Json{{"range", {log10Min, log10Max, binsPerDecade}},
                {"count", count},
                {"zeros", zeros},
                {"max", max},
                {"max_case", maxCase},
                {"max_index", maxIndex},
                {"total", total.toJson()},
                {"counts", counts}};
}

Hist Hist::fromState(const Json& j)
{
    const Json& r = j.at("range");
    Hist h(r.at(0).get<int>(), r.at(1).get<int>(), r.at(2).get<int>());
    h.count = j.at("count").get<std::uint64_t>();
    h.zeros = j.at("zeros").get<std::uint64_t>();
    h.max = j.at("max").get<double>();
    h.maxCase = j.at("max_case").get<std::string>();
    h.maxIndex = j.at("max_index").get<std::uint64_t>();
    h.total = ExactSum::fromJson(j.at("total"));
    h.counts = j.at("counts").get<std::vector<std::uint64_t>>();
    if (!h.counts.empty() && h.counts.size() != h.binCount())
        throw std::runtime_error("histogram state: counts do not match the binning");
    return h;
}

void IterHist::add(int it)
{
    ++count;
    sum += std::uint64_t(it);
    max = std::max(max, it);
    if (counts.size() <= std::size_t(it))
        counts.resize(std::size_t(it) + 1, 0);
    ++counts[std::size_t(it)];
}

void IterHist::merge(const IterHist& o)
{
    count += o.count;
    sum += o.sum;
    max = std::max(max, o.max);
    if (counts.size() < o.counts.size())
        counts.resize(o.counts.size(), 0);
    for (std::size_t i = 0; i < o.counts.size(); ++i)
        counts[i] += o.counts[i];
}

Json IterHist::toJson() const
{
    Json j;
    j["max"] = max;
    j["mean"] = count ? double(sum) / double(count) : 0.0;
    j["counts"] = counts;
    return j;
}

Json IterHist::state() const
{
    return Json{{"count", count}, {"max", max}, {"sum", sum}, {"counts", counts}};
}

IterHist IterHist::fromState(const Json& j)
{
    IterHist h;
    h.count = j.at("count").get<std::uint64_t>();
    h.max = j.at("max").get<int>();
    h.sum = j.at("sum").get<std::uint64_t>();
    h.counts = j.at("counts").get<std::vector<std::uint64_t>>();
    return h;
}

void Stats::merge(const Stats& o)
{
    cases += o.cases;
    failures += o.failures;
    falseOverlap += o.falseOverlap;
    falseSeparation += o.falseSeparation;
    undecidable += o.undecidable;
    nonfinite += o.nonfinite;
    outOfRange += o.outOfRange;
    iterationLimit += o.iterationLimit;
    beyondBound += o.beyondBound;
    invalid += o.invalid;
    for (int i = 0; i < kInvalidReasons; ++i)
        invalidReasons[std::size_t(i)] += o.invalidReasons[std::size_t(i)];
    skipped += o.skipped;
    notApplicable += o.notApplicable;
    refused += o.refused;
    pluginErrors += o.pluginErrors;
    crashed += o.crashed;
    hung += o.hung;
    hasInterval = hasInterval || o.hasInterval;
    certified += o.certified;
    contains += o.contains;
    uncertified += o.uncertified;
    hasPaths = hasPaths || o.hasPaths;
    pathDouble += o.pathDouble;
    pathExtended += o.pathExtended;
    pathDoubleDouble += o.pathDoubleDouble;
    pathExact += o.pathExact;
    bitMismatch += o.bitMismatch;
    widthUlps.merge(o.widthUlps);
    abs.merge(o.abs);
    rel.merge(o.rel);
    ulps.merge(o.ulps);
    normalized.merge(o.normalized);
    boundRatio.merge(o.boundRatio);
    witness.merge(o.witness);
    witnessGap.merge(o.witnessGap);
    witnessRatio.merge(o.witnessRatio);
    inputRounding.merge(o.inputRounding);
    hasInputRounding = hasInputRounding || o.hasInputRounding;
    iterations.merge(o.iterations);
    for (int i = 0; i < kStopReasons; ++i)
        stops[std::size_t(i)] += o.stops[std::size_t(i)];
}

namespace
{
// Stats' merged members, by name, for state() and fromState(): one list for both directions.
template <typename S, typename Count, typename Flag, typename H>
void forEachMember(S& s, Count&& count, Flag&& flag, H&& hist)
{
    count("cases", s.cases);
    count("failures", s.failures);
    count("false_overlap", s.falseOverlap);
    count("false_separation", s.falseSeparation);
    count("undecidable", s.undecidable);
    count("nonfinite", s.nonfinite);
    count("out_of_range", s.outOfRange);
    count("iteration_limit", s.iterationLimit);
    count("beyond_bound", s.beyondBound);
    count("skipped", s.skipped);
    count("not_applicable", s.notApplicable);
    count("refused", s.refused);
    count("plugin_errors", s.pluginErrors);
    count("crashed", s.crashed);
    count("hung", s.hung);
    count("certified", s.certified);
    count("contains", s.contains);
    count("uncertified", s.uncertified);
    flag("has_interval", s.hasInterval);
    flag("has_input_rounding", s.hasInputRounding);
    hist("width_ulps", s.widthUlps);
    hist("abs", s.abs);
    hist("rel", s.rel);
    hist("ulps", s.ulps);
    hist("normalized", s.normalized);
    hist("bound_ratio", s.boundRatio);
    hist("witness", s.witness);
    hist("witness_gap", s.witnessGap);
    hist("input_rounding", s.inputRounding);
}
} // namespace

Json Stats::state() const
{
    Json j;
    forEachMember(
        *this, [&](const char* k, const std::uint64_t& v) { j[k] = v; },
        [&](const char* k, const bool& v) { j[k] = v; },
        [&](const char* k, const Hist& h) { j[k] = h.state(); });
    j["iterations"] = iterations.state();
    j["stops"] = stops;
    j["invalid"] = invalid;
    j["invalid_reasons"] = invalidReasons;
    j["witness_ratio"] = witnessRatio.state();
    if (hasPaths) // written only by correctly rounded variants (older states have none)
        j["correct_paths"] = {pathDouble, pathDoubleDouble, pathExact, bitMismatch, pathExtended};
    return j;
}

Stats Stats::fromState(const Json& j)
{
    Stats s;
    forEachMember(
        s, [&](const char* k, std::uint64_t& v) { v = j.at(k).get<std::uint64_t>(); },
        [&](const char* k, bool& v) { v = j.at(k).get<bool>(); },
        [&](const char* k, Hist& h) { h = Hist::fromState(j.at(k)); });
    s.iterations = IterHist::fromState(j.at("iterations"));
    const auto stops = j.at("stops").get<std::vector<std::uint64_t>>();
    if (stops.size() != s.stops.size())
        throw std::runtime_error("stats state: the number of stop reasons differs");
    std::copy(stops.begin(), stops.end(), s.stops.begin());
    if (j.contains("invalid")) // states before issue 30 have none
    {
        s.invalid = j.at("invalid").get<std::uint64_t>();
        const auto r = j.at("invalid_reasons").get<std::vector<std::uint64_t>>();
        if (r.size() != s.invalidReasons.size())
            throw std::runtime_error("stats state: the number of invalid reasons differs");
        std::copy(r.begin(), r.end(), s.invalidReasons.begin());
        s.witnessRatio = Hist::fromState(j.at("witness_ratio"));
    }
    if (j.contains("correct_paths"))
    {
        const auto p = j.at("correct_paths").get<std::vector<std::uint64_t>>();
        if (p.size() != 4 && p.size() != 5) // 4: before CorrectPath::Extended
            throw std::runtime_error("stats state: correct_paths needs 4 or 5 counts");
        s.hasPaths = true;
        s.pathDouble = p[0];
        s.pathDoubleDouble = p[1];
        s.pathExact = p[2];
        s.bitMismatch = p[3];
        s.pathExtended = p.size() == 5 ? p[4] : 0;
    }
    return s;
}

Json Stats::toJson() const
{
    Json j;
    j["cases"] = cases;
    j["failures"] = failures;
    j["pass"] = failures == 0;
    j["false_overlap"] = falseOverlap;
    j["false_separation"] = falseSeparation;
    j["undecidable"] = undecidable;
    j["nonfinite"] = nonfinite;
    j["out_of_range"] = outOfRange;
    j["iteration_limit"] = iterationLimit;
    j["beyond_bound"] = beyondBound;
    j["invalid"] = invalid;
    Json reasons = Json::object();
    for (int i = 0; i < kInvalidReasons; ++i)
        reasons[invalidName(Invalid(i + 1))] = invalidReasons[std::size_t(i)];
    j["invalid_reasons"] = std::move(reasons);
    j["skipped"] = skipped;
    j["not_applicable"] = notApplicable;
    j["refused"] = refused;
    j["plugin_errors"] = pluginErrors;
    j["crashed"] = crashed;
    j["hung"] = hung;
    j["failure_rate_upper95"] =
        (failures == 0 && cases > 0) ? Json(3.0 / double(cases)) : Json(nullptr);
    Json e;
    e["abs"] = abs.toJson();
    e["rel"] = rel.toJson();
    e["ulps"] = ulps.toJson();
    e["normalized"] = normalized.toJson();
    e["bound_ratio"] = boundRatio.toJson();
    e["witness"] = witness.toJson();
    e["witness_gap"] = witnessGap.toJson();
    e["witness_ratio"] = witnessRatio.toJson();
    if (hasInputRounding)
        e["input_rounding"] = inputRounding.toJson();
    j["errors"] = std::move(e);
    j["iterations"] = iterations.toJson();
    if (hasInterval)
        j["interval"] = {{"certified", certified},
                         {"contains", contains},
                         {"misses", certified - contains},
                         {"uncertified", uncertified},
                         {"width_ulps", widthUlps.toJson()}};
    if (hasPaths)
        j["correct"] = {{"paths",
                         {{"double", pathDouble},
                          {"extended", pathExtended},
                          {"double-double", pathDoubleDouble},
                          {"exact", pathExact}}},
                        {"bit_mismatches", bitMismatch}};
    Json st = Json::object();
    for (int i = 0; i < kStopReasons; ++i)
        st[gjk::stopReasonName(gjk::StopReason(i))] = stops[std::size_t(i)];
    j["stops"] = std::move(st);
    j["ns_per_query"] = nsPerQuery >= 0 ? Json(nsPerQuery) : Json(nullptr);
    j["ns_spread"] = nsPerQuery >= 0 ? Json::array({nsMin, nsMax}) : Json(nullptr);
    j["timing_passes"] = timingPasses;
    j["ratio_to_baseline"] = ratioToBaseline >= 0 ? Json(ratioToBaseline) : Json(nullptr);
    return j;
}

} // namespace gjkval
