// Stats and its histograms: folding one judged query, merging (exactly, in any order), the
// report's JSON and the state of shards and checkpoints, all driven by the member tables of
// stats.hpp.
#include "statistics/stats.hpp"

#include "evaluate/evaluate.hpp"

#include "gjk2d/distance.hpp"

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

namespace
{
// The order of WorstViolation (a total preorder, so that merging is exact in any order): a
// measured violation (a finite excess) ranks above one without a size (+inf: a non-finite answer,
// an error status, a crash, a hang), which is the worst only where the family has no measured one;
// among measured ones the larger excess, among equals the earlier case. A maintainer reads a
// measured excess as the routine's bug, a non-finite answer at 1e160 first as a range limit: the
// worst violation is the case `repro` is run on (docs/peers.md), and the count keeps every one.
// 1 when a violation of excess `key` is worse than one of `excess` by size alone, -1 when it is
// less bad, 0 when only the order of the cases can tell them apart.
int sizeOrder(double key, double excess)
{
    const bool measured = std::isfinite(key), otherMeasured = std::isfinite(excess);
    if (measured != otherMeasured)
        return measured ? 1 : -1;
    if (measured && key != excess)
        return key > excess ? 1 : -1;
    return 0;
}

bool ranksAbove(double key, std::uint64_t i, double excess, std::uint64_t index)
{
    const int order = sizeOrder(key, excess);
    return order != 0 ? order > 0 : i < index;
}
} // namespace

bool WorstViolation::outranks(const WorstViolation& o) const
{
    return any && (!o.any || sizeOrder(excess, o.excess) > 0);
}

void WorstViolation::add(double e, const std::string& name, std::uint64_t i, Violation why)
{
    // NaN (a ratio of nothing) ranks as +inf: a violation without a size.
    const double key = std::isnan(e) ? INFINITY : e;
    if (any && !ranksAbove(key, i, excess, index))
        return;
    any = true;
    excess = key;
    caseName = name;
    index = i;
    reason = why;
}

void WorstViolation::merge(const WorstViolation& o)
{
    if (o.any)
        add(o.excess, o.caseName, o.index, o.reason);
}

Json WorstViolation::toJson() const
{
    if (!any)
        return nullptr;
    return Json{{"case", caseName}, {"reason", violationName(reason)}, {"excess", num(excess)}};
}

Json WorstViolation::state() const
{
    if (!any)
        return nullptr;
    return Json{
        {"excess", num(excess)}, {"case", caseName}, {"index", index}, {"reason", int(reason)}};
}

WorstViolation WorstViolation::fromState(const Json& j)
{
    WorstViolation w;
    if (j.is_null())
        return w;
    w.any = true;
    const Json& e = j.at("excess");
    w.excess = e.is_string() ? INFINITY : e.get<double>(); // num() writes +inf as "inf"
    w.caseName = j.at("case").get<std::string>();
    w.index = j.at("index").get<std::uint64_t>();
    const int r = j.at("reason").get<int>();
    if (r < 1 || r > kViolationReasons)
        throw std::runtime_error("stats state: a worst violation without a reason");
    w.reason = Violation(r);
    return w;
}

void PenetrationStats::merge(const PenetrationStats& o)
{
    any = any || o.any;
    for (const PenetrationCountField& f : kPenetrationCounts)
        this->*f.member += o.*f.member;
    for (const PenetrationHistField& f : kPenetrationHists)
        (this->*f.member).merge(o.*f.member);
    worstViolation.merge(o.worstViolation);
}

// report.json's families[].variants[].penetration (docs/report-schema.md): the counts, the worst
// violation, and the histograms (the error over gjk2d's depth bound last).
Json PenetrationStats::toJson() const
{
    Json j = Json::object();
    for (const PenetrationCountField& f : kPenetrationCounts)
        j[f.name] = this->*f.member;
    j["worst_contract_violation"] = worstViolation.toJson();
    for (const PenetrationHistField& f : kPenetrationHists)
        j[f.name] = (this->*f.member).toJson();
    return j;
}

