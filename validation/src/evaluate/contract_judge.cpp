// Each answer judged by its implementation's own contract (implementations/contract.hpp; docs/
// judgement.md, "Contracts"): the first of three classes of an answer (a contract violation, with
// its reason; then keeping the contract but beyond gjk2d's bound; then within it). gjk2d's own
// contract is gjk2d's judge: a violation is exactly `failed` (failedAnswer), named by its first
// reason. A declared contract (a version-2 plugin's) is held clause by clause, in this file's
// order; the first clause broken names the violation.
#include "evaluate/evaluate.hpp"

#include "inputs/geometry.hpp"

#include <cmath>
#include <limits>
#include <optional>

namespace gjkval
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

// measured / allowed, +inf when nothing is allowed (a tolerance of 0).
double excessOf(double measured, double allowed)
{
    return allowed > 0 ? measured / allowed : kInf;
}

void breaks(VariantOutcome& v, Violation why, double excess = kInf)
{
    v.violation = why;
    v.violationExcess = excess;
}

// gjk2d's own contract: failedAnswer's reasons, the first that applies in the enum's order (a
// plugin's status, non-finite, invalid, then the distance's own: misclassified or beyond the bound,
// the signed variants' depth beyond the depth bound, then gjk2d's special variants' iteration
// limit, interval and bits). The excess of a distance reason is the error over the bound, of a
// depth reason the depth error over the depth bound, of a witness reason the witness ratio.
void judgeOwn(VariantOutcome& v)
{
    v.tolerance = v.bound;
    v.witnessTolerance = v.witnessBound;
    v.depthTolerance = v.depthBound;
    if (!v.failed)
        return;
    if (v.plugin == PluginStatus::Error || v.plugin == PluginStatus::Crashed ||
        v.plugin == PluginStatus::Hung)
        return breaks(v, v.plugin == PluginStatus::Error     ? Violation::Error
                         : v.plugin == PluginStatus::Crashed ? Violation::Crashed
                                                             : Violation::Hung);
    const bool judged = !v.outOfRange;
    if (judged && v.nonfinite)
        return breaks(v, Violation::Nonfinite);
    if (judged && v.invalid == Invalid::NegativeDistance)
        return breaks(v, Violation::NegativeDistance);
    if (judged && v.invalid == Invalid::WitnessOffShape)
        return breaks(v, Violation::WitnessOffShape, v.witnessRatio);
    if (judged && v.invalid == Invalid::WitnessGap)
        return breaks(v, Violation::WitnessGap, excessOf(v.witnessGap, v.witnessBound));
    if (judged && v.mis == Misclass::FalseOverlap)
        return breaks(v, Violation::FalseOverlap, v.boundRatio);
    if (judged && v.mis == Misclass::FalseSeparation)
        return breaks(v, Violation::FalseSeparation, v.boundRatio);
    if (judged && v.beyondBound)
        return breaks(v, Violation::Distance, v.boundRatio);
    if (judged && v.beyondDepthBound)
        return breaks(v, Violation::DepthOff, v.depthRatio);
    if (judged && v.iterationLimit)
        return breaks(v, Violation::IterationLimit);
    if (v.certified && !v.intervalContains)
        return breaks(v, Violation::Interval);
    breaks(v, Violation::BitMismatch); // the one reason left (failedAnswer)
}

