#include "evaluate/bounds.hpp"

#include <fmt/format.h>

namespace gjkval
{

// The a-priori bound derived in docs/error-bound.md, to first order in u:
//   |d_gjk - d| <= u (4 A + 43 B + 10.2 D + 1.5 B~ + 5 W + 6.5 d + 3.5 (rA + rB)) + sub_T
// in A's local frame (the reference variant), every metric in world lengths (geometry.hpp), for
// any finite rotations (c, s) != (0, 0). Term by term (see the doc):
//   15 B + 10.2 D + 1.5 B~ + 1.5 W  mapping B into A's frame, w = a - b~      (vertex error)
//   4 A + 28 B                      choosing the support points (rounded dots, rotated direction)
//   3.5 W + 3 d                     the distance formula |cross(w1, e12)| / |e12|
//   2.5 (d + rA + rB)               back to world lengths: times |qA| = sqrt(cA^2 + sA^2)
//   d + rA + rB                     subtracting the radii
// Every variant is judged against this reference bound, computed in A's local frame whatever the
// variant's own frame (evaluate.cpp): it is what the library promises for the input.
// Duality-gap stopping adds the gap it accepts, 16 u |v| <= 16 u W.
double errorBound(const VariantInfo& variant, const CaseMetrics& m)
{
    const double u = m.unitRoundoff;
    const double d = m.exactDistance;
    double terms = 4 * m.maxA + 43 * m.maxB + 10.2 * m.translation + 1.5 * m.maxBMapped +
                   5 * m.maxW + 6.5 * d;
    if (variant.options.stopping == gjk::StoppingRule::DualityGap)
        terms += 16 * m.maxW;
    // Plus the answer's own resolution: a distance in T's subnormal range is rounded to a
    // multiple of T's smallest subnormal (the rescaled query's final scaling back, and the truth's
    // rounding to double), an absolute error the relative terms cannot express (below ~1e-292 in
    // double, 1e-31 in float, u times the terms underflows too). Found by `gjk-validate search`:
    // float inputs near 1e-45, double near 1e-310, judged against a bound of 0.
    return u * (terms + 3.5 * (m.radiusA + m.radiusB)) + smallestSubnormal(variant.scalar);
}

std::string boundFormula(const VariantInfo& variant)
{
    std::string f = "u (4 A + 43 B + 10.2 D + 1.5 B~ + 5 W + 6.5 d + 3.5 (rA + rB)) + the type's smallest subnormal, A's local frame";
    if (variant.options.stopping == gjk::StoppingRule::DualityGap)
        f += " + 16 u W";
    return f + " (docs/error-bound.md)";
}

// The witness bound derived in docs/error-bound.md ("Witness points"), to first order in u, in world
// lengths, for the reference options (every variant and plugin is held to it). Term by term:
//   9 A + 15 B + 10.2 D + 10.5 B~ + 3 M + 6 (rA + rB)   each point off its shape: the weights' sum,
//                         the combination, to world, B's mapped points (term 1), the radius offsets
//   18 W                  a triangle's (containment) point off B: Cramer's residual with
//                         accurate cross products
//   6 A + 6 B~ + 6 M + 8.5 W + 9.5 d + 12.5 (rA + rB)   ||pB - pA|| against d
//   3 M                   overlapping rounded shapes: the one point between the two, which is off
//                         its shapes by at most the first line plus the gap
// One number for every check: their sum. Plus the subnormal resolution of the two points (a
// rescaled query's points are scaled back, rounded to T's subnormals).
double witnessBound(const VariantInfo& variant, const CaseMetrics& m)
{
    const double u = m.unitRoundoff;
    const double terms = 15 * m.maxA + 15 * m.maxB + 10.2 * m.translation + 16.5 * m.maxBMapped +
                         12 * m.worldExtent + 26.5 * m.maxW + 9.5 * m.exactDistance +
                         18.5 * (m.radiusA + m.radiusB);
    return u * terms + 2 * smallestSubnormal(variant.scalar);
}

std::string witnessBoundFormula(const VariantInfo&)
{
    return "u (15 A + 15 B + 10.2 D + 16.5 B~ + 12 M + 26.5 W + 9.5 d + 18.5 (rA + rB)) + 2 x the "
           "type's smallest subnormal, world lengths (docs/error-bound.md, \"Witness points\")";
}

} // namespace gjkval
