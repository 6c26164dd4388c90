// All routes and the brute force agree with == on exact values: every degenerate kind (under
// several exact transforms) and thousands of seeded random cases.
#include "support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
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

// Checks everything about one case; returns the exact squared distance.
mpq_class checkCase(const Shape& a, const Shape& b, bool withBruteForce = true)
{
    INFO("A = " << describe(a));
    INFO("B = " << describe(b));
    Options o;
    o.exactWitnesses = true;
    Result first;
    const std::vector<Q2> wa_pts = worldPoints(a), wb_pts = worldPoints(b);
    const mpq_class r = radii(a, b);
    for (Route route : exact::kAllRoutes)
    {
        INFO("route " << exact::routeName(route));
        o.route = route;
        const Result x = exact::distance(a, b, o);
        if (route == exact::kAllRoutes[0])
        {
            first = x;
        }
        else
        {
            CHECK(x.squaredNum == first.squaredNum);
            CHECK(x.squaredDen == first.squaredDen);
            CHECK(x.overlap == first.overlap);
            CHECK(x.distance == first.distance);
            CHECK(x.squared == first.squared);
        }
        const mpq_class q = squaredOf(x);
        CHECK(x.overlap == (sgn(q) == 0));
        const Q2 wa = exactPoint(x.exactWitnessA), wb = exactPoint(x.exactWitnessB);
        CHECK(inHull(wa, wa_pts));
        CHECK(inHull(wb, wb_pts));
        const mpq_class dx = wb.x - wa.x, dy = wb.y - wa.y;
        CHECK(dx * dx + dy * dy == q);
        CHECK(distanceRoundsTo(x.distance, q, r));
        CHECK(encloses(x.lower, x.upper, q, r));
        CHECK(x.lower <= x.distance);
        CHECK(x.distance <= x.upper);
        CHECK(rationalRoundsTo(x.squared, q));
    }
    if (withBruteForce)
    {
        const Result bf = exact::bruteForce(a, b);
        CHECK(bf.squaredNum == first.squaredNum);
        CHECK(bf.squaredDen == first.squaredDen);
        CHECK(bf.overlap == first.overlap);
        CHECK(bf.distance == first.distance);
    }
    return squaredOf(first);
}

struct Base
{
    const char* name;
    std::vector<exact::Point> a, b;
    const char* squared; // expected exact squared distance, untransformed
    bool overlap;
};

