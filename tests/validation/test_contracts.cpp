// Each answer judged by its implementation's contract (evaluate/contract_judge.cpp, issue 49), on
// hand-made answers with expected verdicts worked out by hand: every overlap kind and every reason
// of a declared contract, the tolerances T and W, the measure on max(d, 0) of the signed kinds, and
// gjk2d's own contract, whose violations are exactly its failures. The answers are judged as the
// runner judges a plugin's (judge(), then phase 3 on the case's real shapes), once for a double
// and once for a float implementation: every shape and point here is exact in float.
#include "evaluate/evaluate.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace gjkval;

namespace
{
exact::Result truthOf(double d, bool overlap = false)
{
    exact::Result r;
    r.overlap = overlap;
    r.distance = r.lower = r.upper = d;
    return r;
}

ShapeIn square(double x0, double y0, double side)
{
    ShapeIn s;
    s.points = {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
    return s;
}

ShapeIn point(double x, double y, double radius = 0)
{
    ShapeIn s;
    s.points = {{x, y}};
    s.radius = radius;
    return s;
}

Case caseOf(ShapeIn a, ShapeIn b)
{
    Case c;
    c.name = "hand";
    c.a = std::move(a);
    c.b = std::move(b);
    return c;
}

// An implementation of scalar s with contract `c`, as a loaded plugin's variant.
struct Implementation
{
    PluginImpl impl;
    VariantInfo info;
    Implementation(Scalar s, const Contract& c)
        : info{"hand-" + std::string(scalarName(s)), s, gjk::Options{}, "test", false}
    {
        impl.contract = c;
        info.plugin = &impl;
    }
};

Contract declared(Overlap kind, double abs = -1, double rel = -1)
{
    Contract c;
    c.own = false;
    c.overlap = kind;
    c.absTolerance = abs;
    c.relTolerance = rel;
    c.toleranceSource = abs >= 0 || rel >= 0 ? "the test" : "";
    return c;
}

// The answer (d, pA, pB) of `im` on case c with the exact truth `truth` (by hand: the case's own,
// or one that no case could give), gjk2d's bounds set by hand (bound 2^-30, witness bound 2^-2),
// judged: judge(), then phase 3 (the witness points' exact distances to the case's shapes, and the
// contract verdict).
VariantOutcome judged(const Implementation& im, const Case& c, const exact::Result& truth, double d,
                      std::array<double, 2> pA, std::array<double, 2> pB,
                      PluginStatus status = PluginStatus::Ok)
{
    VariantOutcome v;
    v.plugin = status;
    if (status != PluginStatus::Ok)
        v.failed = true; // as takePluginAnswer leaves it
    else
    {
        v.distance = d;
        v.pointA = pA;
        v.pointB = pB;
        v.R = 1;
        v.bound = 0x1p-30;
        v.depthBound = 0x1p-30; // read where a penetration depth is judged
        v.witnessBound = 0x1p-2;
        judge(v, truth, im.info.scalar, false, contractOf(im.info).overlap);
    }
    EvalContext ctx;
    ctx.variants = {&im.info};
    CaseOutcome o;
    computeTruth(c, ctx, o); // the case's prepared shapes, which phase 3 reads, as in a campaign
    REQUIRE(o.rejected.empty());
    o.variants = {v};
    checkWitnesses(c, ctx, o);
    return o.variants[0];
}

std::string reason(const VariantOutcome& v)
{
    const char* n = violationName(v.violation);
    return n ? n : "none";
}

const Scalar kScalars[] = {Scalar::Double, Scalar::Float};
} // namespace

TEST_CASE(
    "a declared contract on separated shapes: the tolerance, the claim of overlap, the points",
    "[contract]")
{
    // A the point (0, 0), B the point (3, 0): exact 3. T = 1e-6 (abs) + gjk2d's bound 2^-30,
    // W = max(2^-2, T) = 2^-2.
    const Case c = caseOf(point(0, 0), point(3, 0));
    const exact::Result t = truthOf(3);
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        const Implementation im(s, declared(Overlap::Zero, 1e-6));
        // Within T but beyond gjk2d's bound (2^-30): keeps it, outside the bound (class 2).
        const VariantOutcome near = judged(im, c, t, 3 + 5e-7, {0, 0}, {3, 0});
        CHECK(near.tolerance == 1e-6 + 0x1p-30);
        CHECK(near.witnessTolerance == 0.25);
        CHECK(near.keepsContract());
        CHECK(near.beyondBound);
        CHECK(std::string(answerClassName(near)) == "outside_bound");
        // 2e-6 off: beyond T, a violation by distance of excess 2e-6 / T.
        const VariantOutcome off = judged(im, c, t, 3 + 2e-6, {0, 0}, {3, 0});
        CHECK(reason(off) == "distance");
        CHECK(off.violationExcess == Approx(2e-6 / (1e-6 + 0x1p-30)).epsilon(1e-6));
        CHECK(std::string(answerClassName(off)) == "breaks_contract");
        // A claim of overlap (-1) on shapes 3 apart: false_overlap, excess 3 / T.
        const VariantOutcome claim = judged(im, c, t, -1, {0, 0}, {0, 0});
        CHECK(reason(claim) == "false_overlap");
        CHECK(claim.violationExcess == Approx(3 / (1e-6 + 0x1p-30)));
        // A's point 0.5 off A (W = 0.25): witness_off_shape, excess 0.5 / 0.25; on W: keeps it.
        CHECK(reason(judged(im, c, t, 3, {0, 0.5}, {3, 0.5})) == "witness_off_shape");
        CHECK(judged(im, c, t, 3, {0, 0.5}, {3, 0.5}).violationExcess == 2);
        CHECK(judged(im, c, t, 3, {0, 0.25}, {3, 0.25}).keepsContract());
        // A the square [-1, 0]^2 (exact 3 from (3, 0) still): (0, -0.5) is on A, the gap
        // sqrt(9.25) - 3 = 0.04 < W: keeps it; B's point at (2.5, 0) is 0.5 off B.
        const Case wide = caseOf(square(-1, -1, 1), point(3, 0));
        CHECK(reason(judged(im, wide, t, 3, {0, -0.5}, {3, 0})) == "none");
        CHECK(reason(judged(im, wide, t, 3, {0, 0}, {2.5, 0})) == "witness_off_shape");
        // A the square [0, 1]^2 against (3, 0): exact 2. (1, 0) and (3, 0): keeps it. (0, 0), on
        // A too, is 3 from (3, 0): the gap 3 - 2 = 1 > W: witness_gap.
        const Case line = caseOf(square(0, 0, 1), point(3, 0));
        CHECK(judged(im, line, truthOf(2), 2, {1, 0}, {3, 0}).keepsContract());
        CHECK(reason(judged(im, line, truthOf(2), 2, {0, 0}, {3, 0})) == "witness_gap");
    }
}

