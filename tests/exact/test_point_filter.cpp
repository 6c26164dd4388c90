// exact::pointToShapeDistance decided in floating point (exact/src/filter.cpp,
// filteredPointDistance; docs/exact.md "Point to shape") gives the GMP route's distance bit for bit
// on hostile points: exactly at world vertices, one ulp around them, on edges (midpoints rounded),
// far from the origin, at extreme scales, under inexact and non-unit rotations, with radii, on
// collinear and duplicate points; and on GJK's own witness points, the points the runner measures.
// Each point also goes through a PreparedShape, the one-shot call and the route before prepared
// shapes, with the same bits and the same route. Each test also asserts that the filter decides a
// share of the points itself, so that a filter that always falls back (only slower) fails it.
#include "support.hpp"

#include "../../exact/src/internal.hpp" // detail::pointDistance, the route before PreparedShape

#include <gjk2d/distance.hpp>

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

using exact::Options;
using exact::Point;
using exact::Shape;

namespace
{

std::uint64_t bits(double v)
{
    return std::bit_cast<std::uint64_t>(v);
}

struct Tally
{
    int points = 0, gmp = 0;
};

// The prepared-shape route (exact::PreparedShape, reused across a shape's points) against the
// one-shot call, the route before prepared shapes (detail::pointDistance: hull and merge of the
// one-point shape per call) and the GMP route (a one-point shape, Options::filter = false): the
// same bits, and the same decision whether the GMP route measured the point.
void filteredEqualsGmp(const exact::PreparedShape& ps, Point p, Tally& t)
{
    const Shape& s = ps.shape();
    bool gmp = true, gmpOneShot = true, gmpSolver = true;
    const double f = exact::pointToShapeDistance(ps, p, &gmp);
    const double one = exact::pointToShapeDistance(s, p, &gmpOneShot);
    Shape q;
    q.points = {p};
    const double solver = exact::detail::pointDistance(q, s, gmpSolver);
    Options o;
    o.filter = false;
    const exact::Result e = exact::distance(q, s, o);
    INFO("point (" << p.x << ", " << p.y << "), radius " << s.radius << ", c " << s.c << ", s "
                   << s.s << ", hull " << ps.hullSize());
    CHECK(e.fallbacks.gmp);
    CHECK(bits(f) == bits(e.distance));
    CHECK(bits(one) == bits(e.distance));
    CHECK(bits(solver) == bits(e.distance));
    CHECK(gmp == gmpSolver);
    CHECK(gmpOneShot == gmpSolver);
    ++t.points;
    t.gmp += gmp ? 1 : 0;
}

void filteredEqualsGmp(const Shape& s, Point p, Tally& t)
{
    filteredEqualsGmp(exact::PreparedShape(s), p, t);
}

// The world point of local p, rounded as a caller would compute it (within a few u R of the
// exact one): the hostile points sit around it.
Point world(const Shape& s, Point p)
{
    return {s.c * p.x - s.s * p.y + s.px, s.s * p.x + s.c * p.y + s.py};
}

double step(double v, int k) // k ulps up (k > 0) or down
{
    for (; k > 0; --k)
        v = std::nextafter(v, HUGE_VAL);
    for (; k < 0; ++k)
        v = std::nextafter(v, -HUGE_VAL);
    return v;
}

// A shape of kind 0 random, 1 collinear, 2 duplicates, 3 small integers, at scale 2^e, with
// rotation kind: identity, quarter turn, (cos, sin) of an angle, a non-unit (c, s).
Shape hostileShape(std::mt19937_64& rng, int kind, int e, int rotation, bool radius)
{
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> n(1, 7), small(-4, 4);
    const double scale = std::ldexp(1.0, e);
    Shape s;
    const int count = n(rng);
    const double dx = u(rng), dy = u(rng);
    for (int i = 0; i < count; ++i)
    {
        if (kind == 0)
            s.points.push_back({u(rng) * scale, u(rng) * scale});
        else if (kind == 1)
            s.points.push_back({i * dx * scale, i * dy * scale}); // collinear up to rounding
        else if (kind == 2)
            s.points.push_back(i % 2 ? Point{dx * scale, dy * scale} : Point{0, scale});
        else
            s.points.push_back({small(rng) * scale, small(rng) * scale});
    }
    const double t = 6.283185307179586 * std::fabs(u(rng));
    if (rotation == 1)
        s.c = 0, s.s = 1;
    else if (rotation == 2)
        s.c = std::cos(t), s.s = std::sin(t);
    else if (rotation == 3)
        s.c = 1.3 * std::cos(t), s.s = 0.7 * std::sin(t) + 0.01; // not a unit rotation
    if (rng() % 2)
        s.px = 4 * u(rng) * scale, s.py = 4 * u(rng) * scale;
    if (rng() % 8 == 0) // far from the origin: a translation 2^30 times the shape's size
        s.px = std::ldexp(u(rng), 30) * scale, s.py = std::ldexp(u(rng), 30) * scale;
    if (radius)
        s.radius = 0.25 * std::fabs(u(rng)) * scale;
    return s;
}

// The hostile points of a shape: each world vertex rounded and its eight one-ulp neighbours, the
// rounded midpoints of every pair of points and one ulp off them, a point outside.
std::vector<Point> hostilePoints(const Shape& s)
{
    std::vector<Point> out;
    std::vector<Point> w;
    for (const Point& p : s.points)
        w.push_back(world(s, p));
    for (const Point& v : w)
        for (int i = -1; i <= 1; ++i)
            for (int j = -1; j <= 1; ++j)
                out.push_back({step(v.x, i), step(v.y, j)});
    for (std::size_t i = 0; i < w.size(); ++i)
        for (std::size_t j = i + 1; j < w.size(); ++j)
        {
            const Point m{0.5 * (w[i].x + w[j].x), 0.5 * (w[i].y + w[j].y)};
            out.push_back(m);
            out.push_back({step(m.x, 1), m.y});
            out.push_back({m.x, step(m.y, -1)});
        }
    out.push_back({w[0].x * 3 + 1e-3, w[0].y - 2});
    return out;
}

} // namespace