Json PenetrationStats::state() const
{
    if (!any)
        return nullptr;
    Json counts = Json::object(), histograms = Json::object();
    for (const PenetrationCountField& f : kPenetrationCounts)
        counts[f.name] = this->*f.member;
    for (const PenetrationHistField& f : kPenetrationHists)
        histograms[f.name] = (this->*f.member).state();
    return Json{{"counts", std::move(counts)},
                {"histograms", std::move(histograms)},
                {"worst_violation", worstViolation.state()}};
}

PenetrationStats PenetrationStats::fromState(const Json& j)
{
    PenetrationStats p;
    if (j.is_null())
        return p;
    p.any = true;
    for (const PenetrationCountField& f : kPenetrationCounts)
        p.*f.member = j.at("counts").at(f.name).get<std::uint64_t>();
    for (const PenetrationHistField& f : kPenetrationHists)
        p.*f.member = Hist::fromState(j.at("histograms").at(f.name));
    p.worstViolation = WorstViolation::fromState(j.at("worst_violation"));
    return p;
}

namespace
{
template <typename T, std::size_t N>
void addEach(std::array<T, N>& to, const std::array<T, N>& from)
{
    for (std::size_t i = 0; i < N; ++i)
        to[i] += from[i];
}

template <typename T, std::size_t N>
void copyExactly(std::array<T, N>& to, const Json& j, const char* what)
{
    const auto v = j.get<std::vector<T>>();
    if (v.size() != N)
        throw std::runtime_error(std::string("stats state: the number of ") + what + " differs");
    std::copy(v.begin(), v.end(), to.begin());
}

// The contract violations' reasons of a state: an older state has fewer (the reasons added since,
// at the end of Violation, count 0 there).
void readReasons(std::array<std::uint64_t, kViolationReasons>& to, const Json& j)
{
    const auto v = j.get<std::vector<std::uint64_t>>();
    if (v.size() > to.size())
        throw std::runtime_error("stats state: more contract violation reasons than this release "
                                 "knows");
    to.fill(0);
    std::copy(v.begin(), v.end(), to.begin());
}
} // namespace

void Stats::merge(const Stats& o)
{
    for (const CountField& f : kCountFields)
        this->*f.member += o.*f.member;
    for (const PathField& f : kPathFields)
        this->*f.member += o.*f.member;
    for (const HistField& f : kHistFields)
        (this->*f.member).merge(o.*f.member);
    for (const FlagField& f : kFlagFields)
        this->*f.member = this->*f.member || o.*f.member;
    hasPaths = hasPaths || o.hasPaths;
    iterations.merge(o.iterations);
    addEach(invalidReasons, o.invalidReasons);
    addEach(violationReasons, o.violationReasons);
    worstViolation.merge(o.worstViolation);
    addEach(stops, o.stops);
    penetration.merge(o.penetration);
}

// The state: StatsState (docs/report-schema.md), each table's rows in their order.
Json Stats::state() const
{
    Json counts = Json::object(), flags = Json::object(), histograms = Json::object();
    for (const CountField& f : kCountFields)
        counts[f.name] = this->*f.member;
    for (const FlagField& f : kFlagFields)
        flags[f.name] = this->*f.member;
    for (const HistField& f : kHistFields)
        histograms[f.name] = (this->*f.member).state();
    Json paths = nullptr; // null: not a correctly rounded variant
    if (hasPaths)
    {
        paths = Json::array();
        for (const PathField& f : kPathFields)
            paths.push_back(this->*f.member);
    }
    return Json{{"counts", std::move(counts)},
                {"flags", std::move(flags)},
                {"histograms", std::move(histograms)},
                {"paths", std::move(paths)},
                {"invalid_reasons", invalidReasons},
                {"violation_reasons", violationReasons},
                {"worst_violation", worstViolation.state()},
                {"stops", stops},
                {"iterations", iterations.state()},
                {"penetration", penetration.state()}};
}

