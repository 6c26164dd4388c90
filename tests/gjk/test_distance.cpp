// Talk sections 3 and 4: GJK between a point or polygon and a polygon, its termination cases, the
// numerical issues the talk lists, witness points, radii, transforms, warm start, and the
// symmetries every distance must have. Expected values are derived by hand beside each case.
#include "gjk2d/distance.hpp"
#include "random_shapes.hpp" // gjk/bench: the speed targets' random distribution

#include "../within.hpp" // within(x, m): an absolute margin and nothing else
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <utility>
#include <vector>

using namespace gjk;

namespace
{
template <class T> using Points = std::vector<Vec2<T>>;

template <class T> struct Scene
{
    Points<T> a, b;
    T radiusA = 0, radiusB = 0;
    Transform<T> xfA{}, xfB{};

    DistanceInput<T> input() const
    {
        return {{a.data(), int(a.size()), radiusA}, {b.data(), int(b.size()), radiusB}, xfA, xfB};
    }
};

template <class T>
DistanceOutput<T> query(const Scene<T>& s, const Options& o = {}, Trace<T>* tr = nullptr)
{
    SimplexCache cache;
    return distance(s.input(), cache, o, tr);
}

// Largest coordinate magnitude of the scene in world coordinates: the problem's scale R.
template <class T> T scaleOf(const Scene<T>& s)
{
    T r = T(0);
    for (auto p : s.a)
    {
        const Vec2<T> w = transformPoint(s.xfA, p);
        r = std::max({r, std::abs(w.x), std::abs(w.y)});
    }
    for (auto p : s.b)
    {
        const Vec2<T> w = transformPoint(s.xfB, p);
        r = std::max({r, std::abs(w.x), std::abs(w.y)});
    }
    return r;
}

// Distance tolerance for the checks below, relative to the problem's scale R: the distance is
// formed by about ten rounded operations (transform, w = wA - wB, a cross product, a length and a
// division) on quantities of magnitude at most a few R, each with error at most u times such a
// quantity; 64 u R covers them with room to spare, and is still 1e-5 R in float (so it would catch
// a wrong feature or a wrong region: those are off by a fraction of R).
template <class T> T tol(T scale)
{
    return T(64) * Tolerances<T>::unitRoundoff * std::max(scale, T(1e-30));
}

// Counter-clockwise convex hull of a small point set (Andrew's monotone chain), in world
// coordinates: the test's own, independent notion of "the shape".
template <class T> Points<T> hullOf(const Points<T>& pts, const Transform<T>& xf)
{
    Points<T> p;
    for (auto v : pts)
        p.push_back(transformPoint(xf, v));
    std::sort(p.begin(), p.end(),
              [](Vec2<T> a, Vec2<T> b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3)
        return p;
    Points<T> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i)
    {
        while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= T(0))
            --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i-- > 0;)
    {
        while (k >= t && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= T(0))
            --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

// Distance from p to the hull of pts, negative inside (max over edges of the outward offset).
// Enough to check that a witness point lies on its shape.
template <class T> T outsideDistance(const Points<T>& pts, const Transform<T>& xf, Vec2<T> p)
{
    const Points<T> h = hullOf(pts, xf);
    if (h.size() == 1)
        return length(p - h[0]);
    if (h.size() == 2)
    {
        const Vec2<T> e = h[1] - h[0];
        const T t = std::clamp(dot(p - h[0], e) / dot(e, e), T(0), T(1));
        return length(p - (h[0] + t * e));
    }
    T worst = -std::numeric_limits<T>::infinity();
    for (size_t i = 0; i < h.size(); ++i)
    {
        const Vec2<T> e = h[(i + 1) % h.size()] - h[i];
        worst = std::max(worst, -cross(e, p - h[i]) / length(e));
    }
    return worst;
}

// Checks every symmetry of the issue on a scene whose exact distance is `expected`: the query
// itself, swapping A and B, a common translation, an exact 90 degree rotation and a mirror.
template <class T> void checkDistanceAndSymmetries(const Scene<T>& s, T expected)
{
    const T R = scaleOf(s);
    const auto out = query(s);
    CHECK(out.stop != StopReason::IterationLimit);
    CHECK(out.distance == within(expected, tol(R)));
    // Witness points on their shapes (radius-free scenes) and as far apart as the distance.
    if (s.radiusA == T(0) && s.radiusB == T(0))
    {
        CHECK(outsideDistance(s.a, s.xfA, out.pointA) <= tol(R));
        CHECK(outsideDistance(s.b, s.xfB, out.pointB) <= tol(R));
        CHECK(length(out.pointB - out.pointA) == within(out.distance, tol(R)));
    }

    Scene<T> swapped = s;
    std::swap(swapped.a, swapped.b);
    std::swap(swapped.radiusA, swapped.radiusB);
    std::swap(swapped.xfA, swapped.xfB);
    const auto sw = query(swapped);
    CHECK(sw.distance == within(out.distance, tol(R)));
    // Swapped witness points: A's point now lies on the old B and vice versa, and the normal
    // flips (witness points need not be unique, e.g. for parallel edges, so positions are not
    // compared).
    if (s.radiusA == T(0) && s.radiusB == T(0))
    {
        CHECK(outsideDistance(s.b, s.xfB, sw.pointA) <= tol(R));
        CHECK(outsideDistance(s.a, s.xfA, sw.pointB) <= tol(R));
    }
    CHECK(length(sw.normal + out.normal) <= tol(T(1)));

    // A common translation by (32, -16): exact for every coordinate used in these tests.
    Scene<T> moved = s;
    moved.xfA.p = moved.xfA.p + Vec2<T>{32, -16};
    moved.xfB.p = moved.xfB.p + Vec2<T>{32, -16};
    CHECK(query(moved).distance == within(out.distance, tol(R + 32)));

    // An exact rotation by 90 degrees of the whole scene: (c, s) = (0, 1) composed with each
    // transform is exact (it only swaps and negates coordinates).
    Scene<T> turned = s;
    for (auto* xf : {&turned.xfA, &turned.xfB})
    {
        xf->q = {-xf->q.s, xf->q.c};
        xf->p = {-xf->p.y, xf->p.x};
    }
    CHECK(query(turned).distance == within(out.distance, tol(R)));

    // A mirror x -> -x of the whole scene: negate x of the points and of the translations, and the
    // rotation becomes (c, -s).
    Scene<T> mirrored = s;
    for (auto* pts : {&mirrored.a, &mirrored.b})
        for (auto& p : *pts)
            p.x = -p.x;
    for (auto* xf : {&mirrored.xfA, &mirrored.xfB})
    {
        xf->p.x = -xf->p.x;
        xf->q.s = -xf->q.s;
    }
    CHECK(query(mirrored).distance == within(out.distance, tol(R)));
}

// The talk's polygon walk-through, drawn as a pentagon with vertex E first (the arbitrary initial
// simplex is vertex 0). Counter-clockwise: D(-1,1) C(3,1) B(3,5) A(-4,6) E(-4,3).
template <class T> Scene<T> walkThrough()
{
    Scene<T> s;
    s.a = {{-4, 3} /*E*/, {-4, 6} /*A*/, {3, 5} /*B*/, {3, 1} /*C*/, {-1, 1} /*D*/};
    s.b = {{0, 0}}; // Q
    return s;
}
} // namespace

TEMPLATE_TEST_CASE("talk walk-through: E, then CE, then CDE, cull E, terminate on repeat",
                   "[gjk][talk]", float, double)
{
    using T = TestType;
    // Hand derivation (Q = origin):
    //  1. simplex {E}, P = E = (-4,3), d = Q - P = (4,-3). dot(d, .): E -25, A -34, B -3, C 9,
    //     D -7 -> support C.
    //  2. simplex {E, C}: e = C - E = (7,-2), u = dot(C, e) = 19 > 0, v = -dot(E, e) = 34 > 0:
    //  edge.
    //     cross(e, -E) = 7*(-3) - (-2)*4 = -13 < 0 -> d = rightPerp(e) = (-2,-7), and
    //     dot(d, Q - E) = 13 > 0. dot(d, .): E -13, A -34, B -41, C -13, D -5 -> support D.
    //  3. simplex {E, C, D}: Q is closest to edge CD (y = 1, x from -1 to 3) at P = (0,1), so E
    //     does not contribute and is culled. P = (1/4) C + (3/4) D.
    //  4. d = perpendicular of CD towards Q = (0,-4): C and D tie at -4, the lowest index (C) wins:
    //     a repeated support point (case 1). Three support points were computed.
    const auto s = walkThrough<T>();
    Trace<T> trace;
    const auto out = query(s, {}, &trace);
    CHECK(out.stop == StopReason::RepeatedSupport);
    CHECK(out.iterations == 3);
    CHECK(out.distance == T(1));
    CHECK(out.pointA == Vec2<T>{0, 1});
    CHECK(out.pointB == Vec2<T>{0, 0});
    CHECK(out.normal == Vec2<T>{0, -1});
    CHECK(out.simplexCount == 2);

    REQUIRE(trace.steps.size() == 3);
    CHECK(trace.steps[0].simplex.count == 1);
    CHECK(trace.steps[0].simplex.v[0].indexA == 0); // E
    CHECK(trace.steps[0].support.indexA == 3);      // C
    CHECK(trace.steps[1].simplex.count == 2);       // CE
    CHECK(trace.steps[1].direction == Vec2<T>{-2, -7});
    CHECK(trace.steps[1].support.indexA == 4); // D
    CHECK(trace.steps[2].simplex.count == 2);  // CDE with E culled: CD
    CHECK(trace.steps[2].simplex.v[0].indexA == 3);
    CHECK(trace.steps[2].simplex.v[1].indexA == 4);
    CHECK(trace.steps[2].simplex.v[0].a == T(0.25));
    CHECK(trace.steps[2].simplex.v[1].a == T(0.75));
    CHECK(trace.steps[2].closest == Vec2<T>{0, 1});
    CHECK(trace.steps[2].support.indexA == 3); // C again: repeated

    checkDistanceAndSymmetries(s, T(1));
}

TEMPLATE_TEST_CASE("the talk's single-precision example: an exactly perpendicular direction",
                   "[gjk][talk][numerics]", float, double)
{
    using T = TestType;
    // Segment A = (0.021119118, 79.584320), B = (0.020964622, -31.515678), Q = origin.
    Simplex<T> s;
    s.v[0].w = {T(0.021119118), T(79.584320)};
    s.v[1].w = {T(0.020964622), T(-31.515678)};
    s.v[0].indexA = 0;
    s.v[1].indexA = 1;
    s.count = 2;
    solve2(s);
    REQUIRE(s.count == 2);
    const Vec2<T> e = s.v[1].w - s.v[0].w;

    const Vec2<T> d = searchDirection(s, SearchDirection::EdgePerpendicular);
    CHECK(dot(d, e) == T(0));        // exactly, as the talk promises
    CHECK(dot(d, -s.v[0].w) > T(0)); // and towards Q

    // The naive direction Q - P is not perpendicular in single precision: the talk measured
    // dot(d, B - A) = 3.2457051e-006 with its barycentric formulas; ours differ, but not in kind.
    if constexpr (std::is_same_v<T, float>)
    {
        const Vec2<T> naive = searchDirection(s, SearchDirection::ClosestPoint);
        CHECK(dot(naive, e) != T(0));
    }

    // The full query: A is that segment, B the point Q. The exact distance is
    // |cross(A, B)| / |B - A| (height of the triangle (Q, A, B)); in double that formula has
    // relative error a few 1e-16, far below the float tolerance.
    Scene<T> scene;
    scene.a = {s.v[0].w, s.v[1].w};
    scene.b = {{0, 0}};
    const double ax = double(scene.a[0].x), ay = double(scene.a[0].y);
    const double bx = double(scene.a[1].x), by = double(scene.a[1].y);
    const double expected = std::abs(ax * by - ay * bx) / std::hypot(bx - ax, by - ay);
    checkDistanceAndSymmetries(scene, T(expected));
}

TEMPLATE_TEST_CASE("termination cases", "[gjk][termination]", float, double)
{
    using T = TestType;
    Scene<T> s;
    s.b = {{0, 0}}; // the query point Q

    SECTION("case 2, containment: Q inside the polygon")
    {
        // Start (-1,-1), d = (1,1) -> (0,1); the edge's perpendicular towards Q -> (1,-1); the
        // triangle has all three barycentric coordinates positive (1/4, 1/4, 1/2 as in the
        // solve3 test).
        s.a = {{-1, -1}, {0, 1}, {1, -1}};
        const auto out = query(s);
        CHECK(out.stop == StopReason::Containment);
        CHECK(out.distance == T(0));
        CHECK(out.simplexCount == 3);
        CHECK(out.normal == Vec2<T>{0, 0});
    }
    SECTION("case 3a, vertex overlap: the initial vertex is Q, d = 0")
    {
        s.a = {{0, 0}, {1, 0}, {0, 1}};
        const auto out = query(s);
        CHECK(out.stop == StopReason::ZeroDirection);
        CHECK(out.iterations == 0);
        CHECK(out.distance == T(0));
    }
    SECTION("case 3b, edge overlap, d pointing away from the polygon: repeated vertex")
    {
        // Q on edge (-1,0)-(1,0) of the square above it. Start (-1,0); d = (1,0) -> (1,0) (ties
        // with (1,2), lowest index). cross(e, -w1) = 0: the sign is arbitrary, we take
        // rightPerp(2,0) = (0,-2), pointing out of the square: the support is (-1,0) or (1,0),
        // already in the simplex.
        s.a = {{-1, 0}, {1, 0}, {1, 2}, {-1, 2}};
        const auto out = query(s);
        CHECK(out.stop == StopReason::RepeatedSupport);
        CHECK(out.distance == T(0));
    }
    SECTION("case 3b, edge overlap, d pointing into the polygon: new vertex, then a repeat")
    {
        // Same edge, square below it. d = (0,-2) finds (1,-2); in triangle (-1,0),(1,0),(1,-2)
        // Q lies on edge w1w2: w123 = n * cross(w1, w2) = 0, so the edge region is kept, the same
        // d finds (1,-2) again: repeated support.
        s.a = {{-1, 0}, {1, 0}, {1, -2}, {-1, -2}};
        const auto out = query(s);
        CHECK((out.stop == StopReason::RepeatedSupport || out.stop == StopReason::Containment));
        CHECK(out.distance == T(0));
    }
    SECTION("case 4, interior edge: Q on a diagonal of the square")
    {
        // Start (-1,-1), d = (1,1) -> (1,1): the simplex is the diagonal through Q, cross = 0,
        // d = rightPerp(2,2) = (2,-2) -> (1,-1). In the triangle Q is on edge w1w2 again: the
        // same d repeats (1,-1).
        s.a = {{-1, -1}, {1, 1}, {1, -1}, {-1, 1}};
        const auto out = query(s);
        CHECK((out.stop == StopReason::RepeatedSupport || out.stop == StopReason::Containment));
        CHECK(out.distance == T(0));
    }
    SECTION("the iteration limit is reported, never silent")
    {
        const auto walk = walkThrough<T>();
        Options o;
        o.maxIterations = 1;
        SimplexCache cache;
        const auto out = distance(walk.input(), cache, o);
        CHECK(out.stop == StopReason::IterationLimit);
        CHECK(out.iterations == 1);
        // The best simplex so far is the edge CE: distance 13/sqrt(53) (|cross(E, C)| / |C - E|
        // = |(-4)(1) - 3*3| / sqrt(49 + 4)), larger than the true 1: the cross product and 53 are
        // exact, so the query rounds the same sqrt and division as the expected value.
        CHECK(out.distance == 13 / std::sqrt(T(53)));
    }
    SECTION("the duality-gap rule stops where repeated support does, with its own name")
    {
        const auto walk = walkThrough<T>();
        Options o;
        o.stopping = StoppingRule::DualityGap;
        const auto out = query(walk, o);
        // At CD the support C is repeated and also gives v.v - v.w = 1 - 1 = 0: both rules hold.
        // The repeat check comes first, so the stop keeps the talk's name.
        CHECK(out.distance == T(1));
        CHECK(out.stop == StopReason::RepeatedSupport);
    }
}

TEMPLATE_TEST_CASE("poorly formed polygons: collinear and non-convex points", "[gjk][talk]", float,
                   double)
{
    using T = TestType;
    SECTION("collinear vertices")
    {
        // (-3,1), (-1,1), (1,1), (3,1) are collinear on y = 1, apex (0,4): distance 1 from Q.
        Scene<T> s;
        s.a = {{-1, 1}, {3, 1}, {-3, 1}, {1, 1}, {0, 4}};
        s.b = {{0, 0}};
        checkDistanceAndSymmetries(s, T(1));
    }
    SECTION("a non-convex input point is never a support point")
    {
        // Square (-2,1) (2,1) (2,3) (-2,3) with a dent B = (0,2) between (-2,1) and (2,1) in the
        // input order: the hull is the square, distance 1 from Q; B can never be extreme.
        Scene<T> s;
        s.a = {{-2, 1}, {0, 2}, {2, 1}, {2, 3}, {-2, 3}};
        s.b = {{0, 0}};
        Trace<T> trace;
        const auto out = query(s, {}, &trace);
        CHECK(out.distance == T(1));
        for (const auto& step : trace.steps)
            CHECK((!step.hasSupport || step.support.indexA != 1));
        checkDistanceAndSymmetries(s, T(1));
    }
    SECTION("duplicates and unordered points")
    {
        Scene<T> s;
        s.a = {{3, 1}, {-1, 1}, {3, 5}, {-1, 1}, {-4, 6}, {3, 1}, {-4, 3}};
        s.b = {{0, 0}};
        checkDistanceAndSymmetries(s, T(1));
    }
}

TEMPLATE_TEST_CASE("polygon to polygon: hand-derived distances and symmetries", "[gjk]", float,
                   double)
{
    using T = TestType;
    const Points<T> unit = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    SECTION("parallel edges: x = 1 against x = 3, distance 2")
    {
        Scene<T> s;
        s.a = unit;
        s.b = {{3, 0}, {4, 1}, {3, 2}};
        checkDistanceAndSymmetries(s, T(2));
    }
    SECTION("vertex to vertex: (1,1) to (2,2), distance sqrt(2)")
    {
        Scene<T> s;
        s.a = unit;
        s.b = {{2, 2}, {3, 2}, {3, 3}, {2, 3}};
        const auto out = query(s);
        CHECK(out.pointA == Vec2<T>{1, 1});
        CHECK(out.pointB == Vec2<T>{2, 2});
        checkDistanceAndSymmetries(s, std::sqrt(T(2)));
    }
    SECTION("edge to vertex on a slanted edge: (3,3) to x + y = 4, distance sqrt(2)")
    {
        // Distance from (3,3) to the line x + y = 4 is (3 + 3 - 4)/sqrt(2); the foot (2,2) lies
        // inside the edge (4,0)-(0,4).
        Scene<T> s;
        s.a = {{0, 0}, {4, 0}, {0, 4}};
        s.b = {{3, 3}, {5, 3}, {4, 5}};
        checkDistanceAndSymmetries(s, std::sqrt(T(2)));
    }
    SECTION("overlapping squares: distance 0")
    {
        Scene<T> s;
        s.a = unit;
        s.b = {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
        CHECK(query(s).distance == T(0));
        checkDistanceAndSymmetries(s, T(0));
    }
    SECTION("segment to segment: (0,0)-(2,0) and (1,1)-(1,3), distance 1 at (1,0)-(1,1)")
    {
        Scene<T> s;
        s.a = {{0, 0}, {2, 0}};
        s.b = {{1, 1}, {1, 3}};
        const auto out = query(s);
        CHECK(out.pointA == Vec2<T>{1, 0});
        CHECK(out.pointB == Vec2<T>{1, 1});
        checkDistanceAndSymmetries(s, T(1));
    }
    SECTION("transforms: B rotated by 90 degrees and moved; A moved")
    {
        // A = unit square at p = (10, 0): [10,11] x [0,1]. B = segment (0,0)-(2,0) rotated by
        // (c, s) = (0, 1) -> (0,0)-(0,2), moved by (13, -0.5): x = 13, y in [-0.5, 1.5].
        // Gap 13 - 11 = 2 along x.
        Scene<T> s;
        s.a = unit;
        s.xfA.p = {10, 0};
        s.b = {{0, 0}, {2, 0}};
        s.xfB = {{13, -0.5}, {0, 1}};
        checkDistanceAndSymmetries(s, T(2));
    }
}

TEMPLATE_TEST_CASE("rounded shapes: radii subtracted at the end", "[gjk][radius]", float, double)
{
    using T = TestType;
    SECTION("two discs apart: centres 5 apart, radii 1 and 2 -> distance 2, points on the circles")
    {
        Scene<T> s;
        s.a = {{0, 0}};
        s.b = {{5, 0}};
        s.radiusA = 1;
        s.radiusB = 2;
        const auto out = query(s);
        CHECK(out.distance == T(2));
        CHECK(out.pointA == Vec2<T>{1, 0});
        CHECK(out.pointB == Vec2<T>{3, 0});
        CHECK(out.normal == Vec2<T>{1, 0});
        checkDistanceAndSymmetries(s, T(2));
    }
    SECTION("capsule and disc: core distance 3, radii 0.5 and 0.5 -> 2")
    {
        Scene<T> s;
        s.a = {{0, 0}, {4, 0}};
        s.b = {{2, 3}};
        s.radiusA = 0.5;
        s.radiusB = 0.5;
        const auto out = query(s);
        CHECK(out.distance == T(2));
        CHECK(out.pointA == Vec2<T>{2, 0.5});
        CHECK(out.pointB == Vec2<T>{2, 2.5});
        checkDistanceAndSymmetries(s, T(2));
    }
    SECTION("overlapping rounded shapes: distance clamped at 0, one common point")
    {
        // Core distance 2 < 1 + 2: overlap; the point rA / (rA + rB) = 1/3 of the way from A's core
        // point to B's, (2/3, 0): within 1 of A and 4/3 <= 2 of B, in both rounded shapes (the
        // midpoint (1, 0) would be in both here too, but not when one radius is small).
        Scene<T> s;
        s.a = {{0, 0}};
        s.b = {{2, 0}};
        s.radiusA = 1;
        s.radiusB = 2;
        const auto out = query(s);
        CHECK(out.distance == T(0));
        CHECK(out.pointA == Vec2<T>{T(2) / T(3), 0});
        CHECK(out.pointB == out.pointA);
    }
    SECTION("overlapping rounded shapes of unequal radii: the common point is in the smaller one")
    {
        // Core distance 0.5 < 0.875 + 0.125: t = 0.875, the point (0.4375, 0), exact: 0.4375
        // from A's core (<= 0.875) and 0.0625 from B's (<= 0.125). The midpoint (0.25, 0) would
        // be 0.25 from B's core, outside B (hard/rounded/17-capsule-disc, docs/error-bound.md).
        Scene<T> s;
        s.a = {{0, 0}};
        s.b = {{0.5, 0}};
        s.radiusA = 0.875;
        s.radiusB = 0.125;
        const auto out = query(s);
        CHECK(out.distance == T(0));
        CHECK(out.pointA == Vec2<T>{0.4375, 0});
        CHECK(out.pointB == out.pointA);
    }
    SECTION("useRadii = false gives the core distance")
    {
        Scene<T> s;
        s.a = {{0, 0}};
        s.b = {{5, 0}};
        s.radiusA = 1;
        Options o;
        o.useRadii = false;
        CHECK(query(s, o).distance == T(5));
    }
}

TEMPLATE_TEST_CASE("conventions: frame, sign of w, direction of the normal", "[gjk][conventions]",
                   float, double)
{
    using T = TestType;
    // A unit square at (4, 4) rotated by 90 degrees, B a point to its right at (7, 4.5).
    // In world, A covers [3,4] x [4,5] ((x,y) -> (-y,x) + (4,4)). Distance 3, pointA = (4, 4.5).
    Scene<T> s;
    s.a = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    s.xfA = {{4, 4}, {0, 1}};
    s.b = {{0, 0}};
    s.xfB.p = {7, 4.5};
    Trace<T> trace;
    const auto out = query(s, {}, &trace);
    CHECK(out.distance == T(3));
    CHECK(out.pointA == Vec2<T>{4, 4.5}); // world coordinates
    CHECK(out.pointB == Vec2<T>{7, 4.5});
    CHECK(out.normal == Vec2<T>{1, 0}); // unit, from A towards B
    // The trace is in A's local frame; its frame maps it back to world.
    CHECK(trace.frame.p == Vec2<T>{4, 4});
    for (const auto& step : trace.steps)
        if (step.hasSupport)
            CHECK(step.support.w == step.support.wA - step.support.wB); // w = wA - wB
    // World frame variant: same answer here (everything is exact).
    Options world;
    world.frame = Frame::World;
    CHECK(query(s, world).distance == T(3));
}

TEMPLATE_TEST_CASE("frame of A keeps small gaps far from the origin", "[gjk][numerics]", float,
                   double)
{
    using T = TestType;
    // Two unit squares under the same rounded rotation (cos 0.3, sin 0.3), B offset by (1.5, 0.25)
    // from A. Moving both by (2^20, 2^20) is exact in float and double (at most 23 significant
    // bits), and in A's frame the relative offset pB - pA is then bit-identical, so the whole
    // computation is: the distance must be exactly the same as at the origin.
    Scene<T> s;
    s.a = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    s.b = s.a;
    const Rot<T> q{std::cos(T(0.3)), std::sin(T(0.3))};
    s.xfA = {{0, 0}, q};
    s.xfB = {{1.5, 0.25}, q};
    Scene<T> far = s;
    const T big = T(1 << 20);
    far.xfA.p = far.xfA.p + Vec2<T>{big, big};
    far.xfB.p = far.xfB.p + Vec2<T>{big, big};
    const auto near = query(s);
    const auto out = query(far);
    CHECK(out.distance == near.distance);
    CHECK(near.distance > T(0));
}

TEMPLATE_TEST_CASE("transforms as given: a rotation (c, s) that is not a unit vector",
                   "[gjk][transform]", float, double)
{
    using T = TestType;
    // x' = c x - s y + p scales by |q| = sqrt(c^2 + s^2). By hand: the square [-1, 1]^2 under
    // q = (2, 0) covers [-2, 2]^2, under q = (0, 2) too (a quarter turn), under (0.5, 0)
    // [-0.5, 0.5]^2; B, a point at (5, 0.25) with radius 0.5, is then at distance 5 - h - 0.5
    // (h = 2 or 0.5), pointA = (h, 0.25), normal (1, 0). Every number is exact, so both frames
    // must give these bits (before transforms were taken as given, A's frame inverted qA by
    // transposing it: B landed at x = 10 in A's frame for q = (2, 0), and the query answered 8.5).
    Scene<T> s;
    s.a = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    s.b = {{0, 0}};
    s.radiusB = T(0.5);
    s.xfB.p = {5, 0.25};
    for (const Rot<T> q : {Rot<T>{2, 0}, Rot<T>{0, 2}, Rot<T>{T(0.5), 0}})
        for (const Frame frame : {Frame::LocalA, Frame::World})
        {
            const T half = q.c + q.s; // the world half-width of A
            INFO("q = (" << q.c << ", " << q.s << "), frame " << int(frame));
            s.xfA = {{0, 0}, q};
            Options o;
            o.frame = frame;
            o.certify = true;
            const auto out = query(s, o);
            CHECK(out.distance == T(5) - half - T(0.5));
            CHECK(out.pointA == Vec2<T>{half, 0.25});
            CHECK(out.pointB == Vec2<T>{4.5, 0.25});
            CHECK(out.normal == Vec2<T>{1, 0});
            CHECK(out.certified);
            CHECK(out.lower <= double(T(5) - half - T(0.5)));
            CHECK(out.upper >= double(T(5) - half - T(0.5)));
        }

    // B's rotation of any size too: B = the segment (-1, 0)-(1, 0) under qB = (0, 3) is the
    // vertical segment x = 6, y in [-3, 3] after p = (6, 0); A the unit square [-1, 1]^2,
    // unrotated: distance 5, the normal (1, 0).
    Scene<T> t;
    t.a = s.a;
    t.b = {{-1, 0}, {1, 0}};
    t.xfB = {{6, 0}, {0, 3}};
    CHECK(query(t).distance == T(5));
    CHECK(query(t).normal == Vec2<T>{1, 0});
}

TEMPLATE_TEST_CASE("transforms as given: a float engine's rotation near unit size",
                   "[gjk][transform]", float, double)
{
    using T = TestType;
    // qA = (1 + 2^-20, 0): |qA| is not 1 in float or double. The square [-1, 1]^2 then has the
    // world half-width 1 + 2^-20 exactly, and the point (4, 0) is at distance 3 - 2^-20, exact in
    // both types (by hand). Transposing qA instead of inverting it (as an earlier version did) put
    // B at 4 (1 + 2^-20)^2 in A's frame: an error of about 4.8e-6 in both types. The bound of
    // docs/error-bound.md for this case is u (4 A + 43 B + 10.2 D + 1.5 B~ + 5 W + 6.5 d) with A
    // ~ 1.41, B = 0, D = 4, B~ ~ 4, W ~ 5.4, d ~ 3: about 100 u.
    const T k = T(1) + std::ldexp(T(1), -20);
    Scene<T> s;
    s.a = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    s.b = {{0, 0}};
    s.xfA = {{0, 0}, {k, 0}};
    s.xfB.p = {4, 0};
    const T expected = T(3) - std::ldexp(T(1), -20);
    const T u = std::numeric_limits<T>::epsilon() / 2;
    for (const Frame frame : {Frame::LocalA, Frame::World})
    {
        Options o;
        o.frame = frame;
        const auto out = query(s, o);
        CHECK(std::abs(out.distance - expected) <= 100 * u);
        CHECK(std::abs(out.pointA.x - k) <= 100 * u);
        CHECK(std::abs(out.normal.x - T(1)) <= 4 * u);
    }
}

TEMPLATE_TEST_CASE(
    "transforms as given: rotations of extreme size are normalised by the rescaled retry",
    "[gjk][transform][range]", float, double)
{
    using T = TestType;
    // qA = (2^e, 0) with 2^(2e) beyond T's range: |qA|^2 overflows, so the first pass is out of
    // range and the rescaled retry normalises qA to (1, 0) and scales A's points by 2^e instead
    // (exact). A = the triangle (0,0) (1,0) (0,1) then covers up to x = 2^e, B a point at 3 * 2^e:
    // distance 2 * 2^e, by hand, bit for bit.
    for (const int e : {std::numeric_limits<T>::max_exponent / 2 + 4,
                        std::numeric_limits<T>::min_exponent / 2 - 4})
    {
        INFO("qA = (2^" << e << ", 0)");
        const T scale = std::ldexp(T(1), e);
        Scene<T> s;
        s.a = {{0, 0}, {1, 0}, {0, 1}};
        s.b = {{0, 0}};
        s.xfA = {{0, 0}, {scale, 0}};
        s.xfB.p = {3 * scale, 0};
        const auto out = query(s);
        CHECK(out.rescaled);
        CHECK_FALSE(out.outOfRange);
        CHECK(out.distance == 2 * scale);
        CHECK(out.pointA == Vec2<T>{scale, 0});
        CHECK(out.normal == Vec2<T>{1, 0});
    }
}

TEMPLATE_TEST_CASE("warm start: the cache from one query seeds the next", "[gjk][cache]", float,
                   double)
{
    using T = TestType;
    const auto s = walkThrough<T>();
    SimplexCache cache; // cold
    const auto cold = distance(s.input(), cache);
    REQUIRE(cache.count == 2);
    CHECK(cache.indexA[0] == 3); // C
    CHECK(cache.indexA[1] == 4); // D
    const auto warm = distance(s.input(), cache);
    CHECK(warm.distance == cold.distance);
    CHECK(warm.pointA == cold.pointA);
    CHECK(warm.iterations == 1); // only the repeated support point is computed
    // A stale cache (indices out of range) falls back to a cold start.
    SimplexCache stale;
    stale.count = 2;
    stale.indexA[0] = 99;
    CHECK(distance(s.input(), stale).distance == cold.distance);
}

TEMPLATE_TEST_CASE(
    "warm start: a repeated query over random pairs gives the cold answer, bit for bit",
    "[gjk][cache]", float, double)
{
    using T = TestType;
    // The speed targets' `random` distribution (gjk/bench/random_shapes.hpp). The cache stores a
    // final edge in canonical order, the origin on the left of w1 -> w2 in Z = A - B, and
    // SimplexCache::edgeBase lets the warm query measure the distance from the cold query's vertex
    // (distance.hpp). The order is checked in world coordinates in long double, independently of
    // the library's frame, where that orientation is far from zero (|cross| > 1e-3; the
    // shapes are of size ~1, so rounding of the frames cannot change its sign).
    std::mt19937_64 rng(7);
    auto shape = [&](Points<T>& pts, Transform<T>& xf)
    {
        auto s = bench::converted<T>(bench::randomShape(rng));
        pts = std::move(s.points);
        xf = s.xf;
    };
    int edges = 0, oriented = 0;
    for (int k = 0; k < 500; ++k)
    {
        Scene<T> s;
        shape(s.a, s.xfA);
        shape(s.b, s.xfB);
        SimplexCache cache;
        const auto cold = distance(s.input(), cache);
        if (cache.count == 2)
        {
            using L = long double;
            auto w = [&](int i)
            {
                const Vec2<T> pa = s.a[cache.indexA[i]], pb = s.b[cache.indexB[i]];
                const L ax = L(s.xfA.q.c) * pa.x - L(s.xfA.q.s) * pa.y + s.xfA.p.x;
                const L ay = L(s.xfA.q.s) * pa.x + L(s.xfA.q.c) * pa.y + s.xfA.p.y;
                const L bx = L(s.xfB.q.c) * pb.x - L(s.xfB.q.s) * pb.y + s.xfB.p.x;
                const L by = L(s.xfB.q.s) * pb.x + L(s.xfB.q.c) * pb.y + s.xfB.p.y;
                return std::pair<L, L>{ax - bx, ay - by};
            };
            const auto [x1, y1] = w(0);
            const auto [x2, y2] = w(1);
            const L c = (x2 - x1) * -y1 - (y2 - y1) * -x1; // cross(w2 - w1, 0 - w1)
            if (std::abs(c) > L(1e-3))
            {
                ++edges;
                oriented += c > 0;
            }
        }
        const auto warm = distance(s.input(), cache);
        CHECK(warm.distance == cold.distance);
        CHECK(warm.pointA == cold.pointA);
        CHECK(warm.pointB == cold.pointB);
        CHECK(warm.normal == cold.normal);
        CHECK(warm.iterations <= 1);
    }
    CHECK(edges > 100);
    CHECK(oriented == edges);
}

TEST_CASE("warm start: a repeat after a culled support point gives the cold answer, bit for bit",
          "[gjk][cache]")
{
    // Regression (found by the fuzzer): B has a vertex at 3.6e18, so the
    // triangle of the last iteration is nearly degenerate and rounding makes solve3 cull the vertex
    // that the next support search finds again: the cold query stops (repeated support) on an edge
    // that does not contain it and answers 0 for an exact distance of 0.6013 (the error bound
    // excuses it: ~1.5e4). A warm start from a cache holding only that edge searched on and found
    // 0.60127678468122: not the cold query's bits, as docs/gjk.md promised. The cache now keeps the
    // simplex before that last solve, which the warm start solves exactly as the cold query did.
    using T = double;
    Scene<T> s;
    s.a = {{0.0099668502807617188, -0.7109375}};
    s.xfA = {{-4.7393143177032471e-05, -1.862645149230957e-07},
             {0.54540534970280896, 0.83817241932406528}};
    s.b = {{-0.7109375, 6.7949295043945312e-06},
           {-5.5511151231257827e-15, -3.5809246537129656e+18},
           {0, -1.0103029524088925e-14},
           {1.6200374375330284e-12, 1.4551471139157002e-11},
           {1.9775847626135601e-16, -8.6736173798840355e-19}};
    SimplexCache cache;
    const auto cold = distance(s.input(), cache);
    REQUIRE(cold.stop == StopReason::RepeatedSupport);
    CHECK(cache.count == 3); // the culled repeat: the triangle before the last solve
    for (int repeat = 0; repeat < 2; ++repeat)
    {
        const auto warm = distance(s.input(), cache);
        CHECK(warm.distance == cold.distance);
        CHECK(warm.pointA == cold.pointA);
        CHECK(warm.pointB == cold.pointB);
        CHECK(warm.normal == cold.normal);
        CHECK(warm.stop == cold.stop);
    }
}

TEMPLATE_TEST_CASE("warm start: the promise holds for every option, on long and degenerate edges",
                   "[gjk][cache]", float, double)
{
    using T = TestType;
    // docs/gjk.md, "The promise, stated exactly": a warm query from the cache a query left behind
    // repeats that query bit for bit, unless it hit the iteration limit or was rescaled. Random
    // pairs (gjk/bench/random_shapes.hpp) under all 32 combinations of direction, stopping rule,
    // frame, support strategy and certification; every third pair has a vertex of A pushed out by
    // up to 2^59 and every fifth a vertex of B at 3.6e15, which make long edges far from the
    // origin. Before the hardening against hostile inputs this failed 14,544 of 640,000 float and
    // 976 double queries (20,000 pairs): the edge's sign test from its far end is a cancellation,
    // and a warm start from the reversed edge took the other side; and an origin exactly on the
    // edge's line made both orders search opposite ways.
    std::mt19937_64 rng(11);
    auto sameBits = [](T a, T b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    int compared = 0, differing = 0;
    for (int k = 0; k < 3000; ++k)
    {
        auto a = bench::converted<T>(bench::randomShape(rng));
        auto b = bench::converted<T>(bench::randomShape(rng));
        if (k % 3 == 1)
            a.points[0] = T(std::ldexp(1.0, int(rng() % 60))) * a.points[0];
        if (k % 5 == 2)
            b.points.push_back(Vec2<T>{T(1e-7), T(3.6e15)});
        const DistanceInput<T> in{{a.points.data(), int(a.points.size()), T(0)},
                                  {b.points.data(), int(b.points.size()), T(0)},
                                  a.xf,
                                  b.xf};
        for (int o = 0; o < 32; ++o)
        {
            Options op;
            op.direction =
                o & 1 ? SearchDirection::ClosestPoint : SearchDirection::EdgePerpendicular;
            op.stopping = o & 2 ? StoppingRule::DualityGap : StoppingRule::RepeatedSupport;
            op.frame = o & 4 ? Frame::World : Frame::LocalA;
            op.support = o & 8 ? SupportStrategy::BinarySearch : SupportStrategy::Linear;
            op.certify = (o & 16) != 0;
            SimplexCache cache;
            const auto cold = distance(in, cache, op);
            if (cold.stop == StopReason::IterationLimit || cold.rescaled)
                continue;
            const auto warm = distance(in, cache, op);
            ++compared;
            differing += !(
                sameBits(cold.distance, warm.distance) && sameBits(cold.pointA.x, warm.pointA.x) &&
                sameBits(cold.pointA.y, warm.pointA.y) && sameBits(cold.pointB.x, warm.pointB.x) &&
                sameBits(cold.pointB.y, warm.pointB.y) && sameBits(cold.normal.x, warm.normal.x) &&
                sameBits(cold.normal.y, warm.normal.y));
        }
    }
    CHECK(compared > 90000);
    CHECK(differing == 0);
}

TEMPLATE_TEST_CASE("the reference options run a constant copy of the query with the same bits",
                   "[gjk][cache]", float, double)
{
    using T = TestType;
    // distance() with referenceOptions and no trace runs a copy of the query in which every option
    // is a constant (docs/speed.md, "The cold query on engine data"); with a trace it runs the
    // general copy. Both must give the same bits, cold and warm, and the same cache. Random pairs
    // with radii, their rotations rounded to float (in double never unit to 2u: the division
    // path of a float engine's transforms) on every other pair, long edges on every third.
    std::mt19937_64 rng(7);
    auto sameBits = [](T a, T b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    auto same = [&](const DistanceOutput<T>& x, const DistanceOutput<T>& y)
    {
        return sameBits(x.distance, y.distance) && sameBits(x.pointA.x, y.pointA.x) &&
               sameBits(x.pointA.y, y.pointA.y) && sameBits(x.pointB.x, y.pointB.x) &&
               sameBits(x.pointB.y, y.pointB.y) && sameBits(x.normal.x, y.normal.x) &&
               sameBits(x.normal.y, y.normal.y) && x.iterations == y.iterations &&
               x.stop == y.stop && x.outOfRange == y.outOfRange && x.rescaled == y.rescaled;
    };
    auto sameCache = [](const SimplexCache& x, const SimplexCache& y)
    {
        bool same = x.count == y.count && x.edgeBase == y.edgeBase && x.searchA == y.searchA &&
                    x.searchB == y.searchB;
        for (int i = 0; same && i < x.count; ++i)
            same = x.indexA[i] == y.indexA[i] && x.indexB[i] == y.indexB[i];
        return same;
    };
    int differing = 0, nonUnit = 0;
    for (int k = 0; k < 4000; ++k)
    {
        auto a = bench::converted<T>(bench::randomShape(rng));
        auto b = bench::converted<T>(bench::randomShape(rng));
        if (k % 3 == 1)
            a.points[0] = T(std::ldexp(1.0, int(rng() % 40))) * a.points[0];
        if (k % 2 == 0)
        { // Rounded through a volatile float: GCC 12 at -O2/-O3 without -ffp-contract=off (the flag
          // matrix's gcc-O3) dropped the plain T(float(x)) here, and nonUnit was 0 (docs/gjk.md,
          // "Compiler flags": the SLP vectorizer and the headers' optimize pragma).
            auto rounded = [](T x)
            {
                volatile float f = float(x);
                return T(f);
            };
            a.xf.q = {rounded(a.xf.q.c), rounded(a.xf.q.s)};
            b.xf.q = {rounded(b.xf.q.c), rounded(b.xf.q.s)};
        }
        nonUnit += !isUnitRotation(squaredSize(a.xf.q));
        const T rA = k % 4 == 0 ? T(0.25) : T(0), rB = k % 5 == 0 ? T(0.5) : T(0);
        const DistanceInput<T> in{{a.points.data(), int(a.points.size()), rA},
                                  {b.points.data(), int(b.points.size()), rB},
                                  a.xf,
                                  b.xf};
        SimplexCache fastCache, generalCache;
        Trace<T> trace;
        const Options copy = referenceOptions; // another object, equal to it
        const auto fast = distance(in, fastCache, copy);
        const auto general = distance(in, generalCache, referenceOptions, &trace);
        const auto fastWarm = distance(in, fastCache, copy);
        const auto generalWarm = distance(in, generalCache, referenceOptions, &trace);
        differing += !(same(fast, general) && same(fastWarm, generalWarm) &&
                       sameCache(fastCache, generalCache));
    }
    if constexpr (std::is_same_v<T, double>)
        CHECK(nonUnit > 1500); // the float rotations: about half of the 4,000 pairs
    CHECK(differing == 0);
}

TEMPLATE_TEST_CASE("isZero: exactly the zero vectors, either sign", "[gjk][numerics]", float,
                   double)
{
    using T = TestType;
    using L = std::numeric_limits<T>;
    CHECK(isZero(Vec2<T>{T(0), T(0)}));
    CHECK(isZero(Vec2<T>{-T(0), T(0)}));
    CHECK(isZero(Vec2<T>{T(0), -T(0)}));
    CHECK(isZero(Vec2<T>{-T(0), -T(0)}));
    CHECK_FALSE(isZero(Vec2<T>{L::denorm_min(), T(0)}));
    CHECK_FALSE(isZero(Vec2<T>{-T(0), -L::denorm_min()}));
    CHECK_FALSE(isZero(Vec2<T>{L::quiet_NaN(), T(0)}));
    CHECK_FALSE(isZero(Vec2<T>{T(0), L::infinity()}));
    CHECK_FALSE(isZero(Vec2<T>{T(1), T(0)}));
}

TEMPLATE_TEST_CASE("outputs carry no negative zero, cold or warm", "[gjk][cache]", float, double)
{
    using T = TestType;
    // Regression (found by the fuzzer): an axis-aligned final edge has a zero normal component
    // whose sign came from the order of the edge's vertices (x - x is +0, -(x - x) is -0), and a
    // warm start from the canonical (reversed) cache gave the other sign. A segment of A on an axis
    // against a point of B across it, in the four axis directions; by hand the normal is +-(1, 0)
    // or +-(0, 1), the witness on A has one zero coordinate.
    const Vec2<T> axes[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (const auto& u : axes)
    {
        const Vec2<T> v = leftPerp(u);
        Scene<T> s;
        s.a = {T(-1) * v, v};
        s.b = {T(2) * u};
        SimplexCache cache;
        const auto cold = distance(s.input(), cache);
        const auto warm = distance(s.input(), cache);
        for (const auto& out : {cold, warm})
        {
            REQUIRE(out.distance == T(2));
            for (T c : {out.normal.x, out.normal.y, out.pointA.x, out.pointA.y, out.pointB.x,
                        out.pointB.y})
                CHECK_FALSE((c == T(0) && std::signbit(c)));
        }
    }
}

TEST_CASE("warm start: the binary-search support starts where the last search started",
          "[gjk][cache][support]")
{
    // Regression (fuzz/corpus/fuzz_distance/finding-warm-cold-float-2, found by
    // fuzz_distance): the galloping search of SupportStrategy::BinarySearch returns, among nearly
    // tied vertices, one that depends on its start. A warm start began at the cached simplex's
    // first vertex, the cold query's last search at its previous support point: the warm repeat
    // found another vertex (B's 0 instead of 2), went on, and answered 2^-66 for the cold 1.65 *
    // 2^-64. SimplexCache::searchA/searchB now keep where the last searches started.
    using T = float;
    Scene<T> s;
    s.a = {{0x1.6p-62f, 0x1.e4p-9f},   {0x1p-62f, 0x1p-9f},        {0x1p-63f, 0x1p-11f},
           {0x1p-64f, 0x1p-13f},       {0x1.8p-65f, 0x1.2p-14f},   {0x1p-65f, 0x1p-15f},
           {0x1p-66f, 0x1p-17f},       {0x1.fp-61f, 0x1.e08p-6f},  {0x1.ep-61f, 0x1.c2p-6f},
           {0x1.d8p-61f, 0x1.b32p-6f}, {0x1.c8p-61f, 0x1.962p-6f}, {0x1.cp-61f, 0x1.88p-6f},
           {0x1.9p-61f, 0x1.388p-6f},  {0x1.6p-61f, 0x1.e4p-7f},   {0x1.58p-61f, 0x1.ce4p-7f},
           {0x1.5p-61f, 0x1.b9p-7f},   {0x1.38p-61f, 0x1.7c4p-7f}, {0x1.1p-61f, 0x1.21p-7f},
           {0x1.ep-62f, 0x1.c2p-8f}};
    s.xfA = {{0, -0x1p-149f}, {0, -1}};
    s.b = {{0x1.b8p+41f, 0x1.7a2p-103f},
           {0x1.ep+41f, 0x1.c2p-103f},
           {-0x1.4p+40f, 0x1.9p-106f},
           {-0x1.ep+39f, 0x1.c2p-107f},
           {-0x1.4p+39f, 0x1.9p-108f},
           {-0x1.4p+38f, 0x1.9p-110f},
           {0, 0},
           {0x1.4p+38f, 0x1.9p-110f},
           {0x1.4p+39f, 0x1.9p-108f},
           {0x1.ep+39f, 0x1.c2p-107f},
           {0x1.4p+40f, 0x1.9p-106f},
           {0x1.9p+40f, 0x1.388p-105f},
           {0x1.ep+40f, 0x1.c2p-105f},
           {0x1.18p+41f, 0x1.324p-104f},
           {0x1.4p+41f, 0x1.9p-104f},
           {0x1.68p+41f, 0x1.fa4p-104f},
           {0x1.9p+41f, 0x1.388p-103f}};
    Options o;
    o.direction = SearchDirection::ClosestPoint;
    o.stopping = StoppingRule::DualityGap;
    o.frame = Frame::World;
    o.support = SupportStrategy::BinarySearch;
    SimplexCache cache;
    const auto cold = distance(s.input(), cache, o);
    REQUIRE_FALSE(cold.rescaled);
    REQUIRE_FALSE(cold.outOfRange);
    const auto warm = distance(s.input(), cache, o);
    CHECK(warm.distance == cold.distance);
    CHECK(warm.pointA == cold.pointA);
    CHECK(warm.pointB == cold.pointB);
    CHECK(warm.normal == cold.normal);
    CHECK(warm.iterations == 1);
}

TEMPLATE_TEST_CASE("many vertices: a 4096-gon approximating a circle", "[gjk][large]", float,
                   double)
{
    using T = TestType;
    // Regular 4096-gon of circumradius 1 at the origin, a point at (3, 0): the closest feature is
    // the vertex (1, 0) (angle 0 is a vertex), so the distance is exactly 2.
    Scene<T> s;
    const int n = 4096;
    for (int i = 0; i < n; ++i)
    {
        const double t = 2 * 3.14159265358979323846 * i / n;
        s.a.push_back({T(std::cos(t)), T(std::sin(t))});
    }
    s.a[0] = {1, 0};
    s.b = {{3, 0}};
    const auto out = query(s);
    CHECK(out.stop != StopReason::IterationLimit);
    CHECK(out.distance == within(T(2), tol(T(3))));
}

TEMPLATE_TEST_CASE("certified interval contains the exact distance", "[gjk][certify]", float,
                   double)
{
    using T = TestType;
    // Scenes with hand-derived exact distances (see the tests above). For sqrt(2) the bracket
    // [down, up] of its double rounding is used: the interval must reach past both ends.
    struct Known
    {
        Scene<T> scene;
        double exactLow, exactHigh;
    };
    const Points<T> unit = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const double r2 = std::sqrt(2.0);
    const double r2lo = std::nextafter(r2, 0.0), r2hi = std::nextafter(r2, 4.0);
    std::vector<Known> cases;
    cases.push_back({walkThrough<T>(), 1, 1});
    {
        Scene<T> s;
        s.a = unit;
        s.b = {{3, 0}, {4, 1}, {3, 2}};
        cases.push_back({s, 2, 2});
    }
    {
        Scene<T> s;
        s.a = unit;
        s.b = {{2, 2}, {3, 2}, {3, 3}, {2, 3}};
        cases.push_back({s, r2lo, r2hi});
    }
    {
        Scene<T> s;
        s.a = {{0, 0}, {4, 0}, {0, 4}};
        s.b = {{3, 3}, {5, 3}, {4, 5}};
        cases.push_back({s, r2lo, r2hi});
    }
    {
        Scene<T> s; // overlap: 0
        s.a = unit;
        s.b = {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}};
        cases.push_back({s, 0, 0});
    }
    {
        Scene<T> s; // capsule and disc: 2
        s.a = {{0, 0}, {4, 0}};
        s.b = {{2, 3}};
        s.radiusA = 0.5;
        s.radiusB = 0.5;
        cases.push_back({s, 2, 2});
    }
    {
        Scene<T> s; // rotated and moved: 2
        s.a = unit;
        s.xfA.p = {10, 0};
        s.b = {{0, 0}, {2, 0}};
        s.xfB = {{13, -0.5}, {0, 1}};
        cases.push_back({s, 2, 2});
    }
    Options o;
    o.certify = true;
    for (const auto& k : cases)
    {
        const auto out = query(k.scene, o);
        REQUIRE(out.certified);
        CHECK(out.lower <= k.exactLow);
        CHECK(out.upper >= k.exactHigh);
        // Tight: a few units of roundoff of the double certificate at scale <= 16.
        CHECK(out.upper - out.lower <= 1e-13);
        // The float or double distance lies in it up to the query's own rounding.
        CHECK(double(out.distance) >= out.lower - double(tol(T(16))));
        CHECK(double(out.distance) <= out.upper + double(tol(T(16))));
    }
    SECTION("containment is certified by exact orientation signs: upper is exactly 0")
    {
        Scene<T> s;
        s.a = {{-1, -1}, {0, 1}, {1, -1}};
        s.b = {{0, 0}};
        const auto out = query(s, o);
        CHECK(out.stop == StopReason::Containment);
        CHECK(out.lower == 0);
        CHECK(out.upper == 0);
    }
}

TEST_CASE("certified interval: an overflow is never certified", "[gjk][certify][range]")
{
    // Regression (an overflow that passed for a certified interval). Points near 1.5e308 rotated by
    // 45 degrees: the world coordinates overflow (c*x - s*y > max double), inf - inf = NaN, and
    // std::max(0, NaN) == 0 made the interval a certified [0, 0] for an exact distance near 1e307:
    // in local coordinates A - B = (0, dy), dy = -1.4e308 - -1.5e308 as doubles (exact, by
    // Sterbenz's lemma), of length dy |q| with |q| = 1 within 2e-16, less A's radius 1 (by hand).
    // The interval must contain that or say it could not certify.
    const double c = 0.7071067811865476;
    Scene<double> s;
    s.a = {{1.5e308, -1.4e308}};
    s.radiusA = 1;
    s.b = {{1.5e308, -1.5e308}};
    s.xfA.q = {c, c};
    s.xfB.q = {c, c};
    Options o;
    o.certify = true;
    const auto out = query(s, o);
    const double dy = s.a[0].y - s.b[0].y;
    const double truthLow = dy * (1 - 1e-15), truthHigh = dy * (1 + 1e-15);
    if (out.certified)
    {
        CHECK(out.lower <= truthLow);
        CHECK(out.upper >= truthHigh);
    }
    else
    {
        CHECK(out.lower == 0);
        CHECK(out.upper == std::numeric_limits<double>::infinity());
    }
    // The distance itself is answered by the rescaled query, within the error bound's order
    // (u R with R = 1.5e308, 15 times the distance: a relative 1e-13 is ample). The world witness
    // point on A, c * 1.5e308 + c * 1.4e308 = 2.05e308, does not fit in a double: flagged.
    CHECK(out.rescaled);
    CHECK(std::isinf(out.pointA.x));
    CHECK(out.outOfRange);
    CHECK(out.distance >= dy * (1 - 1e-13));
    CHECK(out.distance <= dy * (1 + 1e-13));
}

TEMPLATE_TEST_CASE("range: out-of-range queries are rescaled and answered exactly", "[gjk][range]",
                   float, double)
{
    using T = TestType;
    // Triangle (0,0) (1,0) (0,1) against the point (3,0): distance 2, witness (1,0) on A, by hand.
    // Scaled by a power of two the exact answer scales exactly, so the rescaled query must give
    // 2 * scale bit for bit.
    Scene<T> s;
    s.a = {{0, 0}, {1, 0}, {0, 1}};
    s.b = {{3, 0}};
    const auto plain = query(s);
    CHECK_FALSE(plain.outOfRange);
    CHECK_FALSE(plain.rescaled);
    REQUIRE(plain.distance == T(2));
    const int big = std::numeric_limits<T>::max_exponent / 2 + 2;  // products would overflow
    const int tiny = std::numeric_limits<T>::min_exponent / 2 - 4; // products would underflow
    const int subnormal = std::numeric_limits<T>::min_exponent - 4;
    for (int e : {big, tiny, subnormal, std::numeric_limits<T>::max_exponent - 3})
    {
        INFO("scale 2^" << e);
        Scene<T> t = s;
        for (auto* pts : {&t.a, &t.b})
            for (auto& p : *pts)
                p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
        const auto out = query(t);
        CHECK(out.rescaled);
        CHECK_FALSE(out.outOfRange);
        CHECK(out.distance == std::ldexp(T(2), e));
        CHECK(out.pointA.x == std::ldexp(T(1), e));
        CHECK(out.pointA.y == T(0));
        CHECK(out.normal.x == T(1));
    }
}

TEMPLATE_TEST_CASE("tiny simplex edges: answered exactly, never flagged or non-finite",
                   "[gjk][range]", float, double)
{
    using T = TestType;
    // The tiny-edge reproducers (validation/cases/tiny-edges.json, from an adversarial search), in
    // T. Each has a vertical edge of A, x = xe, whose y range contains the point B = (x0, y0): the
    // distance is xe - x0 by hand, a subtraction that is exact in T (Sterbenz, or x0 = 0). The
    // edge's squared length is subnormal, or below 1/max. Before tiny edges were scaled up, the
    // inf-weights cases came out flagged outOfRange with NaN witness points (the weights'
    // reciprocal overflowed, and the rescaled retry could not help: the problem's extent is already
    // ~1), and the subnormal-edge cases were answered only by the rescaled retry.
    struct Case
    {
        double x0, y0, ax, xe, ylo, yhi;
    };
    const Case cases[] = {
        // subnormal-edge-float: A = (2^-50, 0) and the edge x = 1.49e-19, y in +-2.9e-23; B = 0
        {0, 0, 8.881784197001252e-16, 1.4907779871675686e-19, -2.9296678432774486e-23,
         2.9296678432774486e-23},
        // subnormal-edge-double
        {0, 0, 4.004166190366202e-146, 2.051043701080057e-154, -1.7484367828556776e-162,
         1.7484367828556776e-162},
        // inf-weights-float: A = (1, 0) and the edge x = 8.88395e-16; B = (2^-50, 2^-50)
        {8.881784197001252e-16, 8.881784197001252e-16, 1.0, 8.883952601346223e-16,
         8.881716434365472e-16, 8.881851959637033e-16},
        // inf-weights-double
        {2.002083095183101e-146, 2.002083095183101e-146, 1.0, 2.002113644546736e-146,
         2.0020830942508083e-146, 2.0020830961153935e-146},
    };
    int checked = 0;
    for (const Case& k : cases)
    {
        const T x0 = T(k.x0), y0 = T(k.y0), xe = T(k.xe), ylo = T(k.ylo), yhi = T(k.yhi);
        if (!(xe > T(0)) || !(ylo < y0 && y0 < yhi) || !(xe > x0))
            continue; // the case does not survive rounding to T (the double ones in float)
        ++checked;
        INFO("xe = " << k.xe << ", x0 = " << k.x0);
        Scene<T> s;
        s.a = {{T(k.ax), T(0)}, {xe, ylo}, {xe, yhi}};
        s.b = {{x0, y0}};
        const auto out = query(s);
        CHECK_FALSE(out.outOfRange);
        CHECK(out.distance == xe - x0);
        CHECK(std::isfinite(out.pointA.x));
        CHECK(std::isfinite(out.pointA.y));
        // On the edge: x = (a1 + a2) xe with weights a1 + a2 = 1 up to two roundings.
        CHECK(std::abs(out.pointA.x - xe) <= 4 * std::numeric_limits<T>::epsilon() * xe);
        CHECK(out.pointA.y >= ylo);
        CHECK(out.pointA.y <= yhi);
        CHECK(out.normal == Vec2<T>{-1, 0});
    }
    // Every case in double; in float the two float cases (the double ones' 1e-146 coordinates
    // round to 0 there).
    CHECK(checked == (std::is_same_v<T, double> ? 4 : 2));
}

TEMPLATE_TEST_CASE("range: support points that underflow to exactly 0 are rescaled", "[gjk][range]",
                   float, double)
{
    using T = TestType;
    // B = the point (m, m), m = T's smallest subnormal, under qB = (0.45, 0): in world
    // (0.45 m, 0.45 m), each coordinate rounds to 0 in T, so every support point of the first
    // pass is exactly 0 (an exact overlap, to the range check). The exact distance to A = the
    // origin is 0.45 sqrt(2) m = 0.64 m, which rounds to m in T (by hand). Before the fix the
    // query answered 0, unflagged (found by `gjk-validate search` on float inputs near 1e-45).
    const T m = std::numeric_limits<T>::denorm_min();
    Scene<T> s;
    s.a = {{0, 0}};
    s.b = {{m, m}};
    s.xfB.q = {T(0.45), T(0)};
    const auto out = query(s);
    CHECK(out.rescaled);
    CHECK_FALSE(out.outOfRange);
    CHECK(out.distance == m);
    // Two shapes that overlap exactly, of normal size: the zero stands, no retry.
    Scene<T> t;
    t.a = {{1, 1}};
    t.b = {{1, 1}};
    const auto zero = query(t);
    CHECK(zero.distance == T(0));
    CHECK_FALSE(zero.rescaled);
    CHECK_FALSE(zero.outOfRange);
}

TEMPLATE_TEST_CASE("range: points spanning more than the exponent range stay flagged",
                   "[gjk][range]", float, double)
{
    using T = TestType;
    // A tiny triangle and a tiny point, 2^(0.8 emin) in size, with a far point of B at 2^(0.8 emax)
    // that is never a support point: the tiny support points leave the safe range (their products
    // underflow), and scaling the far point to 1 would scale the tiny ones below the smallest
    // subnormal. Rescaling cannot help: the query must stay flagged.
    const T tiny = std::ldexp(T(1), std::numeric_limits<T>::min_exponent * 4 / 5);
    const T huge = std::ldexp(T(1), std::numeric_limits<T>::max_exponent * 4 / 5);
    Scene<T> s;
    s.a = {{0, 0}, {tiny, 0}, {0, tiny}};
    s.b = {{3 * tiny, 0}, {huge, 0}};
    CHECK(query(s).outOfRange);
}

TEMPLATE_TEST_CASE("binary-search support agrees with the linear scan on convex polygons",
                   "[gjk][support]", float, double)
{
    using T = TestType;
    // Counter-clockwise regular n-gons (and one with collinear points on its edges), every
    // direction on a fine circle, including the exact edge normals (ties): the binary search must
    // find a vertex as far along d as the talk's linear scan, up to the rounding of the dots.
    for (int n : {17, 64, 1000, 4096})
    {
        std::vector<Vec2<T>> pts;
        for (int i = 0; i < n; ++i)
            pts.push_back({T(std::cos(2 * M_PI * i / n)), T(std::sin(2 * M_PI * i / n))});
        const Polygon<T> poly{pts.data(), n, T(0)};
        for (int k = 0; k < 720; ++k)
        {
            const double a = 2 * M_PI * k / 720;
            const Vec2<T> d{T(std::cos(a)), T(std::sin(a))};
            const int j = findSupport(poly, d);
            for (int start : {0, n / 3, n - 1, j}) // every start vertex of the galloping search
            {
                const int i = findSupportFrom(poly, d, start);
                CHECK(dot(d, pts[i]) >= dot(d, pts[j]) - T(4) * Tolerances<T>::unitRoundoff);
            }
        }
        for (int i = 0; i < n; ++i) // edge normals: two vertices tie
        {
            const Vec2<T> d = rightPerp(pts[(i + 1) % n] - pts[i]);
            const int b = findSupportFrom(poly, d, (i + n / 2) % n), l = findSupport(poly, d);
            CHECK(dot(d, pts[b]) >= dot(d, pts[l]) - T(4) * Tolerances<T>::unitRoundoff);
        }
    }
    // Clockwise order works the same (the search only uses the rise and fall of dot(d, P[i])).
    {
        const int n = 257;
        std::vector<Vec2<T>> cw;
        for (int i = 0; i < n; ++i)
            cw.push_back({T(std::cos(-2 * M_PI * i / n)), T(std::sin(-2 * M_PI * i / n))});
        const Polygon<T> poly{cw.data(), n, T(0)};
        for (int k = 0; k < 360; ++k)
        {
            const Vec2<T> d{T(std::cos(k * M_PI / 180)), T(std::sin(k * M_PI / 180))};
            const int l = findSupport(poly, d);
            for (int start : {0, 100, 200})
                CHECK(dot(d, cw[findSupportFrom(poly, d, start)]) >=
                      dot(d, cw[l]) - T(4) * Tolerances<T>::unitRoundoff);
        }
    }
    // A square with collinear midpoints on every edge: (-1,-1) (0,-1) (1,-1) (1,0) (1,1) ...
    std::vector<Vec2<T>> sq = {{-1, -1}, {0, -1}, {1, -1}, {1, 0},
                               {1, 1},   {0, 1},  {-1, 1}, {-1, 0}};
    const Polygon<T> poly{sq.data(), int(sq.size()), T(0)};
    for (int k = 0; k < 16; ++k)
    {
        const double a = 2 * M_PI * k / 16;
        const Vec2<T> d{T(std::cos(a)), T(std::sin(a))};
        const int l = findSupport(poly, d);
        for (int start = 0; start < 8; ++start)
        {
            const int b = findSupportFrom(poly, d, start);
            CHECK(dot(d, sq[b]) >= dot(d, sq[l]) - T(4) * Tolerances<T>::unitRoundoff);
        }
    }
}

TEMPLATE_TEST_CASE("binary-search support gives the same distances", "[gjk][support]", float,
                   double)
{
    using T = TestType;
    // Two regular 4096-gons of circumradius 1, centres 2.5 apart: vertex 0 of each faces the
    // other exactly (B is rotated by half a turn: (c, s) = (-1, 0)), so the distance is 0.5.
    const int n = 4096;
    Scene<T> s;
    for (int i = 0; i < n; ++i)
        s.a.push_back({T(std::cos(2 * M_PI * i / n)), T(std::sin(2 * M_PI * i / n))});
    s.a[0] = {1, 0};
    s.b = s.a;
    s.xfB = {{T(2.5), T(0)}, {T(-1), T(0)}};
    Options o;
    o.support = SupportStrategy::BinarySearch;
    const auto fast = query(s, o);
    const auto slow = query(s);
    CHECK(fast.distance == within(T(0.5), tol(T(4))));
    CHECK(fast.distance == within(slow.distance, tol(T(4))));
    CHECK(fast.stop != StopReason::IterationLimit);
}

TEMPLATE_TEST_CASE("batch: the same results as single queries", "[gjk][batch]", float, double)
{
    using T = TestType;
    std::vector<Scene<T>> scenes;
    scenes.push_back(walkThrough<T>());
    Scene<T> s;
    s.a = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    s.b = {{3, 0}, {4, 1}, {3, 2}};
    s.xfB = {{T(0.5), T(-1)}, {T(0), T(1)}};
    scenes.push_back(s);
    std::vector<DistanceInput<T>> inputs;
    for (const auto& x : scenes)
        inputs.push_back(x.input());
    std::vector<SimplexCache> caches(inputs.size());
    std::vector<DistanceOutput<T>> outputs(inputs.size());
    distanceBatch<T>(inputs, caches, outputs);
    for (std::size_t i = 0; i < inputs.size(); ++i)
    {
        SimplexCache c;
        const auto single = distance(inputs[i], c);
        CHECK(outputs[i].distance == single.distance);
        CHECK(outputs[i].pointA == single.pointA);
        CHECK(caches[i].count == c.count);
    }
}

TEMPLATE_TEST_CASE("range: overflowing support scans are caught even when the simplex is in range",
                   "[gjk][range]", float, double)
{
    using T = TestType;
    // Regression (hard/range, validation/cases/range-overflow.json): two squares of side
    // 2^(emax/2 + 8) (float 2^72, double 2^520), far above maxCoordinate, a gap of 2^(emax/2 - 4)
    // apart (in range). Vertex 0 of each faces the other, so the first simplex vertex is
    // w = (-gap, 0), in range, and so are all later ones; but the search direction (size gap)
    // times the squares' far corners (size side) is 2^(emax + 4): the scans overflow. Before the
    // scan check the query answered without the flag.
    const int e = std::numeric_limits<T>::max_exponent / 2;
    const T side = std::ldexp(T(1), e + 8);
    const T gap = std::ldexp(T(1), e - 4);
    REQUIRE(gap <= Tolerances<T>::maxCoordinate);
    Scene<T> s;
    s.a = {{0, 0}, {-side, 0}, {-side, -side}, {0, -side}};
    s.b = {{gap, 0}, {gap + side, 0}, {gap + side, -side}, {gap, -side}};
    // Since the rescaled retry the query is rescaled (by 2^-(e + 9) or so) and answered exactly:
    // the gap.
    const auto out = query(s);
    CHECK(out.rescaled);
    CHECK_FALSE(out.outOfRange);
    CHECK(out.distance == gap);
}

TEST_CASE("the duality-gap rule stops early on near-parallel edges (why it is not the reference)",
          "[gjk][termination]")
{
    // Regression input validation/cases/regressions.json, regression/near-parallel-23-gap1e-12-
    // tilt1e-09 (hard/near-parallel, seed 1): two boxes under nearly equal rotations, a gap of
    // 1e-12 (exact distance 9.9999477915425188e-13, from the exact side). Mechanism: with a gap
    // of 1e-12, v.v ~ 1e-24 while the rounding of v.w is about u |v| |w|, so
    // v.v - v.w <= 16 u v.v is met by rounding noise and the loop stops on an interior diagonal:
    // the runner found an error of 8.8e-10. The reference rule (repeated support) reaches the
    // closest edges: error 2e-17. Double only: in float the gap is below the input's rounding.
    using T = double;
    Scene<T> s;
    s.a = {{-1.0, -0.5}, {1.0, -0.5}, {1.0, 0.5}, {-1.0, 0.5}};
    s.xfA = {{-1.5209451705652013, -2.988554806186266}, {-0.5288291162640548, 0.8487283227225181}};
    s.b = {{-0.9, 0.0}, {0.9, 0.0}, {0.9, 0.6}, {-0.9, 0.6}};
    s.xfB = {{-1.965757295528928, -3.22015202424251}, {-0.5288291171127831, 0.848728322193689}};
    const double exact = 9.9999477915425188e-13;
    Options gap;
    gap.stopping = StoppingRule::DualityGap;
    const auto early = query(s, gap);
    const auto reference = query(s);
    CHECK(early.stop == StopReason::DualityGap);
    CHECK(std::abs(early.distance - exact) > 1e-10);
    CHECK(reference.stop == StopReason::RepeatedSupport);
    CHECK(std::abs(reference.distance - exact) < 1e-15);
}

TEMPLATE_TEST_CASE("containment in a nearly flat triangle: the witness point stays on both shapes",
                   "[gjk][witness]", float, double)
{
    using T = TestType;
    // random/719667 (validation/cases/flat-containment.json, from random:1e7): in float the final
    // triangle is nearly flat and Cramer's weight b = -8.2e-5 put the origin outside it; clamping b
    // to 0 left the witness point 1.7e-4 outside B (the runner's witness bound: 1.7e-5). Expected:
    // the point within 64 u W of B (W the largest |a - b| of the world points, about 4.4; the
    // triangle's 18 u W of docs/error-bound.md, the region signs' 4 u W and the edge solve's 10 u W
    // it can take instead, with margin), its distance to B's world polygon computed by hand in long
    // double (B's points are in counterclockwise order: polygonOnCircle sorts their angles).
    Scene<T> s;
    s.a = {{T(-0.91407016601983937), T(0.8248778430157141)},
           {T(-1.1997976862763406), T(0.27646561506222384)},
           {T(-1.2268274869914273), T(0.10412512409641035)},
           {T(0.87303229369515067), T(-0.86819487355730107)}};
    s.xfA = {{T(-0.78679566251373423), T(-2.878320289535286)},
             {T(0.99975447004871598), T(-0.022158511177675339)}};
    s.b = {{T(0.33459661958265141), T(1.9286847479828964)},
           {T(-0.21594350387893962), T(1.945545722431234)},
           {T(-0.53129540276324683), T(1.884012990916099)},
           {T(-0.75855485235930997), T(1.8045426819280643)},
           {T(-1.5405722704617064), T(1.2076493010897031)},
           {T(-1.9438332551017763), T(-0.23085066882818139)},
           {T(1.7038493751148636), T(-0.96367892052211801)},
           {T(1.9042586536735007), T(-0.4534079122022161)}};
    s.xfB = {{T(0.47729867323811526), T(-1.5052805701094487)},
             {T(-0.1373840206619048), T(0.99051785994335773)}};
    const auto out = query(s);
    REQUIRE(out.stop == StopReason::Containment);
    CHECK(out.distance == T(0));
    using L = long double;
    std::vector<std::array<L, 2>> wb;
    for (const auto& p : s.b)
    {
        const L c = s.xfB.q.c, sn = s.xfB.q.s;
        wb.push_back(
            {c * L(p.x) - sn * L(p.y) + L(s.xfB.p.x), sn * L(p.x) + c * L(p.y) + L(s.xfB.p.y)});
    }
    L W = 0;
    for (const auto& p : s.a)
    {
        const L c = s.xfA.q.c, sn = s.xfA.q.s;
        const L ax = c * L(p.x) - sn * L(p.y) + L(s.xfA.p.x);
        const L ay = sn * L(p.x) + c * L(p.y) + L(s.xfA.p.y);
        for (const auto& q : wb)
            W = std::max(W, std::hypot(ax - q[0], ay - q[1]));
    }
    const L px = out.pointB.x, py = out.pointB.y;
    bool inside = true;
    L off = std::numeric_limits<L>::max();
    for (std::size_t i = 0; i < wb.size(); ++i)
    {
        const auto& p0 = wb[i];
        const auto& p1 = wb[(i + 1) % wb.size()];
        const L ex = p1[0] - p0[0], ey = p1[1] - p0[1], qx = px - p0[0], qy = py - p0[1];
        inside = inside && ex * qy - ey * qx >= 0;
        const L t = std::clamp((ex * qx + ey * qy) / (ex * ex + ey * ey), L(0), L(1));
        off = std::min(off, std::hypot(qx - t * ex, qy - t * ey));
    }
    const L bound = 64 * L(std::numeric_limits<T>::epsilon() / 2) * W;
    INFO("witness point " << out.pointB.x << ", " << out.pointB.y << ": " << (inside ? 0 : off)
                          << " from B, bound " << bound);
    CHECK((inside || off <= bound));
}
