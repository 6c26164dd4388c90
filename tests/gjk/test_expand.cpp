// Options::signedDistance (gjk2d/expand.hpp): the expanding polygon on overlapping shapes, the
// signed distance of rounded shapes whose cores are apart, the stopping rules, the certified
// interval, and separated answers unchanged. Expected depths are derived by hand beside each case;
// the random cases are checked against a brute-force depth (the least support value of Z over
// every direction perpendicular to two points of one shape, a superset of Z's edge normals).
#include "gjk2d/batch.hpp"
#include "gjk2d/distance.hpp"
#include "random_shapes.hpp" // gjk/bench: the speed targets' random distribution

#include "../within.hpp" // within(x, m): an absolute margin and nothing else
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <span>
#include <type_traits>
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

Options signedOptions()
{
    Options o;
    o.signedDistance = true;
    return o;
}

template <class T> DistanceOutput<T> signedQuery(const Scene<T>& s)
{
    SimplexCache cache;
    return distance(s.input(), cache, signedOptions());
}

// The tolerance of the hand-derived checks: 64 u times the problem's scale (as test_distance.cpp's
// tol: about ten rounded operations on quantities of a few times the scale), still 1e-5 in float
// at scale 2, far below any wrong edge (off by a fraction of the scale).
template <class T> T tol(T scale = T(4))
{
    return T(64) * Tolerances<T>::unitRoundoff * scale;
}

template <class T> Vec2<T> rot(double degrees)
{
    const double t = degrees * M_PI / 180;
    return {T(std::cos(t)), T(std::sin(t))};
}

// The checks every signed answer on overlap must pass: distance < 0, the pair's difference is the
// minimal translation along the normal (|pA - pB| = -distance, normal = (pA - pB) / |pA - pB|),
// the certified interval holds the expected value, an expansion stop that ends a normal run.
template <class T>
void checkPenetration(const DistanceOutput<T>& out, double expected, Vec2<T> expectedNormal,
                      T margin)
{
    CHECK(out.distance == within(expected, margin));
    CHECK(!out.outOfRange);
    const Vec2<T> d = out.pointA - out.pointB;
    CHECK(length(d) == within(-double(out.distance), margin));
    CHECK(out.normal.x == within(expectedNormal.x, margin));
    CHECK(out.normal.y == within(expectedNormal.y, margin));
    CHECK(length(out.normal) == within(1.0, margin));
    CHECK(out.certified);
    CHECK(out.lower <= expected + double(margin));
    CHECK(out.upper >= expected - double(margin));
    // The interval encloses the exact value in double; the answer in T is within its own
    // rounding of it (in float ~1e-7 outside a double-narrow interval).
    CHECK(out.lower <= double(out.distance) + double(margin));
    CHECK(out.upper >= double(out.distance) - double(margin));
}

// Brute-force core depth for convex point sets in world coordinates (overlapping): the least
// support value of Z = A - B over the unit perpendiculars of every pair of points of A and of B,
// both signs. Z's edge normals are among them, and no direction's support value is below the
// depth, so the least is the depth.
template <class T> double bruteDepth(const Scene<T>& s)
{
    std::vector<Vec2<double>> A, B;
    auto world = [](const Transform<T>& xf, Vec2<T> p)
    {
        const double c = xf.q.c, sn = xf.q.s;
        return Vec2<double>{c * p.x - sn * p.y + xf.p.x, sn * p.x + c * p.y + xf.p.y};
    };
    for (auto p : s.a)
        A.push_back(world(s.xfA, p));
    for (auto p : s.b)
        B.push_back(world(s.xfB, p));
    auto h = [&](Vec2<double> n)
    {
        double ha = -1e300, hb = -1e300;
        for (auto p : A)
            ha = std::max(ha, dot(n, p));
        for (auto p : B)
            hb = std::max(hb, -dot(n, p));
        return ha + hb;
    };
    double best = std::numeric_limits<double>::infinity();
    for (const auto* P : {&A, &B})
        for (std::size_t i = 0; i < P->size(); ++i)
            for (std::size_t j = 0; j < P->size(); ++j)
            {
                const Vec2<double> e = (*P)[j] - (*P)[i];
                const double len = length(e);
                if (len == 0)
                    continue;
                best = std::min(best, h((1 / len) * rightPerp(e)));
            }
    return best;
}

