// pointToShapeDistance on hand cases, input validation, route names.
#include "support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace exact_test;

TEST_CASE("pointToShapeDistance: hand cases")
{
    const Shape sq = shape({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    CHECK(exact::pointToShapeDistance(sq, {2, 0.5}) == 1.0);   // right edge, foot (1, 1/2)
    CHECK(exact::pointToShapeDistance(sq, {0.5, 0.5}) == 0.0); // inside
    CHECK(exact::pointToShapeDistance(sq, {1, 0.25}) == 0.0);  // on the boundary
    CHECK(exact::pointToShapeDistance(sq, {4, 5}) == 5.0);     // corner (1,1): 3-4-5
    Shape rounded = sq;
    rounded.radius = 0.25;
    CHECK(exact::pointToShapeDistance(rounded, {2, 0.5}) == 0.75);  // 1 - 1/4
    CHECK(exact::pointToShapeDistance(rounded, {1.1, 0.5}) == 0.0); // inside the rounding
    // Slanted edge: triangle (0,0), (1,0), (0,2) and (1,1): 1/sqrt(5), correctly rounded.
    const double d = exact::pointToShapeDistance(shape({{0, 0}, {1, 0}, {0, 2}}), {1, 1});
    CHECK(distanceRoundsTo(d, mpq_class(1, 5), 0));
    // Transformed shape: segment (0,0)-(2,0) turned a quarter (c = 0, s = 1) and moved by (1, 0)
    // is (1,0)-(1,2); the point (3,1) is 2 away, (1,3) is 1 away (end point (1,2)).
    Shape seg = shape({{0, 0}, {2, 0}});
    seg.c = 0;
    seg.s = 1;
    seg.px = 1;
    CHECK(exact::pointToShapeDistance(seg, {3, 1}) == 2.0);
    CHECK(exact::pointToShapeDistance(seg, {1, 3}) == 1.0);
    // single-point shape with radius: a disc
    CHECK(exact::pointToShapeDistance(shape({{0, 0}}, 2.0), {3, 4}) == 3.0);
    // a witness from distance() lies on its shape: distance 0 up to rounding of the witness
    exact::Shape a = shape({{0, 0}}, 1.0), b = shape({{3, 4}}, 0.5);
    const exact::Result r = exact::distance(a, b);
    CHECK(exact::pointToShapeDistance(a, r.witnessA) < 1e-15);
    CHECK(exact::pointToShapeDistance(b, r.witnessB) < 1e-15);
}

TEST_CASE("invalid input throws std::invalid_argument")
{
    const Shape ok = shape({{0, 0}});
    const double nan = std::numeric_limits<double>::quiet_NaN(),
                 inf = std::numeric_limits<double>::infinity();
    Shape empty;
    CHECK_THROWS_AS(exact::distance(empty, ok), std::invalid_argument);
    CHECK_THROWS_AS(exact::distance(ok, empty), std::invalid_argument);
    CHECK_THROWS_AS(exact::distance(shape({{nan, 0}}), ok), std::invalid_argument);
    CHECK_THROWS_AS(exact::distance(ok, shape({{0, inf}})), std::invalid_argument);
    CHECK_THROWS_AS(exact::distance(shape({{0, 0}}, -1.0), ok), std::invalid_argument);
    CHECK_THROWS_AS(exact::distance(shape({{0, 0}}, nan), ok), std::invalid_argument);
    Shape bad = ok;
    bad.c = inf;
    CHECK_THROWS_AS(exact::distance(bad, ok), std::invalid_argument);
    bad = ok;
    bad.py = nan;
    CHECK_THROWS_AS(exact::bruteForce(ok, bad), std::invalid_argument);
    CHECK_THROWS_AS(exact::pointToShapeDistance(ok, {nan, 0}), std::invalid_argument);
    CHECK_THROWS_WITH(exact::distance(empty, ok), Catch::Contains("no points"));
    CHECK_NOTHROW(exact::validateShape(ok));
}

TEST_CASE("route names round-trip")
{
    for (exact::Route r : exact::kAllRoutes)
    {
        exact::Route back = exact::Route::HullOfDifferences;
        CHECK(exact::parseRoute(exact::routeName(r), back));
        CHECK(back == r);
    }
    CHECK(std::string(exact::routeName(exact::Route::HullOfDifferences)) == "hull-of-differences");
    CHECK(std::string(exact::routeName(exact::Route::MinkowskiSum2)) == "minkowski-sum-2");
    CHECK(std::string(exact::routeName(exact::Route::EdgeMerge)) == "edge-merge");
    exact::Route d = exact::Route::HullOfDifferences;
    CHECK(exact::parseRoute("default", d));
    CHECK(d == exact::Route::Default);
    CHECK_FALSE(exact::parseRoute("nope", d));
    CHECK(d == exact::Route::Default);
}
