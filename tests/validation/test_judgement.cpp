// The runner's judgement of one answer, with expected values worked out by hand: the error bound
// term by term (docs/error-bound.md), beyond-bound at exactly the bound, the misclassifications
// (false overlap, false separation, undecidable), the certified interval against the truth's
// enclosure, and an iteration limit. Where an exact truth cannot produce the situation (an error of
// exactly the bound, an exact value just above a certified upper end) the test puts its own truth
// behind EvalContext::truth: the judgement is a function of the answer and the truth, whatever
// computed the truth. These pin the runner mutants of scripts/mutants.json (docs/testing.md).
#include "evaluate/bounds.hpp"
#include "evaluate/evaluate.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace gjkval;

namespace
{
const double kDenormMin = std::numeric_limits<double>::denorm_min(); // 2^-1074

// The truth every evaluateCase of a test returns (set before the call).
exact::Result gTruth;
exact::Result fixedTruth(const exact::PreparedShape&, const exact::PreparedShape&,
                         const exact::Options&)
{
    return gTruth;
}

exact::Result truthOf(double lower, double upper, bool overlap = false)
{
    exact::Result r;
    r.overlap = overlap;
    r.distance = lower;
    r.lower = lower;
    r.upper = upper;
    return r;
}

Case points(double bx, double by)
{
    Case c;
    c.name = "points";
    c.a.points = {{0, 0}};
    c.b.points = {{bx, by}};
    return c;
}

VariantOutcome judge(const Case& c, const VariantInfo* v, bool fixed)
{
    EvalContext ctx;
    ctx.variants = {v};
    if (fixed)
        ctx.truth = &fixedTruth;
    const CaseOutcome o = evaluateCase(c, ctx);
    REQUIRE(o.rejected.empty());
    REQUIRE(o.variants.size() == 1);
    return o.variants[0];
}
} // namespace

TEST_CASE("the error bound, term by term, as docs/error-bound.md writes it", "[judgement][bound]")
{
    // u (4 A + 43 B + 10.2 D + 1.5 B~ + 5 W + 6.5 d + 3.5 (rA + rB)) + sub_T, plus 16 u W for
    // duality-gap stopping. One metric at 1, the others 0: the bound is coefficient * u (u a power
    // of two, so coefficient * u is exact; the subnormal is far below its last bit and rounds
    // away).
    struct Term
    {
        const char* name;
        double CaseMetrics::*metric;
        double coefficient;
        double dualityGapExtra; // what DualityGap stopping adds for this metric
    };
    const Term terms[] = {
        {"A", &CaseMetrics::maxA, 4, 0},           {"B", &CaseMetrics::maxB, 43, 0},
        {"D", &CaseMetrics::translation, 10.2, 0}, {"B~", &CaseMetrics::maxBMapped, 1.5, 0},
        {"W", &CaseMetrics::maxW, 5, 16},          {"d", &CaseMetrics::exactDistance, 6.5, 0},
        {"rA", &CaseMetrics::radiusA, 3.5, 0},     {"rB", &CaseMetrics::radiusB, 3.5, 0}};
    for (const char* name : {"double", "float", "double-duality-gap"})
    {
        const VariantInfo& v = *findVariant(name);
        const double u = v.scalar == Scalar::Float ? 0x1p-24 : 0x1p-53;
        for (const Term& t : terms)
        {
            INFO(name << ": term " << t.name);
            CaseMetrics m;
            m.unitRoundoff = u;
            m.*t.metric = 1;
            const double extra =
                v.options.stopping == gjk::StoppingRule::DualityGap ? t.dualityGapExtra : 0;
            CHECK(errorBound(v, m) == (t.coefficient + extra) * u);
        }
        // Every metric 0: only the type's smallest subnormal, the answer's own resolution.
        CaseMetrics zero;
        zero.unitRoundoff = u;
        CHECK(errorBound(v, zero) == (v.scalar == Scalar::Float ? 0x1p-149 : 0x1p-1074));
    }
    // All together, distinct values (A 1, B 2, D 0, B~ 1, W 2, d 0, rA 2, rB 4):
    // 4 + 86 + 1.5 + 10 + 3.5 * 6 = 122.5; duality gap + 16 * 2 = 154.5.
    CaseMetrics m;
    m.unitRoundoff = 0x1p-53;
    m.maxA = 1;
    m.maxB = 2;
    m.maxBMapped = 1;
    m.maxW = 2;
    m.radiusA = 2;
    m.radiusB = 4;
    CHECK(errorBound(*findVariant("double"), m) == 122.5 * 0x1p-53);
    CHECK(errorBound(*findVariant("double-duality-gap"), m) == 154.5 * 0x1p-53);
}

