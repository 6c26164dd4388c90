// A family's make-up checks folded case by case (makeup.hpp): each metric's value of one case, the
// fold that keeps a count, a minimum or a maximum, its merge and its state for shards.
#include "statistics/makeup.hpp"

#include "evaluate/evaluate.hpp"
#include "inputs/geometry.hpp"

#include "gjk2d/math.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace gjkval
{
namespace
{
using M = MakeupMetric;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNone = std::numeric_limits<double>::quiet_NaN(); // the case adds nothing

enum class Fold
{
    Fraction, // the count of cases whose value is 1, over the cases
    Min,
    Max,
    Distinct,
};

Fold foldOf(M m)
{
    switch (m)
    {
    case M::OverlapFraction:
    case M::SeparatedFraction:
    case M::NearTouchingFraction:
    case M::RadiusFraction:
    case M::OutsideFloatRangeFraction:
    case M::SharedOriginFraction:
    case M::NonUnitRotationFraction:
        return Fold::Fraction;
    case M::MinPositiveDistance:
    case M::MinVertices:
    case M::MinHullVertices:
    case M::MinScale:
    case M::MinEdgeRatio:
    case M::MinSizeRatio:
        return Fold::Min;
    case M::MaxDistance:
    case M::MaxCoordinate:
    case M::MaxVertices:
    case M::MaxAspect:
    case M::MaxSizeRatio:
    case M::MaxPolygonRadius:
        return Fold::Max;
    case M::DistinctDistances:
        return Fold::Distinct;
    }
    throw std::logic_error("makeup: a metric without a fold");
}

// The value a fold starts from: an empty family reports it.
double initial(Fold f)
{
    return f == Fold::Min ? kInf : 0;
}

double sizeRatio(const Case& c)
{
    const double da = hullDiameter(convexHull(c.a.points));
    const double db = hullDiameter(convexHull(c.b.points));
    return std::min(da, db) > 0 ? std::max(da, db) / std::min(da, db) : kInf;
}

bool nonUnit(const ShapeIn& s)
{
    return s.c * s.c + s.s * s.s != 1;
}

// The larger finite aspect ratio of the two shapes; kNone when neither has one.
double maxAspect(const Case& c)
{
    double v = kNone;
    for (const ShapeIn* sh : {&c.a, &c.b})
        if (const double a = aspectRatio(*sh); std::isfinite(a))
            v = std::isnan(v) ? a : std::max(v, a);
    return v;
}

// The smaller shortest-edge-over-diameter ratio of the two hulls; kNone when neither hull has 3
// vertices.
double minEdgeRatio(const Case& c)
{
    double v = kNone;
    for (const ShapeIn* sh : {&c.a, &c.b})
    {
        const auto h = convexHull(sh->points);
        if (h.size() < 3)
            continue;
        double shortest = kInf;
        for (std::size_t i = 0; i < h.size(); ++i)
            shortest = std::min(shortest, std::hypot(h[(i + 1) % h.size()][0] - h[i][0],
                                                     h[(i + 1) % h.size()][1] - h[i][1]));
        const double ratio = shortest / hullDiameter(h);
        v = std::isnan(v) ? ratio : std::min(v, ratio);
    }
    return v;
}

// 1 when the case's largest world coordinate is outside float's query range (gjk::Tolerances).
double outsideFloatRange(const Case& c)
{
    const double x = maxAbsWorldCoordinate(c);
    return (x >= double(gjk::Tolerances<float>::minCoordinate) &&
            x <= double(gjk::Tolerances<float>::maxCoordinate))
               ? 0
               : 1;
}

// The larger radius of a shape with at least 3 points (0 when neither has).
double maxPolygonRadius(const Case& c)
{
    double v = 0;
    for (const ShapeIn* sh : {&c.a, &c.b})
        if (sh->points.size() >= 3)
            v = std::max(v, sh->radius);
    return v;
}

// One case's value for a metric: 0 or 1 for a fraction (SeparatedFraction counts the overlaps and
// is 1 - their fraction, as the check was first written), its value for a minimum or maximum,
// kNone when the case has none (no finite aspect, no hull of 3 vertices, touching).
double caseValue(M m, const Case& c, const exact::Result& t)
{
    switch (m)
    {
    case M::OverlapFraction:
    case M::SeparatedFraction:
        return exactIsZero(t) ? 1 : 0;
    case M::NearTouchingFraction:
        return (!exactIsZero(t) && t.distance <= 1e-2) ? 1 : 0;
    case M::MinPositiveDistance:
        return exactIsZero(t) ? kNone : t.distance;
    case M::MaxDistance:
        return t.distance;
    case M::MaxCoordinate:
    case M::MinScale:
        return maxAbsWorldCoordinate(c);
    case M::MinVertices:
        return double(std::min(c.a.points.size(), c.b.points.size()));
    case M::MaxVertices:
        return double(std::max(c.a.points.size(), c.b.points.size()));
    case M::MinHullVertices:
        return double(std::min(convexHull(c.a.points).size(), convexHull(c.b.points).size()));
    case M::MaxAspect:
        return maxAspect(c);
    case M::RadiusFraction:
        return (c.a.radius > 0 || c.b.radius > 0) ? 1 : 0;
    case M::MinEdgeRatio:
        return minEdgeRatio(c);
    case M::MinSizeRatio:
    case M::MaxSizeRatio:
        return sizeRatio(c);
    case M::OutsideFloatRangeFraction:
        return outsideFloatRange(c);
    case M::DistinctDistances:
        return t.distance;
    case M::SharedOriginFraction:
        return (c.a.px == c.b.px && c.a.py == c.b.py) ? 1 : 0;
    case M::MaxPolygonRadius:
        return maxPolygonRadius(c);
    case M::NonUnitRotationFraction:
        return (nonUnit(c.a) || nonUnit(c.b)) ? 1 : 0;
    }
    throw std::logic_error("makeup: a metric without a value");
}
} // namespace

MakeupFold::MakeupFold(std::vector<MakeupSpec> specs)
{
    for (auto& s : specs)
    {
        const double v = initial(foldOf(s.metric));
        checks_.push_back({std::move(s), v, {}});
    }
}

void MakeupFold::add(const Case& c, const exact::Result& truth)
{
    ++cases_;
    for (auto& k : checks_)
    {
        const double v = caseValue(k.spec.metric, c, truth);
        if (std::isnan(v))
            continue;
        switch (foldOf(k.spec.metric))
        {
        case Fold::Fraction:
            k.value += v;
            break;
        case Fold::Min:
            k.value = std::min(k.value, v);
            break;
        case Fold::Max:
            k.value = std::max(k.value, v);
            break;
        case Fold::Distinct:
            if (k.values.size() < kMaxDistinctCounted)
                k.values.insert(v);
            break;
        }
    }
}

void MakeupFold::merge(const MakeupFold& o)
{
    if (o.checks_.size() != checks_.size())
        throw std::logic_error("MakeupFold::merge: folds of different checks");
    cases_ += o.cases_;
    for (std::size_t i = 0; i < checks_.size(); ++i)
    {
        Check& k = checks_[i];
        const Check& b = o.checks_[i];
        switch (foldOf(k.spec.metric))
        {
        case Fold::Fraction:
            k.value += b.value; // whole counts below 2^53: exact
            break;
        case Fold::Min:
            k.value = std::min(k.value, b.value);
            break;
        case Fold::Max:
            k.value = std::max(k.value, b.value);
            break;
        case Fold::Distinct: // min(kMaxDistinctCounted, distinct values of both), as add() keeps
            for (double v : b.values)
                if (k.values.size() < kMaxDistinctCounted)
                    k.values.insert(v);
            break;
        }
    }
}

Json MakeupFold::state() const
{
    Json checks = Json::array();
    for (const auto& k : checks_)
        checks.push_back({{"check", k.spec.check},
                          {"value", k.value},
                          {"values", std::vector<double>(k.values.begin(), k.values.end())}});
    return Json{{"cases", cases_}, {"checks", std::move(checks)}};
}

MakeupFold MakeupFold::fromState(std::vector<MakeupSpec> specs, const Json& j)
{
    MakeupFold f(std::move(specs));
    const Json& checks = j.at("checks");
    if (checks.size() != f.checks_.size())
        throw std::runtime_error("make-up state: a different number of checks");
    f.cases_ = j.at("cases").get<std::uint64_t>();
    for (std::size_t i = 0; i < f.checks_.size(); ++i)
    {
        Check& k = f.checks_[i];
        if (checks[i].at("check").get<std::string>() != k.spec.check)
            throw std::runtime_error("make-up state: check '" + k.spec.check + "' is missing");
        // A minimum may be +inf (no case yet): JSON has no infinity, and nlohmann writes null.
        const Json& v = checks[i].at("value");
        k.value = v.is_null() ? kInf : v.get<double>();
        for (double x : checks[i].at("values").get<std::vector<double>>())
            k.values.insert(x);
    }
    return f;
}

namespace
{
// The range a check is judged by at n cases, and why it differs from the table's (makeup.hpp).
struct Judged
{
    double min, max;
    bool skipped = false;
    std::string note{};
};

Judged judgedRange(const MakeupSpec& s, std::uint64_t n)
{
    const Fold fold = foldOf(s.metric);
    const std::uint64_t f = s.measuredAt;
    const bool caseByCase =
        s.scope == MakeupScope::EveryCase ||
        (fold == Fold::Fraction && s.min == s.max && (s.min == 0 || s.min == 1));
    if (caseByCase || f == 0 || n == f || (n > f && !s.sweep))
        return {s.min, s.max};
    if (n < f)
    {
        const std::string fewer = fmt::format("fewer than {} cases: ", f);
        switch (fold)
        {
        case Fold::Fraction:
            return {s.min, s.max, true, fewer + "reported, not judged"};
        case Fold::Min:
            if (s.min == -kInf) // no bound left to judge: reported with the table's range
                return {s.min, s.max, true, fewer + "reported, not judged"};
            return {s.min, kInf, false, fewer + "only the lower bound is judged"};
        case Fold::Max:
        case Fold::Distinct:
            if (s.max == kInf)
                return {s.min, s.max, true, fewer + "reported, not judged"};
            return {fold == Fold::Max ? -kInf : 1, s.max, false,
                    fewer + "only the upper bound is judged"};
        }
    }
    const std::uint64_t k = n / f, r = n % f;
    const std::string sweeps = fmt::format("scaled to {} cases: {} sweep(s) of {}", n, k, f);
    switch (fold)
    {
    case Fold::Fraction:
        return {double(k * f) * s.min / double(n), (double(k * f) * s.max + double(r)) / double(n),
                false, sweeps + fmt::format(" and {} more", r)};
    case Fold::Distinct:
        return {s.min, s.max * double(k + (r > 0 ? 1 : 0)), false, sweeps};
    default:
        return {s.min, s.max};
    }
}
} // namespace

std::vector<MakeupResult> MakeupFold::results() const
{
    std::vector<MakeupResult> out;
    const double n = double(cases_);
    for (const auto& k : checks_)
    {
        double v = k.value;
        switch (foldOf(k.spec.metric))
        {
        case Fold::Fraction:
            v = n > 0 ? v / n : 0;
            if (k.spec.metric == M::SeparatedFraction)
                v = n > 0 ? 1 - v : 0;
            break;
        case Fold::Distinct:
            v = double(k.values.size());
            break;
        default:
            break;
        }
        const Judged j = judgedRange(k.spec, cases_);
        const bool inRange = v >= j.min && v <= j.max;
        out.push_back({k.spec.check, v, j.min, j.max, j.skipped || inRange, j.skipped, j.note});
    }
    return out;
}

std::vector<MakeupResult> evaluateMakeup(const std::vector<MakeupSpec>& specs,
                                         const std::vector<const Case*>& cases,
                                         const std::vector<const exact::Result*>& truths)
{
    MakeupFold fold(specs);
    for (std::size_t i = 0; i < cases.size(); ++i)
        fold.add(*cases[i], *truths[i]);
    return fold.results();
}

} // namespace gjkval