TEST_CASE("pointToShapeDistance in floating point equals the GMP route on hostile points",
          "[exact][filter][point]")
{
    std::mt19937_64 rng(3434);
    const int scales[] = {-498, -60, 0, 60, 498}; // 2^-498 ~ 1e-150, 2^498 ~ 1e150
    Tally all, ordinary;
    for (int kind = 0; kind < 4; ++kind)
        for (int e : scales)
            for (int rotation = 0; rotation < 4; ++rotation)
                for (int k = 0; k < 6; ++k)
                {
                    const Shape s = hostileShape(rng, kind, e, rotation, k % 2 == 1);
                    INFO("kind " << kind << " scale 2^" << e << " rotation " << rotation
                                 << " shape " << k);
                    const exact::PreparedShape prepared(s);
                    Tally t;
                    for (const Point& p : hostilePoints(s))
                        filteredEqualsGmp(prepared, p, t);
                    all.points += t.points;
                    all.gmp += t.gmp;
                    if (kind == 0 && rotation == 2)
                    {
                        ordinary.points += t.points;
                        ordinary.gmp += t.gmp;
                    }
                }
    INFO("GMP route for " << all.gmp << " of " << all.points << " points, " << ordinary.gmp
                          << " of " << ordinary.points << " on random shapes");
    // The points left to GMP are mostly far outside a 2^-498 shape, whose products underflow, or
    // within the bound of a midpoint; on random shapes they are rare. Both checks leave a wide
    // margin above what the filter reaches (the INFO line prints the counts).
    CHECK(all.gmp * 4 < all.points);
    CHECK(ordinary.gmp * 20 < ordinary.points);
}

TEST_CASE("pointToShapeDistance at exact vertices and on axis-aligned edges",
          "[exact][filter][point]")
{
    Shape sq;
    sq.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    Tally t;
    for (double r : {0.0, 0.5, 0x1p-60})
    {
        sq.radius = r;
        for (Point p :
             {Point{0, 0}, Point{1, 1}, Point{1, 0.5}, Point{0.5, 1}, Point{1 + 0x1p-52, 0.5},
              Point{-0x1p-1074, 0.5}, Point{1 + 0x1p-52, 1 + 0x1p-52}, Point{3, 5}, Point{1.5, 0.5},
              Point{1 + 0x1p-60, 0.5}})
            filteredEqualsGmp(sq, p, t);
    }
    // Hand values: a vertex at distance 5 (3-4-5 from (1, 1)), 2^-52 off an edge, decided in
    // floating point (exact sums of two doubles).
    sq.radius = 0;
    bool gmp = true;
    CHECK(exact::pointToShapeDistance(sq, {4, 5}, &gmp) == 5.0);
    CHECK_FALSE(gmp);
    CHECK(exact::pointToShapeDistance(sq, {1 + 0x1p-52, 0.5}, &gmp) == 0x1p-52);
    CHECK_FALSE(gmp);
    sq.radius = 0.5; // on the rounded surface exactly: the clamp decided from the exact sign
    CHECK(exact::pointToShapeDistance(sq, {1.5, 0.5}, &gmp) == 0.0);
    CHECK_FALSE(gmp);
    CHECK(t.gmp * 2 < t.points);
}