TEST_CASE("an error of exactly the bound is within it: undecidable, not a failure",
          "[judgement][classification]")
{
    // Two coincident points: GJK answers 0 and every metric of the bound is 0, so the bound is the
    // smallest subnormal alone (u * 6.5 d underflows to 0 for d = 2^-1074). A truth of 2^-1074
    // makes the error exactly the bound: within it ("<=", docs/error-bound.md), so the false
    // overlap is undecidable, not a failure. One subnormal more and it is a failed false overlap.
    const VariantInfo* dbl = findVariant("double");
    const Case c = points(0, 0);

    gTruth = truthOf(kDenormMin, kDenormMin);
    const VariantOutcome at = judge(c, dbl, true);
    REQUIRE(at.distance == 0);
    CHECK(at.bound == kDenormMin);
    CHECK(at.abs == kDenormMin);
    CHECK_FALSE(at.beyondBound);
    CHECK(at.mis == Misclass::Undecidable);
    CHECK_FALSE(at.failed);

    gTruth = truthOf(2 * kDenormMin, 2 * kDenormMin);
    const VariantOutcome beyond = judge(c, dbl, true);
    CHECK(beyond.bound == kDenormMin);
    CHECK(beyond.abs == 2 * kDenormMin);
    CHECK(beyond.beyondBound);
    CHECK(beyond.mis == Misclass::FalseOverlap);
    CHECK(beyond.failed);
}

TEST_CASE("false separation needs a positive answer: a zero answer on a zero truth is right",
          "[judgement][classification]")
{
    const VariantInfo* dbl = findVariant("double");
    // Overlapping squares, the real exact truth: distance 0, GJK 0: no misclassification at all.
    Case overlap;
    overlap.name = "overlap";
    overlap.a.points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    overlap.b.points = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    const VariantOutcome ok = judge(overlap, dbl, false);
    REQUIRE(ok.truth == 0);
    REQUIRE(ok.distance == 0);
    CHECK(ok.mis == Misclass::None);
    CHECK_FALSE(ok.beyondBound);
    CHECK_FALSE(ok.failed);

    // Points 1 apart against a truth of "overlap": GJK's 1 is a false separation, far beyond the
    // bound (a few u): it fails.
    gTruth = truthOf(0, 0, true);
    const VariantOutcome sep = judge(points(1, 0), dbl, true);
    REQUIRE(sep.distance == 1);
    CHECK(sep.abs == 1);
    CHECK(sep.beyondBound);
    CHECK(sep.mis == Misclass::FalseSeparation);
    CHECK(sep.failed);
}

