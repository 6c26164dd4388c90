// One case through the pipeline's middle: its exact truths (phase 1), every variant's answer
// (phase 2: gjk2d's queries here, the plugins' through the implementations layer), each answer's
// judgement against the truth, and the witness points' distances to their shapes (phase 3).
#include "evaluate/evaluate.hpp"

#include "inputs/geometry.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>

namespace gjkval
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <class T> std::array<double, 2> d2(gjk::Vec2<T> v)
{
    return {double(v.x), double(v.y)};
}

template <class T> void fillOutput(const gjk::DistanceOutput<T>& o, VariantOutcome& v)
{
    v.distance = double(o.distance);
    v.pointA = d2(o.pointA);
    v.pointB = d2(o.pointB);
    v.normal = d2(o.normal);
    v.iterations = o.iterations;
    v.stop = o.stop;
    v.outOfRange = o.outOfRange;
    v.certified = o.certified;
    v.lower = o.lower;
    v.upper = o.upper;
    v.path = o.path;
}

} // namespace

const char* misclassName(Misclass m)
{
    switch (m)
    {
    case Misclass::FalseOverlap:
        return "false-overlap";
    case Misclass::FalseSeparation:
        return "false-separation";
    case Misclass::Undecidable:
        return "undecidable";
    default:
        return nullptr;
    }
}

const char* skipReason(const VariantInfo& v, const PreparedCase& p, bool floatInput)
{
    const bool isFloat = v.scalar == Scalar::Float;
    if (contractOf(v).input == InputForm::World) // gjk2d's own variants are never given it
        return p.worldOk[isFloat ? 1 : 0] ? nullptr : kSkipWorldNotRepresentable;
    if (isFloat && !floatInput)
        return kSkipNotRepresentable;
    if (needsConvexOrder(v) && !p.binaryOk[isFloat ? 1 : 0])
        return kSkipNotConvexOrder;
    return nullptr;
}

double ulpOf(Scalar s, double x)
{
    int e = 0;
    std::frexp(x, &e);
    return std::ldexp(1.0, std::max(e, scalarMinExponent(s)) - scalarDigits(s));
}

double worstKey(const VariantOutcome& v)
{
    if (v.skipped || (v.outOfRange && !v.failed)) // not run, or not judged
        return -1;
    if (v.plugin != PluginStatus::NotRun && v.plugin != PluginStatus::Ok)
        return kInf; // error, crash, hang
    return (v.nonfinite || v.invalid != Invalid::None || v.iterationLimit ||
            (v.certified && !v.intervalContains))
               ? kInf
               : std::max(v.normalized, v.depthJudged ? v.depthNormalized : 0.0);
}

double CaseOutcome::worstKey() const
{
    double k = -1;
    for (const auto& v : variants)
        k = std::max(k, gjkval::worstKey(v));
    return k;
}

std::size_t CaseOutcome::worstVariant() const
{
    std::size_t worst = 0;
    for (std::size_t k = 1; k < variants.size(); ++k)
        if (gjkval::worstKey(variants[k]) > gjkval::worstKey(variants[worst]))
            worst = k;
    return worst;
}

bool EvalContext::hasPlugins() const
{
    for (auto* v : variants)
        if (v->plugin)
            return true;
    return false;
}

bool EvalContext::needPenetration() const
{
    for (auto* v : variants)
        if (contractOf(*v).overlap == Overlap::Penetration)
            return true;
    return false;
}

exact::Options EvalContext::truthOptions() const
{
    exact::Options o = exactOptions;
    o.penetration = o.penetration || needPenetration();
    return o;
}

bool EvalContext::needFloatTruth() const
{
    for (auto* v : variants)
        if (v->scalar == Scalar::Float && contractOf(*v).input == InputForm::Case)
            return true;
    return false;
}

bool EvalContext::needWorldTruth(bool isFloat) const
{
    for (auto* v : variants)
        if ((v->scalar == Scalar::Float) == isFloat && contractOf(*v).input == InputForm::World)
            return true;
    return false;
}

int inputView(const VariantInfo& v)
{
    return (contractOf(v).input == InputForm::World ? 2 : 0) + (v.scalar == Scalar::Float ? 1 : 0);
}

