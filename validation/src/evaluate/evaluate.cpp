#include "evaluate/evaluate.hpp"

#include "inputs/geometry.hpp"

#include <gjk2d/correct_fallback.hpp>

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

Json exactJson(const exact::Result& r)
{
    Json j;
    j["distance"] = num(r.distance);
    j["squared"] = r.squaredNum + "/" + r.squaredDen;
    j["overlap"] = r.overlap;
    return j;
}

Json shapeDetail(const ShapeIn& s)
{
    Json j;
    Json pts = Json::array();
    for (const auto& p : s.points)
        pts.push_back(pt(p[0], p[1]));
    j["points"] = std::move(pts);
    j["radius"] = num(s.radius);
    j["transform"] = {{"p", pt(s.px, s.py)}, {"q", pt(s.c, s.s)}};
    Json w = Json::array();
    for (const auto& p : worldPoints(s))
        w.push_back(pt(p[0], p[1]));
    j["world"] = std::move(w);
    return j;
}

template <class T> Json traceJson(const gjk::Trace<T>& tr)
{
    const gjk::Transform<double> f{{double(tr.frame.p.x), double(tr.frame.p.y)},
                                   {double(tr.frame.q.c), double(tr.frame.q.s)}};
    // A rescaled query's trace is in the scaled compute frame (Trace::scaleExponent).
    const int e = -tr.scaleExponent;
    auto point = [&f, e](gjk::Vec2<T> v)
    {
        const auto w = gjk::transformPoint(
            f, gjk::Vec2<double>{std::ldexp(double(v.x), e), std::ldexp(double(v.y), e)});
        return pt(w.x, w.y);
    };
    auto vec = [&f, e](gjk::Vec2<T> v)
    {
        const auto w = gjk::rotate(
            f.q, gjk::Vec2<double>{std::ldexp(double(v.x), e), std::ldexp(double(v.y), e)});
        return pt(w.x, w.y);
    };
    auto vertex = [&](const gjk::SimplexVertex<T>& sv, bool withWeight)
    {
        Json j;
        j["w"] = vec(sv.w);
        j["wA"] = point(sv.wA);
        j["wB"] = point(sv.wB);
        if (withWeight)
            j["a"] = num(double(sv.a));
        j["iA"] = sv.indexA;
        j["iB"] = sv.indexB;
        return j;
    };
    Json steps = Json::array();
    for (const auto& s : tr.steps)
    {
        Json j;
        Json simplex = Json::array();
        for (int i = 0; i < s.simplex.count; ++i)
            simplex.push_back(vertex(s.simplex.v[i], true));
        j["simplex"] = std::move(simplex);
        j["closest"] = vec(s.closest);
        j["direction"] = vec(s.direction);
        j["support"] = s.hasSupport ? vertex(s.support, false) : Json(nullptr);
        steps.push_back(std::move(j));
    }
    return steps;
}