TEST_CASE("a certified interval must contain the truth's whole enclosure", "[judgement][interval]")
{
    // Points (0, 0) and (3, 4): distance 5. The certified interval [lower, upper] holds the exact
    // truth [5, 5]. An exact value strictly between upper and the next double (the enclosure
    // [upper, next(upper)]) is outside it, although the enclosure's lower end is inside: the
    // interval misses the truth, and a certified interval that misses always fails.
    const VariantInfo* cert = findVariant("double-certified");
    const Case c = points(3, 4);
    const VariantOutcome real = judge(c, cert, false);
    REQUIRE(real.certified);
    REQUIRE(real.truth == 5);
    CHECK(real.intervalContains);
    CHECK_FALSE(real.failed);
    REQUIRE(real.lower <= 5);
    REQUIRE(5 <= real.upper);

    const double above = std::nextafter(real.upper, INFINITY);
    gTruth = truthOf(real.upper, above);
    const VariantOutcome justAbove = judge(c, cert, true);
    REQUIRE(justAbove.certified);
    REQUIRE(justAbove.upper == real.upper);
    CHECK_FALSE(justAbove.beyondBound); // the distance is fine, the certificate is not
    CHECK_FALSE(justAbove.intervalContains);
    CHECK(justAbove.failed);

    const double below = std::nextafter(real.lower, -INFINITY);
    gTruth = truthOf(below, real.lower);
    const VariantOutcome justBelow = judge(c, cert, true);
    CHECK_FALSE(justBelow.intervalContains);
    CHECK(justBelow.failed);
}

TEST_CASE("reaching the iteration limit fails, even with the right distance", "[judgement][limit]")
{
    // A square [-1, 1]^2 against the point (0, 5): the first support pair gives a top corner, the
    // second the other top corner, and that edge already holds the answer 4. With one iteration
    // allowed GJK stops there on the limit (docs/judgement.md: an iteration limit is a failure).
    static const VariantInfo limited{"double-one-iteration", Scalar::Double,
                                     gjk::Options{.maxIterations = 1}, "test", true};
    Case c;
    c.name = "square-point";
    c.a.points = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    c.b.points = {{0, 0}};
    c.b.py = 5;
    const VariantOutcome free = judge(c, findVariant("double"), false);
    REQUIRE(free.stop != gjk::StopReason::IterationLimit);
    CHECK(free.distance == 4);
    CHECK_FALSE(free.failed);

    const VariantOutcome v = judge(c, &limited, false);
    REQUIRE(v.stop == gjk::StopReason::IterationLimit);
    CHECK(v.distance == 4);
    CHECK(v.abs == 0);
    CHECK_FALSE(v.beyondBound);
    CHECK(v.iterationLimit);
    CHECK(v.failed);
    CHECK(worstKey(v) == INFINITY);
}

namespace
{
// An answer as a plugin would give it, judged by judge() against `truth` (bounds set by hand).
VariantOutcome answer(double distance, std::array<double, 2> pA, std::array<double, 2> pB,
                      const exact::Result& truth, double bound = 1, double witnessBound = 0.25)
{
    VariantOutcome v;
    v.distance = distance;
    v.pointA = pA;
    v.pointB = pB;
    v.R = 1;
    v.bound = bound;
    v.witnessBound = witnessBound;
    gjkval::judge(v, truth, Scalar::Double, false);
    return v;
}

// Phase 3 on one answer of `double` for case c: its witness points' exact distances to their
// shapes, and the witness verdict.
VariantOutcome checked(const Case& c, VariantOutcome v)
{
    EvalContext ctx;
    ctx.variants = {findVariant("double")};
    CaseOutcome o;
    o.variants = {v};
    checkWitnesses(c, ctx, o);
    return o.variants[0];
}
} // namespace

TEST_CASE("a negative distance is invalid, and a false overlap on separated shapes",
          "[judgement][invalid]")
{
    // Separated (exact 2): -1 claims overlap whatever the bound, so a false overlap, never
    // undecidable (the bound here, 5, covers the error 3), and invalid: a failure.
    const VariantOutcome sep = answer(-1, {0, 0}, {0, 0}, truthOf(2, 2), 5);
    CHECK_FALSE(sep.beyondBound);
    CHECK(sep.mis == Misclass::FalseOverlap);
    CHECK(sep.invalid == Invalid::NegativeDistance);
    CHECK(sep.failed);
    CHECK(worstKey(sep) == INFINITY);
    CHECK(std::string(invalidName(sep.invalid)) == "negative_distance");
    // Overlapping (exact 0): no misclassification (the answer says overlap), still invalid.
    const VariantOutcome ovl = answer(-1, {0, 0}, {0, 0}, truthOf(0, 0, true), 5);
    CHECK(ovl.mis == Misclass::None);
    CHECK(ovl.invalid == Invalid::NegativeDistance);
    CHECK(ovl.failed);
    // -0.0 is not negative: zero, the right answer on overlapping shapes.
    const VariantOutcome zero = answer(-0.0, {0, 0}, {0, 0}, truthOf(0, 0, true), 5);
    CHECK(zero.invalid == Invalid::None);
    CHECK_FALSE(zero.failed);
    // A non-finite answer stays non-finite, never invalid (one reason, no double count).
    const VariantOutcome nan = answer(-1, {NAN, 0}, {0, 0}, truthOf(2, 2), 5);
    CHECK(nan.nonfinite);
    CHECK(nan.invalid == Invalid::None);
    CHECK(nan.failed);
}

