// Exact ground truth for 2D convex-hull distance queries.
//
// Given two point sets, each with a radius and a rigid transform given as doubles, computes with
// no rounding error the distance between the two convex hulls (then minus both radii, clamped at
// 0), and rounds the outputs to doubles correctly. This header is deliberately free of CGAL, GMP
// and MPFR: all of that lives in the library's .cpp files. See docs/exact.md.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace exact
{

struct Point
{
    double x = 0, y = 0;
};

struct Shape
{
    std::vector<Point>
        points;            // any order, duplicates/collinear/interior points allowed; count >= 1
    double radius = 0;     // >= 0
    double px = 0, py = 0; // translation
    double c = 1, s = 0;   // rotation as the two doubles (cos, sin) the float side used, applied
                           // exactly: x' = c*x - s*y + px, y' = s*x + c*y + py
                           // (c, s need NOT satisfy c^2 + s^2 = 1 exactly)
};

// Three independent constructions of the Minkowski difference Z = hull(A) - hull(B) (the library's
// Z = A - B); all give the same exact results (the tests check this with == on exact rationals).
// Default is the fastest.
enum class Route
{
    HullOfDifferences,
    MinkowskiSum2,
    EdgeMerge,
    Default = EdgeMerge
};

// "hull-of-differences", "minkowski-sum-2", "edge-merge".
const char* routeName(Route);
// Accepts the three names above and "default"; returns false (leaving out alone) otherwise.
bool parseRoute(const std::string& name, Route& out);
// All distinct routes, in declaration order (Default is EdgeMerge, not listed twice).
inline constexpr std::array<Route, 3> kAllRoutes = {Route::HullOfDifferences, Route::MinkowskiSum2,
                                                    Route::EdgeMerge};

// An exact rational as decimal strings: "num/den" in lowest terms with den > 1, or the integer
// "num".
struct ExactPoint
{
    std::string x, y;
};

// How the default route (EdgeMerge) decided one case (docs/exact.md, "The filter"). Every
// predicate is first evaluated in interval arithmetic; the counts say how many fell back to exact
// integers. The rounded outputs are first computed in double-double with an error bound; each
// flag says which rounding the bound could not decide, and then the case took the GMP
// construction and MPFR rounding (`gmp`). The other routes and Options::filter = false set `gmp`
// and nothing else.
struct Fallbacks
{
    int hull = 0;         // hull comparisons and orientation signs decided exactly
    int merge = 0;        // edge-angle comparisons of the Minkowski edge merge decided exactly
    int feature = 0;      // closest-feature and overlap predicates decided exactly
    bool squared = false; // the rounded squared distance was undecided
    bool distance =
        false; // the rounded distance (or its clamp at 0, or its enclosure) was undecided
    bool witness = false; // a rounded witness coordinate was undecided
    bool gmp = false;     // the rounded outputs came from the GMP/MPFR route
    // Options::penetration (docs/exact.md, "Penetration depth"):
    int depthTies = 0;  // closest-edge comparisons the error bounds left to exact integers
    bool depth = false; // the signed distance or the penetration pair was undecided by the
                        // filter: they came from GMP/MPFR
};

struct Result
{
    bool overlap = false; // exact: origin inside or on boundary of hull(A) - hull(B) (before radii)
    std::string squaredNum, squaredDen; // exact squared distance between the hulls (before radii),
                                        // lowest terms, den > 0 (empty only when not asked for:
                                        // Options::squaredRational)
    double squared = 0;  // that rational rounded to nearest double (may be +inf above DBL_MAX)
    double distance = 0; // correctly rounded (to nearest) max(0, sqrt(squared) - rA - rB)
    double lower = 0,
           upper = 0; // enclosing doubles of that exact value, lower <= distance <= upper
                      // (finite unless the exact value exceeds DBL_MAX, then upper = +inf);
                      // tight: equal when the exact value is a double, else adjacent
    Point witnessA,
        witnessB; // closest points, world frame, each coordinate correctly rounded to nearest.
                  // With radii: moved by the radius along the unit direction from the hull point
                  // of A to that of B (A forward by rA, B backward by rB). When the hulls touch
                  // or overlap (squared == 0): the hull points themselves, which then coincide:
                  // one common point of both hulls (see docs/exact.md for which one).
    bool hasExactWitnesses = false;
    ExactPoint exactWitnessA,
        exactWitnessB;   // the hull (radius-free) closest points, exact, only when requested
    Fallbacks fallbacks; // how the case was decided; not part of the truth

    // Options::penetration (docs/exact.md, "Penetration depth"): the signed distance of the
    // rounded shapes. When the cores are apart, sqrt(squared) - rA - rB (negative when the radii
    // overlap); when they overlap (overlap == true), -(depth + rA + rB), depth the origin's exact
    // distance to the boundary of hull(A) - hull(B) (0 when the origin is on it).
    bool hasSigned = false;
    double signedDistance = 0; // correctly rounded to nearest
    double signedLower = 0,
           signedUpper = 0; // enclosing doubles of the exact signed distance, as lower/upper
    std::string depthSquaredNum,
        depthSquaredDen; // overlap only: the cores' exact squared depth, lowest terms ("0"/"1"
                         // when touching); empty when the cores are apart, and (as squaredNum)
                         // where the filter decided and Options::squaredRational is false
    // The penetration pair, world frame, each coordinate correctly rounded to nearest: pA on A's
    // rounded boundary, pB on B's, pA - pB the minimal translation of B to contact (the signed
    // distance is -|pA - pB| on overlap). Cores apart: witnessA, witnessB (moved by the radii).
    Point penetrationA, penetrationB;
};

struct Options
{
    Route route = Route::Default;
    bool exactWitnesses = false;
    // EdgeMerge only: decide the rounded outputs in double-double with an error bound where it can
    // (the same results bit for bit). false forces the GMP construction and MPFR rounding for
    // every case (`--truth exact`), for checking.
    bool filter = true;
    // false: where the filter decided, leave squaredNum and squaredDen empty (the rational costs
    // a gcd and two decimal conversions, as much as the rest of the filtered case). For callers
    // that never read it (the runner without --per-case); the GMP route fills it regardless.
    bool squaredRational = true;
    // Also compute the signed distance and the penetration pair (Result::hasSigned and below).
    bool penetration = false;
};

// Throws std::invalid_argument for invalid input (no points, NaN or infinite values, negative
// radius).
Result distance(const Shape& a, const Shape& b, const Options& options = {});

// max(0, dist(p, hull(shape)) - shape.radius), correctly rounded to nearest double; p is in the
// world frame. Used for "witness point lies on its shape" errors. Decided in floating point where
// an error bound allows (docs/exact.md, "Point to shape"), else by the GMP route, with the same
// result bit for bit; `gmpRoute`, when given, says whether the GMP route measured it.
double pointToShapeDistance(const Shape& shape, Point p, bool* gmpRoute = nullptr);

namespace detail
{
struct PreparedData;
}

// A shape prepared once for many pointToShapeDistance() calls (docs/exact.md, "Point to shape"):
// a copy of the shape, its hull as the default route finds it, and the interval enclosures of the
// hull's world points. The constructor validates like validateShape(shape, name)
// (std::invalid_argument; pointToShapeDistance(Shape, ...) names it "shape B").
// A const PreparedShape may be used by several threads at once.
class PreparedShape
{
  public:
    explicit PreparedShape(const Shape& shape, const char* name = "shape");
    explicit PreparedShape(Shape&& shape, const char* name = "shape"); // the shape moved in
    PreparedShape(PreparedShape&&) noexcept;
    PreparedShape& operator=(PreparedShape&&) noexcept;
    ~PreparedShape();

    const Shape& shape() const;
    int hullSize() const; // vertices of the hull: 1 (a point), 2 (a segment) or more
    const detail::PreparedData& data() const { return *data_; }

  private:
    std::unique_ptr<detail::PreparedData> data_;
};

// distance(a.shape(), b.shape(), options), bit for bit, fallback counts included; route EdgeMerge
// takes the prepared hulls instead of making them again (the runner prepares a case's shapes once
// for its truth and its witness checks). The shapes were validated when prepared.
Result distance(const PreparedShape& a, const PreparedShape& b, const Options& options = {});

// pointToShapeDistance(prepared.shape(), p, gmpRoute), bit for bit and with the same route, at
// the cost of locating p against the prepared hull (no hull, merge or allocation per point unless
// the exact fallbacks or the GMP route are needed).
double pointToShapeDistance(const PreparedShape& shape, Point p, bool* gmpRoute = nullptr);

// Independent brute force (plain GMP rationals, no hull construction): exact separating-axis test
// over every pair direction, then the minimum exact squared point-to-segment distance over all
// (point, point-pair segment) combinations. Fills overlap, squared*, distance, lower, upper and the
// witnesses (when separated; the overlap witnesses are left at 0). Cost O((n + m)^3): small inputs
// only.
Result bruteForce(const Shape& a, const Shape& b);

// Independent brute force of the signed distance (plain GMP rationals, no hull construction): on
// overlap, the least over every candidate edge normal n (perpendicular to a pair of points of A or
// of B) of h_Z(n)^2 / |n|^2, h_Z the support function of hull(A) - hull(B); apart, bruteForce's
// distance. Fills everything bruteForce fills plus hasSigned, signedDistance, signedLower,
// signedUpper and depthSquaredNum/Den; the penetration pair only when the cores are apart (the
// witnesses, as distance() gives them), left at 0 on overlap (as bruteForce's witnesses).
// Small inputs only.
Result bruteForceSigned(const Shape& a, const Shape& b);

// Throws std::invalid_argument if the shape is invalid (what distance() checks); `name` prefixes
// the message.
void validateShape(const Shape& shape, const char* name = "shape");

} // namespace exact