const Case& viewCase(const Case& c, const CaseOutcome& out, int view)
{
    if (!viewIsWorld(view))
        return c;
    const std::optional<WorldTruth>& w = out.world[view - 2];
    if (!w)
        throw std::logic_error("viewCase: the world case of '" + c.name + "' was not computed");
    return w->c;
}

const exact::Result& viewTruth(const CaseOutcome& out, int view)
{
    if (viewIsWorld(view))
    {
        if (!out.world[view - 2])
            throw std::logic_error("viewTruth: a world case's truth was not computed");
        return out.world[view - 2]->exact;
    }
    return viewIsFloat(view) ? out.exactFloat : out.exact;
}

// Two kinds of failure, never mixed (hostile-input hardening: a broken invariant of the truth
// rejected cases). The exact side throws std::invalid_argument for an input it cannot take (no
// points, a non-finite number, a negative radius): that case is rejected, as bad input. Anything
// else it throws (std::logic_error: a broken invariant of the truth, CGAL's own failed assertions)
// is a bug of ours and propagates, failing the whole run loudly (gjk-validate: internal error, exit
// code 4), never a "rejected" case.
namespace
{
// The shapes of a view's case (viewCase) on the exact side, prepared (validated:
// std::invalid_argument names "shape A" or "shape B", as exact::distance does). A world case's
// numbers are already in its scalar type: rounding them to float again changes none.
void prepareShapes(const Case& c, int view, TruthShapes& s)
{
    const bool isFloat = viewIsFloat(view) && !viewIsWorld(view);
    s.a[view].emplace(toExact(c.a, isFloat), "shape A");
    s.b[view].emplace(toExact(c.b, isFloat), "shape B");
}

// The world cases' truths (CaseOutcome::world), for the scalar types whose variants need them and
// whose world case fits (the condition of PreparedCase::worldOk: worldCase has a value). The world
// case of a case the exact side took is one it takes (finite points, radius >= 0): its
// std::invalid_argument would be a broken invariant of ours (std::logic_error).
void computeWorldTruths(const Case& c, const EvalContext& ctx, const exact::Options& options,
                        TruthShapes& shapes, CaseOutcome& out)
{
    for (const bool isFloat : {false, true})
    {
        if (!ctx.needWorldTruth(isFloat))
            continue;
        std::optional<Case> w = worldCase(c, isFloat);
        if (!w)
            continue;
        const int view = 2 + (isFloat ? 1 : 0);
        WorldTruth& t = out.world[view - 2].emplace();
        t.c = std::move(*w);
        try
        {
            prepareShapes(t.c, view, shapes);
        }
        catch (const std::invalid_argument& e)
        {
            throw std::logic_error(fmt::format("case '{}': its world case: {}", c.name, e.what()));
        }
        t.exact = ctx.truth(*shapes.a[view], *shapes.b[view], options);
        t.inputRounding = std::abs(t.exact.distance - out.exact.distance);
    }
}
} // namespace

void computeTruth(const Case& c, const EvalContext& ctx, CaseOutcome& out)
{
    auto shapes = std::make_shared<TruthShapes>();
    const exact::Options options = ctx.truthOptions();
    try
    {
        prepareShapes(c, 0, *shapes);
        out.exact = ctx.truth(*shapes->a[0], *shapes->b[0], options);
    }
    catch (const std::invalid_argument& e)
    {
        out.rejected = fmt::format("exact: {}", e.what());
        return;
    }
    out.shapes = shapes;
    // The float variants' truth: the same case with every number rounded to float. Cases whose
    // numbers do not fit in float skip the float variants, with their reason
    // (kSkipNotRepresentable); once they fit, the exact side has no reason to refuse them, so
    // nothing is caught here.
    if (ctx.needFloatTruth() && representableInFloat(c))
    {
        prepareShapes(c, 1, *shapes);
        out.exactFloat = ctx.truth(*shapes->a[1], *shapes->b[1], options);
        out.hasFloatTruth = true;
        out.inputRounding = std::abs(out.exactFloat.distance - out.exact.distance);
    }
    computeWorldTruths(c, ctx, options, *shapes, out);
}

