// The signed distance (Options::signedDistance): when GJK ends with the origin in the Minkowski
// difference Z = A - B (the shapes overlap), the penetration depth is the origin's distance to Z's
// boundary, found by an expanding polygon (EPA) seeded by GJK's final simplex. The talk's GJK
// ends at overlap with distance 0; this is the step after it, in its vocabulary: simplex, support
// point, Minkowski difference, search direction. docs/gjk.md, "Signed distance".
//
//   1. Seed.     GJK's final simplex: a triangle containing the origin (containment), or an edge
//                or a vertex with the origin on it (a zero direction, or a final distance 0).
//                An edge or a vertex grows to a triangle with support points along the edge's
//                perpendiculars (an axis direction for a vertex); if Z has no extent there, Z is a
//                segment or a point through the origin: Touching.
//   2. Expand.   The polygon P (counter-clockwise, its vertices points of Z) contains the origin.
//                Its closest edge e, at distance dist(e) (cross(v_i, e) / |e|), has the outward
//                normal n = rightPerp(e) (exact: no division, as the talk's search direction); the
//                support point w of Z along n gives the support value h = dot(n, w) / |n|.
//                Since P lies in Z and contains the origin, and any direction's support value is
//                at least the depth:  dist(e) <= depth <= h.
//   3. Stop.     ExpandStop::RepeatedSupport: w is already a vertex of P (by index pair, as GJK's
//                case 1); GapClosed: dot(n, w - v_i) <= Tolerances<T>::expandGap * dot(n, w), the
//                interval [dist, h] is as narrow as the answer's own rounding; IterationLimit:
//                expandIterationLimit support points (every other iteration adds a vertex of Z,
//                which has at most countA + countB). Touching: the polygon's closest edge ends at
//                a computed distance <= 0 (the origin on the edge's line, cross(v_i, e) rounding
//                to 0 or below, and nothing found beyond it), or Z has no interior.
//      Else  insert w after v_i, removing the neighbours it makes reflex (the polygon stays the
//            convex hull of its points, which contains the old one and so the origin), and go to 2.
//   4. Answer.   depth = dist(e) of the final closest edge; the penetration pair from the edge's
//                barycentric weights of the origin's projection (pA - pB = depth n / |n|, the
//                minimal translation of B), mapped to world as the witness points are.
//
// Cores apart but rounded shapes overlapping (core distance < rA + rB): GJK's witnesses moved by
// the radii, distance core - rA - rB unclamped, no expansion (ExpandStop::None).
//
// The certified interval (always set on overlap): the exact signed distance of the shapes as
// given (points and transforms as exact numbers, the exact side's map c x - s y + p), enclosed in
// double with certify.hpp's running error bounds, from the final polygon's index pairs:
//   upper: minus the least distance from the origin to the lines of the polygon's edges, with
//          each edge's vertices W = xfA a - xfB b recomputed in world coordinates; valid when
//          every orientation cross(W_k, W_k+1) is certainly positive (then every ray from the
//          origin meets an edge, inside Z, no nearer than its line: the ball of that radius is in
//          Z). Otherwise the norm of one point of Z (the closest edge's foot point): the signed
//          distance is at most the distance to any point of Z.
//   lower: minus the support value of Z along the world normal n, certifyDistance's scan of both
//          shapes: signed >= -h_Z(n) / |n| for every n (depth <= h if overlapping, distance >= -h
//          if apart).
//   Then the radii are subtracted, rounded outwards.
#pragma once

