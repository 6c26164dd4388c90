#include "statistics/stats.hpp"

#include "gjk/distance.hpp"

#include <algorithm>
#include <cmath>

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

void Hist::add(double v, const std::string& caseName)
{
    if (!(v >= 0) || !std::isfinite(v))
        return;
    ++count;
    sum += v;
    if (count == 1 || v > max) // ties keep the first case in case order
    {
        max = v;
        maxCase = caseName;
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
    if (o.max > max)
    {
        max = o.max;
        maxCase = o.maxCase;
    }
    count += o.count;
    zeros += o.zeros;
    sum += o.sum;
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
    j["sum"] = num(sum);
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

void IterHist::add(int it)
{
    ++count;
    sum += it;
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
    j["mean"] = count ? sum / double(count) : 0.0;
    j["counts"] = counts;
    return j;
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
    skipped += o.skipped;
    notApplicable += o.notApplicable;
    hasInterval = hasInterval || o.hasInterval;
    certified += o.certified;
    contains += o.contains;
    uncertified += o.uncertified;
    widthUlps.merge(o.widthUlps);
    abs.merge(o.abs);
    rel.merge(o.rel);
    ulps.merge(o.ulps);
    normalized.merge(o.normalized);
    boundRatio.merge(o.boundRatio);
    witness.merge(o.witness);
    witnessGap.merge(o.witnessGap);
    inputRounding.merge(o.inputRounding);
    hasInputRounding = hasInputRounding || o.hasInputRounding;
    iterations.merge(o.iterations);
    for (int i = 0; i < kStopReasons; ++i)
        stops[std::size_t(i)] += o.stops[std::size_t(i)];
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
    j["skipped"] = skipped;
    j["not_applicable"] = notApplicable;
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
