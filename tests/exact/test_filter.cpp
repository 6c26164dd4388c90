// The default route's filter (exact/src/filter.cpp, docs/exact.md "The filter") gives the GMP
// route's result bit for bit, the squared rational included, on hostile inputs: extreme scales,
// collinear and duplicate points, tiny edges, exact and inexact rotations, radii that make the
// shapes touch. And it decides ordinary random cases itself (else it would only be slower).
#include "support.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

using exact::Options;
using exact::Result;
using exact::Shape;

namespace
{

std::uint64_t bits(double v)
{
    return std::bit_cast<std::uint64_t>(v);
}

// Filtered (the default) and forced-GMP results of one case, field by field; returns the filtered
// result. With `penetration`, the same with Options::penetration, the signed fields and the pair
// included (and the rest as without it), filtered depth counted in *depthGmp.
Result filteredEqualsExact(const Shape& a, const Shape& b, bool penetration = true,
                           int* depthGmp = nullptr)
{
    Options exactOnly;
    exactOnly.filter = false;
    const Result f = exact::distance(a, b), e = exact::distance(a, b, exactOnly);
    CHECK(e.fallbacks.gmp);
    CHECK(exact_test::differentFields(f, e).empty());
    if (penetration)
    {
        Options p;
        p.penetration = true;
        exactOnly.penetration = true;
        const Result fp = exact::distance(a, b, p), ep = exact::distance(a, b, exactOnly);
        CHECK(fp.hasSigned);
        CHECK(exact_test::differentFields(fp, e).empty());
        CHECK(exact_test::differentFields(ep, e).empty());
        CHECK(exact_test::differentSigned(fp, ep, true).empty());
        if (depthGmp)
            *depthGmp += fp.fallbacks.depth;
    }
    return f;
}

// A hostile shape: 1 to 8 points of one kind, at scale 2^scaleExp, under some transform.
Shape hostile(std::mt19937_64& rng, int kind, int scaleExp)
{
    std::uniform_real_distribution<double> u(-1, 1), angle(0, 6.283185307179586);
    std::uniform_int_distribution<int> n(1, 8), small(-4, 4);
    Shape s;
    const double scale = std::ldexp(1.0, scaleExp);
    const int count = n(rng);
    const double x0 = u(rng), y0 = u(rng), dx = u(rng), dy = u(rng);
    for (int i = 0; i < count; ++i)
    {
        switch (kind)
        {
        case 0: // random
            s.points.push_back({u(rng) * scale, u(rng) * scale});
            break;
        case 1: // collinear (exactly: small integer multiples of one dyadic step)
            s.points.push_back({small(rng) * scale, small(rng) * 2 * scale});
            s.points.back().y = s.points.back().x * 2;
            break;
        case 2: // duplicates
            s.points.push_back({x0 * scale, y0 * scale});
            if (i % 2)
                s.points.back() = {dx * scale, dy * scale};
            break;
        case 3: // tiny edges: neighbours a few ulps apart
            s.points.push_back({std::nextafter(x0 * scale, i * scale) + 0.0,
                                std::nextafter(y0 * scale, -i * scale)});
            break;
        default: // small integers: exact values everywhere
            s.points.push_back({double(small(rng)) * scale, double(small(rng)) * scale});
        }
    }
    switch (rng() % 4)
    {
    case 0:
        break; // identity
    case 1:
        s.c = 0, s.s = 1; // exact quarter turn
        break;
    default:
    {
        const double t = angle(rng);
        s.c = std::cos(t), s.s = std::sin(t);
    }
    }
    if (rng() % 2)
        s.px = u(rng) * scale, s.py = u(rng) * scale;
    if (rng() % 2)
        s.radius = std::fabs(u(rng)) * scale * 0.25;
    return s;
}

} // namespace

