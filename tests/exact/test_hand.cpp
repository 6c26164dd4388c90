// Hand-computed exact cases: the expected rationals are derived in the comments and checked on
// every route and on the brute force.
#include "support.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace exact_test;
using exact::Options;
using exact::Result;
using exact::Route;

namespace
{

// Runs every route (exact witnesses on) and the brute force; all must agree on the exact squared
// distance and overlap; returns the default route's result.
Result all(const Shape& a, const Shape& b)
{
    Options o;
    o.exactWitnesses = true;
    const Result def = exact::distance(a, b, o);
    for (Route r : exact::kAllRoutes)
    {
        o.route = r;
        const Result x = exact::distance(a, b, o);
        INFO("route " << exact::routeName(r));
        CHECK(x.squaredNum == def.squaredNum);
        CHECK(x.squaredDen == def.squaredDen);
        CHECK(x.overlap == def.overlap);
        CHECK(x.distance == def.distance);
        // witnesses may differ between routes only when the closest pair is not unique; they must
        // always be on their hulls and realise the distance
        const Q2 wa = exactPoint(x.exactWitnessA), wb = exactPoint(x.exactWitnessB);
        CHECK(inHull(wa, worldPoints(a)));
        CHECK(inHull(wb, worldPoints(b)));
        const mpq_class dx = wb.x - wa.x, dy = wb.y - wa.y;
        CHECK(dx * dx + dy * dy == squaredOf(x));
    }
    const Result bf = exact::bruteForce(a, b);
    CHECK(bf.squaredNum == def.squaredNum);
    CHECK(bf.squaredDen == def.squaredDen);
    CHECK(bf.overlap == def.overlap);
    CHECK(bf.distance == def.distance);
    return def;
}

Shape square(double x0, double y0, double x1, double y1)
{
    return shape({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

} // namespace

TEST_CASE("unit square vs point (2, 1/2): squared 1")
{
    // Closest feature: the right edge x = 1; foot of the perpendicular (1, 1/2); squared (2-1)^2
    // = 1.
    const Result r = all(square(0, 0, 1, 1), shape({{2, 0.5}}));
    CHECK(r.squaredNum == "1");
    CHECK(r.squaredDen == "1");
    CHECK_FALSE(r.overlap);
    CHECK(r.squared == 1.0);
    CHECK(r.distance == 1.0);
    CHECK(r.lower == 1.0);
    CHECK(r.upper == 1.0);
    CHECK(r.exactWitnessA.x == "1");
    CHECK(r.exactWitnessA.y == "1/2");
    CHECK(r.exactWitnessB.x == "2");
    CHECK(r.exactWitnessB.y == "1/2");
    CHECK(r.witnessA.x == 1.0);
    CHECK(r.witnessA.y == 0.5);
}

TEST_CASE("slanted edge: squared 1/5")
{
    // Triangle (0,0), (1,0), (0,2) vs point (1,1). The edge from (1,0) to (0,2) lies on 2x + y = 2;
    // (1,1) gives 2 + 1 - 2 = 1 > 0, so it is outside, at distance 1/sqrt(2^2 + 1^2) = 1/sqrt(5):
    // squared 1/5. Foot: (1,1) - (1/5)(2,1) = (3/5, 4/5) = (1,0) + (2/5)(-1,2), inside the edge.
    const Result r = all(shape({{0, 0}, {1, 0}, {0, 2}}), shape({{1, 1}}));
    CHECK(r.squaredNum == "1");
    CHECK(r.squaredDen == "5");
    CHECK(r.exactWitnessA.x == "3/5");
    CHECK(r.exactWitnessA.y == "4/5");
    CHECK(r.exactWitnessB.x == "1");
    CHECK(r.exactWitnessB.y == "1");
    CHECK(distanceRoundsTo(r.distance, mpq_class(1, 5), 0));
    CHECK(r.witnessA.x == 0.6); // the double nearest to 3/5
    CHECK(r.witnessA.y == 0.8);
    CHECK(r.squared == 0.2);
    CHECK(r.lower <= r.distance);
    CHECK(r.distance <= r.upper);
}

TEST_CASE("exact quarter turn c=0, s=1 with translation")
{
    // A = segment (0,0)-(2,0), c = 0, s = 1, px = 1: x' = -y + 1, y' = x, so A is (1,0)-(1,2).
    // B = point (3,1): foot (1,1), squared 2^2 = 4.
    Shape a = shape({{0, 0}, {2, 0}});
    a.c = 0;
    a.s = 1;
    a.px = 1;
    const Result r = all(a, shape({{3, 1}}));
    CHECK(r.squaredNum == "4");
    CHECK(r.squaredDen == "1");
    CHECK(r.distance == 2.0);
    CHECK(r.exactWitnessA.x == "1");
    CHECK(r.exactWitnessA.y == "1");
}

TEST_CASE("non-unit rotation doubles are applied exactly: c = 0.75 scales")
{
    // c = 3/4, s = 0: (0,0), (4,0), (0,4) become (0,0), (3,0), (0,3). B = (3,3) against the edge
    // x + y = 3: distance (3 + 3 - 3)/sqrt(2), squared 9/2; foot (3,3) - (3/2)(1,1) = (3/2, 3/2).
    Shape a = shape({{0, 0}, {4, 0}, {0, 4}});
    a.c = 0.75;
    const Result r = all(a, shape({{3, 3}}));
    CHECK(r.squaredNum == "9");
    CHECK(r.squaredDen == "2");
    CHECK(r.exactWitnessA.x == "3/2");
    CHECK(r.exactWitnessA.y == "3/2");
    CHECK(distanceRoundsTo(r.distance, mpq_class(9, 2), 0));
}

TEST_CASE("scaled 45-degree turn c = s = 1/2")
{
    // B = point (4,0) with c = s = 1/2: x' = 2, y' = 2. Against the unit square the closest point
    // is the corner (1,1): squared 1 + 1 = 2, distance RN(sqrt 2) = std::sqrt(2.0) (IEEE sqrt is
    // correctly rounded). B = (2,0) instead lands exactly on the corner (1,1): touching.
    Shape b = shape({{4, 0}});
    b.c = b.s = 0.5;
    Result r = all(square(0, 0, 1, 1), b);
    CHECK(r.squaredNum == "2");
    CHECK(r.distance == std::sqrt(2.0));
    CHECK(r.exactWitnessA.x == "1");
    CHECK(r.exactWitnessA.y == "1");
    b.points = {{2, 0}};
    r = all(square(0, 0, 1, 1), b);
    CHECK(r.overlap);
    CHECK(r.squaredNum == "0");
    CHECK(r.squaredDen == "1");
    CHECK(r.exactWitnessA.x == "1");
    CHECK(r.exactWitnessB.y == "1");
}

TEST_CASE("radii: moved witnesses and exact distance 3.5")
{
    // Points (0,0) r = 1 and (3,4) r = 0.5: squared 25, distance 5 - 1.5 = 3.5 exactly. Unit
    // direction (3/5, 4/5): witness A (0,0) + (3/5, 4/5), witness B (3,4) - (1/2)(3/5, 4/5) =
    // (27/10, 18/5); rounded to nearest those are the doubles 0.6, 0.8, 2.7, 3.6.
    const Result r = all(shape({{0, 0}}, 1.0), shape({{3, 4}}, 0.5));
    CHECK(r.squaredNum == "25");
    CHECK(r.distance == 3.5);
    CHECK(r.lower == 3.5);
    CHECK(r.upper == 3.5);
    CHECK(r.witnessA.x == 0.6);
    CHECK(r.witnessA.y == 0.8);
    CHECK(r.witnessB.x == 2.7);
    CHECK(r.witnessB.y == 3.6);
    CHECK(r.exactWitnessA.x == "0");
    CHECK(r.exactWitnessB.y == "4");
}

TEST_CASE("radii larger than the gap clamp the distance to 0")
{
    // (0,0) r = 2 and (3,0) r = 2: hulls 3 apart, not overlapping; max(0, 3 - 4) = 0. The witnesses
    // still move by their radius along (1,0): A to (2,0), B to (1,0).
    const Result r = all(shape({{0, 0}}, 2.0), shape({{3, 0}}, 2.0));
    CHECK_FALSE(r.overlap);
    CHECK(r.squaredNum == "9");
    CHECK(r.distance == 0.0);
    CHECK(r.lower == 0.0);
    CHECK(r.upper == 0.0);
    CHECK(r.witnessA.x == 2.0);
    CHECK(r.witnessB.x == 1.0);
    // exactly touching rounded surfaces: 3 - 1.5 - 1.5 = 0
    const Result t = all(shape({{0, 0}}, 1.5), shape({{3, 0}}, 1.5));
    CHECK(t.distance == 0.0);
    CHECK(t.upper == 0.0);
}

TEST_CASE("irrational witness on a rounded surface")
{
    // (0,0) r = 1 vs (1,1): squared 2, distance sqrt(2) - 1, witness A = (1/sqrt 2, 1/sqrt 2) whose
    // correct rounding is std::sqrt(0.5) (0.5 is exact and IEEE sqrt is correctly rounded).
    const Result r = all(shape({{0, 0}}, 1.0), shape({{1, 1}}));
    CHECK(r.squaredNum == "2");
    CHECK(distanceRoundsTo(r.distance, 2, 1));
    CHECK(r.witnessA.x == std::sqrt(0.5));
    CHECK(r.witnessA.y == std::sqrt(0.5));
    CHECK(r.witnessB.x == 1.0);
    CHECK(encloses(r.lower, r.upper, 2, 1));
}

TEST_CASE("overlapping squares: common witness point")
{
    // [0,2]^2 and [1,3]^2 overlap in [1,2]^2: squared 0, and the (single) witness is in both.
    const Result r = all(square(0, 0, 2, 2), square(1, 1, 3, 3));
    CHECK(r.overlap);
    CHECK(r.squaredNum == "0");
    CHECK(r.distance == 0.0);
    CHECK(r.exactWitnessA.x == r.exactWitnessB.x);
    CHECK(r.exactWitnessA.y == r.exactWitnessB.y);
    CHECK(r.witnessA.x == r.witnessB.x);
}

TEST_CASE("touching along an edge")
{
    // [0,1]^2 and [1,2]x[0,1] share the edge x = 1: overlap (on the boundary), witness on it.
    const Result r = all(square(0, 0, 1, 1), square(1, 0, 2, 1));
    CHECK(r.overlap);
    CHECK(r.squaredNum == "0");
    CHECK(r.exactWitnessA.x == "1");
    const mpq_class y = parseQ(r.exactWitnessA.y);
    CHECK(y >= 0);
    CHECK(y <= 1);
}

TEST_CASE("crossing segments meet in exactly one point")
{
    // (0,0)-(2,2) and (0,2)-(2,0) cross at (1,1), the only possible common witness.
    const Result r = all(shape({{0, 0}, {2, 2}}), shape({{0, 2}, {2, 0}}));
    CHECK(r.overlap);
    CHECK(r.exactWitnessA.x == "1");
    CHECK(r.exactWitnessA.y == "1");
    CHECK(r.exactWitnessB.x == "1");
    CHECK(r.exactWitnessB.y == "1");
}

TEST_CASE("parallel segments: squared 1")
{
    // (0,0)-(2,0) and (1,1)-(3,1): parallel at distance 1; closest pairs are vertical over x in
    // [1,2].
    const Result r = all(shape({{0, 0}, {2, 0}}), shape({{1, 1}, {3, 1}}));
    CHECK(r.squaredNum == "1");
    const Q2 wa = exactPoint(r.exactWitnessA), wb = exactPoint(r.exactWitnessB);
    CHECK(wa.x == wb.x);
    CHECK(wa.x >= 1);
    CHECK(wa.x <= 2);
}

TEST_CASE("containment and identical shapes")
{
    const Result in = all(square(-5, -5, 5, 5), shape({{0, 0}, {1, 0}, {0, 1}}));
    CHECK(in.overlap);
    Shape p = shape({{0, 0}, {3, 1}, {1, 4}, {-1, 2}, {1, 1}});
    p.c = std::cos(0.7);
    p.s = std::sin(0.7);
    p.px = 0.1;
    const Result same = all(p, p);
    CHECK(same.overlap);
    CHECK(same.squaredNum == "0");
}

TEST_CASE("tiny coordinates 1e-300: exact where doubles underflow")
{
    // Unit square and point (2, 1/2), both scaled by c = 1e-300 (t below): the distance is exactly
    // t, so squared = t^2 (about 1e-600: 0 as a double) and distance == t.
    const double t = 1e-300;
    Shape a = square(0, 0, 1, 1), b = shape({{2, 0.5}});
    a.c = b.c = t;
    const Result r = all(a, b);
    const mpq_class tq(t);
    CHECK(squaredOf(r) == tq * tq);
    CHECK(r.squared == 0.0);
    CHECK(r.distance == t);
    CHECK_FALSE(r.overlap);
    // witness B = (2t, t/2) exactly
    CHECK(parseQ(r.exactWitnessB.x) == 2 * tq);
    CHECK(r.witnessB.y == t / 2);
}

TEST_CASE("huge coordinates 1e300: squared overflows, distance does not")
{
    const double h = 1e300;
    Shape a = square(0, 0, 1, 1), b = shape({{2, 0.5}});
    a.c = b.c = h;
    Result r = all(a, b);
    const mpq_class hq(h);
    CHECK(squaredOf(r) == hq * hq);
    CHECK(std::isinf(r.squared));
    CHECK(r.distance == h);
    CHECK(std::isfinite(r.upper));
    // (0,0) vs (1e300, 1e300): distance sqrt(2) * 1e300
    r = all(shape({{0, 0}}), shape({{h, h}}));
    CHECK(squaredOf(r) == 2 * hq * hq);
    CHECK(distanceRoundsTo(r.distance, 2 * hq * hq, 0));
    CHECK(encloses(r.lower, r.upper, 2 * hq * hq, 0));
    // mixed scales: a point near 1e300 and a point near 1e-300
    r = all(shape({{h, -h}}, 1e299), shape({{1e-300, 3e-300}}, 1e-300));
    const mpq_class dx = mpq_class(1e-300) - hq, dy = mpq_class(3e-300) + hq;
    CHECK(squaredOf(r) == dx * dx + dy * dy);
    CHECK(distanceRoundsTo(r.distance, dx * dx + dy * dy, mpq_class(1e299) + mpq_class(1e-300)));
}

TEST_CASE("subnormal coordinates")
{
    const double d = 4.9406564584124654e-324; // 2^-1074
    const Result r = all(shape({{0, 0}}), shape({{3 * d, 4 * d}}));
    CHECK(r.distance == 5 * d);
    CHECK(r.squared == 0.0);
    CHECK(r.witnessB.x == 3 * d);
}

TEST_CASE("beyond DBL_MAX: exact inside, infinite when rounded")
{
    // B = (1.5e308, 0) translated by px = 1.5e308: world x = 3e308 exactly (not a double). Against
    // A = (0,0): squared (3e308)^2, distance 3e308 > DBL_MAX + ulp/2, so it rounds to +inf; the
    // enclosure is [DBL_MAX, +inf].
    Shape b = shape({{1.5e308, 0}});
    b.px = 1.5e308;
    const Result r = all(shape({{0, 0}}), b);
    const mpq_class x = mpq_class(1.5e308) * 2;
    CHECK(squaredOf(r) == x * x);
    CHECK(std::isinf(r.distance));
    CHECK(r.lower == DBL_MAX);
    CHECK(std::isinf(r.upper));
    CHECK(std::isinf(r.witnessB.x));
    // the same geometry moved back into range by a radius: 3e308 - 2e308 = 1e308
    b.radius = 1e308;
    Shape a = shape({{0, 0}}, 1e308);
    const Result s = all(a, b);
    CHECK(distanceRoundsTo(s.distance, x * x, mpq_class(1e308) + mpq_class(1e308)));
    CHECK(std::isfinite(s.distance));
}
