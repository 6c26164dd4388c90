// The signed distance and the penetration pair (Options::penetration, docs/exact.md, "Penetration
// depth"): hand-derived cases (derivations in the comments), every route, filter on and off and
// prepared shapes bit for bit, exact::bruteForceSigned on random overlapping cases drawn at test
// time, correct rounding checked by exact comparisons, and the pair checked geometrically.
#include "support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>

using namespace exact_test;
using exact::Options;
using exact::Result;
using exact::Route;

namespace
{

std::string describe(const Shape& s)
{
    std::ostringstream o;
    o.precision(17);
    o << "{r=" << s.radius << " c=" << s.c << " s=" << s.s << " p=(" << s.px << "," << s.py
      << ") pts=";
    for (const auto& p : s.points)
        o << "(" << p.x << "," << p.y << ")";
    o << "}";
    return o.str();
}

double ulpOf(double v)
{
    v = std::fabs(v);
    return std::nextafter(v, INFINITY) - v;
}

// sign(x - m) for the exact signed distance x of r: -(sqrt(depth^2) + rA + rB) on overlap,
// sqrt(squared) - rA - rB apart.
struct SignedValue
{
    bool overlap;
    mpq_class q, r;
    int cmpTo(const mpq_class& m) const
    {
        if (overlap) // sign(-(sqrt q) - r - m) = -sign(sqrt q - (-(r + m)))
            return -cmpSqrtMinus(q, 0, -(r + m));
        return cmpSqrtMinus(q, r, m);
    }
};

SignedValue signedValue(const Result& x, const Shape& a, const Shape& b)
{
    SignedValue v;
    v.overlap = x.overlap;
    v.q = x.overlap ? parseQ(x.depthSquaredNum + "/" + x.depthSquaredDen) : squaredOf(x);
    v.r = radii(a, b);
    return v;
}

// Largest magnitude among the world coordinates a case involves (the tolerances' scale).
double scaleOf(const Shape& a, const Shape& b, const Result& x)
{
    double m = 0;
    for (const Shape* s : {&a, &b})
    {
        for (const Q2& p : worldPoints(*s))
            m = std::max({m, std::fabs(p.x.get_d()), std::fabs(p.y.get_d())});
        m = std::max({m, std::fabs(s->px), std::fabs(s->py), s->radius});
    }
    for (const exact::Point& p : {x.penetrationA, x.penetrationB})
        m = std::max({m, std::fabs(p.x), std::fabs(p.y)});
    return m;
}

struct Counts
{
    int overlaps = 0, cases = 0;
};

// Everything about one case; returns the default route's result (filter on, exact witnesses off).
Result checkSigned(const Shape& a, const Shape& b, bool withBruteForce, Counts* counts = nullptr)
{
    INFO("A = " << describe(a));
    INFO("B = " << describe(b));
    Options o;
    o.penetration = true;
    const Result def = exact::distance(a, b, o);
    REQUIRE(def.hasSigned);
    // Every route, filter on and off, plain and prepared shapes: the same signed fields. The pair
    // on overlap too; apart it is each result's own witnesses (which may differ between routes
    // where the closest pair is not unique, docs/exact.md "Witnesses").
    const exact::PreparedShape pa(a), pb(b);
    for (Route route : exact::kAllRoutes)
        for (bool filter : {true, false})
            for (bool prepared : {false, true})
            {
                INFO("route " << exact::routeName(route) << " filter " << filter << " prepared "
                              << prepared);
                o.route = route;
                o.filter = filter;
                const Result x = prepared ? exact::distance(pa, pb, o) : exact::distance(a, b, o);
                CHECK(differentSigned(x, def, x.overlap).empty());
                CHECK(differentFields(x, def).size() <= (route == Route::EdgeMerge ? 0u : 4u));
                if (!x.overlap)
                {
                    CHECK(sameBits(x.penetrationA.x, x.witnessA.x));
                    CHECK(sameBits(x.penetrationA.y, x.witnessA.y));
                    CHECK(sameBits(x.penetrationB.x, x.witnessB.x));
                    CHECK(sameBits(x.penetrationB.y, x.witnessB.y));
                }
            }
    // Without Options::penetration: nothing signed.
    CHECK_FALSE(exact::distance(a, b).hasSigned);

    // Correct rounding and the tight enclosure, by exact comparisons.
    const SignedValue v = signedValue(def, a, b);
    auto cmpTo = [&](const mpq_class& m) { return v.cmpTo(m); };
    CHECK(roundsToSigned(def.signedDistance, cmpTo));
    CHECK(v.cmpTo(mpq_class(def.signedLower)) >= 0);
    CHECK(v.cmpTo(mpq_class(def.signedUpper)) <= 0);
    CHECK((def.signedUpper == def.signedLower ||
           def.signedUpper == std::nextafter(def.signedLower, INFINITY)));
    if (def.overlap)
    {
        CHECK(def.signedDistance <= 0);
        CHECK(def.distance == 0);
    }
    else
    {
        CHECK(def.depthSquaredNum.empty());
        // where the unclamped value is positive, the same correctly rounded real as the distance
        if (def.distance > 0)
            CHECK(sameBits(def.signedDistance, def.distance));
    }

    if (def.overlap)
    {
        // The pair: each point on its rounded boundary, pA - pB the minimal translation. Each
        // coordinate is correctly rounded (half an ulp of the scale S at most), so pA is within
        // sqrt(2)/2 ulp(S) of A's boundary; the bound is ulp(S).
        const double S = scaleOf(a, b, def);
        const exact::Point pA = def.penetrationA, pB = def.penetrationB;
        CHECK(exact::pointToShapeDistance(a, pA) <= ulpOf(S));
        CHECK(exact::pointToShapeDistance(b, pB) <= ulpOf(S));
        // |pA - pB| = -signed: the points' errors (ulp(S) a coordinate of the difference), the
        // subtraction, hypot and the signed rounding add up to less than 4 ulp(S); bound 8.
        const double len = std::hypot(pA.x - pB.x, pA.y - pB.y);
        CHECK(std::fabs(len + def.signedDistance) <= 8 * ulpOf(S));
        // Translating B by pA - pB brings the rounded shapes to contact: the exact signed distance
        // is 1-Lipschitz in B's translation, and B's translated position is off the exact one by
        // at most 2.5 ulp(S') a coordinate (pA and pB half an ulp(S) each, the subtraction ulp(S),
        // the addition to B's position half an ulp(S')), so |signed| <= 2.5 sqrt(2) ulp(S') < 4
        // ulp(S') after; bound 4 ulp(S').
        Shape moved = b;
        moved.px += pA.x - pB.x;
        moved.py += pA.y - pB.y;
        const double S2 = std::max({S, std::fabs(moved.px), std::fabs(moved.py)});
        Options po;
        po.penetration = true;
        const Result after = exact::distance(a, moved, po);
        CHECK(std::fabs(after.signedDistance) <= 4 * ulpOf(S2));
    }

    if (withBruteForce)
    {
        const Result bf = exact::bruteForceSigned(a, b);
        CHECK(bf.hasSigned);
        CHECK(bf.overlap == def.overlap);
        CHECK(differentSigned(bf, def, false).empty());
        CHECK(bf.signedDistance == def.signedDistance);
        CHECK(bf.depthSquaredNum == def.depthSquaredNum);
        CHECK(bf.depthSquaredDen == def.depthSquaredDen);
    }
    if (counts)
    {
        ++counts->cases;
        counts->overlaps += def.overlap;
    }
    return def;
}

Shape square(double x0, double y0, double x1, double y1, double radius = 0)
{
    return shape({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, radius);
}

void checkPair(const Result& r, double ax, double ay, double bx, double by)
{
    CHECK(r.penetrationA.x == ax);
    CHECK(r.penetrationA.y == ay);
    CHECK(r.penetrationB.x == bx);
    CHECK(r.penetrationB.y == by);
}

} // namespace

TEST_CASE("penetration: overlapping axis-aligned squares, with and without radii")
{
    // A = [0,2]^2, B = [1,3] x [1/2, 5/2]. Z = A - B = [0-3, 2-1] x [0-5/2, 2-1/2] = [-3,1] x
    // [-5/2, 3/2]; the origin's distances to its sides: 3, 1, 5/2, 3/2: the right side x = 1,
    // depth 1 (the overlap of [0,2] and [1,3] along x). That side is A's right edge minus B's left
    // edge (parallel): from (1, -5/2) = (2,0) - (1,5/2) to (1, 3/2) = (2,2) - (1,1/2); the foot
    // (1, 0) is at t = (5/2)/4 = 5/8, so a* = (2,0) + 5/8 (0,2) = (2, 5/4), b* = (1,5/2) + 5/8
    // (0,-2) = (1, 5/4): pA - pB = (1, 0), translating B by +1 in x makes the squares touch.
    const Result r = checkSigned(square(0, 0, 2, 2), square(1, 0.5, 3, 2.5), true);
    CHECK(r.overlap);
    CHECK(r.depthSquaredNum == "1");
    CHECK(r.depthSquaredDen == "1");
    CHECK(r.signedDistance == -1.0);
    CHECK(r.signedLower == -1.0);
    CHECK(r.signedUpper == -1.0);
    checkPair(r, 2, 1.25, 1, 1.25);
    // Radii 1/4 and 1/2 along n = (1, 0): signed -(1 + 3/4), pA = (2 + 1/4, 5/4), pB = (1 - 1/2,
    // 5/4).
    const Result s = checkSigned(square(0, 0, 2, 2, 0.25), square(1, 0.5, 3, 2.5, 0.5), true);
    CHECK(s.signedDistance == -1.75);
    CHECK(s.depthSquaredNum == "1");
    checkPair(s, 2.25, 1.25, 0.5, 1.25);
}

TEST_CASE("penetration: touching squares, along an edge and at a corner")
{
    // A = [0,1]^2, B = [1,2] x [0,1]: Z = [-2,0] x [-1,1], the origin on Z's right side x = 0
    // (only that side: the others are 2, 1, 1 away): depth 0, n = (1, 0). The side runs from
    // (0,-1) = (1,0) - (1,1) to (0,1) = (1,1) - (1,0); the foot O is at t = 1/2: a* = b* = (1,
    // 1/2).
    const Result r = checkSigned(square(0, 0, 1, 1), square(1, 0, 2, 1), true);
    CHECK(r.overlap);
    CHECK(r.depthSquaredNum == "0");
    CHECK(r.depthSquaredDen == "1");
    CHECK(r.signedDistance == 0.0);
    checkPair(r, 1, 0.5, 1, 0.5);
    // Radii 1/2 each: signed -1, pA = (3/2, 1/2), pB = (1/2, 1/2).
    const Result s = checkSigned(square(0, 0, 1, 1, 0.5), square(1, 0, 2, 1, 0.5), true);
    CHECK(s.signedDistance == -1.0);
    checkPair(s, 1.5, 0.5, 0.5, 0.5);
    // Corner to corner: A = [0,1]^2, B = [1,2]^2, Z = [-2,0]^2, the origin its vertex (0,0): the
    // sides x = 0 (normal (1,0), angle 0) and y = 0 (normal (0,1), angle pi/2) are both at 0; the
    // least normal angle chooses x = 0, from (0,-2) = (1,0) - (1,2) to (0,0) = (1,1) - (1,1), foot
    // at t = 1: a* = b* = (1,1). Radii 1/2 each: pA = (3/2, 1), pB = (1/2, 1), signed -1.
    const Result c = checkSigned(square(0, 0, 1, 1, 0.5), square(1, 1, 2, 2, 0.5), true);
    CHECK(c.depthSquaredNum == "0");
    CHECK(c.signedDistance == -1.0);
    checkPair(c, 1.5, 1, 0.5, 1);
}

TEST_CASE("penetration: the first squares rotated by (c, s) = (3, 4), a rotation scaled by 5")
{
    // 3/5 and 4/5 are not doubles, so the rotation by (3/5, 4/5) is given as the exact scaled
    // rotation (3, 4) (factor 5) on both shapes: the relative geometry is the first case's scaled
    // by 5 and rotated, so depth 5 (squared 25), n = R (1,0) / 5 = (3/5, 4/5), a* = R (2, 5/4) =
    // (6 - 5, 8 + 15/4) = (1, 47/4), b* = R (1, 5/4) = (3 - 5, 4 + 15/4) = (-2, 31/4). The radii
    // are world lengths (not scaled): 1/4 and 1/2, signed -(5 + 3/4), pA = (1 + 3/20, 47/4 + 1/5)
    // = (23/20, 239/20), pB = (-2 - 3/10, 31/4 - 2/5) = (-23/10, 147/20).
    Shape a = square(0, 0, 2, 2, 0.25), b = square(1, 0.5, 3, 2.5, 0.5);
    for (Shape* s : {&a, &b})
    {
        s->c = 3;
        s->s = 4;
    }
    const Result r = checkSigned(a, b, true);
    CHECK(r.depthSquaredNum == "25");
    CHECK(r.signedDistance == -5.75);
    checkPair(r, 1.15, 11.95, -2.3, 7.35); // the literals are the correctly rounded rationals
    // The same with the inexact doubles (0.6, 0.8), a rotation scaled by 1 - 2^-54-ish: checked
    // against the brute force and the routes only.
    for (Shape* s : {&a, &b})
    {
        s->c = 0.6;
        s->s = 0.8;
    }
    const Result q = checkSigned(a, b, true);
    CHECK(q.signedDistance == Approx(-1.75).margin(1e-15));
}

TEST_CASE("penetration: one shape a point or a segment")
{
    // A = [0,4] x [0,2], B = {(1, 3/2)}: Z = [-1,3] x [-3/2, 1/2], distances 1, 3, 3/2, 1/2: the
    // top y = 1/2 (A's top edge minus the point), depth 1/2, a* = (1, 2), b* = (1, 3/2).
    const Result p = checkSigned(square(0, 0, 4, 2), shape({{1, 1.5}}), true);
    CHECK(p.depthSquaredNum == "1");
    CHECK(p.depthSquaredDen == "4");
    CHECK(p.signedDistance == -0.5);
    checkPair(p, 1, 2, 1, 1.5);
    // rB = 1/4: signed -3/4, pB = (1, 3/2 - 1/4).
    const Result pr = checkSigned(square(0, 0, 4, 2), shape({{1, 1.5}}, 0.25), true);
    CHECK(pr.signedDistance == -0.75);
    checkPair(pr, 1, 2, 1, 1.25);
    // B the segment (1, 3/2)-(3, 3/2), parallel to A's top: Z = [-3,3] x [-3/2, 1/2], the top y =
    // 1/2 from (3, 1/2) = (4,2) - (1,3/2) to (-3, 1/2) = (0,2) - (3,3/2), A's top edge plus -B's
    // (parallel): the foot (0, 1/2) at t = 1/2 divides both: a* = (2, 2), b* = (2, 3/2).
    const Result s = checkSigned(square(0, 0, 4, 2), shape({{1, 1.5}, {3, 1.5}}), true);
    CHECK(s.signedDistance == -0.5);
    checkPair(s, 2, 2, 2, 1.5);
    // A the segment (0,0)-(4,0) with radius 1, B = {(1, 0)}: Z is the segment (-1,0)-(3,0) through
    // O, depth 0 on both of its sides (normals (0,1) and (0,-1)): the least angle, (0, 1). So
    // pA = (1, 0) + 1 (0, 1) = (1, 1), pB = (1, 0), signed -1.
    const Result g = checkSigned(shape({{0, 0}, {4, 0}}, 1), shape({{1, 0}}), true);
    CHECK(g.depthSquaredNum == "0");
    CHECK(g.signedDistance == -1.0);
    checkPair(g, 1, 1, 1, 0);
    // Two equal points with radii 1/2 and 1/4: Z = {O}, every direction a normal, the least (1, 0):
    // pA = (1 + 1/2, 2), pB = (1 - 1/4, 2), signed -3/4.
    const Result e = checkSigned(shape({{1, 2}}, 0.5), shape({{1, 2}}, 0.25), true);
    CHECK(e.signedDistance == -0.75);
    checkPair(e, 1.5, 2, 0.75, 2);
}

TEST_CASE("penetration: deep overlap, the minimal translation along the shorter axis")
{
    // A = [0,10] x [0,2], B = [4,6] x [1/4, 3/2] inside it. Z = [0-6, 10-4] x [0-3/2, 2-1/4] =
    // [-6,6] x [-3/2, 7/4]: distances 6, 6, 3/2 (bottom), 7/4 (top): the bottom y = -3/2, n =
    // (0,-1), from (-6,-3/2) = (0,0) - (6,3/2) to (6,-3/2) = (10,0) - (4,3/2), foot (0,-3/2) at t =
    // 1/2: a* = (5, 0), b* = (5, 3/2); B moves down by 3/2 (not sideways by 6).
    const Result r = checkSigned(square(0, 0, 10, 2), square(4, 0.25, 6, 1.5), true);
    CHECK(r.depthSquaredNum == "9");
    CHECK(r.depthSquaredDen == "4");
    CHECK(r.signedDistance == -1.5);
    checkPair(r, 5, 0, 5, 1.5);
    // Symmetric (B = [4,6] x [1/2, 3/2]): top and bottom tie at 3/2; the least normal angle is
    // the top's (0, 1) (pi/2 against 3 pi/2): a* = (5, 2), b* = (5, 1/2).
    const Result t = checkSigned(square(0, 0, 10, 2), square(4, 0.5, 6, 1.5), true);
    CHECK(t.signedDistance == -1.5);
    checkPair(t, 5, 2, 5, 0.5);
}

TEST_CASE("penetration: irrational depth, cores apart with overlapping radii")
{
    // A the triangle (0,0), (4,0), (0,4), B = {(3/2, 3/2)}: the hypotenuse x + y = 4 is (4 - 3) /
    // sqrt 2 away, the legs 3/2: depth^2 = 1/2, the foot (2, 2) = a*, b* = (3/2, 3/2), n = (1,1)/
    // sqrt 2. With rA = 1: pA = (2 + 1/sqrt 2, 2 + 1/sqrt 2), signed -(1/sqrt 2 + 1).
    const Shape a = shape({{0, 0}, {4, 0}, {0, 4}}, 1);
    const Result r = checkSigned(a, shape({{1.5, 1.5}}), true);
    CHECK(r.depthSquaredNum == "1");
    CHECK(r.depthSquaredDen == "2");
    const mpq_class two = 2;
    // pA.x rounds 2 + 1/sqrt(2): cmpShifted(w, a, q, m) = sign(w + a / sqrt(q) - m)
    CHECK(roundsTo(r.penetrationA.x, [&](const mpq_class& m) { return cmpShifted(2, 1, two, m); }));
    CHECK(r.penetrationA.x == r.penetrationA.y);
    CHECK(r.penetrationB.x == 1.5);
    // Cores apart, radii overlapping: A = [0,1]^2 with rA = 1, B = {(2, 1/2)} with rB = 1/2: core
    // distance 1, signed 1 - 3/2 = -1/2 (distance clamped at 0); the pair is the witnesses moved
    // by the radii: pA = (1,1/2) + (1,0) = (2, 1/2), pB = (2,1/2) - (1/2,0) = (3/2, 1/2).
    const Result s = checkSigned(square(0, 0, 1, 1, 1), shape({{2, 0.5}}, 0.5), true);
    CHECK_FALSE(s.overlap);
    CHECK(s.distance == 0);
    CHECK(s.signedDistance == -0.5);
    CHECK(s.depthSquaredNum.empty());
    checkPair(s, 2, 0.5, 1.5, 0.5);
    // Apart with a positive signed distance: the distance itself (3 - 1/2).
    const Result d = checkSigned(square(0, 0, 1, 1), shape({{4, 0.5}}, 0.5), true);
    CHECK(d.signedDistance == 2.5);
    CHECK(d.distance == 2.5);
}

namespace
{

// Small random shapes near one another (mostly overlapping): general doubles under rotations, or
// small-integer grids (collinear, duplicate, touching configurations), some with radii.
Shape nearbyShape(std::mt19937_64& rng, bool grid)
{
    std::uniform_int_distribution<int> count(1, 6), cell(-3, 3), coin(0, 3);
    std::uniform_real_distribution<double> unit(-1, 1), angle(0, 6.283185307179586), radius(0, 0.5);
    Shape s;
    const int n = count(rng);
    for (int i = 0; i < n; ++i)
        s.points.push_back(grid ? Point{double(cell(rng)), double(cell(rng))}
                                : Point{2 * unit(rng), 2 * unit(rng)});
    if (grid)
    {
        static const double quarter[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
        const int k = coin(rng);
        s.c = quarter[k][0];
        s.s = quarter[k][1];
        s.px = cell(rng) / 2.0;
        s.py = cell(rng) / 2.0;
    }
    else
    {
        const double a = angle(rng);
        s.c = std::cos(a);
        s.s = std::sin(a);
        s.px = unit(rng);
        s.py = unit(rng);
    }
    if (coin(rng) == 0)
        s.radius = radius(rng);
    return s;
}

void randomSigned(bool grid, int count)
{
    const std::uint64_t seed = std::random_device{}(); // a new draw each run: cases not kept here
    INFO("seed " << seed << (grid ? " (grid)" : " (doubles)"));
    std::mt19937_64 rng(seed);
    Counts counts;
    for (int k = 0; k < count; ++k)
    {
        const Shape a = nearbyShape(rng, grid), b = nearbyShape(rng, grid);
        INFO("case " << k);
        checkSigned(a, b, true, &counts);
    }
    INFO(counts.overlaps << " of " << count << " overlapping");
    CHECK(counts.overlaps > count / 3);
    CHECK(counts.overlaps < count); // some apart too
}

} // namespace

TEST_CASE("penetration: random overlapping doubles, routes and filter agree with bruteForceSigned")
{
    randomSigned(false, 400);
}

TEST_CASE("penetration: random overlapping small-integer grids agree with bruteForceSigned")
{
    randomSigned(true, 400);
}

TEST_CASE("penetration: larger random polygons, routes and filter agree")
{
    const std::uint64_t seed = std::random_device{}();
    INFO("seed " << seed);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), angle(0, 6.283185307179586);
    for (int k = 0; k < 40; ++k)
    {
        Shape s[2];
        for (Shape& x : s)
        {
            const int n = 10 + k % 20;
            for (int i = 0; i < n; ++i)
            {
                const double t = angle(rng);
                x.points.push_back({std::cos(t), std::sin(t) * 0.5});
            }
            const double a = angle(rng);
            x.c = std::cos(a);
            x.s = std::sin(a);
            x.px = unit(rng) * 0.5;
            x.py = unit(rng) * 0.5;
        }
        INFO("case " << k);
        checkSigned(s[0], s[1], false);
    }
}

TEST_CASE("penetration: bruteForceSigned fields")
{
    // A = [0,2]^2, B = [1,3] x [1/2,5/2] (the first case): depth 1, the pair left at 0.
    const Result r = exact::bruteForceSigned(square(0, 0, 2, 2), square(1, 0.5, 3, 2.5));
    CHECK(r.hasSigned);
    CHECK(r.overlap);
    CHECK(r.depthSquaredNum == "1");
    CHECK(r.signedDistance == -1.0);
    CHECK(r.penetrationA.x == 0);
    CHECK(r.penetrationB.x == 0);
    CHECK_THROWS_AS(exact::bruteForceSigned(Shape{}, square(0, 0, 1, 1)), std::invalid_argument);
}

TEST_CASE("penetration: the filter decides plain overlaps, the depth rational only when asked for")
{
    // The first case again under an inexact rotation (0.6, 0.8) of both shapes: the filter is to
    // decide it (no GMP), and with Options::squaredRational = false leave both rationals out.
    Shape a = square(0, 0, 2, 2, 0.25), b = square(1, 0.5, 3, 2.5, 0.5);
    for (Shape* s : {&a, &b})
    {
        s->c = 0.6;
        s->s = 0.8;
    }
    Options o;
    o.penetration = true;
    const Result full = exact::distance(a, b, o);
    o.squaredRational = false;
    const Result lazy = exact::distance(a, b, o);
    CHECK_FALSE(full.fallbacks.gmp);
    CHECK_FALSE(full.fallbacks.depth);
    CHECK_FALSE(lazy.fallbacks.depth);
    CHECK_FALSE(full.depthSquaredNum.empty());
    CHECK(lazy.depthSquaredNum.empty());
    CHECK(lazy.depthSquaredDen.empty());
    CHECK(sameBits(lazy.signedDistance, full.signedDistance));
    CHECK(sameBits(lazy.penetrationA.x, full.penetrationA.x));
    // The deep overlap's tie (top and bottom both 3/2 away): decided by exact comparison.
    o.squaredRational = true;
    const Result tie = exact::distance(square(0, 0, 10, 2), square(4, 0.5, 6, 1.5), o);
    CHECK(tie.fallbacks.depthTies >= 1);
    CHECK_FALSE(tie.fallbacks.depth);
    CHECK(tie.penetrationA.y == 2);
}
