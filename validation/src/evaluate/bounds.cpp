// The derived error bounds (evaluate/bounds.hpp): the distance's errorBound() and the witness
// points' witnessBound() and the penetration depth's depthBound(), each with its formula's text
// (docs/error-bound.md).
#include "evaluate/bounds.hpp"

#include "gjk2d/math.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

namespace gjkval
{

namespace
{
// One term of a bound: coefficient x metric, and how the formula writes the metric.
struct BoundTerm
{
    double coefficient;
    const char* symbol;
    double (*value)(const CaseMetrics&);
};

// The terms of u (...), in the order the sum runs (left to right, as the formula reads).
template <std::size_t N>
double sumTerms(const BoundTerm (&terms)[N], const CaseMetrics& m, std::size_t count = N)
{
    double sum = 0;
    for (std::size_t i = 0; i < count; ++i)
        sum += terms[i].coefficient * terms[i].value(m);
    return sum;
}

template <std::size_t N> std::string termsText(const BoundTerm (&terms)[N])
{
    std::string s;
    for (const BoundTerm& t : terms)
        s += fmt::format("{}{} {}", s.empty() ? "" : " + ", t.coefficient, t.symbol);
    return s;
}

double metricA(const CaseMetrics& m)
{
    return m.maxA;
}
double metricB(const CaseMetrics& m)
{
    return m.maxB;
}
double metricD(const CaseMetrics& m)
{
    return m.translation;
}
double metricBMapped(const CaseMetrics& m)
{
    return m.maxBMapped;
}
double metricW(const CaseMetrics& m)
{
    return m.maxW;
}
double metricM(const CaseMetrics& m)
{
    return m.worldExtent;
}
double metricDistance(const CaseMetrics& m)
{
    return m.exactDistance;
}
double metricRadii(const CaseMetrics& m)
{
    return m.radiusA + m.radiusB;
}

// The a-priori bound derived in docs/error-bound.md, to first order in u:
//   |d_gjk - d| <= u (4 A + 43 B + 10.2 D + 1.5 B~ + 5 W + 6.5 d + 3.5 (rA + rB)) + sub_T
// in A's local frame (the reference variant), every metric in world lengths (geometry.hpp), for
// any finite rotations (c, s) != (0, 0). Term by term (see the doc):
//   15 B + 10.2 D + 1.5 B~ + 1.5 W  mapping B into A's frame, w = a - b~      (vertex error)
//   4 A + 28 B                      choosing the support points (rounded dots, rotated direction)
//   3.5 W + 3 d                     the distance formula |cross(w1, e12)| / |e12|
//   2.5 (d + rA + rB)               back to world lengths: times |qA| = sqrt(cA^2 + sA^2)
//   d + rA + rB                     subtracting the radii
// The radii's term stays last: the duality-gap term joins the sum before it (errorBound).
constexpr BoundTerm kErrorTerms[] = {
    {4, "A", metricA},
    {43, "B", metricB},
    {10.2, "D", metricD},
    {1.5, "B~", metricBMapped},
    {5, "W", metricW},
    {6.5, "d", metricDistance},
    {3.5, "(rA + rB)", metricRadii},
};
constexpr std::size_t kErrorTermCount = std::size(kErrorTerms);

// Duality-gap stopping adds the gap it accepts, dualityGap |v| <= dualityGap W, dualityGap =
// 16 u (gjk2d/math.hpp, Tolerances): the factor, exact (both are powers of two times 16).
constexpr double kDualityGapFactor =
    gjk::Tolerances<double>::dualityGap / gjk::Tolerances<double>::unitRoundoff;
constexpr BoundTerm kDualityGapTerm = {kDualityGapFactor, "W", metricW};

// The witness bound derived in docs/error-bound.md ("Witness points"), to first order in u, in
// world lengths, for the reference options (every variant and plugin is held to it). Term by term:
//   9 A + 15 B + 10.2 D + 10.5 B~ + 3 M + 6 (rA + rB)   each point off its shape: the weights' sum,
//                         the combination, to world, B's mapped points (term 1), the radius offsets
//   18 W                  a triangle's (containment) point off B: Cramer's residual with
//                         accurate cross products
//   6 A + 6 B~ + 6 M + 8.5 W + 9.5 d + 12.5 (rA + rB)   ||pB - pA|| against d
//   3 M                   overlapping rounded shapes: the one point between the two, which is off
//                         its shapes by at most the first line plus the gap
// One number for every check: their sum.
constexpr BoundTerm kWitnessTerms[] = {
    {15, "A", metricA},         {15, "B", metricB},
    {10.2, "D", metricD},       {16.5, "B~", metricBMapped},
    {12, "M", metricM},         {26.5, "W", metricW},
    {9.5, "d", metricDistance}, {18.5, "(rA + rB)", metricRadii},
};

double metricAbsDistance(const CaseMetrics& m)
{
    return std::abs(m.exactDistance);
}

// The depth bound derived in docs/error-bound.md ("Penetration depth"), to first order in u, for
// the reference options with Options::signedDistance on overlapping shapes, world lengths, d the
// exact signed distance (< 0). Term by term:
//   15 B + 10.2 D + 1.5 B~ + 1.5 W  mapping B into A's frame, w = a - b~: the perturbed hull Z~
//   4 A + 28 B                      choosing the support points (as the distance's term 3)
//   2 W                             the polygon's convexity decided by rounded orientations
//   3.5 W + 3 |d|                   the edge distance cross(v, e) / |e|
//   7 W + 4 |d|                     GapClosed: Tolerances::expandGap = 4u of the support value,
//                                   and the rounding of the gap dot(n, w - v) itself
//   2 |d|                           the answer read from a nearly collinear neighbour edge (three
//                                   edge distances' rounding on that side, see the doc)
//   2.5 |d|                         back to world lengths: times |qA|
//   |d| + 7.5 (rA + rB)             adding the radii; cores apart (radii overlapping): the
//                                   distance's terms with a core distance below rA + rB
// Each coefficient is the larger of the answer's two sides (too deep, too shallow): W 14 and |d|
// 12.5 (docs/error-bound.md, "Penetration depth").
constexpr BoundTerm kDepthTerms[] = {
    {4, "A", metricA},
    {43, "B", metricB},
    {10.2, "D", metricD},
    {1.5, "B~", metricBMapped},
    {14, "W", metricW},
    {12.5, "|d|", metricAbsDistance},
    {7.5, "(rA + rB)", metricRadii},
};
} // namespace

// Every variant is judged against the reference bound (kErrorTerms), computed in A's local frame
// whatever the variant's own frame (evaluate.cpp): it is what the library promises for the input.
double errorBound(const VariantInfo& variant, const CaseMetrics& m)
{
    double terms = sumTerms(kErrorTerms, m, kErrorTermCount - 1);
    if (variant.options.stopping == gjk::StoppingRule::DualityGap)
        terms += kDualityGapTerm.coefficient * kDualityGapTerm.value(m);
    const BoundTerm& radii = kErrorTerms[kErrorTermCount - 1];
    // Plus the answer's own resolution: a distance in T's subnormal range is rounded to a
    // multiple of T's smallest subnormal (the rescaled query's final scaling back, and the truth's
    // rounding to double), an absolute error the relative terms cannot express (below ~1e-292 in
    // double, 1e-31 in float, u times the terms underflows too): float inputs near 1e-45, double
    // near 1e-310 were otherwise judged against a bound of 0.
    return m.unitRoundoff * (terms + radii.coefficient * radii.value(m)) +
           smallestSubnormal(variant.scalar);
}

std::string boundFormula(const VariantInfo& variant)
{
    std::string f =
        "u (" + termsText(kErrorTerms) + ") + the type's smallest subnormal, A's local frame";
    if (variant.options.stopping == gjk::StoppingRule::DualityGap)
        f += fmt::format(" + {} u {}", kDualityGapTerm.coefficient, kDualityGapTerm.symbol);
    return f + " (docs/error-bound.md)";
}

// Plus the subnormal resolution of the two points (a rescaled query's points are scaled back,
// rounded to T's subnormals).
double witnessBound(const VariantInfo& variant, const CaseMetrics& m)
{
    return m.unitRoundoff * sumTerms(kWitnessTerms, m) + 2 * smallestSubnormal(variant.scalar);
}

std::string witnessBoundFormula(const VariantInfo&)
{
    return "u (" + termsText(kWitnessTerms) +
           ") + 2 x the type's smallest subnormal, world lengths (docs/error-bound.md, \"Witness "
           "points\")";
}

// Plus the duality-gap term for a variant that stops GJK by it (the cores-apart case is a GJK
// distance), and the answer's subnormal resolution, as errorBound.
double depthBound(const VariantInfo& variant, const CaseMetrics& m)
{
    double terms = sumTerms(kDepthTerms, m);
    if (variant.options.stopping == gjk::StoppingRule::DualityGap)
        terms += kDualityGapTerm.coefficient * kDualityGapTerm.value(m);
    return m.unitRoundoff * terms + smallestSubnormal(variant.scalar);
}

std::string depthBoundFormula(const VariantInfo& variant)
{
    std::string f =
        "u (" + termsText(kDepthTerms) +
        ") + the type's smallest subnormal, d the exact signed distance, A's local frame";
    if (variant.options.stopping == gjk::StoppingRule::DualityGap)
        f += fmt::format(" + {} u {}", kDualityGapTerm.coefficient, kDualityGapTerm.symbol);
    return f + " (docs/error-bound.md, \"Penetration depth\")";
}

} // namespace gjkval