template <class T> bool sameBits(T a, T b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}
template <class T> bool sameOutput(const DistanceOutput<T>& x, const DistanceOutput<T>& y)
{
    return sameBits(x.distance, y.distance) && sameBits(x.pointA.x, y.pointA.x) &&
           sameBits(x.pointA.y, y.pointA.y) && sameBits(x.pointB.x, y.pointB.x) &&
           sameBits(x.pointB.y, y.pointB.y) && sameBits(x.normal.x, y.normal.x) &&
           sameBits(x.normal.y, y.normal.y) && x.iterations == y.iterations &&
           x.simplexCount == y.simplexCount && x.stop == y.stop && x.outOfRange == y.outOfRange &&
           x.rescaled == y.rescaled && x.certified == y.certified && sameBits(x.lower, y.lower) &&
           sameBits(x.upper, y.upper) && x.expand == y.expand;
}

template <class T> Scene<T> randomScene(std::mt19937_64& rng)
{
    const auto a = bench::converted<T>(bench::randomShape(rng));
    const auto b = bench::converted<T>(bench::randomShape(rng));
    Scene<T> s;
    s.a = a.points;
    s.b = b.points;
    s.xfA = a.xf;
    s.xfB = b.xf;
    return s;
}
} // namespace

TEMPLATE_TEST_CASE("signed distance: two squares overlapping by a known amount", "[gjk][expand]",
                   float, double)
{
    using T = TestType;
    // A = [0, 2]^2, B = [0, 2]^2 moved by (1.5, 0.5): they overlap by 0.5 along x and 1.5 along
    // y, so the depth is the smaller, 0.5, and B leaves A along +x. pA on A's right side x = 2,
    // pB on B's left side x = 1.5, at a common height inside the overlap y in [0.5, 2].
    Scene<T> s;
    s.a = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    s.b = s.a;
    s.xfB.p = {T(1.5), T(0.5)};
    const auto out = signedQuery(s);
    checkPenetration<T>(out, -0.5, {1, 0}, tol<T>());
    CHECK(out.pointA.x == within(2.0, tol<T>()));
    CHECK(out.pointB.x == within(1.5, tol<T>()));
    CHECK(out.pointA.y == within(out.pointB.y, tol<T>()));
    CHECK(out.pointA.y >= T(0.5) - tol<T>());
    CHECK(out.pointA.y <= T(2) + tol<T>());
    CHECK((out.expand == ExpandStop::GapClosed || out.expand == ExpandStop::RepeatedSupport));

    SECTION("swapping A and B negates the normal, the depth stays")
    {
        std::swap(s.a, s.b);
        std::swap(s.xfA, s.xfB);
        checkPenetration<T>(signedQuery(s), -0.5, {-1, 0}, tol<T>());
    }
    SECTION("a common translation far away changes nothing but the points")
    {
        s.xfA.p = s.xfA.p + Vec2<T>{T(100), T(-50)};
        s.xfB.p = s.xfB.p + Vec2<T>{T(100), T(-50)};
        checkPenetration<T>(signedQuery(s), -0.5, {1, 0}, tol<T>(T(200)));
    }
    SECTION("an exact 90 degree rotation of the scene rotates the normal")
    {
        // (x, y) -> (-y, x): A's frame rotated by (0, 1), B's translation rotated.
        s.xfA.q = {0, 1};
        s.xfB.q = {0, 1};
        s.xfB.p = {T(-0.5), T(1.5)};
        checkPenetration<T>(signedQuery(s), -0.5, {0, 1}, tol<T>());
    }
}

TEMPLATE_TEST_CASE("signed distance: a square rotated by 45 degrees on a square", "[gjk][expand]",
                   float, double)
{
    using T = TestType;
    // A = [-1, 1]^2; B the same square rotated by 45 degrees (a diamond, vertices sqrt2 from its
    // centre) centred at (2, 0). Overlaps along the edge normals (separating-axis theorem: Z's
    // edges are A's and B's): along (1, 0), A's max 1 minus B's min 2 - sqrt2 = sqrt2 - 1; along
    // (1, +-1)/sqrt2, A's max sqrt2 minus B's min (2 - sqrt2)/sqrt2 = sqrt2 - 1 gives 1; along
    // (0, +-1) and the negative ones, more than 2. Depth sqrt2 - 1 = 0.41421..., normal (1, 0).
    Scene<T> s;
    s.a = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    s.b = s.a;
    s.xfB = {{T(2), T(0)}, {rot<T>(45).x, rot<T>(45).y}};
    const auto out = signedQuery(s);
    // The rotation (cos 45, sin 45) is rounded to T: its size differs from 1 by about u, which
    // moves the diamond's vertex by about u sqrt2 (inside tol).
    checkPenetration<T>(out, -(std::sqrt(2.0) - 1), {1, 0}, tol<T>());
    CHECK(out.pointA.x == within(1.0, tol<T>()));
    CHECK(out.pointB.x == within(2 - std::sqrt(2.0), tol<T>()));
    CHECK(out.pointB.y == within(0.0, tol<T>()));
}