TEST_CASE("a declared contract's tolerance: abs + rel * exact + gjk2d's bound, or the bound alone",
          "[contract]")
{
    const Case c = caseOf(point(0, 0), point(4, 0));
    const exact::Result t = truthOf(4);
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        // rel 1e-6 alone: T = 4e-6 + 2^-30; abs 1e-6 + rel 1e-6: T = 5e-6 + 2^-30 (gjk2d's bound
        // added: the rounding a stopping rule's tolerance does not cover).
        const VariantOutcome rel =
            judged(Implementation(s, declared(Overlap::Zero, -1, 1e-6)), c, t, 4, {0, 0}, {4, 0});
        CHECK(rel.tolerance == Approx(4e-6 + 0x1p-30).epsilon(1e-12));
        const VariantOutcome both =
            judged(Implementation(s, declared(Overlap::Zero, 1e-6, 1e-6)), c, t, 4, {0, 0}, {4, 0});
        CHECK(both.tolerance == Approx(5e-6 + 0x1p-30).epsilon(1e-12));
        // Nothing stated: gjk2d's bound (2^-30) and witness bound hold it.
        const Implementation none(s, declared(Overlap::Zero));
        const VariantOutcome in = judged(none, c, t, 4 + 0x1p-31, {0, 0}, {4, 0});
        CHECK(in.tolerance == 0x1p-30);
        CHECK(in.witnessTolerance == 0x1p-2);
        CHECK(in.keepsContract());
        CHECK(reason(judged(none, c, t, 4 + 0x1p-28, {0, 0}, {4, 0})) == "distance");
    }
}