template <class T> Json tracedRun(const Case& c, const VariantInfo& v, gjk::DistanceOutput<T>& out)
{
    const PreparedCase p = prepare(c);
    gjk::Trace<T> tr;
    out = query<T>(p, v, &tr);
    return traceJson(tr);
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

PreparedCase prepare(const Case& c)
{
    PreparedCase p;
    p.ad.reserve(c.a.points.size());
    p.af.reserve(c.a.points.size());
    p.bd.reserve(c.b.points.size());
    p.bf.reserve(c.b.points.size());
    for (const auto& q : c.a.points)
    {
        p.ad.push_back({q[0], q[1]});
        p.af.push_back({float(q[0]), float(q[1])});
    }
    for (const auto& q : c.b.points)
    {
        p.bd.push_back({q[0], q[1]});
        p.bf.push_back({float(q[0]), float(q[1])});
    }
    p.xad = {{c.a.px, c.a.py}, {c.a.c, c.a.s}};
    p.xbd = {{c.b.px, c.b.py}, {c.b.c, c.b.s}};
    p.xaf = {{float(c.a.px), float(c.a.py)}, {float(c.a.c), float(c.a.s)}};
    p.xbf = {{float(c.b.px), float(c.b.py)}, {float(c.b.c), float(c.b.s)}};
    p.rad = c.a.radius;
    p.rbd = c.b.radius;
    p.raf = float(c.a.radius);
    p.rbf = float(c.b.radius);
    p.floatOk = representableInFloat(c);
    auto convex = [](const auto& pts)
    {
        if (int(pts.size()) <= kLinearSupportMaxPoints)
            return true;
        std::vector<P2> q;
        q.reserve(pts.size());
        for (const auto& v : pts)
            q.push_back({double(v.x), double(v.y)});
        return inConvexOrder(q);
    };
    p.binaryOk[0] = convex(p.ad) && convex(p.bd);
    p.binaryOk[1] = p.floatOk && convex(p.af) && convex(p.bf);
    return p;
}

const char* skipReason(const VariantInfo& v, const PreparedCase& p, bool floatInput)
{
    const bool isFloat = v.scalar == Scalar::Float;
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
               : v.normalized;
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

bool EvalContext::needFloatTruth() const
{
    for (auto* v : variants)
        if (v->scalar == Scalar::Float)
            return true;
    return false;
}

// Two kinds of failure, never mixed (hostile-input hardening: a broken invariant of the truth
// rejected cases). The exact side throws std::invalid_argument for an input it cannot take (no
// points, a non-finite number, a negative radius): that case is rejected, as bad input. Anything
// else it throws (std::logic_error: a broken invariant of the truth, CGAL's own failed assertions)
// is a bug of ours and propagates, failing the whole run loudly (gjk-validate: internal error, exit
// code 4), never a "rejected" case.
namespace
{
// The case's shapes on the exact side for one input type, prepared (validated:
// std::invalid_argument names "shape A" or "shape B", as exact::distance does).
void prepareShapes(const Case& c, bool isFloat, TruthShapes& s)
{
    const int t = isFloat ? 1 : 0;
    s.a[t].emplace(toExact(c.a, isFloat), "shape A");
    s.b[t].emplace(toExact(c.b, isFloat), "shape B");
}
} // namespace

void computeTruth(const Case& c, const EvalContext& ctx, CaseOutcome& out)
{
    auto shapes = std::make_shared<TruthShapes>();
    try
    {
        prepareShapes(c, false, *shapes);
        out.exact = ctx.truth(*shapes->a[0], *shapes->b[0], ctx.exactOptions);
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
        prepareShapes(c, true, *shapes);
        out.exactFloat = ctx.truth(*shapes->a[1], *shapes->b[1], ctx.exactOptions);
        out.hasFloatTruth = true;
        out.inputRounding = std::abs(out.exactFloat.distance - out.exact.distance);
    }
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

// The bounds a variant's answer is judged against (distance, witness points): the reference
// variant's (A's local frame scales `sc`), what the library promises for this input, so that a
// variant that computes differently (world frame) fails where it breaks that promise.
void boundsOf(const VariantInfo& vi, const Case& c, const FrameScales& sc, double exactDistance,
              VariantOutcome& v)
{
    const bool isFloat = vi.scalar == Scalar::Float;
    CaseMetrics m;
    m.R = sc.R;
    m.unitRoundoff = unitRoundoff(vi.scalar);
    m.radiusA = isFloat ? roundToFloat(c.a.radius) : c.a.radius;
    m.radiusB = isFloat ? roundToFloat(c.b.radius) : c.b.radius;
    m.countA = int(c.a.points.size());
    m.countB = int(c.b.points.size());
    m.exactDistance = exactDistance;
    m.maxA = sc.A;
    m.maxB = sc.B;
    m.maxBMapped = sc.Bmapped;
    m.translation = sc.D;
    m.maxW = sc.W;
    m.worldExtent = sc.M;
    v.bound = errorBound(vi, m);
    v.witnessBound = witnessBound(vi, m);
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
void measureErrors(VariantOutcome& v, double td, Scalar scalar)
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
    v.abs = std::abs(v.distance - td);
    v.rel = td > 0 ? v.abs / td : kNaN;
    v.ulps = td > 0 ? v.abs / ulpOf(scalar, td) : kNaN;
    v.normalized = v.abs == 0 ? 0 : (v.R > 0 ? v.abs / (u * v.R) : kInf);
    v.boundRatio = v.abs == 0 ? 0 : (v.bound > 0 ? v.abs / v.bound : kInf);
    v.witnessGap =
        std::abs(std::hypot(v.pointB[0] - v.pointA[0], v.pointB[1] - v.pointA[1]) - v.distance);
    v.beyondBound = !(v.abs <= v.bound);
}

// A finite answer in range: its claim of overlap against the truth's, and its own contract.
void classifyAnswer(VariantOutcome& v, bool truthZero)
{
    // A negative distance claims overlap (and is not a distance): on separated shapes a false
    // overlap whatever its error.
    if (truthZero && v.distance > 0)
        v.mis = Misclass::FalseSeparation;
    else if (!truthZero && v.distance <= 0)
        v.mis = Misclass::FalseOverlap;
    if (v.mis != Misclass::None && !v.beyondBound && v.distance >= 0)
        v.mis = Misclass::Undecidable;
    // The answer's own contract, first part (the witness points' distances to their shapes are
    // measured in phase 3, checkWitnesses, which may replace WitnessGap).
    if (v.distance < 0)
        v.invalid = Invalid::NegativeDistance;
    else if (!(v.witnessGap <= v.witnessBound))
        v.invalid = Invalid::WitnessGap;
}
} // namespace

namespace
{
// Whether a judged answer fails: the one rule, for judge() and for acceptTwoCommonPoints(). Cases
// GJK flags out of range are not judged (docs/error-bound.md, assumptions); a certified interval
// that misses the truth, or a correctly rounded distance that is not the exact side's, always
// fails.
bool failedAnswer(const VariantOutcome& v)
{
    return (!v.outOfRange &&
            (v.nonfinite || v.invalid != Invalid::None || v.iterationLimit || v.beyondBound)) ||
           (v.certified && !v.intervalContains) || v.bitMismatch;
}
} // namespace

void judge(VariantOutcome& v, const exact::Result& truth, Scalar scalar, bool zeroTolerance)
{
    v.truth = truth.distance;
    v.nonfinite = !std::isfinite(v.distance) || !std::isfinite(v.pointA[0]) ||
                  !std::isfinite(v.pointA[1]) || !std::isfinite(v.pointB[0]) ||
                  !std::isfinite(v.pointB[1]) || !std::isfinite(v.normal[0]) ||
                  !std::isfinite(v.normal[1]);
    v.iterationLimit = v.stop == gjk::StopReason::IterationLimit;
    measureErrors(v, truth.distance, scalar);
    if (!v.nonfinite && !v.outOfRange)
        classifyAnswer(v, exactIsZero(truth));
    // The exact value lies in [truth.lower, truth.upper] (equal, or adjacent doubles with the
    // value strictly between): the double interval [lower, upper] contains it iff it contains
    // that enclosure.
    v.intervalContains = v.certified && v.lower <= truth.lower && truth.upper <= v.upper;
    v.witness = v.witnessRatio = kNaN;
    // Options::correctlyRounded: the distance must be the exact side's, bit for bit, on every
    // case (out of range ones too: the exact completion answers them).
    if (zeroTolerance)
        v.bitMismatch = std::bit_cast<std::uint64_t>(v.distance) !=
                        std::bit_cast<std::uint64_t>(truth.distance);
    v.failed = failedAnswer(v);
}

void completeExactly(const gjk::DistanceInput<double>& in, const gjk::Options& options,
                     gjk::DistanceOutput<double>& out)
{
    exact::completeCorrectlyRounded(in, options, out);
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
    CaseScales scales(c);
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
    {
        const VariantInfo& vi = *ctx.variants[k];
        VariantOutcome& v = out.variants[k];
        const bool isFloat = vi.scalar == Scalar::Float;
        if (const char* why = skipReason(vi, p, out.hasFloatTruth))
        {
            v.skipped = true;
            v.notApplicable = why == kSkipNotConvexOrder;
            continue;
        }
        const exact::Result& truth = isFloat ? out.exactFloat : out.exact;
        if (vi.plugin && !takePluginAnswer(out, k, vi, v))
            continue;
        if (!vi.plugin)
            runQuery(c, p, vi, truth.distance, v);
        // The normalised error uses the scale of the variant's own compute frame.
        v.R = scales.get(vi.options.frame == gjk::Frame::World, isFloat).R;
        boundsOf(vi, c, scales.get(false, isFloat), truth.distance, v);
        judge(v, truth, vi.scalar, vi.options.correctlyRounded);
    }
}

namespace
{
// A case's shapes on the exact side, as given and rounded to float: computeTruth's prepared shapes
// (TruthShapes), or prepared here when a caller gave none.
class ExactShapes
{
  public:
    ExactShapes(const Case& c, const TruthShapes* truth) : c_(c), truth_(truth) {}
    // max(0, dist(p, shape) - radius), correctly rounded: exact::pointToShapeDistance's value
    // (decided in floating point or by its GMP route); `exactCount` counts the points the GMP
    // route measured.
    double distance(bool isFloat, bool ofA, const std::array<double, 2>& p, int& exactCount)
    {
        Pair& s = get(isFloat);
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
    Pair& get(bool isFloat)
    {
        const int t = isFloat ? 1 : 0;
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
                own_.a[t].emplace(toExact(c_.a, isFloat), "shape A");
                own_.b[t].emplace(toExact(c_.b, isFloat), "shape B");
                s.pa = &*own_.a[t];
                s.pb = &*own_.b[t];
            }
            have_[t] = true;
        }
        return shapes_[t];
    }
    const Case& c_;
    const TruthShapes* truth_;
    TruthShapes own_;
    Pair shapes_[2];
    bool have_[2] = {false, false};
};

// The witness verdict (judge() left the rest): off its shape comes before the gap.
// An answer of overlap (distance 0) may give two points that each lie in both shapes instead of
// one (docs/validate-your-gjk.md, "The whole answer is judged"): Bullet's penetration points, Box2D
// v3's points on each outline. Either point proves the overlap. Then the witness gap is how far
// the points are from the other shape, and within the witness bound the answer is valid: the
// failure WitnessGap set from ||pB - pA|| is withdrawn (the other reasons stand).
void acceptTwoCommonPoints(VariantOutcome& v, ExactShapes& shapes, bool isFloat)
{
    v.witnessPoints += 2;
    const double aInB = shapes.distance(isFloat, false, v.pointA, v.witnessExact);
    const double bInA = shapes.distance(isFloat, true, v.pointB, v.witnessExact);
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
    ExactShapes shapes(c, out.shapes.get());
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
        const bool isFloat = ctx.variants[k]->scalar == Scalar::Float;
        // Variants often return the very same witness points (same scalar type): each distinct
        // point is measured once per case; a variant's counts include the points it shares.
        double wa = -1, wb = -1;
        Measured& mk = m[k];
        for (std::size_t j = 0; j < k && (wa < 0 || wb < 0); ++j)
        {
            if (m[j].done == 0 || (ctx.variants[j]->scalar == Scalar::Float) != isFloat)
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
            wa = shapes.distance(isFloat, true, v.pointA, n);
            mk.exactA = char(n);
        }
        n = 0;
        if (wb < 0)
        {
            wb = shapes.distance(isFloat, false, v.pointB, n);
            mk.exactB = char(n);
        }
        v.witnessPoints += 2;
        v.witnessExact += mk.exactA + mk.exactB;
        mk.a = wa;
        mk.b = wb;
        mk.done = 1;
        if (v.invalid == Invalid::WitnessGap && v.distance == 0)
            acceptTwoCommonPoints(v, shapes, isFloat);
        judgeWitnesses(v, wa, wb);
    }
    out.shapes.reset(); // the chunk's hulls are not kept past this phase
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

namespace
{
// The exact result as the case JSON gives it (CaseDetail and cases.jsonl alike).
Json exactDetail(const exact::Result& r)
{
    Json e = exactJson(r);
    e["witnessA"] = pt(r.witnessA.x, r.witnessA.y);
    e["witnessB"] = pt(r.witnessB.x, r.witnessB.y);
    e["lower"] = num(r.lower);
    e["upper"] = num(r.upper);
    return e;
}

// One variant's result on a case, as the case JSON gives it (CaseDetail adds the trace).
Json variantResultJson(const VariantInfo& vi, const VariantOutcome& v)
{
    Json vj;
    vj["type"] = scalarName(vi.scalar);
    if (v.skipped)
    {
        vj["skipped"] = v.plugin == PluginStatus::Refused ? kSkipRefused
                        : v.notApplicable                 ? kSkipNotConvexOrder
                                                          : kSkipNotRepresentable;
        return vj;
    }
    if (v.plugin != PluginStatus::NotRun && v.plugin != PluginStatus::Ok)
    {
        vj["plugin_status"] = pluginStatusName(v.plugin);
        vj["plugin_detail"] = v.pluginDetail;
        vj["failed"] = v.failed;
        return vj;
    }
    vj["distance"] = num(v.distance);
    vj["pointA"] = pt(v.pointA[0], v.pointA[1]);
    vj["pointB"] = pt(v.pointB[0], v.pointB[1]);
    vj["normal"] = pt(v.normal[0], v.normal[1]);
    vj["iterations"] = v.iterations;
    vj["stop"] = vi.plugin ? "plugin" : gjk::stopReasonName(v.stop); // a plugin gives no reason
    vj["truth"] = vi.scalar == Scalar::Float ? "exact_float_input" : "exact";
    vj["R"] = num(v.R);
    vj["bound"] = num(v.bound);
    vj["witness_bound"] = num(v.witnessBound);
    vj["errors"] = {{"abs", num(v.abs)},
                    {"rel", optNum(v.rel)},
                    {"ulps", optNum(v.ulps)},
                    {"normalized", num(v.normalized)},
                    {"bound_ratio", num(v.boundRatio)},
                    {"witness", optNum(v.witness)},
                    {"witness_gap", num(v.witnessGap)},
                    {"witness_ratio", optNum(v.witnessRatio)}};
    const char* mis = misclassName(v.mis);
    vj["misclassified"] = mis ? Json(mis) : Json(nullptr);
    const char* invalid = invalidName(v.invalid);
    vj["invalid"] = invalid ? Json(invalid) : Json(nullptr);
    vj["out_of_range"] = v.outOfRange;
    if (vi.options.correctlyRounded)
    {
        vj["path"] = gjk::correctPathName(v.path);
        vj["bit_mismatch"] = v.bitMismatch;
    }
    if (vi.options.certify)
    {
        vj["certified"] = v.certified;
        vj["lower"] = num(v.lower);
        vj["upper"] = num(v.upper);
        vj["interval_contains"] = v.intervalContains;
    }
    vj["failed"] = v.failed;
    return vj;
}

} // namespace

namespace
{
// The exact result of a case detail, with its squared rational: the campaign leaves it out where
// the filter decided (exact::Options::squaredRational), so it is asked for here, for the few
// cases whose details are written (the filter is deterministic: the same result, bit for bit).
Json truthDetail(const Case& c, const EvalContext& ctx, const exact::Result& r, bool floatInput)
{
    if (!r.squaredNum.empty())
        return exactDetail(r);
    exact::Options o = ctx.exactOptions;
    o.squaredRational = true;
    const exact::PreparedShape a(toExact(c.a, floatInput), "shape A");
    const exact::PreparedShape b(toExact(c.b, floatInput), "shape B");
    return exactDetail(ctx.truth(a, b, o));
}
} // namespace

// A cases.jsonl line, and what a CaseDetail starts from: name, family, and either the reason the
// case was rejected or the exact results and each variant's result.
Json perCaseJson(const Case& c, const std::string& family, const EvalContext& ctx,
                 const CaseOutcome& o)
{
    Json j;
    j["name"] = c.name;
    j["family"] = family;
    if (!o.rejected.empty())
    {
        j["rejected"] = o.rejected;
        return j;
    }
    j["exact"] = truthDetail(c, ctx, o.exact, false);
    if (o.hasFloatTruth)
    {
        j["exact_float_input"] = truthDetail(c, ctx, o.exactFloat, true);
        j["input_rounding"] = num(o.inputRounding);
    }
    Json vs = Json::object();
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
        vs[ctx.variants[k]->name] = variantResultJson(*ctx.variants[k], o.variants[k]);
    j["variants"] = std::move(vs);
    return j;
}

Json caseDetail(const Case& c, const std::string& family, const EvalContext& ctx,
                const CaseOutcome& o, const std::string& worstBy)
{
    Json j = perCaseJson(c, family, ctx, o);
    j["worst_by"] = worstBy;
    if (!c.source.empty())
        j["source"] = c.source;
    if (!c.comment.empty())
        j["comment"] = c.comment;
    j["a"] = shapeDetail(c.a);
    j["b"] = shapeDetail(c.b);
    Json mk = Json::array();
    for (const auto& p : minkowskiDifference(worldPoints(c.a), worldPoints(c.b)))
        mk.push_back(pt(p[0], p[1]));
    j["minkowski"] = std::move(mk);
    if (!o.rejected.empty())
        return j;
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
    {
        const VariantInfo& vi = *ctx.variants[k];
        if (o.variants[k].skipped || vi.plugin) // a plugin gives no trace
            continue;
        Json& vj = j["variants"][vi.name];
        if (vi.scalar == Scalar::Float)
        {
            gjk::DistanceOutput<float> out;
            vj["trace"] = tracedRun<float>(c, vi, out);
        }
        else
        {
            gjk::DistanceOutput<double> out;
            vj["trace"] = tracedRun<double>(c, vi, out);
        }
    }
    return j;
}

} // namespace gjkval