TEST_CASE("pointToShapeDistance falls back where a product underflows", "[exact][filter][point]")
{
    // fuzz_truth's finding: a rotation of size 95 and subnormal x coordinates.
    // c x_j underflows, so the edge vector's expansion is refused; the filter read its empty
    // component list as "d.x = 0" (an axis-aligned edge) and answered 266.4 where the exact
    // distance rounds to 259.3. Now a refused expansion sends the point to the GMP route.
    Shape s;
    s.points = {{0, 0},
                {0x0.01d3ap-1022, 0x1.64p+6},
                {0x0.03a74p-1022, 0x1.64p+7},
                {0x0.057aep-1022, 0x1.0bp+8}};
    s.c = 0x1.ffffffffffffcp-1, s.s = 0x1.7cp+6;
    s.px = 0x1.0afffffffffffp+8, s.py = 0x1.0f0f0f0f0f0f1p+2;
    s.radius = 0x1.321642c8590b2p-1;
    Tally t;
    filteredEqualsGmp(s, {0x0.057aep-1022, 0x1.0bp+8}, t);
    CHECK(exact::pointToShapeDistance(s, {0x0.057aep-1022, 0x1.0bp+8}) == 0x1.03578a37b2946p+8);
}

TEMPLATE_TEST_CASE("pointToShapeDistance decides GJK's witness points", "[exact][filter][point]",
                   float, double)
{
    // The runner's random family alike: 3-8 points in [-1, 1]^2, a rotation, a translation, a
    // radius on every other case; the witness points of the plain query in T, each measured
    // against its own shape (in T's values, as the runner does for a float variant).
    using T = TestType;
    std::mt19937_64 rng(34 + sizeof(T));
    std::uniform_real_distribution<double> u(-1, 1), angle(0, 6.283185307179586), off(-2.5, 2.5);
    std::uniform_int_distribution<int> n(3, 8);
    Tally t;
    for (int k = 0; k < 1500; ++k)
    {
        std::vector<gjk::Vec2<T>> pts[2];
        Shape s[2];
        gjk::Transform<T> xf[2];
        for (int side = 0; side < 2; ++side)
        {
            for (int i = n(rng); i > 0; --i)
                pts[side].push_back({T(u(rng)), T(u(rng))});
            const double a = angle(rng);
            xf[side].q = {T(std::cos(a)), T(std::sin(a))};
            xf[side].p = {T(off(rng)), T(off(rng))};
            const T radius = k % 2 ? T(0.3 * std::fabs(u(rng))) : T(0);
            for (const auto& p : pts[side])
                s[side].points.push_back({double(p.x), double(p.y)});
            s[side].c = double(xf[side].q.c), s[side].s = double(xf[side].q.s);
            s[side].px = double(xf[side].p.x), s[side].py = double(xf[side].p.y);
            s[side].radius = double(radius);
        }
        gjk::DistanceInput<T> in;
        in.proxyA = {pts[0].data(), int(pts[0].size()), T(s[0].radius)};
        in.proxyB = {pts[1].data(), int(pts[1].size()), T(s[1].radius)};
        in.transformA = xf[0];
        in.transformB = xf[1];
        const gjk::DistanceOutput<T> out = gjk::distance(in);
        INFO("case " << k);
        filteredEqualsGmp(s[0], {double(out.pointA.x), double(out.pointA.y)}, t);
        filteredEqualsGmp(s[1], {double(out.pointB.x), double(out.pointB.y)}, t);
    }
    INFO("GMP route for " << t.gmp << " of " << t.points << " witness points");
    // A witness point lies about u R from its shape, which the expansions decide: GMP is rare.
    CHECK(t.gmp * 100 < t.points);
}