TEST_CASE("zero: on overlap only the sign is judged, and the error is measured on max(d, 0)",
          "[contract]")
{
    // Squares [0, 2]^2 and [1, 3]^2 overlap: exact 0.
    const Case c = caseOf(square(0, 0, 2), square(1, 1, 2));
    const exact::Result t = truthOf(0, true);
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        const Implementation im(s, declared(Overlap::Zero, 1e-6));
        // FCL's -1 with points (0, 0) far outside B: keeps it; error max(-1, 0) - 0 = 0: within
        // gjk2d's bound. gjk2d's own rules call it invalid (a measure here, not the verdict).
        const VariantOutcome v = judged(im, c, t, -1, {0, 0}, {0, 0});
        CHECK(v.keepsContract());
        CHECK(v.abs == 0);
        CHECK_FALSE(v.beyondBound);
        CHECK(v.invalid == Invalid::NegativeDistance);
        CHECK(std::string(answerClassName(v)) == "within_bound");
        // Non-finite points are not judged on overlap either; a non-finite distance is.
        CHECK(judged(im, c, t, 0, {NAN, 0}, {0, 0}).keepsContract());
        CHECK(reason(judged(im, c, t, NAN, {0, 0}, {0, 0})) == "nonfinite");
        // A distance within T is not a separation; 0.5 is: false_separation, excess 0.5 / T.
        CHECK(judged(im, c, t, 5e-7, {0, 0}, {0, 0}).keepsContract());
        const VariantOutcome sep = judged(im, c, t, 0.5, {2, 1}, {2.5, 1});
        CHECK(reason(sep) == "false_separation");
        CHECK(sep.violationExcess == Approx(0.5 / (1e-6 + 0x1p-30))); // T with gjk2d's bound
    }
}

TEST_CASE("zero: a claim of overlap within the tolerance of touching keeps it", "[contract]")
{
    // Unit squares 2^-22 apart (FCL's default distance_tolerance is 1e-6): -1 keeps it, and the
    // error max(-1, 0) against 2^-22 is beyond gjk2d's bound: class 2. 2^-19 apart (1.9e-6): no.
    const exact::Result near = truthOf(0x1p-22), far = truthOf(0x1p-19);
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        const Implementation im(s, declared(Overlap::Zero, 1e-6));
        const VariantOutcome v = judged(im, caseOf(square(0, 0, 1), square(1 + 0x1p-22, 0, 1)),
                                        near, -1, {0, 0}, {0, 0});
        CHECK(v.keepsContract());
        CHECK(v.abs == 0x1p-22);
        CHECK(std::string(answerClassName(v)) == "outside_bound");
        CHECK(reason(judged(im, caseOf(square(0, 0, 1), square(1 + 0x1p-19, 0, 1)), far, -1, {0, 0},
                            {0, 0})) == "false_overlap");
    }
}