Stats Stats::fromState(const Json& j)
{
    Stats s;
    for (const CountField& f : kCountFields)
        s.*f.member = j.at("counts").at(f.name).get<std::uint64_t>();
    for (const FlagField& f : kFlagFields)
        s.*f.member = j.at("flags").at(f.name).get<bool>();
    for (const HistField& f : kHistFields)
        s.*f.member = Hist::fromState(j.at("histograms").at(f.name));
    const Json& paths = j.at("paths");
    s.hasPaths = !paths.is_null();
    if (s.hasPaths)
    {
        std::array<std::uint64_t, std::size(kPathFields)> p{};
        copyExactly(p, paths, "correct paths");
        for (std::size_t i = 0; i < p.size(); ++i)
            s.*kPathFields[i].member = p[i];
    }
    copyExactly(s.invalidReasons, j.at("invalid_reasons"), "invalid reasons");
    readReasons(s.violationReasons, j.at("violation_reasons"));
    s.worstViolation = WorstViolation::fromState(j.at("worst_violation"));
    copyExactly(s.stops, j.at("stops"), "stop reasons");
    s.iterations = IterHist::fromState(j.at("iterations"));
    // Absent from a state written before penetration was judged: none.
    s.penetration = PenetrationStats::fromState(j.value("penetration", Json()));
    return s;
}

namespace
{
// The report's top-level counts, with the fields derived beside them (the exceptions in
// stats.hpp): "pass" after failures, "invalid_reasons" after invalid.
void writeCounts(const Stats& s, Json& j)
{
    for (const CountField& f : kCountFields)
    {
        if (f.section != Section::Top)
            continue;
        j[f.name] = s.*f.member;
        if (f.member == &Stats::failures)
            j["pass"] = s.failures == 0;
        if (f.member == &Stats::invalid)
        {
            Json reasons = Json::object();
            for (int i = 0; i < kInvalidReasons; ++i)
                reasons[invalidName(Invalid(i + 1))] = s.invalidReasons[std::size_t(i)];
            j["invalid_reasons"] = std::move(reasons);
        }
    }
    for (const CountField& f : kCountFields)
    {
        if (f.section != Section::Contract)
            continue;
        if (f.member != &Stats::contractViolations)
        {
            j[f.name] = s.*f.member;
            continue;
        }
        Json reasons = Json::object(); // the reasons that occur, in Violation's order
        for (int i = 0; i < kViolationReasons; ++i)
            if (s.violationReasons[std::size_t(i)] > 0)
                reasons[violationName(Violation(i + 1))] = s.violationReasons[std::size_t(i)];
        j[f.name] = {{"count", s.contractViolations},
                     {"reasons", std::move(reasons)},
                     {"worst", s.worstViolation.toJson()}};
    }
}

// The report's Truth rows, under "truth".
Json truthJson(const Stats& s)
{
    Json t = Json::object();
    for (const CountField& f : kCountFields)
        if (f.section == Section::Truth)
            t[f.name] = s.*f.member;
    return t;
}
Json errorsJson(const Stats& s)
{
    Json e;
    for (const HistField& f : kHistFields)
        if (f.section == Section::Top && (f.shownIf == nullptr || s.*f.shownIf))
            e[f.name] = (s.*f.member).toJson();
    return e;
}

// Certified variants: the Interval rows, "misses" (derived) after contains.
Json intervalJson(const Stats& s)
{
    Json in;
    for (const CountField& f : kCountFields)
        if (f.section == Section::Interval)
        {
            in[f.name] = s.*f.member;
            if (f.member == &Stats::contains)
                in["misses"] = s.certified - s.contains;
        }
    for (const HistField& f : kHistFields)
        if (f.section == Section::Interval)
            in[f.name] = (s.*f.member).toJson();
    return in;
}

Json correctJson(const Stats& s)
{
    Json paths;
    for (const PathField& f : kPathFields)
        paths[gjk::correctPathName(f.path)] = s.*f.member;
    Json c{{"paths", std::move(paths)}};
    for (const CountField& f : kCountFields)
        if (f.section == Section::Correct)
            c[f.name] = s.*f.member;
    return c;
}
} // namespace