namespace
{
// A case's frame scales per (frame, float-rounded input), computed when first needed.
class CaseScales
{
  public:
    explicit CaseScales(const Case& c) : c_(c) {}
    const FrameScales& get(bool world, bool isFloat)
    {
        const int f = world ? 1 : 0, t = isFloat ? 1 : 0;
        if (!have_[f][t])
        {
            if (isFloat && !haveFloatShapes_)
            {
                fa_ = roundedToFloat(c_.a);
                fb_ = roundedToFloat(c_.b);
                haveFloatShapes_ = true;
            }
            scales_[f][t] = frameScales(isFloat ? fa_ : c_.a, isFloat ? fb_ : c_.b, world);
            have_[f][t] = true;
        }
        return scales_[f][t];
    }

  private:
    const Case& c_;
    FrameScales scales_[2][2];
    bool have_[2][2] = {{false, false}, {false, false}};
    ShapeIn fa_, fb_;
    bool haveFloatShapes_ = false;
};

// The frame scales of the case each view gives (inputView): the case's (CaseScales, its numbers
// rounded to float for view 1), or the world case's (its numbers already in their scalar type).
class ViewScales
{
  public:
    ViewScales(const Case& c, const CaseOutcome& out) : c_(c), out_(out), own_(c) {}
    const FrameScales& get(int view, bool worldFrame)
    {
        if (!viewIsWorld(view))
            return own_.get(worldFrame, viewIsFloat(view));
        std::optional<CaseScales>& w = world_[view - 2];
        if (!w)
            w.emplace(viewCase(c_, out_, view));
        return w->get(worldFrame, false);
    }