TEST_CASE("PreparedShape on degenerate shapes equals the one-shot and GMP routes",
          "[exact][filter][point]")
{
    // Hulls of 1 and 2 vertices (one point, duplicates, a segment, exactly collinear points,
    // a zero rotation), with and without radius, under a non-unit rotation and at extreme scales;
    // the hostile points of each, all through one PreparedShape.
    struct Case
    {
        std::vector<Point> points;
        int hull;
    };
    const Case cases[] = {{{{0.5, -0.25}}, 1},
                          {{{1, 2}, {1, 2}, {1, 2}}, 1},
                          {{{-1, 0.5}, {2, 1.5}}, 2},
                          {{{0, 0}, {1, 1}, {3, 3}, {2, 2}, {1, 1}}, 2},
                          {{{0, 0}, {0, 3}, {0, 1}}, 2},
                          {{{0, 0}, {1, 0}, {0.5, 0.5}, {0, 1}, {0, 1}, {0.25, 0.25}}, 3}};
    Tally t;
    for (const Case& c : cases)
        for (int e : {-498, 0, 498})
            for (int rotation = 0; rotation < 3; ++rotation)
                for (double r : {0.0, 0.375})
                {
                    Shape s;
                    for (const Point& p : c.points)
                        s.points.push_back({std::ldexp(p.x, e), std::ldexp(p.y, e)});
                    s.radius = std::ldexp(r, e);
                    s.px = std::ldexp(0.75, e), s.py = std::ldexp(-1.5, e);
                    if (rotation == 1)
                        s.c = 1.3 * 0.6, s.s = 0.7 * 0.8 + 0.01; // not a unit rotation
                    else if (rotation == 2)
                        s.c = 0, s.s = 0; // every point maps to the translation: a one-point hull
                    exact::PreparedShape prepared(s);
                    const exact::PreparedShape moved(std::move(prepared));
                    INFO("points " << c.points.size() << " scale 2^" << e << " rotation "
                                   << rotation << " radius " << r);
                    CHECK(moved.hullSize() == (rotation == 2 ? 1 : c.hull));
                    for (const Point& p : hostilePoints(s))
                        filteredEqualsGmp(moved, p, t);
                }
    INFO("GMP route for " << t.gmp << " of " << t.points << " points");
    CHECK(t.gmp * 4 < t.points);
}

TEST_CASE("PreparedShape rejects invalid shapes and points", "[exact][point]")
{
    Shape empty;
    CHECK_THROWS_AS(exact::PreparedShape(empty), std::invalid_argument);
    Shape s;
    s.points = {{0, 0}, {1, 0}};
    s.radius = -1;
    CHECK_THROWS_AS(exact::PreparedShape(s), std::invalid_argument);
    s.radius = 0;
    const exact::PreparedShape ps(s);
    CHECK_THROWS_AS(exact::pointToShapeDistance(ps, {NAN, 0}), std::invalid_argument);
    CHECK(exact::pointToShapeDistance(ps, {0.5, 2}) == 2.0);
}

namespace
{
// The Z vertex p - w_k of a shape's point b_k as exact rationals, independently of filter.cpp:
// w_k = (c x - s y + px, s x + c y + py) with every double taken exactly.
std::pair<mpq_class, mpq_class> zExact(Point p, const Shape& s, Point b)
{
    const mpq_class c(s.c), sn(s.s), bx(b.x), by(b.y);
    return {mpq_class(p.x) - (c * bx - sn * by + mpq_class(s.px)),
            mpq_class(p.y) - (sn * bx + c * by + mpq_class(s.py))};
}
} // namespace

