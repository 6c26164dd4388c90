// One case: the exact truth, every variant's GJK result, its errors against the truth, its
// witness-point errors; and the case-detail JSON (docs/report-schema.md, "CaseDetail").
#pragma once

#include "evaluate/bounds.hpp"
#include "evaluate/violation.hpp"
#include "implementations/contract.hpp"
#include "implementations/plugins.hpp"
#include "implementations/prepared.hpp"
#include "implementations/variants.hpp"
#include "inputs/cases.hpp"

#include "gjk2d/batch.hpp"
#include "gjk2d/distance.hpp"

#include <gjk2d/exact.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gjkval
{

// Why a variant does not run on a case (skipped, not a failure), or null. floatInput: the case's
// float-rounded input is usable (finite, with an exact truth when one is needed). A variant given
// world points (InputForm::World) runs where its world case fits its scalar type
// (PreparedCase::worldOk), whatever the case's own float rounding.
const char* skipReason(const VariantInfo& v, const PreparedCase& p, bool floatInput);
inline constexpr const char* kSkipNotRepresentable = "input not representable in float";
inline constexpr const char* kSkipWorldNotRepresentable =
    "world points not representable in the implementation's scalar type";
inline constexpr const char* kSkipRefused = "refused by the implementation (plugin)";
inline constexpr const char* kSkipNotConvexOrder =
    "not applicable: binary-search support needs each shape's points in convex order";

// Start::EveryStart: the query from every start the variant tries, the answer farthest
// from `truth` (a non-finite answer is the farthest) returned; ties keep the earlier start. Where
// SIMD lanes pay on the case's shapes (gjk::bestBatchIsaFor: always for float, for double on small
// shapes), the starts after the cold one are answered as one gjk::distanceBatchLanes, the same
// input in every slot (about 35 queries a `random` case; the scalar query's bits, gjk2d/batch.hpp);
// elsewhere by the scalar query one start after the other, which is what the batch would run, less
// its copies (docs/speed.md, "The every-start variants' starts in SIMD lanes").
template <class T> struct StartBatch
{
    std::vector<gjk::DistanceInput<T>> inputs;
    std::vector<gjk::SimplexCache> caches;
    std::vector<gjk::DistanceOutput<T>> outputs;
};

template <class T>
gjk::DistanceOutput<T> worstStart(const PreparedCase& p, const VariantInfo& v, double truth)
{
    const gjk::DistanceInput<T> in = p.input<T>();
    const int nA = in.proxyA.count, nB = in.proxyB.count;
    gjk::DistanceOutput<T> worst = query<T>(p, v); // the cold start
    double worstError = std::abs(double(worst.distance) - truth);
    thread_local StartBatch<T> b; // reused: no allocation once a thread has seen as many starts
    const bool lanes = gjk::bestBatchIsaFor(std::span<const gjk::DistanceInput<T>>(&in, 1)) !=
                       gjk::BatchIsa::Scalar;
    b.caches.clear();
    const int strideA = (nA + 11) / 12, strideB = (nB + 11) / 12;
    for (int i = 0; i < nA; i += strideA)
        for (int j = 0; j < nB; j += strideB)
            b.caches.push_back({1, {i, 0, 0}, {j, 0, 0}});
    // Edges and triangles of index pairs that are rarely adjacent on Z: whatever GJK makes of them,
    // every cached vertex is a point of Z, so the answer must still be right.
    b.caches.push_back({2, {0, nA / 2, 0}, {0, nB / 2, 0}});
    b.caches.push_back({2, {0, nA - 1, 0}, {nB - 1, 0, 0}});
    b.caches.push_back({3, {0, nA / 3, (2 * nA) / 3}, {0, nB / 3, (2 * nB) / 3}});
    b.caches.push_back({3, {0, 0, nA - 1}, {0, nB - 1, 0}});
    auto consider = [&](const gjk::DistanceOutput<T>& o)
    {
        const double e = std::abs(double(o.distance) - truth);
        if (!(e <= worstError)) // NaN counts as worst
        {
            worst = o;
            worstError = e;
        }
    };
    if (!lanes)
    {
        for (gjk::SimplexCache& cache : b.caches)
            consider(gjk::distance(in, cache, v.options));
        return worst;
    }
    b.inputs.assign(b.caches.size(), in);
    b.outputs.resize(b.caches.size());
    gjk::distanceBatchLanes(std::span<const gjk::DistanceInput<T>>(b.inputs),
                            std::span<gjk::SimplexCache>(b.caches),
                            std::span<gjk::DistanceOutput<T>>(b.outputs), v.options);
    for (const gjk::DistanceOutput<T>& o : b.outputs)
        consider(o);
    return worst;
}

enum class Misclass
{
    None,
    FalseOverlap,    // exact distance > 0, GJK 0, |error| > bound
    FalseSeparation, // exact distance 0, GJK > 0, |error| > bound
    Undecidable,     // one of the two, but |error| <= bound: not decidable at this precision
};
const char* misclassName(Misclass m); // null for None

struct VariantOutcome
{
    bool skipped = false;       // not run: skipReason() (not representable, or not applicable)
    bool notApplicable = false; // skipped because the variant's precondition fails (convex order)
    const char* skipWhy = nullptr; // skipped: skipReason()'s, or kSkipRefused
    // Given the case's world case (InputForm::World), not the case: judged on it
    // (CaseOutcome::world)
    bool worldInput = false;
    double distance = 0;
    std::array<double, 2> pointA{}, pointB{}, normal{};
    int iterations = 0;
    gjk::StopReason stop = gjk::StopReason::RepeatedSupport;
    double truth = 0; // the exact distance this variant is judged against
    double R = 0;     // scale in the compute frame
    double bound = 0;
    double witnessBound =
        0; // each witness point's distance to its shape, and the gap, at most this
    // Errors; NaN = not applicable (rel and ulps when the truth is 0, witness before checking).
    double abs = 0, rel = 0, ulps = 0, normalized = 0, boundRatio = 0;
    double witness = 0, witnessGap = 0;
    // max(witness, witnessGap) / witnessBound (0 when both are 0), set with witness in phase 3.
    double witnessRatio = 0;
    Misclass mis = Misclass::None;
    Invalid invalid = Invalid::None; // judged cases only (not outOfRange); a failure
    bool nonfinite = false, iterationLimit = false;
    bool outOfRange =
        false; // GJK's own flag (DistanceOutput::outOfRange): not judged, counted apart
    bool beyondBound = false; // |error| > bound (or not finite)
    // Certified variants (Options::certify): the interval and whether it holds the exact distance.
    bool certified = false, intervalContains = false;
    double lower = 0, upper = 0;
    // Correctly rounded variants: how the distance was decided, and whether it differs from the
    // exact side's in any bit (a failure: zero tolerance).
    gjk::CorrectPath path = gjk::CorrectPath::Plain;
    bool bitMismatch = false;
    bool failed = false;
    // Witness points whose distance to their shape was measured (phase 3), and of those the ones
    // the GMP route measured (exact::pointToShapeDistance's floating-point filter did not decide
    // them). A point shared with another variant counts for each.
    int witnessPoints = 0, witnessExact = 0;
    // Plugin variants: how the implementation answered (Ok, or Refused with skipped set, or
    // Error / Crashed / Hung: failed, no errors measured) and how it died.
    PluginStatus plugin = PluginStatus::NotRun;
    std::string pluginDetail;
    // The verdict by the implementation's own contract (judgeContract, phase 3): why the answer
    // breaks it (None: it keeps it), and by how much: the measured over the allowed (+inf for a
    // break that has no size: an error status, a non-finite or negative answer). For gjk2d's own
    // contract the violation is exactly `failed`, named by its first reason. Three classes per
    // answer: a violation; keeping the contract but beyondBound (a measured accuracy, not a
    // failure); within gjk2d's bound.
    Violation violation = Violation::None;
    double violationExcess = 0;
    // A declared contract's distance tolerance T and witness tolerance W for this case (gjk2d's
    // own: bound and witnessBound).
    double tolerance = 0, witnessTolerance = 0;
    // Penetration (an implementation whose contract's overlap is Penetration: gjk2d's signed
    // variants, plugins that declare it) on shapes whose exact signed distance s is < 0, set by
    // judge() (docs/judgement.md, "Penetration"): the answer's signed distance d against s.
    // depthBound is gjk2d's depth bound for the case (evaluate/bounds.hpp), depthTolerance what the
    // contract holds the depth to (its depth clause abs + rel |s| when stated, else depthBound;
    // judgeContracts sets it). depthAbs = |d - s| (+inf for a non-finite answer), depthRel =
    // depthAbs / |s|, depthRatio = depthAbs / depthBound.
    bool depthJudged = false;
    double signedTruth = 0, depthBound = 0, depthTolerance = 0;
    double depthAbs = 0, depthRel = 0, depthRatio = 0;
    double depthNormalized = 0;    // depthAbs / (u R): ranks the worst cases beside `normalized`
    bool beyondDepthBound = false; // depthAbs > depthBound (or not finite)
    bool truthZero = false;        // the exact distance is 0 (exactIsZero), set by judge()
    bool keepsContract() const { return violation == Violation::None; }
};

// The inputs a variant may be given of a case, its views: 0 the case as given, 1 its numbers
// rounded to float (a float variant), 2 its world case in double, 3 its world case rounded to float
// (a variant whose contract's input is InputForm::World; inputs/geometry.hpp, worldCase).
inline constexpr int kInputViews = 4;
int inputView(const VariantInfo& v);
inline bool viewIsFloat(int view)
{
    return view % 2 == 1;
}
inline bool viewIsWorld(int view)
{
    return view >= 2;
}

// A case's shapes on the exact side, prepared once (hull and interval world points) by
// computeTruth for its truths and kept for the witness checks, which read the same hulls: by view
// (inputView), each when its truth was computed.
struct TruthShapes
{
    std::optional<exact::PreparedShape> a[kInputViews], b[kInputViews];
};

// The world case a variant given world points runs on (InputForm::World), for one scalar type:
// the case, its exact truth, and |exact.distance - the case's exact distance| (its input change,
// the report's input_rounding).
struct WorldTruth
{
    Case c;
    exact::Result exact;
    double inputRounding = 0;
};

struct CaseOutcome
{
    std::string rejected; // non-empty: not evaluated
    // computeTruth's prepared shapes, released by checkWitnesses once it has read them.
    std::shared_ptr<const TruthShapes> shapes;
    exact::Result exact;
    bool hasFloatTruth = false;
    exact::Result exactFloat; // exact truth of the float-rounded input
    double inputRounding = 0; // |exactFloat.distance - exact.distance|
    // The world cases, [0] double and [1] float, computed when some variant of that scalar type is
    // given world points and the world case fits (PreparedCase::worldOk); else empty.
    std::optional<WorldTruth> world[2];
    std::vector<VariantOutcome> variants;
    // The plugin variants' answers (answerPluginVariants), by variant index; empty without them.
    std::vector<ExternalAnswer> external;

    // The key the worst cases are ranked by: the largest worstKey() of its variants.
    double worstKey() const;
    // The variant of that key (the first of equals).
    std::size_t worstVariant() const;
};

// How bad one variant's result is, for ranking the worst cases: -1 when it is not judged (not run,
// or flagged out of range by GJK without failing), +inf for a non-finite or invalid result, an
// iteration limit or a certified interval that misses the truth, else the normalised error (for a
// judged penetration depth, the larger of it and the depth's: depthNormalized).
double worstKey(const VariantOutcome& v);

struct EvalContext
{
    std::vector<const VariantInfo*> variants;
    exact::Options exactOptions;
    // The oracle, behind one adapter: exact::distance. Tests put a failing one here to check that a
    // broken invariant of the truth fails the run instead of rejecting the case.
    exact::Result (*truth)(const exact::PreparedShape&, const exact::PreparedShape&,
                           const exact::Options&) = &exact::distance;
    double pluginTimeoutSeconds = kDefaultPluginTimeoutSeconds; // per plugin call
    // The children that answer shared-library plugins for a campaign, kept from chunk to chunk
    // (used between parallel phases only); null: children for each call only.
    std::shared_ptr<PluginServers> pluginServers;
    // Some variant given the case as it is (InputForm::Case) is float: the float truth is needed.
    bool needFloatTruth() const;
    // Some variant of that scalar type is given world points: the world case's truth is needed.
    bool needWorldTruth(bool isFloat) const;
    bool hasPlugins() const;
    // Some variant's contract says Penetration: the truth then carries the exact signed distance.
    bool needPenetration() const;
    // The options every truth of the context is computed with: exactOptions, with
    // exact::Options::penetration set when needPenetration() (the exact depth costs only the runs
    // that judge one).
    exact::Options truthOptions() const;
};

// The judgement of one answer v (v.R, v.bound and v.witnessBound set) against the exact `truth`:
// its errors, its misclassification, whether it is invalid (negative distance, witness gap; the
// witness points' distances to their shapes come in phase 3), whether its certified interval holds
// the truth, and whether it failed (docs/judgement.md, "Failures"). runVariants calls it.
// `overlap`: what the implementation answers on overlap; for Zero and Penetration a negative
// distance is their way to say 0, and the errors are measured on max(d, 0). For Penetration a
// negative distance is not invalid, the witness gap is | ||pB - pA|| - |d| |, a certified
// interval is held to the exact signed distance, and on shapes whose exact signed distance is < 0
// the depth is judged (v.depthBound set): beyond it, the answer fails.
void judge(VariantOutcome& v, const exact::Result& truth, Scalar scalar, bool zeroTolerance,
           Overlap overlap = Overlap::CommonPoint);
// Whether a judged answer fails: the one rule, for judge() and for the witness verdict (phase 3).
// Cases GJK flags out of range are not judged (docs/error-bound.md, assumptions); a certified
// interval that misses the truth, or a correctly rounded distance that is not the exact side's,
// always fails.
bool failedAnswer(const VariantOutcome& v);

// Phase 1: the exact truths. The truth's std::invalid_argument rejects the case (bad input);
// any other exception (a broken invariant of ours) propagates and fails the run.
void computeTruth(const Case& c, const EvalContext& ctx, CaseOutcome& out);
// Phase 2a: the plugin variants' answers for n cases (truth computed, inputs prepared), in child
// processes (answerContained): out[i].external. Not thread-safe: called between parallel phases.
void answerPluginVariants(const Case* cases, const PreparedCase* prepared, CaseOutcome* out,
                          std::size_t n, const EvalContext& ctx);
// Phase 2: GJK for every variant, errors, misclassification, failure.
void runVariants(const Case& c, const PreparedCase& p, const EvalContext& ctx, CaseOutcome& out);
// Phase 3: exact distance of each witness point to its shape, and the witness verdict (a point off
// its shape beyond the witness bound makes the answer invalid, and failed).
void checkWitnesses(const Case& c, const EvalContext& ctx, CaseOutcome& out);
// The contract verdict of every variant of the case (judgeContract), once its witnesses are
// measured: checkWitnesses calls it last.
void judgeContracts(const Case& c, const EvalContext& ctx, CaseOutcome& out);
// All of them.
CaseOutcome evaluateCase(const Case& c, const EvalContext& ctx);

// An answer's class (docs/judgement.md, "Contracts"): "breaks_contract" (a violation of its
// implementation's contract), "out_of_range" (gjk2d's own, flagged by GJK: not judged),
// "outside_bound" (keeps its contract, beyond gjk2d's bound: a measured accuracy, not a failure),
// "within_bound"; "skipped" when it did not run.
inline const char* answerClassName(const VariantOutcome& v)
{
    if (v.skipped)
        return "skipped";
    if (!v.keepsContract())
        return "breaks_contract";
    if (v.outOfRange)
        return "out_of_range";
    return v.beyondBound || v.beyondDepthBound ? "outside_bound" : "within_bound";
}

// Exact distance is 0: the (rounded) shapes touch or overlap.
inline bool exactIsZero(const exact::Result& r)
{
    return r.overlap || r.upper == 0;
}

// The exact signed distance is known and < 0: the rounded shapes overlap with a depth > 0 (the
// cases whose penetration depth is judged; touching shapes, depth 0, are not among them).
inline bool overlapsBySigned(const exact::Result& r)
{
    return r.hasSigned && r.signedUpper < 0;
}

// The case of a view (inputView): c for 0 and 1 (1 rounded to float where it is read), the world
// case (out.world) for 2 and 3; std::logic_error when that world case was not computed.
const Case& viewCase(const Case& c, const CaseOutcome& out, int view);
// The exact truth a view is judged on: out.exact, out.exactFloat, or the world case's.
const exact::Result& viewTruth(const CaseOutcome& out, int view);

// Unit in the last place of the variant's type at x > 0.
double ulpOf(Scalar s, double x);

// docs/report-schema.md "CaseDetail", with traces (the query is run again with a trace).
Json caseDetail(const Case& c, const std::string& family, const EvalContext& ctx,
                const CaseOutcome& o, const std::string& worstBy);
// One line of cases.jsonl.
Json perCaseJson(const Case& c, const std::string& family, const EvalContext& ctx,
                 const CaseOutcome& o);

} // namespace gjkval
