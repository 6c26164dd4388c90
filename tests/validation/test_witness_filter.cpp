// The witness checks' floating-point filter (evaluate/witness_filter.hpp): where it answers, its
// answer (0) is the exact route's (exact::pointToShapeDistance); where it cannot tell (a point on
// the boundary, one just off it, the deciding ones of the witness bound) the exact route answers:
// in floating point where its own bound decides, else by GMP, and then the fallback is counted.
// Expected values by hand, and from the exact side on the built-in families.
#include "evaluate/evaluate.hpp"
#include "evaluate/witness_filter.hpp"
#include "inputs/families.hpp"
#include "inputs/geometry.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace gjkval;

namespace
{
exact::Shape square(double x0, double y0, double radius = 0)
{
    exact::Shape s;
    s.points = {{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}};
    s.radius = radius;
    return s;
}

// The filter's answer where it gives one, else the exact route's: what checkWitnesses reports.
bool decides(const exact::Shape& s, exact::Point p)
{
    return certainlyOnShape(filterShape(s), p);
}
} // namespace

TEST_CASE("witness filter: hand cases on the unit square", "[witness-filter]")
{
    const exact::Shape sq = square(0, 0);
    CHECK(decides(sq, {0.5, 0.5}));               // inside: distance 0
    CHECK(decides(sq, {0.999, 0.001}));           // inside, 1e-3 from two edges
    CHECK_FALSE(decides(sq, {2, 0.5}));           // outside: distance 1, the exact route's
    CHECK_FALSE(decides(sq, {1, 0.25}));          // on the boundary: no strict certificate
    CHECK_FALSE(decides(sq, {0, 0}));             // a vertex
    CHECK_FALSE(decides(sq, {1 - 0x1p-53, 0.5})); // inside by 2^-53, below the bound (~3.4e-16)
    CHECK_FALSE(decides(sq, {1 + 0x1p-52, 0.5})); // outside by 2^-52: exact 2^-52, never 0
    CHECK(exact::pointToShapeDistance(sq, {1 + 0x1p-52, 0.5}) == 0x1p-52);
    // A rounded square (radius 1/2): within the radius of an edge is on the shape.
    const exact::Shape rounded = square(0, 0, 0.5);
    CHECK(decides(rounded, {1.25, 0.5}));      // 1/4 from the edge x = 1
    CHECK(decides(rounded, {1.3, 1.3}));       // 0.3 sqrt 2 = 0.42 from the corner
    CHECK_FALSE(decides(rounded, {1.6, 0.5})); // 0.6 from the edge: exact 0.1
    CHECK_FALSE(decides(rounded, {1.5, 0.5})); // exactly at the radius: left to the exact route
    // A segment and a point: no triangle, only the radius can decide.
    exact::Shape seg;
    seg.points = {{0, 0}, {2, 0}};
    CHECK_FALSE(decides(seg, {1, 0}));
    seg.radius = 0.25;
    CHECK(decides(seg, {1, 0.2}));
    CHECK_FALSE(decides(seg, {1, 0.3}));
    exact::Shape dot;
    dot.points = {{3, 4}};
    dot.radius = 5.5;
    CHECK(decides(dot, {0, 0})); // 5 from the point
    dot.radius = 5;
    CHECK_FALSE(decides(dot, {0, 0})); // exactly 5: exact 0, left to the exact route
}

TEST_CASE("witness filter: a rotated and translated shape", "[witness-filter]")
{
    // c, s rounded from cos and sin of 0.7 (c^2 + s^2 is not exactly 1): the exact side applies
    // them as given, the filter bounds the rounding of c x - s y + px.
    exact::Shape sq = square(-0.5, -0.5);
    sq.c = std::cos(0.7);
    sq.s = std::sin(0.7);
    sq.px = 1e6;
    sq.py = -3e5;
    CHECK(decides(sq, {1e6, -3e5}));             // the centre
    CHECK(decides(sq, {1e6 + 0.3, -3e5}));       // inside the inscribed disk (radius 1/2)
    CHECK_FALSE(decides(sq, {1e6 + 0.8, -3e5})); // outside the circumscribed disk (0.707)
    CHECK(exact::pointToShapeDistance(sq, {1e6 + 0.3, -3e5}) == 0);
    // Coordinates that overflow in the filter: the exact route answers.
    exact::Shape huge = square(0, 0);
    huge.px = 1.7e308;
    huge.c = 1e308; // c x + px overflows
    CHECK_FALSE(decides(huge, {1.7e308, 0.5}));
}