// T and W for a declared contract (the answer's v.bound and v.witnessBound set): T = abs + rel *
// exact + gjk2d's bound, a clause not stated counting 0, or gjk2d's bound alone when neither is
// stated; W = max(gjk2d's witness bound, T) when a tolerance is stated (a library that promises its
// distance to T cannot promise its points closer), else gjk2d's witness bound.
// Why the bound is added to a stated tolerance: a library's tolerance is its stopping rule (GJK
// stops when the gap is within it), a promise about the iteration, not about the rounding of its
// scalar type, which grows with the coordinates. parry's absolute 1.19e-6 in f32 cannot hold on a
// case of coordinates 1e9 (a depth of 6.59e9 answered 1,112 off, relative 1.7e-7, in
// random:2000 + hard): held to the tolerance alone, that is a "violation" no maintainer would
// accept. gjk2d's a-priori bound for the scalar type stands in for that rounding.
void setTolerances(VariantOutcome& v, const Contract& c)
{
    if (!c.statesTolerance())
    {
        v.tolerance = v.bound;
        v.witnessTolerance = v.witnessBound;
        return;
    }
    v.tolerance =
        std::max(c.absTolerance, 0.0) + std::max(c.relTolerance, 0.0) * std::abs(v.truth) + v.bound;
    v.witnessTolerance = std::max(v.witnessBound, v.tolerance);
}

// Separated shapes (exact > 0): a claim of overlap keeps the contract within T of touching (its
// points are then not judged); a distance within T; each point within W of its shape (phase 3's
// v.witness, the larger of the two), ||pB - pA|| within W of d.
void judgeSeparated(VariantOutcome& v, bool claimsOverlap)
{
    const double T = v.tolerance, W = v.witnessTolerance;
    if (claimsOverlap)
    {
        if (!(v.truth <= T))
            breaks(v, Violation::FalseOverlap, excessOf(v.truth, T));
        return;
    }
    const double error = std::abs(v.distance - v.truth);
    if (!(error <= T))
        return breaks(v, Violation::Distance, excessOf(error, T));
    if (!(v.witness <= W))
        return breaks(v, Violation::WitnessOffShape, excessOf(v.witness, W));
    if (!(v.witnessGap <= W))
        breaks(v, Violation::WitnessGap, excessOf(v.witnessGap, W));
}

// Midpoint on overlap: both points at one point (||pA - pB|| <= W) midway between the cores. The
// midpoint of the cores' closest points is dc/2 from each core (dc their exact distance; a common
// point of the cores, dc = 0, when they overlap), so each point must be within dc/2 + W of both.
// `toCores` gives a point's distances to A's core and B's core.
template <class ToCores> void judgeMidpoint(VariantOutcome& v, ToCores&& toCores, double dc)
{
    const double W = v.witnessTolerance;
    const double gap = std::hypot(v.pointB[0] - v.pointA[0], v.pointB[1] - v.pointA[1]);
    if (!(gap <= W))
        return breaks(v, Violation::WitnessGap, excessOf(gap, W));
    const double allowed = dc / 2 + W;
    double worst = 0;
    for (const auto& p : {v.pointA, v.pointB})
    {
        const std::array<double, 2> d = toCores(p);
        worst = std::max({worst, d[0], d[1]});
    }
    if (!(worst <= allowed))
        breaks(v, Violation::MidpointOff, excessOf(worst, allowed));
}

// The depth tolerance Td of a penetration contract on a case whose depth is judged: its depth
// clause, abs + rel x the exact depth |s| (a clause not stated counting 0) plus gjk2d's depth bound
// (the rounding its stopping rule does not cover, as for T), when it states one; else gjk2d's depth
// bound alone.
bool statesDepth(const Contract& c)
{
    return c.depthAbsTolerance >= 0 || c.depthRelTolerance >= 0;
}

void setDepthTolerance(VariantOutcome& v, const Contract& c)
{
    v.depthTolerance = statesDepth(c)
                           ? std::max(c.depthAbsTolerance, 0.0) +
                                 std::max(c.depthRelTolerance, 0.0) * -v.signedTruth + v.depthBound
                           : v.depthBound;
}