Json Stats::toJson() const
{
    Json j;
    writeCounts(*this, j);
    j["failure_rate_upper95"] =
        (failures == 0 && cases > 0) ? Json(3.0 / double(cases)) : Json(nullptr);
    j["errors"] = errorsJson(*this);
    j["iterations"] = iterations.toJson();
    if (hasInterval)
        j["interval"] = intervalJson(*this);
    if (hasPaths)
        j["correct"] = correctJson(*this);
    if (penetration.any)
        j["penetration"] = penetration.toJson();
    Json st = Json::object();
    for (int i = 0; i < kStopReasons; ++i)
        st[gjk::stopReasonName(gjk::StopReason(i))] = stops[std::size_t(i)];
    j["stops"] = std::move(st);
    j["ns_per_query"] = nsPerQuery >= 0 ? Json(nsPerQuery) : Json(nullptr);
    j["ns_spread"] = nsPerQuery >= 0 ? Json::array({nsMin, nsMax}) : Json(nullptr);
    j["timing_passes"] = timingPasses;
    j["prepare_ns_per_shape"] = prepareNsPerShape >= 0 ? Json(prepareNsPerShape) : Json(nullptr);
    j["prepared_ns_per_query"] = preparedNsPerQuery >= 0 ? Json(preparedNsPerQuery) : Json(nullptr);
    j["ratio_to_baseline"] = ratioToBaseline >= 0 ? Json(ratioToBaseline) : Json(nullptr);
    j["truth"] = truthJson(*this); // last (Section::Truth)
    return j;
}

// --- Folding one query ---------------------------------------------------------------------------
// statistics/ reads evaluate/'s outcomes: it is the layer above it, as worst.hpp is; stats.hpp only
// names the outcome types.

namespace
{
// A query judged against the truth (not out of range): misclassification, bound, validity and,
// when the answer is finite, its errors.
// One case's truth: how the exact side decided it (exact::Fallbacks).
void addTruth(Stats& s, const exact::Fallbacks& f)
{
    s.truthGmp += f.gmp ? 1 : 0;
    s.truthHull += f.hull > 0 ? 1 : 0;
    s.truthMerge += f.merge > 0 ? 1 : 0;
    s.truthFeature += f.feature > 0 ? 1 : 0;
    s.truthSquared += f.squared ? 1 : 0;
    s.truthDistance += f.distance ? 1 : 0;
    s.truthWitness += f.witness ? 1 : 0;
}

void addJudged(Stats& s, const VariantOutcome& v, const std::string& name, std::uint64_t index)
{
    s.falseOverlap += v.mis == Misclass::FalseOverlap ? 1 : 0;
    s.falseSeparation += v.mis == Misclass::FalseSeparation ? 1 : 0;
    s.undecidable += v.mis == Misclass::Undecidable ? 1 : 0;
    s.beyondBound += v.beyondBound ? 1 : 0;
    if (v.invalid != Invalid::None)
    {
        ++s.invalid;
        ++s.invalidReasons[std::size_t(v.invalid) - 1];
    }
    if (v.nonfinite)
        return;
    s.abs.add(v.abs, name, index);
    s.rel.add(v.rel, name, index); // NaN (not applicable) is ignored by add()
    s.ulps.add(v.ulps, name, index);
    s.normalized.add(v.normalized, name, index);
    s.boundRatio.add(v.boundRatio, name, index);
    s.witness.add(v.witness, name, index);
    s.witnessGap.add(v.witnessGap, name, index);
    s.witnessRatio.add(v.witnessRatio, name, index); // NaN (not checked) is ignored
}

// The answer's class by its implementation's contract: a violation (by reason, the worst kept),
// or, keeping it, judged and beyond gjk2d's bound.
void addContract(Stats& s, const VariantOutcome& v, const std::string& name, std::uint64_t index)
{
    if (!v.keepsContract())
    {
        ++s.contractViolations;
        ++s.violationReasons[std::size_t(v.violation) - 1];
        s.worstViolation.add(v.violationExcess, name, index, v.violation);
    }
    else if (!v.outOfRange && v.beyondBound)
        ++s.beyondBoundKeepingContract;
}

// Certified variants: the interval given, whether it holds the truth, its width.
void addInterval(Stats& s, const VariantOutcome& v, const std::string& name, std::uint64_t index,
                 const VariantInfo& vi)
{
    s.hasInterval = true;
    if (!v.certified)
    {
        ++s.uncertified;
        return;
    }
    ++s.certified;
    s.contains += v.intervalContains ? 1 : 0;
    if (v.truth > 0)
        s.widthUlps.add((v.upper - v.lower) / ulpOf(vi.scalar, v.truth), name, index);
}
} // namespace

