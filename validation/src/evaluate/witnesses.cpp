// Phase 3 of a case: each witness point's exact distance to its shape, and the witness verdict
// (docs/error-bound.md, "Witness points"): a point off its shape beyond the witness bound makes
// the answer invalid.
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

// A case's shapes on the exact side, by view (inputView: as given, rounded to float, its world
// cases): computeTruth's prepared shapes (TruthShapes), or prepared here when a caller gave none.
class ExactShapes
{
  public:
    ExactShapes(const Case& c, const CaseOutcome& out) : c_(c), out_(out), truth_(out.shapes.get())
    {
    }
    // max(0, dist(p, shape) - radius), correctly rounded: exact::pointToShapeDistance's value
    // (decided in floating point or by its GMP route); `exactCount` counts the points the GMP
    // route measured.
    double distance(int view, bool ofA, const std::array<double, 2>& p, int& exactCount)
    {
        Pair& s = get(view);
        const exact::Point q{p[0], p[1]};
        bool gmp = false;
        const double d = exact::pointToShapeDistance(ofA ? *s.pa : *s.pb, q, &gmp);
        exactCount += gmp ? 1 : 0;
        return d;
    }

  private:
    struct Pair
    {
        const exact::PreparedShape *pa = nullptr, *pb = nullptr;
    };
    Pair& get(int t)
    {
        if (!have_[t])
        {
            Pair& s = shapes_[t];
            if (truth_ && truth_->a[t] && truth_->b[t])
            {
                s.pa = &*truth_->a[t];
                s.pb = &*truth_->b[t];
            }
            else
            {
                // A world case's numbers are in their scalar type already.
                const Case& c = viewCase(c_, out_, t);
                const bool isFloat = viewIsFloat(t) && !viewIsWorld(t);
                own_.a[t].emplace(toExact(c.a, isFloat), "shape A");
                own_.b[t].emplace(toExact(c.b, isFloat), "shape B");
                s.pa = &*own_.a[t];
                s.pb = &*own_.b[t];
            }
            have_[t] = true;
        }
        return shapes_[t];
    }
    const Case& c_;
    const CaseOutcome& out_;
    const TruthShapes* truth_;
    TruthShapes own_;
    Pair shapes_[kInputViews];
    bool have_[kInputViews] = {};
};

// The witness verdict (judge() left the rest): off its shape comes before the gap.
// An answer of overlap (distance 0) may give two points that each lie in both shapes instead of
// one (docs/judgement.md, "Failures"), e.g. Box2D v3's points on each
// outline. Either point proves the overlap. (A penetration pair is not such a pair: each of its
// points is on its own shape only; a contract that declares penetration is judged by its own
// clause, contract_judge.cpp.) Then the witness gap is how far
// the points are from the other shape, and within the witness bound the answer is valid: the
// failure WitnessGap set from ||pB - pA|| is withdrawn (the other reasons stand).
void acceptTwoCommonPoints(VariantOutcome& v, ExactShapes& shapes, int view)
{
    v.witnessPoints += 2;
    const double aInB = shapes.distance(view, false, v.pointA, v.witnessExact);
    const double bInA = shapes.distance(view, true, v.pointB, v.witnessExact);
    const double gap = std::max(aInB, bInA);
    if (!(gap <= v.witnessBound))
        return;
    v.witnessGap = gap;
    v.invalid = Invalid::None;
    v.failed = failedAnswer(v);
}

void judgeWitnesses(VariantOutcome& v, double wa, double wb)
{
    v.witness = std::max(wa, wb);
    const double worst = std::max(v.witness, v.witnessGap);
    v.witnessRatio = worst == 0 ? 0 : (v.witnessBound > 0 ? worst / v.witnessBound : kInf);
    if (!v.outOfRange && (v.invalid == Invalid::None || v.invalid == Invalid::WitnessGap) &&
        !(v.witness <= v.witnessBound))
    {
        v.invalid = Invalid::WitnessOffShape;
        v.failed = true;
    }
}
} // namespace

void checkWitnesses(const Case& c, const EvalContext& ctx, CaseOutcome& out)
{
    if (!out.rejected.empty())
        return;
    ExactShapes shapes(c, out);
    const std::size_t nv = ctx.variants.size();
    struct Measured // a variant's two points' distances, and whether the GMP route measured each
    {
        double a = 0, b = 0;
        char done = 0, exactA = 0, exactB = 0;
    };
    std::vector<Measured> m(nv);
    for (std::size_t k = 0; k < nv; ++k)
    {
        VariantOutcome& v = out.variants[k];
        if (v.skipped || v.nonfinite ||
            (v.plugin != PluginStatus::NotRun && v.plugin != PluginStatus::Ok))
            continue;
        // The shapes the variant was given: the case (rounded to float) or its world case.
        const int view = inputView(*ctx.variants[k]);
        // Variants often return the very same witness points (same view): each distinct point is
        // measured once per case; a variant's counts include the points it shares.
        double wa = -1, wb = -1;
        Measured& mk = m[k];
        for (std::size_t j = 0; j < k && (wa < 0 || wb < 0); ++j)
        {
            if (m[j].done == 0 || inputView(*ctx.variants[j]) != view)
                continue;
            const VariantOutcome& u = out.variants[j];
            if (wa < 0 && u.pointA == v.pointA)
            {
                wa = m[j].a;
                mk.exactA = m[j].exactA;
            }
            if (wb < 0 && u.pointB == v.pointB)
            {
                wb = m[j].b;
                mk.exactB = m[j].exactB;
            }
        }
        int n = 0;
        if (wa < 0)
        {
            wa = shapes.distance(view, true, v.pointA, n);
            mk.exactA = char(n);
        }
        n = 0;
        if (wb < 0)
        {
            wb = shapes.distance(view, false, v.pointB, n);
            mk.exactB = char(n);
        }
        v.witnessPoints += 2;
        v.witnessExact += mk.exactA + mk.exactB;
        mk.a = wa;
        mk.b = wb;
        mk.done = 1;
        if (v.invalid == Invalid::WitnessGap && v.distance == 0)
            acceptTwoCommonPoints(v, shapes, view);
        judgeWitnesses(v, wa, wb);
    }
    judgeContracts(c, ctx, out); // the verdict by each implementation's contract, on the measures
    out.shapes.reset();          // the chunk's hulls are not kept past this phase
}

} // namespace gjkval