TEMPLATE_TEST_CASE("signed distance: rounded shapes", "[gjk][expand]", float, double)
{
    using T = TestType;
    Scene<T> s;
    s.a = {{-1, 0}, {1, 0}}; // a capsule's core
    s.b = s.a;
    s.radiusA = T(0.5);
    s.radiusB = T(0.5);
    SECTION("cores apart, radii overlapping: core distance minus both radii, unclamped")
    {
        // Parallel cores 0.8 apart, rA + rB = 1: distance 0.8 - 1 = -0.2, B leaves along +y.
        // pA on A's rounded surface y = 0.5, pB on B's y = 0.8 - 0.5 = 0.3.
        s.xfB.p = {T(0.25), T(0.8)};
        const auto out = signedQuery(s);
        checkPenetration<T>(out, -0.2, {0, 1}, tol<T>());
        CHECK(out.expand == ExpandStop::None);
        CHECK(out.pointA.y == within(0.5, tol<T>()));
        CHECK(out.pointB.y == within(0.3, tol<T>()));
        CHECK(out.pointA.x == within(out.pointB.x, tol<T>()));
    }
    SECTION("cores overlapping: minus (core depth + rA + rB)")
    {
        // Squares [-1, 1]^2, B moved by (1.5, 0): core depth 0.5 along +x; radii 0.25 each:
        // distance -(0.5 + 0.5) = -1. pA = A's core point (1, y) + 0.25 x = 1.25, pB = B's core
        // point (0.5, y) - 0.25 x = 0.25.
        s.a = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        s.b = s.a;
        s.radiusA = s.radiusB = T(0.25);
        s.xfB.p = {T(1.5), T(0)};
        const auto out = signedQuery(s);
        checkPenetration<T>(out, -1.0, {1, 0}, tol<T>());
        CHECK(out.pointA.x == within(1.25, tol<T>()));
        CHECK(out.pointB.x == within(0.25, tol<T>()));
        CHECK(out.expand != ExpandStop::None);
    }
    SECTION("apart beyond the radii: the unsigned answer")
    {
        s.xfB.p = {T(0), T(1.5)};
        const auto out = signedQuery(s);
        CHECK(out.distance == within(0.5, tol<T>()));
        CHECK(out.expand == ExpandStop::None);
    }
}

TEMPLATE_TEST_CASE("signed distance: a shape on itself, the depth is its least width",
                   "[gjk][expand]", float, double)
{
    using T = TestType;
    Scene<T> s;
    SECTION("a rectangle 4 x 2: Z = [-4, 4] x [-2, 2], depth 2 along +-y")
    {
        s.a = {{0, 0}, {4, 0}, {4, 2}, {0, 2}};
        s.b = s.a;
        const auto out = signedQuery(s);
        CHECK(out.distance == within(-2.0, tol<T>()));
        CHECK(std::abs(out.normal.y) == within(1.0, tol<T>()));
        CHECK(length(out.pointA - out.pointB) == within(2.0, tol<T>()));
        CHECK(out.certified);
        CHECK(out.lower <= -2.0);
        CHECK(out.upper >= -2.0);
    }
    SECTION("a right triangle with legs 3: depth the least altitude 3 / sqrt2")
    {
        // Z = T - T; its support value along n is T's width along n, least across the
        // hypotenuse: area 4.5 = hypotenuse 3 sqrt2 x altitude / 2, altitude 3 / sqrt2.
        s.a = {{0, 0}, {3, 0}, {0, 3}};
        s.b = s.a;
        s.xfA.p = s.xfB.p = {T(-7), T(5)};
        const auto out = signedQuery(s);
        // Z is symmetric: the normal is either diagonal, (1, 1) / sqrt2 or its opposite.
        const T sign = out.normal.x < T(0) ? T(-1) : T(1);
        const T diag = sign * T(std::sqrt(0.5));
        checkPenetration<T>(out, -3 / std::sqrt(2.0), {diag, diag}, tol<T>(T(16)));
    }
}