  private:
    const Case& c_;
    const CaseOutcome& out_;
    CaseScales own_;
    std::optional<CaseScales> world_[2];
};

// The bounds a variant's answer is judged against (distance, witness points, and the depth where
// its contract says Penetration and the exact signed distance is < 0): the reference variant's
// (A's local frame scales `sc`), what the library promises for this input, so that a variant that
// computes differently (world frame) fails where it breaks that promise.
void boundsOf(const VariantInfo& vi, const Case& c, const FrameScales& sc,
              const exact::Result& truth, VariantOutcome& v)
{
    const bool isFloat = vi.scalar == Scalar::Float;
    CaseMetrics m;
    m.R = sc.R;
    m.unitRoundoff = unitRoundoff(vi.scalar);
    m.radiusA = isFloat ? roundToFloat(c.a.radius) : c.a.radius;
    m.radiusB = isFloat ? roundToFloat(c.b.radius) : c.b.radius;
    m.countA = int(c.a.points.size());
    m.countB = int(c.b.points.size());
    m.exactDistance = truth.distance;
    m.maxA = sc.A;
    m.maxB = sc.B;
    m.maxBMapped = sc.Bmapped;
    m.translation = sc.D;
    m.maxW = sc.W;
    m.worldExtent = sc.M;
    v.bound = errorBound(vi, m);
    v.witnessBound = witnessBound(vi, m);
    if (contractOf(vi).overlap == Overlap::Penetration && overlapsBySigned(truth))
    {
        m.exactDistance = truth.signedDistance;
        v.depthBound = depthBound(vi, m);
    }
}

template <class T> bool sameBits(T a, T b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// The variant's query; a batch variant's is checked against the scalar query, bit for bit in every
// output field and the cache (gjk2d/batch.hpp's promise). A difference is a broken invariant of the
// library (std::logic_error: exit code 4), never a failure of the case.
template <class T>
gjk::DistanceOutput<T> checkedQuery(const Case& c, const PreparedCase& p, const VariantInfo& v)
{
    if (!v.batch)
        return query<T>(p, v);
    if (v.start != Start::Cold)
        throw std::logic_error(fmt::format("variant {}: a batch variant must start cold", v.name));
    const gjk::DistanceInput<T> in = p.input<T>();
    gjk::SimplexCache batchCache, scalarCache;
    gjk::DistanceOutput<T> out;
    gjk::distanceBatchLanes(std::span<const gjk::DistanceInput<T>>(&in, 1),
                            std::span<gjk::SimplexCache>(&batchCache, 1),
                            std::span<gjk::DistanceOutput<T>>(&out, 1), v.options);
    const gjk::DistanceOutput<T> ref = gjk::distance(in, scalarCache, v.options);
    bool same = sameBits(out.distance, ref.distance) && sameBits(out.pointA.x, ref.pointA.x) &&
                sameBits(out.pointA.y, ref.pointA.y) && sameBits(out.pointB.x, ref.pointB.x) &&
                sameBits(out.pointB.y, ref.pointB.y) && sameBits(out.normal.x, ref.normal.x) &&
                sameBits(out.normal.y, ref.normal.y) && out.iterations == ref.iterations &&
                out.simplexCount == ref.simplexCount && out.stop == ref.stop &&
                out.outOfRange == ref.outOfRange && out.rescaled == ref.rescaled &&
                out.certified == ref.certified && sameBits(out.lower, ref.lower) &&
                sameBits(out.upper, ref.upper) && batchCache.count == scalarCache.count &&
                batchCache.edgeBase == scalarCache.edgeBase &&
                batchCache.searchA == scalarCache.searchA &&
                batchCache.searchB == scalarCache.searchB;
    for (int i = 0; i < 3; ++i)
        same = same && batchCache.indexA[i] == scalarCache.indexA[i] &&
               batchCache.indexB[i] == scalarCache.indexB[i];
    if (!same)
        throw std::logic_error(fmt::format(
            "variant {}: case '{}': gjk::distanceBatchLanes ({}) differs from gjk::distance "
            "(distance {} vs {}, {} vs {} iterations): gjk2d/batch.hpp promises the same bits",
            v.name, c.name, gjk::batchIsaName(gjk::bestBatchIsa()), double(out.distance),
            double(ref.distance), out.iterations, ref.iterations));
    return out;
}
} // namespace

namespace
{
// The answer's errors against the truth td: absolute, relative, in ulps, normalised, against the
// bound, and the witness gap ||pB - pA|| - distance; all infinite for a non-finite answer.
// `signedOverlap`: the implementation answers overlap with a distance of 0 or below (Overlap::Zero,
// Penetration), so its negative distance is gjk2d's 0 in that convention, and the distance errors
// (beyond_bound among them) are measured on max(d, 0); the witness gap keeps the raw d, or for a
// penetration pair (`penetration`) |d|: its points are |d| apart.
void measureErrors(VariantOutcome& v, double td, Scalar scalar, bool signedOverlap,
                   bool penetration)
{
    if (v.nonfinite)
    {
        v.abs = v.normalized = v.boundRatio = kInf;
        v.rel = td > 0 ? kInf : kNaN;
        v.ulps = td > 0 ? kInf : kNaN;
        v.witnessGap = kInf;
        v.beyondBound = true;
        return;
    }
    const double u = unitRoundoff(scalar);
    const double d = signedOverlap ? std::max(v.distance, 0.0) : v.distance;
    v.abs = std::abs(d - td);
    v.rel = td > 0 ? v.abs / td : kNaN;
    v.ulps = td > 0 ? v.abs / ulpOf(scalar, td) : kNaN;
    v.normalized = v.abs == 0 ? 0 : (v.R > 0 ? v.abs / (u * v.R) : kInf);
    v.boundRatio = v.abs == 0 ? 0 : (v.bound > 0 ? v.abs / v.bound : kInf);
    v.witnessGap = std::abs(std::hypot(v.pointB[0] - v.pointA[0], v.pointB[1] - v.pointA[1]) -
                            (penetration ? std::abs(v.distance) : v.distance));
    v.beyondBound = !(v.abs <= v.bound);
}

// Penetration on shapes whose exact signed distance s is < 0 (v.depthBound set): the answer's
// signed distance against s, whatever its sign (a distance of 0 or more on overlap is |s| off).
void measureDepth(VariantOutcome& v, double s, Scalar scalar)
{
    v.depthJudged = true;
    v.signedTruth = s;
    v.depthAbs = v.nonfinite ? kInf : std::abs(v.distance - s);
    v.depthRel = v.depthAbs / -s;
    v.depthRatio = v.depthAbs == 0 ? 0 : (v.depthBound > 0 ? v.depthAbs / v.depthBound : kInf);
    v.depthNormalized =
        v.depthAbs == 0 ? 0 : (v.R > 0 ? v.depthAbs / (unitRoundoff(scalar) * v.R) : kInf);
    v.beyondDepthBound = !(v.depthAbs <= v.depthBound);
}

// A finite answer in range: its claim of overlap against the truth's, and its own contract (a
// penetration answer's negative distance is minus its depth, not invalid).
void classifyAnswer(VariantOutcome& v, bool truthZero, bool penetration)
{
    // A negative distance claims overlap (and is not a distance): on separated shapes a false
    // overlap whatever its error.
    if (truthZero && v.distance > 0)
        v.mis = Misclass::FalseSeparation;
    else if (!truthZero && v.distance <= 0)
        v.mis = Misclass::FalseOverlap;
    // Within the bound the claim is undecidable at this precision; a penetration answer's negative
    // distance is a claim like any other (minus its depth), not an invalid one.
    if (v.mis != Misclass::None && !v.beyondBound && (v.distance >= 0 || penetration))
        v.mis = Misclass::Undecidable;
    // The answer's own contract, first part (the witness points' distances to their shapes are
    // measured in phase 3, checkWitnesses, which may replace WitnessGap).
    if (v.distance < 0 && !penetration)
        v.invalid = Invalid::NegativeDistance;
    else if (!(v.witnessGap <= v.witnessBound))
        v.invalid = Invalid::WitnessGap;
}
} // namespace

bool failedAnswer(const VariantOutcome& v)
{
    return (!v.outOfRange && (v.nonfinite || v.invalid != Invalid::None || v.iterationLimit ||
                              v.beyondBound || v.beyondDepthBound)) ||
           (v.certified && !v.intervalContains) || v.bitMismatch;
}

void judge(VariantOutcome& v, const exact::Result& truth, Scalar scalar, bool zeroTolerance,
           Overlap overlap)
{
    v.truth = truth.distance;
    v.truthZero = exactIsZero(truth);
    v.nonfinite = !std::isfinite(v.distance) || !std::isfinite(v.pointA[0]) ||
                  !std::isfinite(v.pointA[1]) || !std::isfinite(v.pointB[0]) ||
                  !std::isfinite(v.pointB[1]) || !std::isfinite(v.normal[0]) ||
                  !std::isfinite(v.normal[1]);
    v.iterationLimit = v.stop == gjk::StopReason::IterationLimit;
    const bool penetration = overlap == Overlap::Penetration;
    measureErrors(v, truth.distance, scalar, overlap == Overlap::Zero || penetration, penetration);
    v.depthJudged = false;
    v.beyondDepthBound = false;
    if (penetration && overlapsBySigned(truth))
        measureDepth(v, truth.signedDistance, scalar);
    if (!v.nonfinite && !v.outOfRange)
        classifyAnswer(v, exactIsZero(truth), penetration);
    // The exact value lies in [truth.lower, truth.upper] (equal, or adjacent doubles with the
    // value strictly between): the double interval [lower, upper] contains it iff it contains
    // that enclosure. A penetration answer's interval encloses its signed distance: it is held
    // to the exact signed distance's enclosure (the distance's where the shapes are apart).
    const bool bySigned = penetration && truth.hasSigned;
    const double lo = bySigned ? truth.signedLower : truth.lower,
                 hi = bySigned ? truth.signedUpper : truth.upper;
    v.intervalContains = v.certified && v.lower <= lo && hi <= v.upper;
    v.witness = v.witnessRatio = kNaN;
    // Options::correctlyRounded: the distance must be the exact side's, bit for bit, on every
    // case (out of range ones too: the exact completion answers them).
    if (zeroTolerance)
        v.bitMismatch = std::bit_cast<std::uint64_t>(v.distance) !=
                        std::bit_cast<std::uint64_t>(truth.distance);
    v.failed = failedAnswer(v);
}

namespace
{
// Plugin variant k's answer, which answerPluginVariants gave: false when there is nothing to judge
// (refused: skipped; an error status, a crash or a hang: failed).
bool takePluginAnswer(const CaseOutcome& out, std::size_t k, const VariantInfo& vi,
                      VariantOutcome& v)
{
    if (out.external.size() != out.variants.size() ||
        out.external[k].status == PluginStatus::NotRun)
        throw std::logic_error("runVariants: plugin variant '" + vi.name +
                               "' has no answer (answerPluginVariants not run)");
    const ExternalAnswer& a = out.external[k];
    v.plugin = a.status;
    v.pluginDetail = a.detail;
    if (a.status == PluginStatus::Refused)
    {
        v.skipped = true;
        v.skipWhy = kSkipRefused;
        return false;
    }
    if (a.status != PluginStatus::Ok)
    {
        v.failed = true;
        return false;
    }
    v.distance = a.distance;
    v.pointA = a.pointA;
    v.pointB = a.pointB;
    // The implementation gives no normal: the unit vector from A's witness to B's.
    const double dx = a.pointB[0] - a.pointA[0], dy = a.pointB[1] - a.pointA[1];
    const double len = std::hypot(dx, dy);
    v.normal = len > 0 ? std::array<double, 2>{dx / len, dy / len} : std::array<double, 2>{0, 0};
    v.iterations = a.iterations;
    return true;
}

// gjk2d's answer for the variant: the worst of every start's, or the (batch-checked) query's.
void runQuery(const Case& c, const PreparedCase& p, const VariantInfo& vi, double truth,
              VariantOutcome& v)
{
    const bool isFloat = vi.scalar == Scalar::Float;
    if (vi.start == Start::EveryStart)
    {
        if (isFloat)
            fillOutput(worstStart<float>(p, vi, truth), v);
        else
            fillOutput(worstStart<double>(p, vi, truth), v);
    }
    else if (isFloat)
        fillOutput(checkedQuery<float>(c, p, vi), v);
    else
        fillOutput(checkedQuery<double>(c, p, vi), v);
}
} // namespace

void runVariants(const Case& c, const PreparedCase& p, const EvalContext& ctx, CaseOutcome& out)
{
    out.variants.assign(ctx.variants.size(), {});
    if (!out.rejected.empty())
        return;
    ViewScales scales(c, out);
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
    {
        const VariantInfo& vi = *ctx.variants[k];
        VariantOutcome& v = out.variants[k];
        if (const char* why = skipReason(vi, p, out.hasFloatTruth))
        {
            v.skipped = true;
            v.skipWhy = why;
            v.notApplicable = why == kSkipNotConvexOrder;
            continue;
        }
        // The variant's view: the case, or the world case it was given (its truth, its scales).
        const int view = inputView(vi);
        v.worldInput = viewIsWorld(view);
        const exact::Result& truth = viewTruth(out, view);
        if (vi.plugin && !takePluginAnswer(out, k, vi, v))
            continue;
        if (!vi.plugin)
            runQuery(c, p, vi, truth.distance, v);
        // The normalised error uses the scale of the variant's own compute frame.
        v.R = scales.get(view, vi.options.frame == gjk::Frame::World).R;
        boundsOf(vi, viewCase(c, out, view), scales.get(view, false), truth, v);
        judge(v, truth, vi.scalar, vi.options.correctlyRounded, contractOf(vi).overlap);
    }
}

void answerPluginVariants(const Case* cases, const PreparedCase* prepared, CaseOutcome* out,
                          std::size_t n, const EvalContext& ctx)
{
    if (!ctx.hasPlugins())
        return;
    std::vector<PluginTask> tasks;
    for (std::size_t i = 0; i < n; ++i)
    {
        CaseOutcome& o = out[i];
        o.external.assign(ctx.variants.size(), {});
        if (!o.rejected.empty())
            continue;
        for (std::size_t k = 0; k < ctx.variants.size(); ++k)
        {
            const VariantInfo& vi = *ctx.variants[k];
            if (!vi.plugin || skipReason(vi, prepared[i], o.hasFloatTruth))
                continue; // runVariants skips it
            if (refusedByDescription(vi, prepared[i]))
                o.external[k].status = PluginStatus::Refused;
            else
                tasks.push_back({&vi, &prepared[i], &o.external[k], &cases[i].name});
        }
    }
    if (ctx.pluginServers)
        answerContained(tasks, ctx.pluginTimeoutSeconds, *ctx.pluginServers);
    else
        answerContained(tasks, ctx.pluginTimeoutSeconds);
}

CaseOutcome evaluateCase(const Case& c, const EvalContext& ctx)
{
    CaseOutcome o;
    computeTruth(c, ctx, o);
    const PreparedCase p = prepare(c);
    answerPluginVariants(&c, &p, &o, 1, ctx);
    runVariants(c, p, ctx, o);
    checkWitnesses(c, ctx, o);
    return o;
}

} // namespace gjkval