TEST_CASE("common-point: as gjk2d's own on overlap, and no negative distance", "[contract]")
{
    const Case c = caseOf(square(0, 0, 2), square(1, 1, 2));
    const exact::Result t = truthOf(0, true);
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        const Implementation im(s, declared(Overlap::CommonPoint));
        CHECK(judged(im, c, t, 0, {1.5, 1.5}, {1.5, 1.5}).keepsContract());
        // (0.5, 0.5) is in A and 0.71 from B, so not a second common point: the gap
        // ||pB - pA|| = 1.41 > W (2^-2) is the witness_gap.
        CHECK(reason(judged(im, c, t, 0, {0.5, 0.5}, {1.5, 1.5})) == "witness_gap");
        // A point off its own shape comes first: B's point (0.5, 0.5) is 0.71 from B.
        CHECK(reason(judged(im, c, t, 0, {0.5, 0.5}, {0.5, 0.5})) == "witness_off_shape");
        // Two points each in both shapes (docs/validate-your-gjk.md): kept, as gjk2d's own.
        CHECK(judged(im, c, t, 0, {2, 2}, {1, 1}).keepsContract());
        CHECK(reason(judged(im, c, t, -1, {1.5, 1.5}, {1.5, 1.5})) == "negative_distance");
    }
}

TEST_CASE("midpoint: one point, within dc/2 + W of both cores", "[contract]")
{
    // Discs: A the point (0, 0) with radius 1, B the point (1.5, 0) with radius 1. They overlap
    // (1.5 < 2); their cores are 1.5 apart, so dc/2 = 0.75, and with W = 2^-2 each point must be
    // within 1 of both centres. (0.75, 0): 0.75 from each, the midpoint: keeps it. (0.75, 0.5):
    // sqrt(0.5625 + 0.25) = 0.90: keeps it. (0.75, 0.75): sqrt(1.125) = 1.06: midpoint_off, excess
    // 1.06 / 1. planck's pointA - pointB = (-1.5, 0): 3 from B's core: midpoint_off, excess 3.
    const Case discs = caseOf(point(0, 0, 1), point(1.5, 0, 1));
    // Squares overlapping at radius 0: the cores overlap (dc = 0): a common point within W.
    const Case squares = caseOf(square(0, 0, 2), square(1, 1, 2));
    const exact::Result t = truthOf(0, true);
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        const Implementation im(s, declared(Overlap::Midpoint));
        CHECK(judged(im, discs, t, 0, {0.75, 0}, {0.75, 0}).keepsContract());
        CHECK(judged(im, discs, t, 0, {0.75, 0.5}, {0.75, 0.5}).keepsContract());
        const VariantOutcome off = judged(im, discs, t, 0, {0.75, 0.75}, {0.75, 0.75});
        CHECK(reason(off) == "midpoint_off");
        CHECK(off.violationExcess == Approx(std::sqrt(1.125)));
        const VariantOutcome planck = judged(im, discs, t, 0, {-1.5, 0}, {-1.5, 0});
        CHECK(reason(planck) == "midpoint_off");
        CHECK(planck.violationExcess == Approx(3));
        // Two points 0.5 apart: witness_gap (||pA - pB|| > W), before the cores.
        CHECK(reason(judged(im, discs, t, 0, {0.5, 0}, {1, 0})) == "witness_gap");
        CHECK(judged(im, squares, t, 0, {1.5, 1.5}, {1.5, 1.5}).keepsContract());
        CHECK(reason(judged(im, squares, t, 0, {0.5, 0.5}, {0.5, 0.5})) == "midpoint_off");
        CHECK(reason(judged(im, squares, t, -0.25, {1.5, 1.5}, {1.5, 1.5})) == "negative_distance");
    }
}