TEMPLATE_TEST_CASE("signed distance: touching edge to edge is depth 0, ExpandStop::Touching",
                   "[gjk][expand]", float, double)
{
    using T = TestType;
    // A = [0, 1]^2, B = [1, 2] x [0, 1]: they share the edge x = 1; Z = [-2, 0] x [-1, 1] has the
    // origin on its boundary (exact in both types).
    Scene<T> s;
    s.a = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    s.b = s.a;
    s.xfB.p = {T(1), T(0)};
    SECTION("without radii: distance 0")
    {
        const auto out = signedQuery(s);
        CHECK(out.distance == T(0));
        CHECK(out.expand == ExpandStop::Touching);
        CHECK(out.certified);
        CHECK(out.lower <= 0);
        CHECK(out.upper >= 0);
    }
    SECTION("with radii: minus both radii, along the shared edge's normal")
    {
        s.radiusA = T(0.125);
        s.radiusB = T(0.25);
        const auto out = signedQuery(s);
        checkPenetration<T>(out, -0.375, {1, 0}, tol<T>());
        CHECK(out.expand == ExpandStop::Touching);
    }
    SECTION("a vertex touching a vertex: Z's corner")
    {
        s.xfB.p = {T(1), T(1)};
        const auto out = signedQuery(s);
        CHECK(out.distance == T(0));
        CHECK(out.expand == ExpandStop::Touching);
    }
    SECTION("collinear segments overlapping: Z is a segment, no interior")
    {
        s.a = {{0, 0}, {2, 0}};
        s.b = s.a;
        s.xfB.p = {T(1), T(0)};
        s.radiusA = T(0.5);
        const auto out = signedQuery(s);
        // Depth 0 (Z has no interior) plus rA: along either perpendicular of the segments.
        checkPenetration<T>(out, -0.5, {0, out.normal.y < T(0) ? T(-1) : T(1)}, tol<T>());
        CHECK(out.expand == ExpandStop::Touching);
    }
}

TEMPLATE_TEST_CASE("signed distance: a point inside a polygon", "[gjk][expand]", float, double)
{
    using T = TestType;
    // A = the point (0.5, 0.25), B = [0, 2] x [0, 1]. The point's distances to B's sides: left
    // 0.5, right 1.5, bottom 0.25, top 0.75: depth 0.25, pB = (0.5, 0) on B's bottom, and B leaves
    // A along +y (moving B up by 0.25 puts its bottom on the point).
    Scene<T> s;
    s.a = {{T(0.5), T(0.25)}};
    s.b = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
    const auto out = signedQuery(s);
    checkPenetration<T>(out, -0.25, {0, 1}, tol<T>());
    CHECK(out.pointA.x == within(0.5, tol<T>()));
    CHECK(out.pointA.y == within(0.25, tol<T>()));
    CHECK(out.pointB.x == within(0.5, tol<T>()));
    CHECK(out.pointB.y == within(0.0, tol<T>()));

    SECTION("the point on a vertex of the difference (GJK's zero direction)")
    {
        // A = the point (0, 0) = B's vertex 0: GJK's first vertex is the origin itself. The point
        // is on B's corner: depth 0.
        s.a = {{0, 0}};
        const auto o = signedQuery(s);
        CHECK(o.stop == StopReason::ZeroDirection);
        CHECK(o.distance == T(0));
        CHECK(o.expand == ExpandStop::Touching);
    }
}

TEMPLATE_TEST_CASE("signed distance: random overlaps against a brute-force depth", "[gjk][expand]",
                   float, double)
{
    using T = TestType;
    std::mt19937_64 rng(51);
    int overlapping = 0;
    for (int i = 0; i < 4000; ++i)
    {
        const Scene<T> s = randomScene<T>(rng);
        const auto out = signedQuery(s);
        if (!(out.distance < T(0)))
            continue;
        ++overlapping;
        const double depth = bruteDepth(s);
        INFO("case " << i << " depth " << depth << " distance " << out.distance);
        // Scale 8: shapes within [-6, 6]^2.
        checkPenetration<T>(out, -depth, out.normal, tol<T>(T(8)));
        CHECK(out.expand != ExpandStop::IterationLimit);
        CHECK(out.expand != ExpandStop::None);
        // The interval is narrow: the polygon's final edge is Z's.
        CHECK(out.upper - out.lower <= double(tol<T>(T(8))));
    }
    CHECK(overlapping > 400); // the distribution overlaps in about a fifth of its pairs
}