TEST_CASE("the witness gap: ||pB - pA|| against d, within the witness bound or invalid",
          "[judgement][invalid]")
{
    // d = 1 and exact 1 (no distance error), witness bound 0.25 = 2^-2: points 1.25 apart are
    // exactly on the bound (valid), one ulp further beyond it (invalid, witness_gap).
    const VariantOutcome on = answer(1, {0, 0}, {1.25, 0}, truthOf(1, 1));
    CHECK(on.witnessGap == 0.25);
    CHECK(on.invalid == Invalid::None);
    CHECK_FALSE(on.failed);
    const VariantOutcome beyond = answer(1, {0, 0}, {std::nextafter(1.25, 2.0), 0}, truthOf(1, 1));
    CHECK(beyond.invalid == Invalid::WitnessGap);
    CHECK(beyond.mis == Misclass::None);
    CHECK_FALSE(beyond.beyondBound); // the distance is right; the answer is not
    CHECK(beyond.failed);
    // Negative distance comes first: one reason per answer.
    CHECK(answer(-1, {0, 0}, {5, 0}, truthOf(1, 1)).invalid == Invalid::NegativeDistance);
}

TEST_CASE("a witness point off its shape beyond the witness bound is invalid",
          "[judgement][invalid]")
{
    // A the point (0, 0), B the point (3, 0), the exact answer 3 with witnesses on the points.
    // A's witness moved up by 0.25 (the witness bound, 2^-2) is on the bound: valid; by 0.5:
    // witness_off_shape, which also replaces a witness_gap (first in the order).
    const Case c = points(3, 0);
    const exact::Result truth = truthOf(3, 3);
    const VariantOutcome right = checked(c, answer(3, {0, 0}, {3, 0}, truth));
    CHECK(right.witness == 0);
    CHECK(right.invalid == Invalid::None);
    CHECK_FALSE(right.failed);
    // (0, 0.25) to (3, 0): gap sqrt(9.0625) - 3 = 0.0104 < 0.25, so only the shape decides.
    const VariantOutcome on = checked(c, answer(3, {0, 0.25}, {3, 0}, truth));
    CHECK(on.witness == 0.25);
    CHECK(on.invalid == Invalid::None);
    CHECK_FALSE(on.failed);
    const VariantOutcome off = checked(c, answer(3, {0, 0.5}, {3, 0}, truth));
    CHECK(off.witness == 0.5);
    CHECK(off.invalid == Invalid::WitnessOffShape);
    CHECK(off.failed);
    CHECK(worstKey(off) == INFINITY);
    // Swapped witnesses: gap 0 (same two points), each point 3 from its own shape.
    const VariantOutcome swapped = checked(c, answer(3, {3, 0}, {0, 0}, truth));
    CHECK(swapped.witnessGap == 0);
    CHECK(swapped.witness == 3);
    CHECK(swapped.invalid == Invalid::WitnessOffShape);
    // Off its shape and a gap: the shape is named (before the gap in the order).
    const VariantOutcome both = answer(3, {0, 1}, {3, 5}, truth);
    REQUIRE(both.invalid == Invalid::WitnessGap);
    CHECK(checked(c, both).invalid == Invalid::WitnessOffShape);
    // A negative distance keeps its reason.
    CHECK(checked(c, answer(-3, {0, 1}, {3, 0}, truth)).invalid == Invalid::NegativeDistance);
}