TEST_CASE("the filtered default route equals the GMP route bit for bit on hostile inputs",
          "[exact][filter]")
{
    std::mt19937_64 rng(34);
    const int scales[] = {-1000, -600, -60, -20, 0, 20, 60, 500, 900};
    int cases = 0;
    for (int kind = 0; kind < 5; ++kind)
        for (int scaleExp : scales)
            for (int k = 0; k < 60; ++k)
            {
                const Shape a = hostile(rng, kind, scaleExp);
                const Shape b = hostile(rng, static_cast<int>(rng() % 5), scaleExp);
                INFO("kind " << kind << " scale 2^" << scaleExp << " case " << k);
                filteredEqualsExact(a, b);
                // Touching with radii: B's radius set so that the exact distance is 0 or nearly.
                Shape bt = b;
                bt.radius = 0;
                const Result r = exact::distance(a, bt);
                bt.radius = std::max(0.0, r.distance - a.radius);
                filteredEqualsExact(a, bt);
                cases += 2;
            }
    CHECK(cases == 5 * 9 * 60 * 2);
}

TEST_CASE("the filter decides ordinary random cases itself", "[exact][filter]")
{
    // 3-8 random points in [-1, 1]^2 per shape, random rotation, translation and radius (the
    // runner's random family is alike): the filter is to leave fewer than 1 in 1,000 to GMP.
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> u(-1, 1), angle(0, 6.283185307179586), off(-2.5, 2.5);
    std::uniform_int_distribution<int> n(3, 8);
    const int count = 4000;
    int gmp = 0, depthGmp = 0;
    for (int k = 0; k < count; ++k)
    {
        Shape s[2];
        for (Shape& sh : s)
        {
            for (int i = n(rng); i > 0; --i)
                sh.points.push_back({u(rng), u(rng)});
            const double t = angle(rng);
            sh.c = std::cos(t), sh.s = std::sin(t);
            sh.px = off(rng), sh.py = off(rng);
            sh.radius = k % 2 ? 0.3 * std::fabs(u(rng)) : 0.0;
        }
        gmp += filteredEqualsExact(s[0], s[1], true, &depthGmp).fallbacks.gmp;
    }
    CHECK(gmp * 1000 < count);
    CHECK(depthGmp * 1000 < count);
}

TEST_CASE("the filter decides the depth of ordinary overlapping cases itself",
          "[exact][filter][penetration]")
{
    // As above with the shapes' centres within 1/2 of each other (most cases overlap): the signed
    // distance and the pair are to leave fewer than 1 in 1,000 to GMP.
    std::mt19937_64 rng(51);
    std::uniform_real_distribution<double> u(-1, 1), angle(0, 6.283185307179586), off(-0.5, 0.5);
    std::uniform_int_distribution<int> n(3, 8);
    const int count = 4000;
    int overlaps = 0, depthGmp = 0;
    for (int k = 0; k < count; ++k)
    {
        Shape s[2];
        for (Shape& sh : s)
        {
            for (int i = n(rng); i > 0; --i)
                sh.points.push_back({u(rng), u(rng)});
            const double t = angle(rng);
            sh.c = std::cos(t), sh.s = std::sin(t);
            sh.px = off(rng), sh.py = off(rng);
            sh.radius = k % 2 ? 0.3 * std::fabs(u(rng)) : 0.0;
        }
        overlaps += filteredEqualsExact(s[0], s[1], true, &depthGmp).overlap;
    }
    CHECK(overlaps * 4 > count * 3);
    CHECK(depthGmp * 1000 < count);
}

TEST_CASE("the squared rational is left out only when not asked for", "[exact][filter]")
{
    Shape a, b;
    a.points = {{0, 0}, {1, 0}, {0, 1}};
    b.points = {{3, 0.5}, {4, 1}, {3.5, 2}};
    b.c = 0.6, b.s = 0.8; // (3/5, 4/5) rounded: an inexact rotation, decided by the filter
    Options o;
    o.squaredRational = false;
    const Result lazy = exact::distance(a, b, o), full = filteredEqualsExact(a, b);
    CHECK_FALSE(full.fallbacks.gmp);
    CHECK_FALSE(lazy.fallbacks.gmp);
    CHECK(lazy.squaredNum.empty());
    CHECK(lazy.squaredDen.empty());
    CHECK_FALSE(full.squaredNum.empty());
    CHECK(bits(lazy.distance) == bits(full.distance));
}