TEST_CASE("perimeter: each point on its own perimeter, rA + rB - dc apart, or one point where the "
          "cores meet",
          "[contract]")
{
    // Discs: A the point (0, 0) with radius 1, B the point (1.5, 0) with radius 1 (overlapping by
    // their radii, cores dc = 1.5 apart). Box2D v3 keeps each point on its own perimeter along the
    // cores' closest points: pA = (0, 0) + 1 (1, 0) = (1, 0), pB = (1.5, 0) - 1 (1, 0) = (0.5, 0),
    // ||pA - pB|| = 0.5 = rA + rB - dc: keeps it. Swapped, (0.5, 0) and (1, 0): each 0.5 from its
    // own centre, | 0.5 - 1 | = 0.5 off the perimeter > W = 2^-2: perimeter_off, excess 0.5 / 0.25.
    // The midpoint (0.75, 0) twice: 0.25 off each perimeter (within W) but 0 apart for a depth of
    // 0.5: | 0 - 0.5 | = 0.5: perimeter_off. Squares overlapping at radius 0 (dc = 0): one common
    // point, as a midpoint of cores 0 apart.
    const Case discs = caseOf(point(0, 0, 1), point(1.5, 0, 1));
    const Case squares = caseOf(square(0, 0, 2), square(1, 1, 2));
    const exact::Result t = truthOf(0, true);
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        const Implementation im(s, declared(Overlap::Perimeter));
        CHECK(judged(im, discs, t, 0, {1, 0}, {0.5, 0}).keepsContract());
        const VariantOutcome swapped = judged(im, discs, t, 0, {0.5, 0}, {1, 0});
        CHECK(reason(swapped) == "perimeter_off");
        CHECK(swapped.violationExcess == Approx(2));
        CHECK(reason(judged(im, discs, t, 0, {0.75, 0}, {0.75, 0})) == "perimeter_off");
        CHECK(judged(im, squares, t, 0, {1.5, 1.5}, {1.5, 1.5}).keepsContract());
        CHECK(reason(judged(im, squares, t, 0, {0.5, 0.5}, {0.5, 0.5})) == "midpoint_off");
        CHECK(reason(judged(im, discs, t, -0.5, {1, 0}, {0.5, 0})) == "negative_distance");
    }
}

TEST_CASE("penetration: each point on its shape, ||pA - pB|| the depth |d|", "[contract]")
{
    // Squares [0, 2]^2 and [1, 3]^2: the depth is 1 (along x or y). A's point (2, 1.5) and B's
    // (1, 1.5), d = -1: each on its shape, ||pA - pB|| = 1 = |d|: keeps every clause. B's point at
    // (1.5, 1.5): | 0.5 - 1 | = 0.5 > W: penetration_gap. A's point at (2.5, 1.5), 0.5 off A:
    // witness_off_shape. (The truth here has no signed distance: the depth itself is not judged;
    // the next tests judge it.)
    const Case c = caseOf(square(0, 0, 2), square(1, 1, 2));
    const exact::Result t = truthOf(0, true);
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        const Implementation im(s, declared(Overlap::Penetration));
        const VariantOutcome v = judged(im, c, t, -1, {2, 1.5}, {1, 1.5});
        CHECK(v.keepsContract());
        CHECK_FALSE(v.depthJudged);
        CHECK(v.abs == 0);                 // measured on max(d, 0)
        CHECK(v.invalid == Invalid::None); // a negative distance is minus the depth, not invalid
        CHECK(v.witnessGap == 0);          // ||pA - pB|| against |d|
        CHECK(reason(judged(im, c, t, -1, {2, 1.5}, {1.5, 1.5})) == "penetration_gap");
        CHECK(reason(judged(im, c, t, -1, {2.5, 1.5}, {1, 1.5})) == "witness_off_shape");
    }
}

namespace
{
// The exact truth of overlapping shapes whose exact signed distance is `s` (< 0; 0: touching), as
// the exact side gives it with exact::Options::penetration.
exact::Result signedTruthOf(double s)
{
    exact::Result r = truthOf(0, s < 0);
    r.hasSigned = true;
    r.signedDistance = r.signedLower = r.signedUpper = s;
    return r;
}

Contract declaredDepth(double abs, double rel = -1)
{
    Contract c = declared(Overlap::Penetration);
    c.depthAbsTolerance = abs;
    c.depthRelTolerance = rel;
    c.depthSource = "the test";
    return c;
}
} // namespace