std::vector<Base> degenerateKinds()
{
    const double e = std::ldexp(1.0, -52);
    return {
        {"point-point", {{0, 0}}, {{3, 4}}, "25", false},
        {"equal points", {{1, 2}}, {{1, 2}}, "0", true},
        {"point inside segment", {{0, 0}, {4, 0}}, {{1, 0}}, "0", true},
        {"point on segment line beyond it", {{0, 0}, {4, 0}}, {{6, 0}}, "4", false},
        {"point off segment", {{0, 0}, {4, 0}}, {{1, 3}}, "9", false},
        {"collinear overlapping segments", {{0, 0}, {4, 0}}, {{2, 0}, {6, 0}}, "0", true},
        {"collinear disjoint segments", {{0, 0}, {1, 0}}, {{3, 0}, {5, 0}}, "4", false},
        {"collinear segments touching at an end", {{0, 0}, {2, 0}}, {{2, 0}, {5, 0}}, "0", true},
        {"parallel segments", {{0, 0}, {2, 0}}, {{1, 1}, {3, 1}}, "1", false},
        {"crossing segments", {{0, 0}, {2, 2}}, {{0, 2}, {2, 0}}, "0", true},
        {"T-touching segments", {{0, 0}, {2, 0}}, {{1, 0}, {1, 3}}, "0", true},
        {"skew segments", {{0, 0}, {2, 0}}, {{3, 1}, {4, 5}}, "2", false},
        {"all points equal",
         {{1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}},
         {{2, 2}, {3, 2}, {3, 3}, {2, 3}},
         "2",
         false},
        {"collinear unordered with duplicates",
         {{3, 3}, {0, 0}, {1, 1}, {2, 2}, {1, 1}},
         {{4, 0}},
         "8",
         false},
        {"clockwise input", {{0, 0}, {0, 2}, {2, 2}, {2, 0}}, {{3, 1}}, "1", false},
        {"unordered with interior points",
         {{1, 1}, {2, 0}, {0, 0}, {0.5, 0.5}, {2, 2}, {1, 0.25}, {0, 2}},
         {{-1, 3}},
         "2",
         false},
        {"touching vertex to vertex",
         {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
         {{1, 1}, {2, 1}, {2, 2}, {1, 2}},
         "0",
         true},
        {"touching vertex to edge",
         {{0, 0}, {2, 0}, {2, 2}, {0, 2}},
         {{2, 1}, {3, 0}, {3, 2}},
         "0",
         true},
        {"touching along part of an edge",
         {{0, 0}, {2, 0}, {2, 2}, {0, 2}},
         {{2, 1}, {4, 1}, {4, 3}, {2, 3}},
         "0",
         true},
        {"one inside the other",
         {{0, 0}, {10, 0}, {10, 10}, {0, 10}},
         {{1, 1}, {2, 1}, {1, 2}},
         "0",
         true},
        {"identical",
         {{0, 0}, {3, 1}, {1, 4}, {-1, 2}},
         {{0, 0}, {3, 1}, {1, 4}, {-1, 2}},
         "0",
         true},
        {"near miss by 2^-52",
         {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
         {{1 + e, 0.5}},
         "1/20282409603651670423947251286016",
         false},
        {"near touch collinear",
         {{0, 0}, {1, 0}},
         {{1 + e, 0}, {2, 0}},
         "1/20282409603651670423947251286016",
         false},
        {"parallel edges, separated",
         {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
         {{2, 0.5}, {3, 0.5}, {3, 1.5}, {2, 1.5}},
         "1",
         false},
        {"segment parallel to an edge",
         {{0, 3}, {5, 3}},
         {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
         "4",
         false},
    };
}

struct Transform
{
    const char* name;
    double c, s, px, py;
};

} // namespace

TEST_CASE("degenerate kinds: all routes and brute force agree, under exact transforms")
{
    const Transform transforms[] = {
        {"identity", 1, 0, 0, 0},
        {"scale 1e-300", 1e-300, 0, 0, 0},
        {"scale 1e300", 1e300, 0, 0, 0},
        {"quarter turn", 0, 1, 1, -1},
        {"rotation 0.3 rad + translation", std::cos(0.3), std::sin(0.3), 0.1, -7.25},
        {"translation 1e300", 1, 0, 1e300, -1e300},
        {"scaled eighth turn c = s = 1/2", 0.5, 0.5, 0, 0},
        {"rotation near 1e-150 scale", 3e-150 * std::cos(2.0), 3e-150 * std::sin(2.0), 1e-140, 0},
    };
    int cases = 0;
    for (const Base& base : degenerateKinds())
    {
        for (const Transform& t : transforms)
        {
            INFO(base.name << " under " << t.name);
            for (int swap = 0; swap < 2; ++swap)
            {
                Shape a = shape(swap ? base.b : base.a), b = shape(swap ? base.a : base.b);
                for (Shape* s : {&a, &b})
                {
                    s->c = t.c;
                    s->s = t.s;
                    s->px = t.px;
                    s->py = t.py;
                }
                const mpq_class q = checkCase(a, b);
                // The map is a similarity with factor sqrt(c^2 + s^2), applied exactly: squared
                // distances scale by c^2 + s^2 and touching stays touching.
                const mpq_class c(t.c), s(t.s);
                CHECK(q == parseQ(base.squared) * (c * c + s * s));
                ++cases;
            }
        }
    }
    CHECK(cases == static_cast<int>(degenerateKinds().size()) * 8 * 2);
}

namespace
{

// Random shapes of several kinds (fixed seed): general doubles, small-integer grids (collinear,
// duplicate and touching configurations everywhere), and grids at extreme scales.
Shape randomShape(std::mt19937_64& rng, int kind, int maxPoints)
{
    std::uniform_int_distribution<int> count(1, maxPoints), grid(-3, 3), coin(0, 3);
    std::uniform_real_distribution<double> unit(-1, 1), angle(0, 6.283185307179586), radius(0, 0.5);
    Shape s;
    const int n = count(rng);
    for (int i = 0; i < n; ++i)
    {
        if (kind == 0)
            s.points.push_back({unit(rng), unit(rng)});
        else
            s.points.push_back({double(grid(rng)), double(grid(rng))});
    }
    if (kind == 0)
    {
        const double a = angle(rng);
        s.c = std::cos(a);
        s.s = std::sin(a);
        s.px = 2 * unit(rng);
        s.py = 2 * unit(rng);
    }
    else
    {
        static const double quarter[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
        const int k = coin(rng);
        s.c = quarter[k][0];
        s.s = quarter[k][1];
        s.px = grid(rng);
        s.py = grid(rng);
        if (kind == 2)
        { // extreme scales: both shapes share the scale (set by the caller)
            s.c *= 0.5;
            s.s *= 0.5;
        }
    }
    if (coin(rng) == 0)
        s.radius = radius(rng);
    return s;
}

void randomAgreement(int kind, int count, int maxPoints, std::uint64_t seed)
{
    std::mt19937_64 rng(seed);
    int overlaps = 0;
    for (int k = 0; k < count; ++k)
    {
        Shape a = randomShape(rng, kind, maxPoints), b = randomShape(rng, kind, maxPoints);
        if (kind == 2)
        {
            const double scale = (k % 2) ? 1e-300 : 1e300;
            for (Shape* s : {&a, &b})
            {
                s->c *= scale;
                s->s *= scale;
                s->px *= scale;
                s->py *= scale;
                s->radius *= scale;
            }
        }
        INFO("kind " << kind << " case " << k);
        const mpq_class q = checkCase(a, b);
        overlaps += sgn(q) == 0;
    }
    // both outcomes must be exercised
    CHECK(overlaps > count / 20);
    CHECK(overlaps < count - count / 20);
}

} // namespace

TEST_CASE("random doubles with rotations: routes and brute force agree")
{
    randomAgreement(0, 1500, 8, 1);
}

TEST_CASE("random small-integer grids (degenerate-rich): routes and brute force agree")
{
    randomAgreement(1, 1500, 7, 2);
}

TEST_CASE("random grids at scales 1e-300 and 1e300: routes and brute force agree")
{
    randomAgreement(2, 600, 6, 3);
}

TEST_CASE("larger random polygons: routes agree (no brute force)")
{
    std::mt19937_64 rng(4);
    std::uniform_int_distribution<int> count(9, 40);
    std::uniform_real_distribution<double> unit(-1, 1), angle(0, 6.283185307179586);
    for (int k = 0; k < 150; ++k)
    {
        Shape s[2];
        for (Shape& sh : s)
        {
            const int n = count(rng);
            for (int i = 0; i < n; ++i)
            {
                const double t = angle(rng),
                             r = k % 3 == 0 ? 1.0 : std::sqrt(0.5 + 0.5 * unit(rng));
                sh.points.push_back({r * std::cos(t), r * std::sin(t)});
            }
            const double a = angle(rng);
            sh.c = std::cos(a);
            sh.s = std::sin(a);
            sh.px = 1.5 * unit(rng);
            sh.py = 1.5 * unit(rng);
        }
        INFO("case " << k);
        checkCase(s[0], s[1], false);
    }
}