// Penetration on overlap: each point on its own shape within W, and ||pA - pB|| the depth |d|
// within W; then, where the exact signed distance s is < 0 (v.depthJudged), the depth. The
// contract promises minus the depth ("a negative distance", gjk2d/plugin.h): a distance of 0 or
// more breaks it unless the exact depth |s| is within Td (touching, to the contract's precision:
// 0 is then within Td of -|s|); a depth off by more than a stated Td breaks it (`depth_off`); with
// none stated, a depth beyond gjk2d's depth bound keeps the contract, a measured accuracy
// (v.beyondDepthBound, shown apart).
void judgePenetration(VariantOutcome& v, const Contract& c)
{
    const double W = v.witnessTolerance;
    if (!(v.witness <= W))
        return breaks(v, Violation::WitnessOffShape, excessOf(v.witness, W));
    const double gap = std::abs(std::hypot(v.pointB[0] - v.pointA[0], v.pointB[1] - v.pointA[1]) -
                                std::abs(v.distance));
    if (!(gap <= W))
        return breaks(v, Violation::PenetrationGap, excessOf(gap, W));
    if (!v.depthJudged)
        return;
    const double Td = v.depthTolerance, depth = -v.signedTruth;
    if (v.distance >= 0 && !(depth <= Td))
        return breaks(v, Violation::NoDepth, excessOf(depth, Td));
    if (statesDepth(c) && !(v.depthAbs <= Td))
        breaks(v, Violation::DepthOff, excessOf(v.depthAbs, Td));
}

// Perimeter on overlap (Box2D v3: "Keep closest points on perimeter even if overlapped"): where the
// cores meet (dc = 0) GJK's one common point, as a midpoint of cores dc = 0 apart; where they are
// apart, each point on its own rounded shape's perimeter along the cores' closest points: its
// distance to its core is its radius, within W, and ||pA - pB|| = rA + rB - dc, the rounded
// shapes' exact penetration depth (the cores' closest pair moved by each radius towards the
// other), within W. `toCores` as for judgeMidpoint.
template <class ToCores>
void judgePerimeter(VariantOutcome& v, ToCores&& toCores, double dc, double rA, double rB)
{
    if (dc == 0)
        return judgeMidpoint(v, toCores, 0);
    const double W = v.witnessTolerance;
    const double onA = std::abs(toCores(v.pointA)[0] - rA);
    const double onB = std::abs(toCores(v.pointB)[1] - rB);
    const double apart =
        std::abs(std::hypot(v.pointB[0] - v.pointA[0], v.pointB[1] - v.pointA[1]) - (rA + rB - dc));
    const double worst = std::max({onA, onB, apart});
    if (!(worst <= W))
        breaks(v, Violation::PerimeterOff, excessOf(worst, W));
}

// The cores (the shapes at radius 0) of a case on the exact side, for a midpoint answer on
// overlapping shapes: each point's distance to both, and their distance. Without radii the shapes
// are their cores and overlap (dc = 0): computeTruth's prepared shapes serve; else the cores are
// prepared here, once per case and input type, and their exact distance computed.
class Cores
{
  public:
    // c: the view's case (viewCase); t: the view (inputView). A world case's numbers are in their
    // scalar type already: rounding them to float again changes none.
    Cores(const Case& c, int t, const TruthShapes* truth)
    {
        const bool isFloat = viewIsFloat(t);
        exact::Shape a = toExact(c.a, isFloat), b = toExact(c.b, isFloat);
        radiusA_ = isFloat ? roundToFloat(c.a.radius) : c.a.radius;
        radiusB_ = isFloat ? roundToFloat(c.b.radius) : c.b.radius;
        if (a.radius == 0 && b.radius == 0 && truth && truth->a[t] && truth->b[t])
        {
            a_ = &*truth->a[t];
            b_ = &*truth->b[t];
            return;
        }
        a.radius = b.radius = 0;
        ownA_.emplace(std::move(a), "shape A");
        ownB_.emplace(std::move(b), "shape B");
        a_ = &*ownA_;
        b_ = &*ownB_;
        distance_ = exact::distance(*a_, *b_).distance;
    }
    std::array<double, 2> to(const std::array<double, 2>& p) const
    {
        const exact::Point q{p[0], p[1]};
        return {exact::pointToShapeDistance(*a_, q), exact::pointToShapeDistance(*b_, q)};
    }
    double distance() const { return distance_; }
    double radiusA() const { return radiusA_; } // in the answer's input type
    double radiusB() const { return radiusB_; }