TEST_CASE("zSignExact: the predicates' exact signs by expansions equal the rationals' signs",
          "[exact][filter][point]")
{
    using exact::detail::kZUnsure;
    using exact::detail::ZPredicate;
    std::mt19937_64 rng(4343);
    const int scales[] = {-498, -60, 0, 60, 498};
    int decided = 0, asked = 0, zeros = 0;
    for (int kind = 0; kind < 4; ++kind)
        for (int e : scales)
            for (int rotation = 0; rotation < 4; ++rotation)
            {
                const Shape s = hostileShape(rng, kind, e, rotation, false);
                for (const Point& p : hostilePoints(s))
                    for (const Point& bi : s.points)
                        for (const Point& bj : s.points)
                        {
                            const auto [xi, yi] = zExact(p, s, bi);
                            const auto [xj, yj] = zExact(p, s, bj);
                            const int cross = sgn(xi * yj - yi * xj);
                            const int dot = sgn(xi * (xj - xi) + yi * (yj - yi));
                            const int zero = (sgn(xi) == 0 && sgn(yi) == 0) ? 0 : 1;
                            INFO("kind " << kind << " scale 2^" << e << " rotation " << rotation
                                         << " p (" << p.x << ", " << p.y << ")");
                            const int got[3] = {
                                exact::detail::zSignExact(ZPredicate::Cross, p, s, bi, bj),
                                exact::detail::zSignExact(ZPredicate::Dot, p, s, bi, bj),
                                exact::detail::zSignExact(ZPredicate::IsZero, p, s, bi, bj)};
                            const int want[3] = {cross, dot, zero};
                            for (int t = 0; t < 3; ++t)
                            {
                                ++asked;
                                if (got[t] == kZUnsure)
                                    continue;
                                ++decided;
                                CHECK(got[t] == want[t]);
                            }
                            zeros += (cross == 0) + (dot == 0) + (zero == 0);
                        }
            }
    INFO(decided << " of " << asked << " signs decided, " << zeros << " of them exactly 0");
    // The signs left undecided are refusals (a product of expansion components below
    // expansion.hpp's 2^-960, or a coordinate scaling would cut); the exact zeros are the case a
    // bound alone never decides, so they must be many (the INFO line prints the counts).
    CHECK(decided * 20 > asked * 19);
    CHECK(zeros > 1000);
}

TEST_CASE("distance of prepared shapes equals distance of the shapes, fallback counts included",
          "[exact][point]")
{
    std::mt19937_64 rng(2727);
    const int scales[] = {-498, 0, 498};
    int cases = 0, exactHull = 0, gmp = 0;
    for (int kind = 0; kind < 4; ++kind)
        for (int e : scales)
            for (int rotation = 0; rotation < 4; ++rotation)
                for (int k = 0; k < 4; ++k)
                {
                    Shape a = hostileShape(rng, kind, e, rotation, k % 2 == 1);
                    const Shape b = hostileShape(rng, (kind + k) % 4, e, (rotation + 1) % 4, false);
                    if (k == 3) // touching: A moved onto one of B's world vertices
                    {
                        const Point w = world(b, b.points[0]);
                        const Point v = world(a, a.points[0]);
                        a.px += w.x - v.x;
                        a.py += w.y - v.y;
                    }
                    const exact::PreparedShape pa(a, "shape A"), pb(b, "shape B");
                    for (const bool filter : {true, false})
                        for (const exact::Route route : exact::kAllRoutes)
                        {
                            Options o;
                            o.filter = filter;
                            o.route = route;
                            const exact::Result want = exact::distance(a, b, o);
                            const exact::Result got = exact::distance(pa, pb, o);
                            INFO("kind " << kind << " scale 2^" << e << " rotation " << rotation
                                         << " shape " << k << " route " << exact::routeName(route)
                                         << " filter " << filter);
                            CHECK(exact_test::differentFields(got, want).empty());
                            CHECK(got.fallbacks.hull == want.fallbacks.hull);
                            CHECK(got.fallbacks.merge == want.fallbacks.merge);
                            CHECK(got.fallbacks.feature == want.fallbacks.feature);
                            CHECK(got.fallbacks.squared == want.fallbacks.squared);
                            CHECK(got.fallbacks.distance == want.fallbacks.distance);
                            CHECK(got.fallbacks.witness == want.fallbacks.witness);
                            CHECK(got.fallbacks.gmp == want.fallbacks.gmp);
                            ++cases;
                            exactHull += want.fallbacks.hull > 0;
                            gmp += want.fallbacks.gmp && filter;
                        }
                }
    INFO(cases << " results, " << exactHull << " with hull decisions left to exact integers, "
               << gmp << " filtered ones on the GMP route");
    // The counts must be exercised for the fallback comparison to mean anything: exact hull
    // decisions come from collinear and duplicate points, the GMP route from extreme scales and
    // touching shapes (the INFO line prints the counts).
    CHECK(exactHull > 50);
}
