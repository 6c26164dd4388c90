// The error bounds each case is judged against. ONE function each, errorBound() for the distance
// and witnessBound() for the witness points: replace its body (and its formula's text) to change
// the bound for every report, test and exit code.
#pragma once

#include "implementations/variants.hpp"

#include <string>

namespace gjkval
{

// What a bound may depend on, for one case and one variant (docs/judgement.md, "Truth and
// metrics"). All computed in double from the input the variant sees (float-rounded for float
// variants), in the variant's compute frame: A's local frame (Frame::LocalA) or the world
// (Frame::World).
struct CaseMetrics
{
    double R = 0; // scale: max |coordinate| of A plus of B~ (infinity norm), plus rA + rB
    double unitRoundoff = 0; // u of the variant's type
    double radiusA = 0, radiusB = 0;
    int countA = 0, countB = 0;
    double exactDistance = 0; // d: the truth the variant is judged against
    double maxA = 0;          // A  = max |a_i| (Euclidean), a_i A's points in the compute frame
    double maxB = 0;          // B  = max |b_j|, B's points in B's own frame
    double maxBMapped = 0;    // B~ = max |b~_j|, B's points mapped into the compute frame
    double translation = 0;   // D  = |pB - pA| (world translations)
    double maxW = 0;        // W  = max |a_i - b~_j| (exact over pairs when n*m <= 1e6, else A + B~)
    double worldExtent = 0; // M = max |world coordinate| of A's and B's points, + max(rA, rB)
};

// The derived bound of docs/error-bound.md. Cases GJK flags outOfRange are not judged against it
// (counted apart).
double errorBound(const VariantInfo& variant, const CaseMetrics& metrics);
// Human-readable formula for the report ("variants[].bound.formula").
std::string boundFormula(const VariantInfo& variant);

// The witness bound of docs/error-bound.md ("Witness points"): each witness point within it of its
// shape, and ||pB - pA|| within it of the answer's own distance. Plugins are held to the
// reference options' (as for errorBound).
double witnessBound(const VariantInfo& variant, const CaseMetrics& metrics);
// Human-readable formula for the report ("variants[].witness_bound.formula").
std::string witnessBoundFormula(const VariantInfo& variant);

// The depth bound of docs/error-bound.md ("Penetration depth"): |signed distance - exact| on
// overlapping shapes, for a variant with Options::signedDistance (and for a plugin whose contract
// promises penetration and states no depth tolerance, the reference options' of its scalar type).
// metrics.exactDistance is then the exact signed distance (negative).
double depthBound(const VariantInfo& variant, const CaseMetrics& metrics);
// Human-readable formula for the report ("variants[].depth_bound.formula").
std::string depthBoundFormula(const VariantInfo& variant);

} // namespace gjkval
