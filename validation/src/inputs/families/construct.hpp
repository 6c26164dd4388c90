// The constructions the family generators share (inputs/families/*.cpp): shapes, poses, and
// placing one shape at a chosen gap from another. Internal to inputs/: the interface of the
// families is inputs/families.hpp.
#pragma once

#include "inputs/cases.hpp"
#include "inputs/geometry.hpp"
#include "inputs/rng.hpp"

#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace gjkval::families
{

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// --- Shapes ----------------------------------------------------------------------------------

ShapeIn poly(std::vector<P2> pts, double radius = 0);
// n points on a circle at sorted random angles: a convex polygon, counter-clockwise.
ShapeIn polygonOnCircle(Rng& r, int n, double radius);
ShapeIn regularPolygon(int n, double radius, double phase);
// 3 to 8 points on a circle of radius 0.5 to 2.
ShapeIn randomPolygon(Rng& r);

// --- Poses -----------------------------------------------------------------------------------

// The rotation is stored as the two doubles (cos t, sin t), computed once.
void setPose(ShapeIn& s, double angle, double px, double py);
// A random angle and a translation in [-4, 4]^2.
void randomPose(Rng& r, ShapeIn& s);
// Compose: world pose of a shape given relative to A's pose (rel first, then A's).
void poseRelativeTo(const ShapeIn& a, ShapeIn& b, double relAngle, P2 relP);
// b takes a's rotation and translation: points given in A's frame.
void copyPose(const ShapeIn& a, ShapeIn& b);
// The same rigid map for both shapes: exact contact in local coordinates stays exact contact for
// the exact side (an affine map preserves incidence in rational arithmetic).
void sharedPose(Case& c, double cc, double ss, double px, double py);
// Points replaced by their world coordinates (rounded), identity transform.
void bake(ShapeIn& s);
// Both shapes moved by `offset` along the angle phi, in their transforms or (baked) into their
// coordinates: a common offset that A's frame cancels, or that nothing can.
void moveFar(Case& c, double offset, double phi, bool baked);

// --- Placing B against A ---------------------------------------------------------------------

// Moves B (keeping its rotation) so that its extreme vertex along -n sits at the signed gap `gap`
// (negative: penetration) from a point inside a random edge of hull(A), n the edge's outward
// normal: B is then in the half plane beyond that edge's line, and the distance between the
// rounded shapes is `gap` up to the rounding of this construction.
void placeAtGap(const ShapeIn& a, ShapeIn& b, double gap, Rng& r);
// A random pair: random polygons and poses; mode 0 places B at a small gap, mode 1 at a small
// penetration, mode 2 within [-1, 1]^2 of A's position (deep overlap), otherwise independent.
void randomPair(Rng& r, Case& c, int mode);
// The tag of randomPair's mode (mode mod 4): "gap", "penetration", "deep-overlap", "random".
std::string randomPairTag(int mode);

// A stream for geometry shared by several cases of a family (a configuration swept over scales or
// offsets, a pair in every point order): derived from the family's seed and a key only.
Rng sharedRng(const Rng& r, std::uint64_t key);

} // namespace gjkval::families
