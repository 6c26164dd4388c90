// Double-precision geometry for the runner's own bookkeeping (generators, scales, pictures).
// Never used to judge correctness: the exact side does that.
#pragma once

#include "inputs/cases.hpp"

#include <array>
#include <optional>
#include <vector>

namespace gjkval
{

using P2 = std::array<double, 2>;

P2 applyTransform(const ShapeIn& s, P2 p); // c*x - s*y + px, s*x + c*y + py
std::vector<P2> worldPoints(const ShapeIn& s);

// The world case of a case, for an implementation that cannot take its transforms exactly (the
// adapter protocol's `input NAME world` line, docs/plugin-abi.md): each point mapped by its
// shape's transform in double, x' = (c*x - s*y) + px, y' = (s*x + c*y) + py, each operation
// rounded to double (applyTransform; the project builds with -ffp-contract=off: no FMA), then,
// for a float implementation (toFloat), rounded to float; the radius rounded to float likewise;
// the transform the identity (p = (0, 0), c = 1, s = 0). Name, source and comment are kept. The
// one home of what such an implementation is given, judged on and reproduced with. Empty when a
// number of it is not finite (a point that overflows in double, or in float for toFloat): the
// variant skips that case (kSkipWorldNotRepresentable, evaluate/evaluate.hpp).
std::optional<Case> worldCase(const Case& c, bool toFloat);
// worldCase(c, toFloat) has a value: the same numbers checked, nothing built (prepare() asks it
// of every case).
bool worldCaseFits(const Case& c, bool toFloat);
// Counter-clockwise convex hull (Andrew's monotone chain, collinear points dropped); fewer than 3
// points for degenerate sets.
std::vector<P2> convexHull(std::vector<P2> pts);
// True when the sequence is in convex order, what SupportStrategy::BinarySearch needs: no two
// cyclically consecutive points equal, every turn (p[i-1], p[i], p[i+1]) of one sign or collinear,
// no collinear turn going back, and one single turn around (a simple convex polygon, either
// winding, with collinear points allowed on its edges). Exact (filtered double orientation with a
// GMP fallback). Fewer than 3 points: true for 1 point, false otherwise (a segment turns back).
bool inConvexOrder(const std::vector<P2>& pts);
// Hull of A - B (world frame), counter-clockwise, decimated to at most maxVertices vertices.
std::vector<P2> minkowskiDifference(const std::vector<P2>& a, const std::vector<P2>& b,
                                    std::size_t maxVertices = 2000);

// The problem's scales in a compute frame (A's local frame, or the world), the points mapped into
// the frame in double (the fields of CaseMetrics, bounds.hpp), all in world lengths: A's frame
// measures in units of |qA| = hypot(cA, sA), so its lengths are multiplied by |qA| (1 for a unit
// rotation):
//   R  = |qA| (max_i |a_i|_inf + max_j |b~_j|_inf) + rA + rB
//   A  = |qA| max_i |a_i|, B = |qB| max_j |b_j| (own frame), B~ = |qA| max_j |b~_j|,
//   D  = |pB - pA|, W = |qA| max_ij |a_i - b~_j| (exact when n*m <= 1e6, else A + B~).
struct FrameScales
{
    double R = 0, A = 0, B = 0, Bmapped = 0, D = 0, W = 0;
    // M: the largest |world coordinate| of either shape's points, plus the larger radius (the
    // size of a world witness point, whatever the compute frame).
    double M = 0;
};
FrameScales frameScales(const ShapeIn& a, const ShapeIn& b, bool worldFrame);
double maxAbsWorldCoordinate(const Case& c);
double maxAbsWorldCoordinate(const ShapeIn& a, const ShapeIn& b);
double maxAbsTranslation(const Case& c);
// Diameter / minimum width of the hull of the local points (inf for segments and points);
// computed for at most 64 hull vertices, else 0.
double aspectRatio(const ShapeIn& s);
// Largest distance between two points of h.
double hullDiameter(const std::vector<P2>& h);

// Every length of the shape (points, radius, translation) times k; the rotation (c, s) is kept.
// Each number is one product, rounded once (exact when k is a power of two and nothing
// overflows or underflows).
void scaleShape(ShapeIn& s, double k);
// Both shapes scaled by k about the world origin.
void scaleCase(Case& c, double k);

} // namespace gjkval