  private:
    std::optional<exact::PreparedShape> ownA_, ownB_;
    const exact::PreparedShape *a_ = nullptr, *b_ = nullptr;
    double distance_ = 0, radiusA_ = 0, radiusB_ = 0;
};

// A declared contract's verdict on one answer (phase 3 done: v.witness measured where the answer
// was finite). `cores` gives the case's cores for this answer's input type.
template <class GetCores> void judgeDeclared(VariantOutcome& v, const Contract& c, GetCores&& cores)
{
    setTolerances(v, c);
    if (v.depthJudged)
        setDepthTolerance(v, c);
    if (v.plugin == PluginStatus::Error)
        return breaks(v, Violation::Error);
    if (v.plugin == PluginStatus::Crashed)
        return breaks(v, Violation::Crashed);
    if (v.plugin == PluginStatus::Hung)
        return breaks(v, Violation::Hung);
    const bool signedKind = c.overlap == Overlap::Zero || c.overlap == Overlap::Penetration;
    // The points are judged unless the answer is Zero's on overlapping shapes.
    const bool pointsJudged = !(c.overlap == Overlap::Zero && v.truthZero);
    if (!std::isfinite(v.distance) || (pointsJudged && v.nonfinite))
        return breaks(v, Violation::Nonfinite);
    if (!signedKind && v.distance < 0)
        return breaks(v, Violation::NegativeDistance);
    if (!v.truthZero)
        return judgeSeparated(v, v.distance <= 0);
    if (!(v.distance <= v.tolerance))
        return breaks(v, Violation::FalseSeparation, excessOf(v.distance, v.tolerance));
    switch (c.overlap)
    {
    case Overlap::Zero:
        return;                // only the sign
    case Overlap::CommonPoint: // as gjk2d's own: each point on its shape, the gap (phase 3's)
        if (!(v.witness <= v.witnessTolerance))
            return breaks(v, Violation::WitnessOffShape, excessOf(v.witness, v.witnessTolerance));
        if (!(v.witnessGap <= v.witnessTolerance))
            breaks(v, Violation::WitnessGap, excessOf(v.witnessGap, v.witnessTolerance));
        return;
    case Overlap::Midpoint:
    {
        const Cores& k = cores();
        return judgeMidpoint(
            v, [&](const std::array<double, 2>& p) { return k.to(p); }, k.distance());
    }
    case Overlap::Penetration:
        return judgePenetration(v, c);
    case Overlap::Perimeter:
    {
        const Cores& k = cores();
        return judgePerimeter(
            v, [&](const std::array<double, 2>& p) { return k.to(p); }, k.distance(), k.radiusA(),
            k.radiusB());
    }
    }
}
} // namespace

void judgeContracts(const Case& c, const EvalContext& ctx, CaseOutcome& out)
{
    if (!out.rejected.empty())
        return;
    std::optional<Cores> cores[kInputViews]; // by view (inputView)
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
    {
        VariantOutcome& v = out.variants[k];
        v.violation = Violation::None;
        v.violationExcess = 0;
        if (v.skipped)
            continue;
        const VariantInfo& vi = *ctx.variants[k];
        const Contract& contract = contractOf(vi);
        if (contract.own)
        {
            judgeOwn(v);
            continue;
        }
        const int view = inputView(vi);
        auto getCores = [&]() -> const Cores&
        {
            std::optional<Cores>& slot = cores[view];
            if (!slot)
                slot.emplace(viewCase(c, out, view), view, out.shapes.get());
            return *slot;
        };
        judgeDeclared(v, contract, getCores);
    }
}

} // namespace gjkval