TEST_CASE("witness filter: never 0 where the exact route is not, on every built-in family",
          "[witness-filter]")
{
    // Points on, near and off each shape: its own points, their midpoints, and both moved by tiny
    // and larger offsets; where the filter decides, the exact route must give 0.
    std::size_t decided = 0, fallbacks = 0, checked = 0;
    std::vector<GeneratedFamily> families = generateFamilies("hard:8", 11);
    families.push_back(generateFamilies("random:300", 11)[0]);
    for (const GeneratedFamily& fam : families)
        for (const Case& c : fam.cases)
            for (const ShapeIn* sh : {&c.a, &c.b})
            {
                const exact::Shape s = toExact(*sh);
                const FilterShape f = filterShape(s);
                const auto world = worldPoints(*sh);
                for (std::size_t i = 0; i < world.size() && i < 16; ++i)
                {
                    const auto& w = world[i];
                    const auto& v = world[(i + 1) % world.size()];
                    for (double t : {0.0, 0.5})
                        for (double off : {0.0, 1e-15, -1e-15, 1e-9, -1e-3, 0.3})
                        {
                            const double k = 1 + std::abs(w[0]) + std::abs(w[1]);
                            const exact::Point p{w[0] + t * (v[0] - w[0]) + off * k,
                                                 w[1] + t * (v[1] - w[1]) - off * k};
                            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                                continue;
                            ++checked;
                            if (certainlyOnShape(f, p))
                            {
                                ++decided;
                                INFO(c.name << " point " << p.x << ", " << p.y);
                                CHECK(exact::pointToShapeDistance(s, p) == 0);
                            }
                            else
                                ++fallbacks;
                        }
                }
            }
    CHECK(checked > 1000);
    CHECK(decided > 0);   // the filter answers somewhere
    CHECK(fallbacks > 0); // and leaves the boundary to the exact route
}

TEST_CASE("witness checks count the points the exact route measured", "[witness-filter]")
{
    // A = [0,1]^2, B = [2,3] x [0,1], both untransformed. Three double variants' answers, set by
    // hand: the first has A's point inside A (the filter's 0) and B's 2^-1074 below B's edge (a
    // subnormal distance: exact::pointToShapeDistance's floating-point filter leaves it to the GMP
    // route, counted); the second shares A's point and has B's inside B; the third puts A's point
    // 2^-40 off A, beyond the witness bound (measured in floating point, 2^-40 exactly, not
    // counted) and shares B's with the first (counted again): it fails.
    Case c;
    c.name = "two squares";
    c.a.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    c.b.points = {{2, 0}, {3, 0}, {3, 1}, {2, 1}};
    EvalContext ctx;
    ctx.variants = {findVariant("double"), findVariant("double-closest-point"),
                    findVariant("double-warm")};
    for (auto* v : ctx.variants)
        REQUIRE(v != nullptr);
    CaseOutcome out;
    out.variants.resize(3);
    const std::array<double, 2> pa[3] = {{0.5, 0.5}, {0.5, 0.5}, {1 + 0x1p-40, 0.5}};
    const std::array<double, 2> pb[3] = {{2.5, -0x1p-1074}, {2.5, 0.5}, {2.5, -0x1p-1074}};
    for (int k = 0; k < 3; ++k)
    {
        VariantOutcome& v = out.variants[std::size_t(k)];
        v.pointA = pa[k];
        v.pointB = pb[k];
        v.witnessBound = 1e-14;
    }
    checkWitnesses(c, ctx, out);
    CHECK(out.variants[0].witnessPoints == 2);
    CHECK(out.variants[0].witnessExact == 1);
    CHECK(out.variants[0].witness == 0x1p-1074);
    CHECK(out.variants[1].witnessExact == 0);
    CHECK(out.variants[1].witness == 0);
    CHECK(out.variants[2].witnessPoints == 2);
    CHECK(out.variants[2].witnessExact == 1);
    CHECK(out.variants[2].witness == 0x1p-40);
    CHECK(out.variants[2].invalid == Invalid::WitnessOffShape);
    CHECK(out.variants[2].failed);
}