#include "gjk2d/certify.hpp"
#include "gjk2d/detail/macros.hpp"
#include "gjk2d/distance.hpp"
#include "gjk2d/math.hpp"
#include "gjk2d/simplex.hpp"
#include "gjk2d/support.hpp"
#include "gjk2d/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk
{

// The expansion's iteration limit: support points computed in step 2 for shapes of countA and
// countB points. Each iteration that does not stop adds to P a vertex of Z it did not hold (exact
// arithmetic: a support point along an outward normal, strictly beyond the edge, is a vertex of
// Z's hull, and a vertex of Z's hull in P stays a vertex of P). Z's hull has at most
// countA + countB vertices, so with the iteration that stops, countA + countB + 1 support points
// suffice; more means a cycle made by rounding (ExpandStop::IterationLimit).
constexpr int expandIterationLimit(int countA, int countB)
{
    return countA + countB + 1;
}

// The expanding polygon: vertices counter-clockwise (points of Z with their index pairs), and the
// signed distance from the origin to each edge's line (edge k from vertex k to k + 1, edgeDistance
// below): positive when the origin is on the inner side. Each edge's distance is computed once,
// when the edge is made.
template <class T> struct ExpandPolygon
{
    static constexpr int inlineCapacity = 32;
    SimplexVertex<T> inlineV[inlineCapacity];
    T inlineDist[inlineCapacity];
    std::vector<SimplexVertex<T>> heapV; // shapes with more points
    std::vector<T> heapDist;
    SimplexVertex<T>* v = inlineV;
    T* dist = inlineDist;
    int count = 0;

    explicit ExpandPolygon(int capacity)
    {
        if (capacity > inlineCapacity)
        {
            heapV.resize(std::size_t(capacity));
            heapDist.resize(std::size_t(capacity));
            v = heapV.data();
            dist = heapDist.data();
        }
    }
    ExpandPolygon(const ExpandPolygon&) = delete;
    int next(int k) const { return k + 1 == count ? 0 : k + 1; }
    bool holds(int indexA, int indexB) const
    {
        for (int k = 0; k < count; ++k)
            if (v[k].indexA == indexA && v[k].indexB == indexB)
                return true;
        return false;
    }
};

// The origin's signed distance to the line of the edge from v1 to v2 (positive on its left, the
// inside of a counter-clockwise polygon): cross(v1, e) / |e|, simplexDistance's formula with its
// sign kept; +inf for an edge of length 0 (never the closest).
template <class T> T edgeDistance(Vec2<T> v1, Vec2<T> v2)
{
    const Vec2<T> e = edgeOfSafeSize(v2 - v1);
    const T len = length(e);
    if (!(len > T(0)))
        return std::numeric_limits<T>::infinity();
    return cross(v1, e) / len;
}

// Why the expansion stopped, its closest edge (its first vertex) and how many support points it
// computed.
struct ExpandEnd
{
    ExpandStop stop = ExpandStop::None;
    int edge = 0;
    int supports = 0;
    bool degenerate = false; // Z has no interior (a segment or a point): no edge, depth 0
};

// Insert w after vertex k (the closest edge's first vertex), removing the vertices it makes reflex
// or collinear on either side (as an incremental convex hull does), so that the polygon stays the
// convex hull of its points, which holds the old polygon and so the origin. At least two old
// vertices stay, so the polygon keeps three.
template <class T> void insertVertex(ExpandPolygon<T>& P, int k, const SimplexVertex<T>& w)
{
    // The common case, both neighbours stay convex: shift the vertices after k by one.
    const int k1 = P.next(k);
    const int k0 = k == 0 ? P.count - 1 : k - 1;
    const int k2 = P.next(k1);
    if (cross(P.v[k1].w - w.w, P.v[k2].w - P.v[k1].w) > T(0) &&
        cross(P.v[k].w - P.v[k0].w, w.w - P.v[k].w) > T(0))
    {
        for (int j = P.count; j > k + 1; --j)
        {
            P.v[j] = P.v[j - 1];
            P.dist[j] = P.dist[j - 1];
        }
        P.v[k + 1] = w;
        ++P.count;
        P.dist[k] = edgeDistance(P.v[k].w, w.w);
        P.dist[k + 1] = edgeDistance(w.w, P.v[P.next(k + 1)].w);
        return;
    }
    // o[0 .. m) = the old vertices from k + 1 round to k, with their edges' distances.
    const int m = P.count;
    SimplexVertex<T> tmp[ExpandPolygon<T>::inlineCapacity];
    T tmpDist[ExpandPolygon<T>::inlineCapacity];
    std::vector<SimplexVertex<T>> tmpHeap;
    std::vector<T> tmpDistHeap;
    SimplexVertex<T>* o = tmp;
    T* od = tmpDist;
    if (m > ExpandPolygon<T>::inlineCapacity)
    {
        tmpHeap.resize(std::size_t(m));
        tmpDistHeap.resize(std::size_t(m));
        o = tmpHeap.data();
        od = tmpDistHeap.data();
    }
    for (int j = 0, i = k + 1; j < m; ++j, ++i)
    {
        if (i == m)
            i = 0;
        o[j] = P.v[i];
        od[j] = P.dist[i];
    }
    // Forward side: drop o[0], o[1], ... while the turn w -> o[j] -> o[j + 1] is not strictly left.
    int first = 0, last = m - 1; // o[last] is vertex k
    while (last - first >= 2 && cross(o[first].w - w.w, o[first + 1].w - o[first].w) <= T(0))
        ++first;
    // Backward side: drop o[last], ... while o[last - 1] -> o[last] -> w is not strictly left.
    while (last - first >= 2 && cross(o[last].w - o[last - 1].w, w.w - o[last].w) <= T(0))
        --last;
    P.count = 0;
    P.v[0] = w;
    P.dist[0] = edgeDistance(w.w, o[first].w);
    P.count = 1;
    for (int j = first; j <= last; ++j, ++P.count)
    {
        P.v[P.count] = o[j];
        P.dist[P.count] = j < last ? od[j] : edgeDistance(o[last].w, w.w);
    }
}

// Steps 1: a triangle (or more) around the origin from GJK's final simplex of 1 to 3 vertices,
// counter-clockwise. Returns false when Z shows no extent (a segment or a point: Touching), with
// `normal` a perpendicular of that segment (or (1, 0) for a point).
template <class T, class Shape>
bool seedPolygon(Shape& A, Shape& B, const Simplex<T>& s, ExpandPolygon<T>& P, ExpandEnd& end,
                 Vec2<T>& normal)
{
    SimplexVertex<T> v0 = s.v[0];
    SimplexVertex<T> v1 = s.v[s.count > 1 ? 1 : 0];
    if (s.count == 3)
    {
        P.count = 3;
        P.v[0] = s.v[0];
        const bool ccw = cross(s.v[1].w - s.v[0].w, s.v[2].w - s.v[0].w) > T(0);
        P.v[1] = ccw ? s.v[1] : s.v[2];
        P.v[2] = ccw ? s.v[2] : s.v[1];
        return true;
    }
    // A vertex (or an edge of length 0): find a second point of Z along an axis direction.
    if (s.count == 1 || v1.w == v0.w)
    {
        const Vec2<T> axes[4] = {{T(1), T(0)}, {T(-1), T(0)}, {T(0), T(1)}, {T(0), T(-1)}};
        bool found = false;
        for (const Vec2<T>& d : axes)
        {
            const SimplexVertex<T> w = findMinkowskiSupport<T>(A, B, d);
            ++end.supports;
            if (dot(d, w.w - v0.w) > T(0))
            {
                v1 = w;
                found = true;
                break;
            }
        }
        if (!found) // Z is the point v0
        {
            normal = {T(1), T(0)};
            return false;
        }
    }
    // An edge v0 v1 through (or next to) the origin: the support points along its perpendiculars.
    const Vec2<T> e = edgeOfSafeSize(v1.w - v0.w);
    const SimplexVertex<T> wL = findMinkowskiSupport<T>(A, B, leftPerp(e));
    ++end.supports;
    if (cross(e, wL.w - v0.w) > T(0))
    {
        P.count = 3;
        P.v[0] = v0, P.v[1] = v1, P.v[2] = wL;
        return true;
    }
    const SimplexVertex<T> wR = findMinkowskiSupport<T>(A, B, rightPerp(e));
    ++end.supports;
    if (cross(e, wR.w - v0.w) < T(0))
    {
        P.count = 3;
        P.v[0] = v0, P.v[1] = wR, P.v[2] = v1;
        return true;
    }
    normal = rightPerp(e); // Z is a segment on the line of v0 v1
    return false;
}

// Steps 2 and 3: expand until a stopping rule holds; end.edge is the closest edge.
template <class T, class Shape>
GJK_INLINE void expandPolygon(Shape& A, Shape& B, ExpandPolygon<T>& P, int limit, ExpandEnd& end)
{
    for (int j = 0; j < P.count; ++j)
        P.dist[j] = edgeDistance(P.v[j].w, P.v[P.next(j)].w);
    for (int iteration = 0;; ++iteration)
    {
        // The closest edge (the first of equals).
        int k = 0;
        for (int j = 1; j < P.count; ++j)
            if (P.dist[j] < P.dist[k])
                k = j;
        end.edge = k;
        if (iteration == limit)
        {
            end.stop = ExpandStop::IterationLimit;
            return;
        }
        const SimplexVertex<T>& vk = P.v[k];
        const Vec2<T> n = rightPerp(edgeOfSafeSize(P.v[P.next(k)].w - vk.w)); // outward
        const SimplexVertex<T> w = findMinkowskiSupport<T>(A, B, n);
        ++end.supports;
        if (P.holds(w.indexA, w.indexB))
        {
            end.stop = ExpandStop::RepeatedSupport;
            return;
        }
        // The gap between the support value and the edge's distance, both times |n|: measured
        // from the edge's vertex (w - v_k is exact or nearly, no cancellation of two large dots).
        if (dot(n, w.w - vk.w) <= Tolerances<T>::expandGap * dot(n, w.w))
        {
            end.stop = ExpandStop::GapClosed;
            return;
        }
        insertVertex(P, k, w);
    }
}

// The weight of the second vertex in the origin's projection on the line of edge k (unclamped):
// in [0, 1] when the foot lies on the edge. dot(-v1, e12) / |e12|^2, with readEdge's scaled e in
// numerator and denominator (edgeOfSafeSize's power of two cancels; a tiny edge's own square would
// underflow).
template <class T> T footWeight(const ExpandPolygon<T>& P, int k)
{
    const Vec2<T> v1 = P.v[k].w;
    const Vec2<T> e12 = P.v[P.next(k)].w - v1;
    const Vec2<T> e = edgeOfSafeSize(e12);
    const T ee = dot(e, e12);
    return ee > T(0) ? dot(-v1, e) / ee : T(0);
}

// The edge the answer is read from: the closest edge k, or, when the origin's foot on k's line
// falls off the edge, the neighbour on that side if the foot on its line falls on it. Two nearly
// collinear edges have nearly equal line distances, so rounding may make either the closest while
// the foot lies on only one of them, up to the length of the other away (search: a touching
// edge's mutation, depth 5.3e-12, with the foot 5e-12 beyond the chosen edge's end, which read the
// shared vertex as the pair: |pA - pB| = 7.3e-12). The depth changes by the two lines' difference
// only; the pair then lies on its edge, |pA - pB| = depth.
template <class T> int answerEdge(const ExpandPolygon<T>& P, int k)
{
    const T t = footWeight(P, k);
    const int j = t < T(0) ? (k == 0 ? P.count - 1 : k - 1) : t > T(1) ? P.next(k) : k;
    if (j == k)
        return k;
    const T tj = footWeight(P, j);
    return tj >= T(0) && tj <= T(1) ? j : k;
}

// The penetration answer in the compute frame from the closest edge k: depth, unit outward normal,
// and the core points from the barycentric weights of the origin's projection on the edge.
// `weights` receives the edge as a two-vertex simplex with those weights (the certified interval's
// point of Z).
template <class T> Answer<T> readEdge(const ExpandPolygon<T>& P, int k, Simplex<T>& weights)
{
    const SimplexVertex<T>& v1 = P.v[k];
    const SimplexVertex<T>& v2 = P.v[P.next(k)];
    const Vec2<T> e = edgeOfSafeSize(v2.w - v1.w); // the edge times a power of two
    const T len = length(e);
    const T t = std::clamp(footWeight(P, k), T(0), T(1));
    Answer<T> a;
    if (!(len > T(0))) // every edge of length 0 (the polygon collapsed to a point): depth 0
    {
        a.pointA = v1.wA;
        a.pointB = v1.wB;
        a.normal = {T(1), T(0)};
        weights.count = 1;
        weights.v[0] = v1;
        weights.v[0].a = T(1);
        return a;
    }
    a.distance = std::max(cross(v1.w, e) / len, T(0));
    a.normal = (T(1) / len) * rightPerp(e);
    a.pointA = (T(1) - t) * v1.wA + t * v2.wA;
    a.pointB = (T(1) - t) * v1.wB + t * v2.wB;
    weights.count = 2;
    weights.v[0] = v1;
    weights.v[1] = v2;
    weights.v[0].a = T(1) - t;
    weights.v[1].a = t;
    return a;
}

// --- The certified interval of a signed answer
// ----------------------------------------------------

namespace certify
{
// Lower end of the core signed distance: -h_Z(n) / |n| rounded down, h_Z(n) = max n.A - min n.B
// over the exact world points (supportUpper); valid for every direction n != 0. -inf for n = 0.
template <class T> double signedLowerCore(const DistanceInput<T>& in, Vec2<T> normal)
{
    if (normal.x == T(0) && normal.y == T(0))
        return -std::numeric_limits<double>::infinity();
    const Bounded nx = exactly(double(normal.x)), ny = exactly(double(normal.y));
    const Bounded mnx = exactly(-double(normal.x)), mny = exactly(-double(normal.y));
    const double hA = supportUpper(in.transformA, in.proxyA.points, in.proxyA.count, nx, ny);
    const double hBneg = supportUpper(in.transformB, in.proxyB.points, in.proxyB.count, mnx, mny);
    const double h = up(hA + hBneg);
    const double nnHi = up(std::sqrt(up(up(nx.v * nx.v) + up(ny.v * ny.v))));
    const double nnLo = down(std::sqrt(down(down(nx.v * nx.v) + down(ny.v * ny.v))));
    if (h > 0)
        return nnLo > 0 ? down(-h / nnLo) : -std::numeric_limits<double>::infinity();
    return down(-h / nnHi);
}

// Lower end of the depth from the polygon's index pairs: the least distance from the origin to
// the lines of its edges, with every vertex W = xfA a - xfB b recomputed with error bounds, when
// every orientation cross(W_k, W_k+1) is certainly positive; else -1 (not certified).
template <class T>
double depthLowerFromPolygon(const DistanceInput<T>& in, const ExpandPolygon<T>& P)
{
    auto world = [&](int k)
    {
        const BoundedVec a = toWorld(in.transformA, in.proxyA.points[P.v[k].indexA]);
        const BoundedVec b = toWorld(in.transformB, in.proxyB.points[P.v[k].indexB]);
        return BoundedVec{a.x - b.x, a.y - b.y};
    };
    double least = std::numeric_limits<double>::infinity();
    const BoundedVec W0 = world(0);
    BoundedVec Wk = W0;
    for (int k = 0; k < P.count; ++k)
    {
        const BoundedVec Wn = k + 1 < P.count ? world(k + 1) : W0;
        const double c = lo(Wk.x * Wn.y - Wk.y * Wn.x);
        if (!(c > 0))
            return -1;
        const BoundedVec e = {Wn.x - Wk.x, Wn.y - Wk.y};
        const double len = upperNorm(e, exactly(1.0)); // |e| rounded up
        least = std::min(least, down(c / len));
        Wk = Wn;
    }
    return least;
}
} // namespace certify

// The interval of the signed distance from the core signed distance's [lowerCore, upperCore]:
// minus the radii, rounded outwards. certified only when both ends are numbers and ordered.
inline void setSignedInterval(double lowerCore, double upperCore, double rA, double rB,
                              bool& certified, double& lower, double& upper)
{
    using namespace certify;
    const double rSum = rA + rB;
    const double rLow = rB == 0 ? rA : down(rSum), rHigh = rB == 0 ? rA : up(rSum);
    lower = rHigh == 0 ? lowerCore : down(lowerCore - rHigh);
    upper = rLow == 0 ? upperCore : up(upperCore - rLow);
    certified = lower >= -std::numeric_limits<double>::max() &&
                upper <= std::numeric_limits<double>::max() && lower <= upper;
    if (!certified)
    {
        lower = -std::numeric_limits<double>::infinity();
        upper = std::numeric_limits<double>::infinity();
    }
}

// --- The signed answer
// ----------------------------------------------------------------------------

// Replaces `out` (the unsigned answer of a query that found overlap or rounded overlap) with the
// signed one. A and B: the query's shapes in its compute frame; `world` and `scale` its map to
// world (toWorldFrame). Returns whether the expansion left the safe range (a support point beyond
// Tolerances<T>::maxCoordinate, a support scan's overflow, or a non-finite answer).
template <class T, bool Scaled, class Shape>
[[gnu::noinline]] bool signedAnswer(const DistanceInput<T>& input, const Options& options, Shape& A,
                                    Shape& B, const Transform<T>& world, int scale, StopReason stop,
                                    const Simplex<T>& simplex, int edgeBase, DistanceOutput<T>& out)
{
    const T rA = options.useRadii ? input.proxyA.radius : T(0);
    const T rB = options.useRadii ? input.proxyB.radius : T(0);
    Answer<T> core = readSimplex(simplex, edgeBase);
    // GJK's own verdict of overlap; or a distance within rounding of 0 (Tolerances<T>::
    // expandNearZero times the final simplex's size), where the last side test of an edge through
    // the origin may have been rounded the wrong way: the expansion then decides (gjk-validate
    // search: nested shapes, GJK distance 7.4e-17 for a depth of 3.9).
    const bool gjkOverlap = stop == StopReason::Containment || stop == StopReason::ZeroDirection ||
                            !(core.distance > T(0));
    T size = T(0);
    for (int i = 0; i < simplex.count; ++i)
        size = std::max({size, std::abs(simplex.v[i].w.x), std::abs(simplex.v[i].w.y)});
    const bool nearZero = !gjkOverlap && core.distance <= Tolerances<T>::expandNearZero * size;

    ExpandPolygon<T> P(gjkOverlap || nearZero
                           ? expandIterationLimit(input.proxyA.count, input.proxyB.count) + 4
                           : 0);
    ExpandEnd end;
    Answer<T> a;
    Simplex<T> foot; // the point of Z the upper end falls back to
    T maxAbs = T(0);
    bool expanded = false;
    if (gjkOverlap || nearZero)
    {
        Vec2<T> flatNormal{};
        if (seedPolygon<T>(A, B, simplex, P, end, flatNormal))
        {
            expandPolygon<T>(A, B, P, expandIterationLimit(input.proxyA.count, input.proxyB.count),
                             end);
            end.edge = answerEdge(P, end.edge);
            a = readEdge(P, end.edge, foot);
            if (!(a.distance > T(0)) && end.stop != ExpandStop::IterationLimit)
                end.stop = ExpandStop::Touching;
            for (int k = 0; k < P.count; ++k)
                maxAbs = std::max({maxAbs, std::abs(P.v[k].w.x), std::abs(P.v[k].w.y)});
        }
        else
        {
            // Z has no interior: depth 0, the penetration pair GJK's own common point.
            end.stop = ExpandStop::Touching;
            end.degenerate = true;
            foot = simplex;
            computeWitnessPoints(simplex, a.pointA, a.pointB);
            a.distance = T(0);
            a.normal = (T(1) / length(flatNormal)) * flatNormal;
        }
        // Near zero, the expansion's verdict: the origin strictly inside its polygon.
        expanded = gjkOverlap || a.distance > T(0);
    }
    if (!expanded)
    {
        // Cores apart: the answer stands unless the radii overlap (distance 0 after the radii).
        if (!(out.distance == T(0)))
            return false;
        toWorldFrame<T, Scaled>(core, world, scale);
        const T d = core.distance - (rA + rB);
        if (!(d < T(0)))
            return false; // exactly touching: the unsigned answer stands
        const Vec2<T> zero{};
        out.distance = d;
        out.normal = core.normal + zero;
        out.pointA = core.pointA + rA * core.normal + zero;
        out.pointB = core.pointB - rB * core.normal + zero;
        out.expand = ExpandStop::None;
        const double upperCore = certify::upperHullBound(input, simplex);
        setSignedInterval(certify::signedLowerCore(input, out.normal), upperCore, double(rA),
                          double(rB), out.certified, out.lower, out.upper);
        return !(std::isfinite(out.distance) && std::isfinite(out.pointA.x) &&
                 std::isfinite(out.pointA.y) && std::isfinite(out.pointB.x) &&
                 std::isfinite(out.pointB.y));
    }
    toWorldFrame<T, Scaled>(a, world, scale);
    const Vec2<T> zero{};
    out.expand = end.stop;
    out.iterations += end.supports;
    if (a.distance > T(0) || rA + rB > T(0))
    {
        out.distance = -(a.distance + (rA + rB));
        out.normal = a.normal + zero;
        out.pointA = a.pointA + rA * a.normal + zero;
        out.pointB = a.pointB - rB * a.normal + zero;
    }
    // else touching without radii: distance 0 and GJK's common point stand

    const double depthLower = end.degenerate ? -1 : certify::depthLowerFromPolygon(input, P);
    const double upperCore = depthLower >= 0 ? -depthLower : certify::upperHullBound(input, foot);
    setSignedInterval(certify::signedLowerCore(input, a.normal), upperCore, double(rA), double(rB),
                      out.certified, out.lower, out.upper);
    return !(maxAbs <= Tolerances<T>::maxCoordinate) || A.overflowed() || B.overflowed() ||
           !(std::isfinite(out.distance) && std::isfinite(out.pointA.x) &&
             std::isfinite(out.pointA.y) && std::isfinite(out.pointB.x) &&
             std::isfinite(out.pointB.y));
}

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