TEST_CASE("an overlap answered with two points that each lie in both shapes is valid",
          "[judgement][invalid]")
{
    // A the square [0, 2]^2, B the square [1, 3]^2: they overlap in [1, 2]^2 (exact 0).
    // docs/validate-your-gjk.md: distance 0 and one point in both shapes, or two such points.
    Case c;
    c.name = "overlapping-squares";
    c.a.points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    c.b.points = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    const exact::Result truth = truthOf(0, 0, true);
    // (1, 1) and (2, 2), a penetration pair as Bullet gives it: each in both shapes, 1.41 apart.
    const VariantOutcome pair = answer(0, {2, 2}, {1, 1}, truth);
    REQUIRE(pair.invalid == Invalid::WitnessGap); // ||pB - pA|| alone says no
    const VariantOutcome judged = checked(c, pair);
    CHECK(judged.invalid == Invalid::None);
    CHECK(judged.witnessGap == 0); // each point's distance to the other shape
    CHECK_FALSE(judged.failed);
    // (0, 0) is in A but 1.41 from B: not a common point, the gap stands.
    const VariantOutcome outside = checked(c, answer(0, {0, 0}, {1, 1}, truth));
    CHECK(outside.invalid == Invalid::WitnessGap);
    CHECK(outside.failed);
    // (2.25, 2) is 0.25 from A (the witness bound): within it, valid; (2.5, 2) is not.
    CHECK_FALSE(checked(c, answer(0, {2, 2}, {2.25, 2}, truth)).failed);
    CHECK(checked(c, answer(0, {2, 2}, {2.5, 2}, truth)).failed);
    // A positive distance never takes this way: points 1.41 apart for d = 0.5 stay a gap.
    CHECK(checked(c, answer(0.5, {2, 2}, {1, 1}, truth)).invalid == Invalid::WitnessGap);
}

TEST_CASE("the witness bound, term by term, as docs/error-bound.md writes it", "[judgement][bound]")
{
    // u (15 A + 15 B + 10.2 D + 16.5 B~ + 12 M + 26.5 W + 9.5 d + 18.5 (rA + rB)) + 2 sub_T.
    struct Term
    {
        double CaseMetrics::*metric;
        double coefficient;
    };
    const Term terms[] = {{&CaseMetrics::maxA, 15},           {&CaseMetrics::maxB, 15},
                          {&CaseMetrics::translation, 10.2},  {&CaseMetrics::maxBMapped, 16.5},
                          {&CaseMetrics::worldExtent, 12},    {&CaseMetrics::maxW, 26.5},
                          {&CaseMetrics::exactDistance, 9.5}, {&CaseMetrics::radiusA, 18.5},
                          {&CaseMetrics::radiusB, 18.5}};
    for (const Term& t : terms)
    {
        CaseMetrics m;
        m.unitRoundoff = 0x1p-53;
        m.*t.metric = 1;
        INFO("coefficient " << t.coefficient);
        CHECK(witnessBound(*findVariant("double"), m) == t.coefficient * 0x1p-53);
    }
    CaseMetrics none;
    none.unitRoundoff = 0x1p-24;
    CHECK(witnessBound(*findVariant("float"), none) == 2 * 0x1p-149);
}