TEMPLATE_TEST_CASE("signed distance: separated answers are bit for bit those without it",
                   "[gjk][expand]", float, double)
{
    using T = TestType;
    std::mt19937_64 rng(52);
    int separated = 0;
    for (int i = 0; i < 4000; ++i)
    {
        Scene<T> s = randomScene<T>(rng);
        s.radiusA = T(i % 3) * T(0.125);
        for (const bool certify : {false, true})
        {
            Options plain;
            plain.certify = certify;
            Options sgn = plain;
            sgn.signedDistance = true;
            SimplexCache c1, c2;
            const auto a = distance(s.input(), c1, plain);
            const auto b = distance(s.input(), c2, sgn);
            if (a.distance > T(0))
            {
                ++separated;
                CHECK(sameOutput(a, b));
                CHECK(std::memcmp(&c1, &c2, sizeof c1) == 0);
            }
            else
                CHECK(b.distance <= T(0));
        }
    }
    CHECK(separated > 4000);
}

TEMPLATE_TEST_CASE("signed distance: the SIMD batch runs the scalar query", "[gjk][expand][batch]",
                   float, double)
{
    using T = TestType;
    std::mt19937_64 rng(53);
    std::vector<Scene<T>> scenes;
    for (int i = 0; i < 300; ++i)
        scenes.push_back(randomScene<T>(rng));
    std::vector<DistanceInput<T>> inputs;
    for (auto& s : scenes)
        inputs.push_back(s.input());
    std::vector<SimplexCache> caches(inputs.size());
    std::vector<DistanceOutput<T>> outputs(inputs.size());
    BatchStats stats;
    distanceBatchLanes(std::span<const DistanceInput<T>>(inputs), caches, outputs, signedOptions(),
                       BatchIsa::Best, &stats);
    int negative = 0;
    for (std::size_t i = 0; i < inputs.size(); ++i)
    {
        SimplexCache c;
        const auto one = distance(inputs[i], c, signedOptions());
        CHECK(sameOutput(one, outputs[i]));
        negative += outputs[i].distance < T(0);
    }
    CHECK(stats.laneQueries == 0);
    CHECK(negative > 0);
}

TEMPLATE_TEST_CASE("signed distance: tiny and huge shapes run rescaled, the depth scales exactly",
                   "[gjk][expand][range]", float, double)
{
    using T = TestType;
    // The two squares of the first case scaled by 2^k, beyond Tolerances<T>'s safe range (double:
    // 2^-700 and 2^520, outside [2^-484, ~2^509]; float: 2^-60 and 2^70, outside
    // [2^-51, ~2^61]). Scaling by a power of two is exact, so the depth is 0.5 * 2^k and the
    // query, rescaled, answers it to the same relative accuracy as at scale 1.
    const bool isDouble = std::is_same_v<T, double>;
    for (const int k : {isDouble ? -700 : -60, isDouble ? 520 : 70})
    {
        INFO("k = " << k);
        const T s2 = std::ldexp(T(1), k);
        Scene<T> s;
        s.a = {{0, 0}, {2 * s2, 0}, {2 * s2, 2 * s2}, {0, 2 * s2}};
        s.b = s.a;
        s.xfB.p = {T(1.5) * s2, T(0.5) * s2};
        const auto out = signedQuery(s);
        CHECK(out.rescaled);
        CHECK(!out.outOfRange);
        CHECK(double(out.distance) / double(s2) == within(-0.5, tol<T>()));
        CHECK(out.normal.x == within(1.0, tol<T>()));
        CHECK(out.expand != ExpandStop::None);
    }
}

