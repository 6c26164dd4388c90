// Internal interfaces of the exact library (GMP, no CGAL): what each route produces, the shared
// closest-feature search, and the final rounding step.
#pragma once

#include <gjk2d/exact.hpp>

#include <gmpxx.h>

#include <stdexcept>
#include <vector>

namespace exact::detail
{

struct QPoint
{
    mpq_class x, y;
};

// Z = hull(A) - hull(B) as a route built it: its vertices counterclockwise (no three collinear; one
// vertex for a point, two for a segment), each with its provenance: z[k] = a[k] - b[k], a[k] a
// vertex of hull(A) and b[k] one of hull(B). Canonical rationals. Filled for Options::penetration
// when the cores overlap (the depth needs every edge of Z, the distance only the located feature).
struct Polygon
{
    std::vector<QPoint> z, a, b;
};

// What every route computes, exactly: the rest of Result is derived from it by finish().
struct ExactResult
{
    Polygon polygon; // Options::penetration and overlap only (else empty)
    bool overlap = false;
    mpq_class squared; // canonical
    QPoint z; // closest point of Z = hull(A) - hull(B) to the origin (zero when overlapping); z =
              // wa - wb
    QPoint wa, wb; // closest points of hull(A) and hull(B) (a common point when overlapping)
    // z, wa and wb may be unreduced fractions (denominator > 0, not in lowest terms): only finish()
    // reads them, and it reduces them before any use that needs canonical rationals.
};

// Rounds everything (distance with radii, witnesses on the rounded surfaces) and formats strings.
Result finish(const ExactResult& e, double radiusA, double radiusB, bool exactWitnesses);

// Correctly rounded (to nearest, ties to even, subnormals and overflow handled) double of q.
double roundToDouble(const mpq_class& q);
// Correctly rounded max(0, sqrt(q) - rA - rB) with an enclosure; q >= 0, rA, rB >= 0.
void roundDistance(const mpq_class& q, double rA, double rB, double& value, double& lower,
                   double& upper);

std::string toString(const mpq_class& q); // "num" or "num/den"

// ---------------------------------------------------------------- penetration (penetration.cpp)

// Correctly rounded sigma sqrt(q) - rA - rB (sigma = +1 or -1, q >= 0), not clamped, with its tight
// enclosure (finish.cpp).
void roundSigned(const mpq_class& q, int sigma, double rA, double rB, double& value, double& lower,
                 double& upper);
// Correctly rounded a + rA n/|n| and b - rB n/|n|, coordinate by coordinate; n != 0 (finish.cpp).
void roundPair(const QPoint& a, const QPoint& b, const QPoint& n, double rA, double rB, Point& pA,
               Point& pB);

// The depth of the origin in Z (overlap): the closest edge's line (docs/exact.md, "Penetration
// depth"), the edge chosen among equally close ones by the least angle in [0, 2 pi) of its outward
// normal; its squared distance, an outward normal (not unit), the foot point's decomposition
// a - b (a on hull(A), b on hull(B), dividing A's and B's edges in the ratio the foot divides Z's).
struct Depth
{
    mpq_class squared;
    QPoint normal;
    QPoint a, b;
};
Depth deepest(const Polygon& z);
// The signed fields of r (Options::penetration) from e: cores apart, from e.squared and r's
// witnesses (already rounded); overlapping, from e.polygon.
void finishSigned(const ExactResult& e, double rA, double rB, Result& r);

// The three routes. Inputs are validated by the caller.
// wantPolygon: fill ExactResult::polygon when the cores overlap (Options::penetration).
ExactResult edgeMerge(const Shape& a, const Shape& b, bool wantPolygon = false);
// Route EdgeMerge to the end: with options.filter, the rounded outputs from filteredFinish() where
// it decides them and the exact squared distance from the located feature; otherwise (and when
// it does not decide) edgeMerge() and finish(). Fills Result::fallbacks.
Result edgeMergeResult(const Shape& a, const Shape& b, const Options& options);
// The same from prepared shapes (exact::PreparedShape): their hulls, not made again; the same
// result, fallback counts included.
Result edgeMergeResult(const PreparedData& a, const PreparedData& b, const Options& options);
ExactResult hullOfDifferences(const Shape& a, const Shape& b, bool wantPolygon = false);
ExactResult minkowskiSum2(const Shape& a, const Shape& b, bool wantPolygon = false);

// ----------------------------------------------------------------------------------------------
// Closest feature of a convex polygon Z (vertices v_0..v_{k-1}, counterclockwise, no repeated
// vertices; collinear vertices allowed; k = 1 a point, k = 2 a segment) to the origin O, located
// with sign predicates only. Pr provides
//   int orientO(i, j)   sign of cross(v_i, v_j) = orientation(v_i, v_j, O)
//   int dotSign(i, j)   sign of (O - v_i) . (v_j - v_i)
//   bool isZero(i)      v_i == O
struct Feature
{
    enum Kind
    {
        Vertex,
        Edge,
        Triangle
    } kind = Vertex;
    bool overlap = false; // O in Z (inside or on the boundary)
    int i = 0, j = 0, l = 0;
    // Vertex: closest point is v_i (overlap: v_i == O).
    // Edge: closest point is the projection of O on segment v_i v_j, strictly inside it (overlap: O
    // on it). Triangle (overlap only, k >= 3): O lies in the closed triangle v_i v_j v_l (a fan
    // triangle, i = 0).
};

// The closest feature of a segment v_0 v_1 (k = 2): an end, or the inside of the edge.
template <class Pr> Feature locateOnSegment(Pr& pr)
{
    Feature f;
    if (pr.dotSign(0, 1) <= 0)
    {
        f.kind = Feature::Vertex;
        f.i = 0;
        f.overlap = pr.isZero(0);
    }
    else if (pr.dotSign(1, 0) <= 0)
    {
        f.kind = Feature::Vertex;
        f.i = 1;
        f.overlap = pr.isZero(1);
    }
    else
    {
        f.kind = Feature::Edge;
        f.i = 0;
        f.j = 1;
        f.overlap = pr.orientO(0, 1) == 0;
    }
    return f;
}

// O inside or on the boundary of a polygon (k >= 3): the fan triangle (v_0, v_t, v_{t+1}) holding
// it. orientO(0, t) >= 0 holds for t = 1 (an edge) and is kept as the loop invariant.
template <class Pr> Feature locateInside(int k, Pr& pr)
{
    Feature f;
    f.kind = Feature::Triangle;
    f.overlap = true;
    int t = 1;
    while (t + 1 < k - 1 && pr.orientO(0, t + 1) > 0)
        ++t;
    f.i = 0;
    f.j = t;
    f.l = t + 1;
    return f;
}

// O outside a polygon (k >= 3), edge firstOut seeing it: the closest point is inside a visible
// edge or a vertex next to one.
template <class Pr> Feature locateOutside(int k, int firstOut, Pr& pr)
{
    Feature f;
    for (int n = 0; n < k; ++n)
    {
        const int e = (firstOut + n) % k;
        const int g = e + 1 == k ? 0 : e + 1;
        if (n > 0 && pr.orientO(e, g) >= 0)
            continue;
        if (pr.dotSign(e, g) <= 0)
        {
            if (pr.dotSign(e, e == 0 ? k - 1 : e - 1) <= 0)
            {
                f.kind = Feature::Vertex;
                f.i = e;
                return f;
            }
            continue;
        }
        if (pr.dotSign(g, e) <= 0)
        {
            if (pr.dotSign(g, g + 1 == k ? 0 : g + 1) <= 0)
            {
                f.kind = Feature::Vertex;
                f.i = g;
                return f;
            }
            continue;
        }
        f.kind = Feature::Edge;
        f.i = e;
        f.j = g;
        return f;
    }
    throw std::logic_error("exact: closest feature not found (polygon not convex?)");
}

// The feature of Z (k vertices in counter-clockwise order) closest to the origin O.
template <class Pr> Feature locate(int k, Pr& pr)
{
    if (k == 1)
    {
        Feature f;
        f.kind = Feature::Vertex;
        f.i = 0;
        f.overlap = pr.isZero(0);
        return f;
    }
    if (k == 2)
        return locateOnSegment(pr);
    for (int e = 0; e < k; ++e)
        if (pr.orientO(e, e + 1 == k ? 0 : e + 1) < 0)
            return locateOutside(k, e, pr);
    return locateInside(k, pr);
}

// filter.cpp: the rounded fields of Result (overlap, squared, distance, lower, upper, witnesses;
// not the squared rational's strings) for located feature f, whose 1 to 3 vertices (as construct()
// below) are the differences of input points as[t] of A and bs[t] of B, computed in double-double
// with an error bound. True when every rounding is decided; false otherwise, with
// r.fallbacks.{squared, distance, witness} saying which was not.
// With `penetration` and separated cores, also the unclamped signed distance (and its enclosure)
// where the bound decides it: then r.hasSigned (else the caller rounds it with GMP).
bool filteredFinish(const Feature& f, const Shape& A, const Shape& B, const Point* as,
                    const Point* bs, Result& r, bool penetration = false);

// filter.cpp: overlapping cores, the closest edge of Z chosen (count = 2: its two vertices, the
// differences of input points as[t] of A and bs[t] of B, in Z's counterclockwise order) or Z a
// single point (count = 1): the signed distance, its enclosure and the penetration pair of r, in
// double-double with error bounds. True when every rounding is decided (r's other fields
// untouched); false: the GMP route.
bool filteredDepth(int count, const Shape& A, const Shape& B, const Point* as, const Point* bs,
                   Result& r);

// filter.cpp: max(0, dist(p, hull(B)) - B.radius), correctly rounded to nearest, for the located
// feature f of Z = {p} - hull(B) (p in the world frame; bs: B's input points of the feature's Z
// vertices i and j), from exact expansions of the world coordinates' differences. True when
// decided (`out` then is the GMP route's distance bit for bit); false: take the GMP route.
bool filteredPointDistance(const Feature& f, Point p, const Shape& B, const Point* bs, double& out);
// filter.cpp: the exact sign, by floating-point expansions, of one of PointLocator's predicates on
// Z = {p} - hull(B) (p in the world frame, Z vertex k = p - w_k for B's input point b_k):
// Cross: sign(z_i x z_j); Dot: sign(z_i . (z_j - z_i)); IsZero: 0 when z_i == 0, else 1 (bj
// unused). kZUnsure where an expansion cannot be exact (overflow, underflow, scaling): take the GMP
// route.
enum class ZPredicate
{
    Cross,
    Dot,
    IsZero
};
constexpr int kZUnsure = 2;
int zSignExact(ZPredicate kind, Point p, const Shape& B, Point bi, Point bj);
// edge_merge.cpp: pointToShapeDistance's computation before PreparedShape (now its GMP route's
// fallback and the tests' reference), point a one-point shape with the identity
// transform and no radius (validated): the located feature, then filteredPointDistance or, where
// it does not decide, the GMP construction and MPFR rounding (`gmp` says which).
double pointDistance(const Shape& point, const Shape& shape, bool& gmp);
// edge_merge.cpp: pointDistance(), bit for bit and with the same `gmp`, for a prepared shape
// (exact::PreparedShape): p located against the prepared hull with the same predicates; where
// filteredPointDistance does not decide, pointDistance() itself (the GMP route).
double preparedPointDistance(const PreparedData& shape, Point p, bool& gmp);

// Builds the exact result from a located feature, given for each of the feature's vertices (in the
// order i, j, l; 1, 2 or 3 of them as the kind needs) the exact Z vertex zs[], and the hull points
// as[] of A and bs[] of B with zs[t] = as[t] - bs[t]. Plain rationals: used by the CGAL routes.
ExactResult construct(const Feature& f, const QPoint* zs, const QPoint* as, const QPoint* bs);

} // namespace exact::detail