TEST_CASE("penetration: the depth judged against the exact signed distance",
          "[contract][penetration]")
{
    // Two unit squares, A = [0, 1]^2 and B = [0.75, 1.75] x [0, 1], overlap by 0.25 along x (by 1
    // along y): the exact signed distance is -0.25, the minimal translation of B (0.25, 0), the
    // penetration pair pA = (1, 0.5) on A's boundary, pB = (0.75, 0.5) on B's. gjk2d's depth bound
    // is set by hand to 2^-30 (judged() below), so:
    // - d = -0.25 with that pair: |d - s| = 0, kept, within the bound;
    // - d = -0.24, pA = (1, 0.5), pB = (0.76, 0.5) (both on their shapes, 0.24 apart): |d - s| =
    //   0.01, relative 0.04, beyond gjk2d's depth bound; with no depth clause stated that keeps the
    //   contract (a measured accuracy, "outside_bound"); with abs 0.02 stated it keeps it; with abs
    //   0.005 it breaks it, depth_off, 0.01 / 0.005 = 2 times what it allows; with rel 0.02 stated
    //   (Td = 0.02 x 0.25 = 0.005) the same;
    // - d = 0 with the common point (0.875, 0.5): no depth where the contract promises one, the
    //   exact depth 0.25 over Td (2^-30): no_depth.
    const Case c = caseOf(square(0, 0, 1), square(0.75, 0, 1));
    const exact::Result t = signedTruthOf(-0.25);
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        const Implementation none(s, declared(Overlap::Penetration));
        const VariantOutcome exactPair = judged(none, c, t, -0.25, {1, 0.5}, {0.75, 0.5});
        CHECK(exactPair.depthJudged);
        CHECK(exactPair.depthAbs == 0);
        CHECK(exactPair.keepsContract());
        CHECK(std::string(answerClassName(exactPair)) == "within_bound");
        const double d = s == Scalar::Float ? double(-0.24f) : -0.24;
        const double pb = s == Scalar::Float ? double(0.76f) : 0.76;
        const VariantOutcome off = judged(none, c, t, d, {1, 0.5}, {pb, 0.5});
        CHECK(off.depthAbs == Approx(0.01));
        CHECK(off.depthRel == Approx(0.04));
        CHECK(off.depthTolerance == 0x1p-30); // no clause: gjk2d's depth bound
        CHECK(off.beyondDepthBound);
        CHECK(off.keepsContract());
        CHECK(std::string(answerClassName(off)) == "outside_bound");
        CHECK(judged(Implementation(s, declaredDepth(0.02)), c, t, d, {1, 0.5}, {pb, 0.5})
                  .keepsContract());
        const VariantOutcome broken =
            judged(Implementation(s, declaredDepth(0.005)), c, t, d, {1, 0.5}, {pb, 0.5});
        CHECK(reason(broken) == "depth_off");
        CHECK(broken.violationExcess == Approx(2));
        CHECK(reason(judged(Implementation(s, declaredDepth(-1, 0.02)), c, t, d, {1, 0.5},
                            {pb, 0.5})) == "depth_off");
        const VariantOutcome zero = judged(none, c, t, 0, {0.875, 0.5}, {0.875, 0.5});
        CHECK(reason(zero) == "no_depth");
        CHECK(zero.violationExcess == Approx(0.25 / 0x1p-30));
    }
}