TEMPLATE_TEST_CASE("signed distance: the pair lies on its edge when two edges are nearly collinear",
                   "[gjk][expand][regression]", float, double)
{
    using T = TestType;
    // gjk-validate search (double-signed, from hard/scale-sweep/98-touching-edge-x1, mutated:
    // search/12216): B holds two of A's vertices, so Z has two nearly collinear edges meeting at
    // a vertex 7.3e-12 from the origin, both lines 5.26e-12 from it. Rounding made the one whose
    // foot lies 5e-12 beyond its end the closest (the line distances differ by 3e-18), and the
    // clamped foot read the shared vertex as the pair: |pA - pB| = 7.3e-12 for a depth of
    // 5.26e-12 (witness gap 2e-12, 200 times the witness bound). The answer is now read from the
    // neighbour on whose line the foot falls (answerEdge). Exact depth (exact side, explain):
    // 5.2567428407330149e-12; the depth's error is unchanged (4.8e-17).
    Scene<T> s;
    s.a = {{T(0.3702469970423971), T(-0.3357146361559567)},
           {T(0.3183393218407997), T(0.38661755848642726)},
           {T(-0.3277301071516858), T(0.393985217258568)},
           {T(-0.1572474375739205), T(-0.4812110282292808)}};
    s.b = {{T(0.3183393218407997), T(0.386617558486428)},
           {T(0.3702469970423971), T(-0.3357146361559567)},
           {T(0.8022419210229663), T(-0.358465950755043)},
           {T(0.3183393218407997), T(0.386617558486428)}};
    s.xfA = {{T(-0.6488079320650453), T(0.7331423557741962)},
             {T(-0.19408624808338204), T(0.9809844689417442)}};
    s.xfB = {{T(-0.6488079320650506), T(0.7331423557741943)},
             {T(-0.19408624806911381), T(0.9809844689445671)}};
    const auto out = signedQuery(s);
    // |pA - pB| = -distance to the answer's own rounding (a few u times the points' size 1.2).
    CHECK(double(length(out.pointA - out.pointB)) ==
          within(-double(out.distance), 16 * Tolerances<T>::unitRoundoff));
    if constexpr (std::is_same_v<T, double>)
    {
        CHECK(out.distance == within(-5.2567428407330149e-12, 1e-15));
        CHECK(out.lower <= -5.2567428407330149e-12);
        CHECK(out.upper >= -5.2567428407330149e-12);
    }
}

TEST_CASE("signed distance: deep overlap behind a GJK distance within rounding of 0",
          "[gjk][expand][regression]")
{
    // gjk-validate search (double-signed, from hard/identical-nested/14-nested-half, mutated:
    // search/265194): B is A's hexagon halved, on the same transform, so Z holds the origin 3.9
    // deep; GJK's last edge passes 7.4e-17 from the origin and its side test rounded the wrong way:
    // it stops apart at 7.4e-17 (within the distance's bound, the exact distance being 0). The
    // signed query then expands too (Tolerances::expandNearZero: 64 u times the simplex's size,
    // here ~5e-14) and finds the origin inside. Exact signed distance (exact side, explain):
    // -3.9087648763546006. double only: the case is the search's double input.
    using T = double;
    Scene<T> s;
    s.a = {{2.8584639912161975, 0.939721062491304},    {0.6154096830193261, 2.9453629634419376},
           {-2.243054308196872, 2.0056419009506343},   {-2.8584639912161975, -0.9397210624913037},
           {-0.6154096830193283, -2.9453629634419376}, {2.2430543081968715, -2.0056419009506348},
           {2.30579541107123, -1.7054739801751113}};
    s.b = {{1.4292319956080988, 0.469860531245652},     {0.30770484150966304, 1.4726814817209688},
           {-1.121527154098436, 1.0028209504753172},    {-1.4292319956080988, -0.46986053124565186},
           {-0.30770484150966415, -1.4726814817209688}, {1.1215271540984357, -1.0028209504753174}};
    s.xfA = {{-6.002052997121733, -6.592293901233031}, {0.6529492920104807, 0.7574016253369226}};
    s.xfB = s.xfA;
    SimplexCache cache;
    const auto plain = distance(s.input(), cache);
    CHECK(plain.distance > 0); // the mechanism: GJK alone answers apart
    const auto out = signedQuery(s);
    CHECK(out.distance == within(-3.9087648763546006, 1e-13));
    CHECK(length(out.pointA - out.pointB) == within(3.9087648763546006, 1e-13));
    CHECK(out.lower <= -3.9087648763546006);
    CHECK(out.upper >= -3.9087648763546006);
}