TEST_CASE("containment witness points stay in both shapes on flat and needle triangles",
          "[judgement][invalid][regression]")
{
    // Found by `gjk-validate search` (docs/error-bound.md, "Witness points"): the final triangle
    // nearly flat (search/72252, from hard/float-rotation/8-gap: three support points nearly
    // collinear around the origin) or a needle (search/108683, from hard/sliver/10-aspect1e3-tri-
    // poly, in float). With Cramer's rule on plain cross products A's witness lay 2.7e-7 (8e6
    // times the witness bound) and, in float, ~300 times the bound outside B; with accurateCross
    // both are within the bound.
    auto shape =
        [](std::vector<std::array<double, 2>> pts, double px, double py, double c, double s)
    {
        ShapeIn sh;
        sh.points = std::move(pts);
        sh.px = px;
        sh.py = py;
        sh.c = c;
        sh.s = s;
        return sh;
    };
    Case flat;
    flat.name = "search/72252";
    flat.a = shape({{0.8686044812202454, 0.08791938424110413},
                    {-0.6163510084152222, 0.6183162331581116},
                    {-0.6937233642904539, 0.5201058034695785},
                    {-0.7454050183296204, 0.45450514554977417},
                    {-0.6388614177703857, -0.5950291156768799},
                    {-0.4588640332221985, -0.742729663848877},
                    {0.06453361362218857, -0.8706543445587158},
                    {0.5129231810569763, -0.706479549407959},
                    {0.6879420876502991, -0.5375306606292725}},
                   5.586376190185547, -10.841957092285156, 0.9393212795257568, -0.3430386185646057);
    flat.b = shape({{0.6617704033851624, 0.11496075242757797},
                    {-0.4936705231666565, 0.45546185970306396},
                    {-0.6408209800720215, 0.20125748217105865},
                    {-0.5082963109016418, -0.4390796422958374},
                    {-0.07896000891923904, -0.6670242547988892},
                    {0.477524995803833, -0.47236210107803345},
                    {0.6538886427879333, -0.15357643365859985}},
                   4.635489471885757, -9.63930208207774, -0.9983991384506226, 0.056560784578323364);
    Case needle;
    needle.name = "search/108683";
    needle.a =
        shape({{274.2227783203125, 405.9635009765625},    {274.2227783203125, 405.9635009765625},
               {274.2227783203125, 405.9635009765625},    {274.2227783203125, 405.9635009765625},
               {274.2227783203125, 405.9635009765625},    {384.21697998046875, -302.19866943359375},
               {382.44244384765625, -304.2544250488281},  {343.87408447265625, -348.9342041015625},
               {377.13580322265625, -305.16033935546875}, {377.25823974609375, -304.9992370605469},
               {378.3247375488281, -303.5958557128906},   {379.21417236328125, -302.425537109375},
               {366.6611022949219, -324.6916198730469},   {366.6611022949219, -324.6916198730469},
               {384.21697998046875, -302.19866943359375}, {398.2632751464844, -284.20562744140625},
               {405.3813171386719, -275.0823059082031},   {274.2227783203125, 405.9635009765625},
               {414.7442321777344, -255.66603088378906},  {405.3813171386719, -275.0823059082031},
               {467.17877197265625, -146.93026733398438}, {377.13580322265625, -305.16033935546875},
               {459.7385559082031, -125.50267791748047},  {274.2227783203125, 405.9635009765625}},
              -64.09922790527344, -655.9564819335938, 0.3758563697338104, -0.926677942276001);
    needle.b =
        shape({{-281.18194580078125, -7.342854132730281e-06},
               {-120.78231048583984, -0.08126325905323029},
               {281.18206787109375, -0.28117579221725464},
               {281.18206787109375, -0.256115585565567},
               {281.18206787109375, -0.256115585565567},
               {281.18206787109375, -0.24581149220466614},
               {281.1817932128906, 0.17696113884449005},
               {281.181884765625, 0.2617097496986389},
               {281.1817626953125, 0.28330761194229126},
               {281.1817626953125, 0.28330761194229126},
               {281.1817626953125, 0.28330761194229126}},
              -223.92135620117188, -1031.0787353515625, 0.41824260354042053, 0.9083353281021118);
    for (const Case* c : {&flat, &needle})
        for (const char* name : {"double", "float", "double-batch", "float-batch"})
        {
            INFO(c->name << " " << name);
            const VariantOutcome v = judge(*c, findVariant(name), false);
            CHECK(v.distance == 0);
            CHECK(v.witness <= v.witnessBound);
            CHECK(v.invalid == Invalid::None);
            CHECK_FALSE(v.failed);
        }
}