TEST_CASE("penetration: touching shapes may answer 0", "[contract][penetration]")
{
    // A = [0, 1]^2, B = [1, 2] x [0, 1] touch along x = 1: exact signed distance 0, no depth to
    // judge; the common point (1, 0.5) with d = 0 keeps the contract. The same shapes with a
    // truth (by hand) of depth 2^-40, below Td = gjk2d's depth bound 2^-30: touching to the
    // contract's precision, so 0 still keeps it; a stated clause of abs 2^-45 adds to the bound
    // (Td = 2^-45 + 2^-30): 2^-40 is still touching, a depth of 2^-29 is a real one: no_depth.
    const Case c = caseOf(square(0, 0, 1), square(1, 0, 1));
    for (Scalar s : kScalars)
    {
        INFO(scalarName(s));
        const Implementation none(s, declared(Overlap::Penetration));
        const VariantOutcome touching = judged(none, c, signedTruthOf(0), 0, {1, 0.5}, {1, 0.5});
        CHECK_FALSE(touching.depthJudged);
        CHECK(touching.keepsContract());
        const VariantOutcome shallow =
            judged(none, c, signedTruthOf(-0x1p-40), 0, {1, 0.5}, {1, 0.5});
        CHECK(shallow.depthJudged);
        CHECK(shallow.depthAbs == 0x1p-40);
        CHECK(shallow.keepsContract());
        const Implementation clause(s, declaredDepth(0x1p-45));
        CHECK(judged(clause, c, signedTruthOf(-0x1p-40), 0, {1, 0.5}, {1, 0.5}).keepsContract());
        CHECK(reason(judged(clause, c, signedTruthOf(-0x1p-29), 0, {1, 0.5}, {1, 0.5})) ==
              "no_depth");
    }
}

TEST_CASE("gjk2d's signed variants: gjk2d's own contract, overlap answered by penetration",
          "[contract][penetration]")
{
    // The contract of double-signed and float-signed is gjk2d's own with overlap = penetration, no
    // depth clause (gjk2d's depth bound); every other gjk2d variant's overlap is common-point.
    for (const char* name : {"double-signed", "float-signed"})
    {
        INFO(name);
        const VariantInfo* v = findVariant(name);
        REQUIRE(v != nullptr);
        CHECK(v->judged);
        CHECK(v->start == Start::Cold);
        CHECK(v->options.signedDistance);
        const Contract& c = contractOf(*v);
        CHECK(c.own);
        CHECK(c.overlap == Overlap::Penetration);
        CHECK(c.depthAbsTolerance < 0);
        CHECK(c.depthRelTolerance < 0);
    }
    CHECK(contractOf(*findVariant("double")).overlap == Overlap::CommonPoint);
    EvalContext ctx;
    ctx.variants = {findVariant("double")};
    CHECK_FALSE(ctx.truthOptions().penetration); // the exact depth only when a run judges one
    ctx.variants.push_back(findVariant("float-signed"));
    CHECK(ctx.truthOptions().penetration);

    // Judged by gjk2d's own contract (failures), on the squares overlapping by 0.25 above: the
    // exact pair keeps it; a depth 0.01 off is beyond gjk2d's depth bound (2^-30 here): a failure,
    // depth_off, its excess the error over the bound; a certified interval that misses the exact
    // signed distance fails (interval).
    const Case c = caseOf(square(0, 0, 1), square(0.75, 0, 1));
    const exact::Result t = signedTruthOf(-0.25);
    const Implementation own(Scalar::Double, ownContract({.signedDistance = true}));
    const VariantOutcome right = judged(own, c, t, -0.25, {1, 0.5}, {0.75, 0.5});
    CHECK_FALSE(right.failed);
    CHECK(right.keepsContract());
    const VariantOutcome off = judged(own, c, t, -0.24, {1, 0.5}, {0.76, 0.5});
    CHECK(off.failed);
    CHECK(reason(off) == "depth_off");
    CHECK(off.violationExcess == off.depthRatio);
    CHECK(off.depthRatio == Approx(0.01 / 0x1p-30));
    VariantOutcome v;
    v.distance = -0.25;
    v.pointA = {1, 0.5};
    v.pointB = {0.75, 0.5};
    v.R = 1;
    v.bound = v.depthBound = 0x1p-30;
    v.witnessBound = 0x1p-2;
    v.certified = true;
    v.lower = -0.25;
    v.upper = -0.25 + 0x1p-40;
    judge(v, t, Scalar::Double, false, Overlap::Penetration);
    CHECK(v.intervalContains);
    CHECK_FALSE(v.failed);
    v.lower = -0.25 + 0x1p-50; // above the exact -0.25
    judge(v, t, Scalar::Double, false, Overlap::Penetration);
    CHECK_FALSE(v.intervalContains);
    CHECK(v.failed);
}

