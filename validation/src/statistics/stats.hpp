// Mergeable statistics: counts, extrema, sums and fixed log10 bins (percentiles are read from the
// bins), so that shards merge exactly and the report does not depend on the number of threads.
#pragma once

#include "common/common.hpp"
#include "evaluate/violation.hpp"
#include "statistics/exact_sum.hpp"

#include "gjk2d/distance.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gjkval
{

struct Hist
{
    int log10Min = -40;
    int log10Max = 40;
    int binsPerDecade = 10;
    std::uint64_t count = 0; // values added (zeros included)
    std::uint64_t zeros = 0;
    double max = 0;
    std::string maxCase;
    std::uint64_t maxIndex = 0; // maxCase's place in the family: ties go to the earlier case
    ExactSum total;             // exact: the sum and mean do not depend on the order of merges
    std::vector<std::uint64_t> counts; // bins; sized on first use

    Hist() = default;
    Hist(int lo, int hi, int perDecade = 10) : log10Min(lo), log10Max(hi), binsPerDecade(perDecade)
    {
    }

    std::size_t binCount() const { return std::size_t((log10Max - log10Min) * binsPerDecade); }
    std::size_t binOf(double v) const; // v > 0
    double upperEdge(std::size_t bin) const;
    // v >= 0 and finite (callers count non-finite values apart); `index` is the case's place in
    // its family, which breaks ties of the maximum.
    void add(double v, const std::string& caseName = {}, std::uint64_t index = 0);
    void merge(const Hist& other); // same binning; any order gives the same result
    double sum() const { return total.value(); }
    double mean() const { return count ? sum() / double(count) : 0; }
    // The upper edge of the bin where the cumulative count (zeros first) reaches ceil(count * num /
    // den); 0 when that rank falls among the zeros, and 0 for an empty histogram.
    double percentile(std::uint64_t num, std::uint64_t den) const;
    Json toJson() const;
    // Everything merge() needs, exactly (shards, checkpoints); fromState(state()) == *this.
    Json state() const;
    static Hist fromState(const Json& j);
};

struct IterHist
{
    std::uint64_t count = 0;
    int max = 0;
    std::uint64_t sum = 0;
    std::vector<std::uint64_t> counts; // counts[i]: cases with i iterations
    void add(int iterations);
    void merge(const IterHist& other);
    Json toJson() const;
    Json state() const;
    static IterHist fromState(const Json& j);
};

inline constexpr int kStopReasons = int(gjk::stopReasonCount);

// A family x variant's worst contract violation: the largest finite excess (the measured over the
// allowed, VariantOutcome::violationExcess), ties to the earlier case; one without a size (+inf:
// non-finite, an error status, a crash, a hang) only where there is no measured one (stats.cpp,
// ranksAbove). It merges exactly in any order, as Hist's maximum does. The case name is what
// `gjk-validate repro` and `explain` take.
struct WorstViolation
{
    bool any = false;
    double excess = 0;
    std::string caseName;
    std::uint64_t index = 0; // the case's place in its family
    Violation reason = Violation::None;
    void add(double e, const std::string& name, std::uint64_t i, Violation why);
    void merge(const WorstViolation& o);
    // Worse than `o` by size alone (in the order above; ties are the caller's to break: the
    // earlier family keeps its place in report.json's worst_contract_violation).
    bool outranks(const WorstViolation& o) const;
    // {"case", "reason", "excess"}, or null when there is none.
    Json toJson() const;
    Json state() const; // null when there is none; fromState(state()) == *this
    static WorstViolation fromState(const Json& j);
};

struct VariantOutcome; // evaluate/evaluate.hpp (below statistics/ in the pipeline)
struct VariantInfo;
struct CaseOutcome;

// A family x variant's penetration block (report.json families[].variants[].penetration), for an
// implementation whose contract's overlap is Penetration: its answers on the cases whose exact
// signed distance is < 0 (VariantOutcome::depthJudged, not out of range), their depth errors and
// their verdict. Its members are data as Stats' are (kPenetrationCounts, kPenetrationHists below).
// The state of shards and checkpoints holds it under "penetration", null without it: a state
// written before it (gjk-shard/3 of an earlier revision) reads as a variant without penetration
// answers, so it needs no new version.
struct PenetrationStats
{
    bool any = false;        // the variant's contract says Penetration: the block is written
    std::uint64_t cases = 0; // overlapping cases whose depth was judged
    std::uint64_t contractViolations = 0; // of which: answers that break the contract (any reason)
    std::uint64_t beyondBound = 0;        // of which: |d - s| beyond gjk2d's depth bound
    std::uint64_t beyondBoundKeepingContract = 0; // of which: keeping the contract (class 2)
    std::uint64_t nonfinite = 0;                  // of which: a non-finite answer (no error)
    WorstViolation worstViolation;                // the worst of contractViolations
    // |d - s|, |d - s| / |s| and |d - s| / gjk2d's depth bound.
    Hist abs{-40, 40}, rel{-20, 40}, boundRatio{-20, 40};

    void add(const VariantOutcome& v, const std::string& name, std::uint64_t index);
    void merge(const PenetrationStats& other);
    Json toJson() const;
    Json state() const; // null when !any; fromState(state()) == *this
    static PenetrationStats fromState(const Json& j);
};

struct PenetrationCountField
{
    const char* name; // the report's and the state's key
    std::uint64_t PenetrationStats::*member;
};
inline constexpr PenetrationCountField kPenetrationCounts[] = {
    {"cases", &PenetrationStats::cases},
    {"contract_violations", &PenetrationStats::contractViolations},
    {"beyond_bound", &PenetrationStats::beyondBound},
    {"beyond_bound_keeping_contract", &PenetrationStats::beyondBoundKeepingContract},
    {"nonfinite", &PenetrationStats::nonfinite},
};
struct PenetrationHistField
{
    const char* name;
    Hist PenetrationStats::*member;
};
inline constexpr PenetrationHistField kPenetrationHists[] = {
    {"abs", &PenetrationStats::abs},
    {"rel", &PenetrationStats::rel},
    {"bound_ratio", &PenetrationStats::boundRatio},
};

// One family x one variant.
struct Stats
{
    std::uint64_t cases = 0;
    std::uint64_t failures = 0;
    std::uint64_t falseOverlap = 0, falseSeparation = 0, undecidable = 0;
    std::uint64_t nonfinite = 0, outOfRange = 0, iterationLimit = 0;
    std::uint64_t beyondBound = 0; // judged cases with |error| > bound
    // Judged cases whose answer is not a valid answer (negative distance, witness points beyond the
    // witness bound), each also a failure; by reason (Invalid, common.hpp: [r - 1] for reason r).
    std::uint64_t invalid = 0;
    std::array<std::uint64_t, kInvalidReasons> invalidReasons{};
    // The verdict by each implementation's own contract (evaluate/contract_judge.cpp; for gjk2d's
    // own contract the same answers as `failures`): answers that break it, by reason (Violation:
    // [r - 1] for reason r), and the worst; judged answers that keep it but are beyond gjk2d's
    // bound (class 2, a measured accuracy: of `beyond_bound`; the distance's only: a depth beyond
    // gjk2d's depth bound is counted in `penetration`).
    std::uint64_t contractViolations = 0, beyondBoundKeepingContract = 0;
    std::array<std::uint64_t, kViolationReasons> violationReasons{};
    WorstViolation worstViolation;
    std::uint64_t skipped = 0;       // not run: input not representable, or not applicable
    std::uint64_t notApplicable = 0; // of which: the variant's precondition fails (convex order)
    // Plugin variants (implementations/plugins.hpp): cases the implementation refused (not run, not
    // failed, apart from `skipped`), and cases it answered GJK2D_STATUS_ERROR, crashed or hung on
    // (each counted in `cases` and `failures`, without errors measured).
    std::uint64_t refused = 0, pluginErrors = 0, crashed = 0, hung = 0;
    // Certified variants: intervals given, intervals holding the truth, queries left uncertified.
    bool hasInterval = false;
    std::uint64_t certified = 0, contains = 0, uncertified = 0;
    Hist widthUlps{-20, 40}; // (upper - lower) / ulp(d_exact), d_exact > 0
    // Correctly rounded variants (Options::correctlyRounded): the queries each path decided
    // (gjk::CorrectPath Double, Extended, DoubleDouble, Exact) and the answers not bit-identical
    // to the exact side's (each a failure).
    bool hasPaths = false;
    std::uint64_t pathDouble = 0, pathExtended = 0, pathDoubleDouble = 0, pathExact = 0,
                  bitMismatch = 0;
    // Witness points measured (two per checked answer, four when an overlap's two common points
    // are checked), and of those the ones the GMP route measured: exact::pointToShapeDistance's
    // floating-point filter did not decide them.
    std::uint64_t witnessPoints = 0, witnessExact = 0;
    // The truth this variant is judged against (exact::Fallbacks, docs/exact.md "The filter"):
    // cases whose rounded outputs came from the GMP route, and cases with at least one exact
    // decision of each kind (predicates decided by exact integers; roundings the filter left open).
    std::uint64_t truthGmp = 0, truthHull = 0, truthMerge = 0, truthFeature = 0, truthSquared = 0,
                  truthDistance = 0, truthWitness = 0;
    Hist abs{-40, 40}, rel{-20, 40}, ulps{-20, 40}, normalized{-20, 40}, boundRatio{-20, 40};
    Hist witness{-40, 40}, witnessGap{-40, 40}, inputRounding{-40, 40};
    Hist witnessRatio{-20, 40}; // max(witness, witness_gap) / witness bound; > 1: invalid
    bool hasInputRounding = false;
    IterHist iterations;
    std::array<std::uint64_t, kStopReasons> stops{};
    PenetrationStats penetration; // a penetration contract's depths (its own block)

    // Timing (not merged: measured once per family and variant).
    double nsPerQuery = -1, nsMin = -1, nsMax = -1, ratioToBaseline = -1;
    int timingPasses = 0;
    // The preparation of one shape, timed apart from the query (a variant with a preparation step:
    // implementations/plugins.hpp, Preparation; gjk2d's own with a prepared form: gjk::prepare);
    // -1: none measured.
    double prepareNsPerShape = -1;
    // gjk2d's own variant with a prepared form: the same queries on prepared shapes, nsPerQuery
    // staying the plain query's (timing/timing.hpp, preparedLoop); -1: none measured.
    double preparedNsPerQuery = -1;

    // Folds one judged query (case `name`, its place `index` in the family) of variant `vi`.
    void add(const VariantOutcome& v, const std::string& name, std::uint64_t index,
             const VariantInfo& vi, const CaseOutcome& o);
    void merge(const Stats& other);
    Json toJson() const;
    // The merged part (not the timing), exactly: what a shard or a checkpoint writes.
    Json state() const;
    static Stats fromState(const Json& j);
};

// --- Stats' members as data: the one place a metric is named -------------------------------------
// A new counter or histogram: declare it in Stats above, fold it in Stats::add, and give it one
// row below. merge, toJson (the report, docs/report-schema.md), state/fromState (shards and
// checkpoints) and `gjk-validate compare` (the rows with `regresses`) all read these tables.
// Rows are in the report's order; where a member sits in the report is its Section. The report
// writes three derived fields beside a row: "pass" after failures, "invalid_reasons" after
// invalid, "misses" after contains (stats.cpp, toJson); and the Contract rows after the Top ones,
// contract_violations as an object with its reasons and worst case. The state is the tables in
// their order (docs/report-schema.md, StatsState): a row added, renamed or removed changes it, so
// bump the state's version with it (kShardSchema, kCheckpointSchema and kOldStateVersions in
// campaign/campaign.hpp).
enum class Section : std::uint8_t
{
    Top,      // report: top level (a histogram: under "errors")
    Contract, // report: top level after the Top rows; contract_violations as {"count", ...}
    Interval, // report: under "interval" (certified variants)
    Correct,  // report: under "correct" (correctly rounded variants)
    Truth,    // report: under "truth", the last key
};

struct CountField
{
    const char* name; // the report's and the state's key
    std::uint64_t Stats::*member;
    Section section;
    bool regresses; // `compare` flags any increase (docs/report-schema.md, Stats)
};

inline constexpr CountField kCountFields[] = {
    {"cases", &Stats::cases, Section::Top, false},
    {"failures", &Stats::failures, Section::Top, true},
    {"false_overlap", &Stats::falseOverlap, Section::Top, true},
    {"false_separation", &Stats::falseSeparation, Section::Top, true},
    {"undecidable", &Stats::undecidable, Section::Top, true},
    {"nonfinite", &Stats::nonfinite, Section::Top, true},
    {"out_of_range", &Stats::outOfRange, Section::Top, true},
    {"iteration_limit", &Stats::iterationLimit, Section::Top, true},
    {"beyond_bound", &Stats::beyondBound, Section::Top, true},
    {"invalid", &Stats::invalid, Section::Top, true},
    {"skipped", &Stats::skipped, Section::Top, true},
    // `compare` reads contract_violations.count (its own row; the Contract rows are not top-level
    // numbers there), flagging any increase.
    {"contract_violations", &Stats::contractViolations, Section::Contract, true},
    {"beyond_bound_keeping_contract", &Stats::beyondBoundKeepingContract, Section::Contract, false},
    {"not_applicable", &Stats::notApplicable, Section::Top, false},
    {"refused", &Stats::refused, Section::Top, false},
    {"plugin_errors", &Stats::pluginErrors, Section::Top, false},
    {"crashed", &Stats::crashed, Section::Top, false},
    {"hung", &Stats::hung, Section::Top, false},
    {"witness_points", &Stats::witnessPoints, Section::Top, false},
    {"witness_exact", &Stats::witnessExact, Section::Top, false},
    {"certified", &Stats::certified, Section::Interval, false},
    {"contains", &Stats::contains, Section::Interval, false},
    {"uncertified", &Stats::uncertified, Section::Interval, false},
    {"bit_mismatches", &Stats::bitMismatch, Section::Correct, false},
    {"gmp_route", &Stats::truthGmp, Section::Truth, false},
    {"hull", &Stats::truthHull, Section::Truth, false},
    {"merge", &Stats::truthMerge, Section::Truth, false},
    {"feature", &Stats::truthFeature, Section::Truth, false},
    {"squared", &Stats::truthSquared, Section::Truth, false},
    {"distance", &Stats::truthDistance, Section::Truth, false},
    {"witness", &Stats::truthWitness, Section::Truth, false},
};

struct HistField
{
    const char* name;
    Hist Stats::*member;
    Section section;      // Top: under the report's "errors"
    bool Stats::*shownIf; // the report writes it only when this flag is set; nullptr: always
};

inline constexpr HistField kHistFields[] = {
    {"abs", &Stats::abs, Section::Top, nullptr},
    {"rel", &Stats::rel, Section::Top, nullptr},
    {"ulps", &Stats::ulps, Section::Top, nullptr},
    {"normalized", &Stats::normalized, Section::Top, nullptr},
    {"bound_ratio", &Stats::boundRatio, Section::Top, nullptr},
    {"witness", &Stats::witness, Section::Top, nullptr},
    {"witness_gap", &Stats::witnessGap, Section::Top, nullptr},
    {"witness_ratio", &Stats::witnessRatio, Section::Top, nullptr},
    {"input_rounding", &Stats::inputRounding, Section::Top, &Stats::hasInputRounding},
    {"width_ulps", &Stats::widthUlps, Section::Interval, nullptr},
};

// Flags merged by "or"; hasPaths is not one: the state's "paths" (null without) stands for it.
struct FlagField
{
    const char* name;
    bool Stats::*member;
};

inline constexpr FlagField kFlagFields[] = {
    {"has_interval", &Stats::hasInterval},
    {"has_input_rounding", &Stats::hasInputRounding},
};

// The queries each gjk::CorrectPath decided, in the report's order; named by gjk::correctPathName.
struct PathField
{
    gjk::CorrectPath path;
    std::uint64_t Stats::*member;
};

inline constexpr PathField kPathFields[] = {
    {gjk::CorrectPath::Double, &Stats::pathDouble},
    {gjk::CorrectPath::Extended, &Stats::pathExtended},
    {gjk::CorrectPath::DoubleDouble, &Stats::pathDoubleDouble},
    {gjk::CorrectPath::Exact, &Stats::pathExact},
};

} // namespace gjkval