// One answer of a penetration contract on shapes whose exact signed distance is < 0.
void PenetrationStats::add(const VariantOutcome& v, const std::string& name, std::uint64_t index)
{
    ++cases;
    if (!v.keepsContract())
    {
        ++contractViolations;
        worstViolation.add(v.violationExcess, name, index, v.violation);
    }
    beyondBound += v.beyondDepthBound ? 1 : 0;
    beyondBoundKeepingContract += v.beyondDepthBound && v.keepsContract() ? 1 : 0;
    if (v.nonfinite)
    {
        ++nonfinite;
        return;
    }
    abs.add(v.depthAbs, name, index);
    rel.add(v.depthRel, name, index);
    boundRatio.add(v.depthRatio, name, index);
}

void Stats::add(const VariantOutcome& v, const std::string& name, std::uint64_t index,
                const VariantInfo& vi, const CaseOutcome& o)
{
    penetration.any = penetration.any || contractOf(vi).overlap == Overlap::Penetration;
    if (v.plugin == PluginStatus::Refused)
    {
        ++refused;
        return;
    }
    if (v.skipped)
    {
        ++skipped;
        notApplicable += v.notApplicable ? 1 : 0;
        return;
    }
    ++cases;
    // The truth the answer was judged on: the case's, its float rounding's, or its world case's.
    const int view = inputView(vi);
    addTruth(*this, viewTruth(o, view).fallbacks);
    failures += v.failed ? 1 : 0;
    addContract(*this, v, name, index);
    if (v.plugin != PluginStatus::NotRun && v.plugin != PluginStatus::Ok)
    {
        pluginErrors += v.plugin == PluginStatus::Error ? 1 : 0;
        crashed += v.plugin == PluginStatus::Crashed ? 1 : 0;
        hung += v.plugin == PluginStatus::Hung ? 1 : 0;
        return; // no answer to measure
    }
    witnessPoints += std::uint64_t(v.witnessPoints);
    witnessExact += std::uint64_t(v.witnessExact);
    outOfRange += v.outOfRange ? 1 : 0;
    nonfinite += v.nonfinite ? 1 : 0;
    iterationLimit += v.iterationLimit ? 1 : 0;
    if (!v.outOfRange) // cases GJK flags out of range are counted apart, not judged
        addJudged(*this, v, name, index);
    if (!v.outOfRange && v.depthJudged)
        penetration.add(v, name, index);
    if (viewIsWorld(view)) // |exact(world case) - exact(case)|, double or float
    {
        hasInputRounding = true;
        inputRounding.add(o.world[view - 2]->inputRounding, name, index);
    }
    else if (vi.scalar == Scalar::Float)
    {
        hasInputRounding = true;
        inputRounding.add(o.inputRounding, name, index);
    }
    if (vi.options.certify)
        addInterval(*this, v, name, index, vi);
    if (vi.plugin)
    {
        if (v.iterations >= 0) // -1: the implementation does not count
            iterations.add(v.iterations);
        return; // no stop reason
    }
    if (vi.options.correctlyRounded)
    {
        hasPaths = true;
        for (const PathField& f : kPathFields)
            this->*f.member += v.path == f.path ? 1 : 0;
        bitMismatch += v.bitMismatch ? 1 : 0;
    }
    iterations.add(v.iterations);
    ++stops[std::size_t(v.stop)];
}

} // namespace gjkval