TEST_CASE("an error status, a crash or a hang breaks a declared contract", "[contract]")
{
    const Case c = caseOf(point(0, 0), point(3, 0));
    for (Scalar s : kScalars)
    {
        const Implementation im(s, declared(Overlap::Zero, 1e-6));
        CHECK(reason(judged(im, c, truthOf(3), 0, {}, {}, PluginStatus::Error)) == "error");
        CHECK(reason(judged(im, c, truthOf(3), 0, {}, {}, PluginStatus::Crashed)) == "crashed");
        const VariantOutcome hung = judged(im, c, truthOf(3), 0, {}, {}, PluginStatus::Hung);
        CHECK(reason(hung) == "hung");
        CHECK(hung.violationExcess == INFINITY);
    }
}

TEST_CASE("gjk2d's own contract: a violation is exactly a failure, named by its first reason",
          "[contract]")
{
    // A gjk2d variant's answers through the whole pipeline (evaluateCase, the real truth).
    for (const char* name : {"double", "float"})
    {
        INFO(name);
        const VariantInfo* v = findVariant(name);
        REQUIRE(contractOf(*v).own);
        EvalContext ctx;
        ctx.variants = {v};
        const CaseOutcome o = evaluateCase(caseOf(square(0, 0, 1), point(3, 0.5)), ctx);
        const VariantOutcome& right = o.variants[0];
        CHECK_FALSE(right.failed);
        CHECK(right.keepsContract());
        CHECK(right.tolerance == right.bound);
        CHECK(std::string(answerClassName(right)) == "within_bound");
    }
    // Hand-made failures of `double` (its own contract): the reason follows failedAnswer's.
    const Implementation own(Scalar::Double, ownContract());
    const Case c = caseOf(point(0, 0), point(3, 0));
    const VariantOutcome beyond = judged(own, c, truthOf(3), 3.5, {0, 0}, {3.5, 0});
    CHECK(beyond.failed);
    CHECK(reason(beyond) == "witness_off_shape"); // (3.5, 0) is 0.5 from B: invalid first
    const VariantOutcome dist = judged(own, c, truthOf(3), 3 + 0x1p-20, {0, 0}, {3, 0});
    CHECK(dist.failed);
    CHECK(reason(dist) == "distance");
    CHECK(dist.violationExcess == dist.boundRatio);
    const VariantOutcome neg = judged(own, c, truthOf(3), -1, {0, 0}, {3, 0});
    CHECK(reason(neg) == "negative_distance");
    CHECK(reason(judged(own, c, truthOf(3), 0, {}, {}, PluginStatus::Crashed)) == "crashed");
}

TEST_CASE(
    "a declared contract is checked: a NaN or infinite tolerance, a bad margin or overlap kind "
    "are refused",
    "[contract]")
{
    // gjk2d/plugin.h: a negative tolerance is "not stated", a non-finite one is refused; the margin
    // is a finite number >= 0; the overlap one of the five kinds (0..4).
    CHECK(checkContract(declared(Overlap::Zero, 1e-6, -1)).empty());
    CHECK(checkContract(declared(Overlap::Midpoint)).empty());
    CHECK_FALSE(checkContract(declared(Overlap::Zero, std::nan(""))).empty());
    CHECK_FALSE(checkContract(declared(Overlap::Zero, -1, std::numeric_limits<double>::infinity()))
                    .empty());
    Contract c = declared(Overlap::Penetration);
    c.margin = -0.5;
    CHECK_FALSE(checkContract(c).empty());
    c.margin = std::numeric_limits<double>::infinity();
    CHECK_FALSE(checkContract(c).empty());
    c = declared(Overlap(kOverlapKinds));
    CHECK_FALSE(checkContract(c).empty());
}
