// The Box2D 2.4.1 adapter (validation/plugins/box2d-2.4/box2d.cpp) on hand-derived cases: its
// declared contract, and the overlap clause (`midpoint`) through b2Distance itself (float,
// useRadii = true). docs/peers/box2d.md.
#include "peer_plugin.hpp"

#include "within.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace
{

const peers::Plugin& box2d()
{
    static const peers::Plugin p(GJK2D_BOX2D_PLUGIN, "box2d-2.4.1");
    return p;
}

// A disc: one point with a radius, at (px, py).
peers::Shape disc(double r, double px, double py = 0)
{
    return peers::Shape{{0, 0}, r, px, py};
}

} // namespace

TEST_CASE("the contract: midpoint on overlap (b2_distance.cpp:588-596), no tolerance, margin 0")
{
    const gjk2d_contract* c = box2d().contract();
    REQUIRE(c != nullptr);
    CHECK(c->overlap == GJK2D_OVERLAP_MIDPOINT);
    CHECK(std::string(c->overlap_source).find("src/collision/b2_distance.cpp:588-596") !=
          std::string::npos);
    CHECK(std::string(c->overlap_source).find("Box2D 2.4.1") != std::string::npos);
    CHECK((c->distance_abs_tolerance < 0 && c->distance_rel_tolerance < 0));
    CHECK(c->margin == 0);
}

// Discs of radius 1 centred at (0, 0) and (1.5, 0): the cores (the centres) are 1.5 apart, within
// rA + rB = 2, so b2Distance takes its overlap branch: distance 0, both points at 0.5 (pointA +
// pointB) = (0.75, 0), exact in float. Apart by 3 instead: 3 - 2 = 1, the points moved onto the
// discs, (1, 0) and (2, 0).
TEST_CASE("discs of radius 1 1.5 apart: distance 0, both points at the midpoint (0.75, 0)")
{
    const peers::Answer r = box2d().distance(disc(1, 0), disc(1, 1.5));
    REQUIRE(r.status == GJK2D_STATUS_OK);
    CHECK(r.distance == 0);
    CHECK((r.ax == 0.75 && r.ay == 0 && r.bx == 0.75 && r.by == 0));
    const peers::Answer s = box2d().distance(disc(1, 0), disc(1, 3));
    REQUIRE(s.status == GJK2D_STATUS_OK);
    CHECK(s.distance == 1);
    CHECK((s.ax == 1 && s.ay == 0 && s.bx == 2 && s.by == 0));
}

// Radius 0, away from the origin (where planck's bug shows, tests/plugins/adapter_driver.py):
// [10, 11]^2 and [10.5, 11.5]^2 overlap in [10.5, 11]^2. GJK ends on a triangle around the origin
// with both points the same combination of the shapes' points, a point of both cores; the overlap
// branch (0 <= rA + rB) takes their midpoint: that point. Checked to 1e-5, a few float ulps of 11
// (9.5e-7 each).
TEST_CASE("overlapping squares at (10, 10): distance 0, one point in both squares")
{
    const double tol = 1e-5;
    const peers::Answer r =
        box2d().distance(peers::unitSquare(10, 10), peers::unitSquare(10.5, 10.5));
    REQUIRE(r.status == GJK2D_STATUS_OK);
    INFO("pA (" << r.ax << ", " << r.ay << "), pB (" << r.bx << ", " << r.by << ")");
    CHECK(r.distance == 0);
    CHECK((r.ax == r.bx && r.ay == r.by));
    CHECK((r.ax >= 10.5 - tol && r.ax <= 11 + tol && r.ay >= 10.5 - tol && r.ay <= 11 + tol));
}
