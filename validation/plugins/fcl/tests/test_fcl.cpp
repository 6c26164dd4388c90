// The FCL 0.7 adapter (validation/plugins/fcl/fcl.cpp) on hand-derived cases; docs/peers/fcl.md,
// states the findings these tests reproduce. Unit squares are [0, 1]^2 placed by their case's
// transform.
//
// Tolerances (each derived here, checked against what FCL 0.7.0 answered):
// - kPolygon = 64 u S with S = 5, the largest coordinate: the adapter rounds the world points
//   once (u S) and FCL's GJK projects onto an edge in a few operations; the largest error measured
//   on these cases is 2 ulps of 3.57 (4.4e-16, the edge-nearest squares), 80 times below it.
// - kRounded = 1e-6, FCL's documented GJK stopping threshold (DistanceRequest::distance_tolerance,
//   default 1e-6): a Sphere or Capsule is curved, GJK stops near it. Measured, with the adapter's
//   per-case prism half height: indep 3.1e-7 (sphere), 1.7e-7 (capsule); libccd 1.5e-11 (sphere),
//   9.4e-7 (capsule: close to the threshold, which for libccd bounds nothing; with half height 1
//   these were 1.7e-9, 6e-8, 1.4e-11 and 1.6e-8).
#include "peer_plugin.hpp"

#include "within.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace
{

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
constexpr double kPolygon = 64 * kU * 5;
constexpr double kRounded = 1e-6;

const peers::Plugin& libccd()
{
    static const peers::Plugin p(GJK2D_FCL_PLUGIN, "fcl-0.7-libccd");
    return p;
}

const peers::Plugin& indep()
{
    static const peers::Plugin p(GJK2D_FCL_PLUGIN, "fcl-0.7-indep");
    return p;
}

const peers::Plugin& signedLibccd()
{
    static const peers::Plugin p(GJK2D_FCL_PLUGIN, "fcl-0.7-libccd-signed");
    return p;
}

} // namespace

TEST_CASE("the library names FCL and its pkg-config version, both solvers are double")
{
    CHECK(libccd().library() == "FCL " GJK2D_FCL_VERSION " (Debian libfcl-dev)");
    CHECK(libccd().implementation().scalar == GJK2D_SCALAR_DOUBLE);
    CHECK(indep().implementation().scalar == GJK2D_SCALAR_DOUBLE);
}

// A = [0, 1]^2, B = [4, 5] x [0, 1]: the faces x = 1 and x = 4 face each other, distance 3.
TEST_CASE("two unit squares 3 apart: distance 3 between x = 1 and x = 4, both solvers")
{
    for (const peers::Plugin* p : {&libccd(), &indep()})
    {
        INFO(p->implementation().name);
        const peers::Answer r = p->distance(peers::unitSquare(), peers::unitSquare(4, 0));
        REQUIRE(r.status == GJK2D_STATUS_OK);
        CHECK(r.distance == within(3, kPolygon));
        CHECK(r.ax == within(1, kPolygon));
        CHECK(r.bx == within(4, kPolygon));
        CHECK(r.ay == within(r.by, kPolygon));
        CHECK((r.ay >= 0 && r.ay <= 1));
    }
}

// B = [4.57, 5.57] x [0.5, 1.5]: A's face x = 1 (y in [0, 1]) and B's face x = 4.57 (y in
// [0.5, 1.5]) overlap in y on [0.5, 1], so an edge pair is nearest: distance 3.57. A point at
// (3, 0.5) and A: the nearest feature is A's edge x = 1, distance 2.
TEST_CASE("GST_INDEP answers the edge distance where an edge is nearest")
{
    const peers::Answer r = indep().distance(peers::unitSquare(), peers::unitSquare(4.57, 0.5));
    REQUIRE(r.status == GJK2D_STATUS_OK);
    CHECK(r.distance == within(4.57 - 1, kPolygon));
    CHECK(r.ax == within(1, kPolygon));
    CHECK((r.ay >= 0.5 - kPolygon && r.ay <= 1 + kPolygon));
    const peers::Answer q = indep().distance(peers::Shape{{0, 0}, 0, 3, 0.5}, peers::unitSquare());
    REQUIRE(q.status == GJK2D_STATUS_OK);
    CHECK(q.distance == within(2, kPolygon));
    CHECK(q.by == within(0.5, kPolygon));
}

// The finding (FCL issue #508), measured so that docs/peers.md states what this FCL does: on the
// same two cases GST_LIBCCD answers the distance between two vertices, A's (1, 0) and B's
// (4.57, 0.5): sqrt(3.57^2 + 0.5^2) = 3.6048..., and (1, 1) to (3, 0.5): sqrt(4 + 0.25).
// A fixed FCL fails this test: then update docs/peers.md.
TEST_CASE("GST_LIBCCD answers a vertex-to-vertex distance where an edge is nearest (FCL 508)")
{
    const peers::Answer r = libccd().distance(peers::unitSquare(), peers::unitSquare(4.57, 0.5));
    REQUIRE(r.status == GJK2D_STATUS_OK);
    CHECK(r.distance == within(std::hypot(4.57 - 1, 0.5), kPolygon));
    CHECK(r.distance - 3.57 > 0.03);
    const peers::Answer q = libccd().distance(peers::Shape{{0, 0}, 0, 3, 0.5}, peers::unitSquare());
    REQUIRE(q.status == GJK2D_STATUS_OK);
    CHECK(q.distance == within(std::hypot(2, 0.5), kPolygon));
}

// The contract each variant declares (fcl.cpp, kContracts): overlap `zero` for both, GST_INDEP's
// distance_tolerance as abs and rel 1e-6, none for GST_LIBCCD (FCL says its tolerance is no bound),
// margin 0; every stated clause names its FCL 0.7.0 source.
TEST_CASE("the contracts: zero on overlap, GST_INDEP's tolerance 1e-6, none for GST_LIBCCD")
{
    for (const peers::Plugin* p : {&libccd(), &indep()})
    {
        INFO(p->implementation().name);
        const gjk2d_contract* c = p->contract();
        REQUIRE(c != nullptr);
        CHECK(c->overlap == GJK2D_OVERLAP_ZERO);
        CHECK(std::string(c->overlap_source).find("distance_result.h:55-64") != std::string::npos);
        CHECK(std::string(c->overlap_source).find("FCL 0.7.0") != std::string::npos);
        CHECK(std::string(c->tolerance_source).find("FCL 0.7.0") != std::string::npos);
        CHECK(c->margin == 0);
    }
    CHECK(indep().contract()->distance_abs_tolerance == 1e-6);
    CHECK(indep().contract()->distance_rel_tolerance == 1e-6);
    CHECK(libccd().contract()->distance_abs_tolerance < 0);
    CHECK(libccd().contract()->distance_rel_tolerance < 0);
}

// The tolerance clause through FCL. Squares 5e-7 apart (B = [1 + 5e-7, 2 + 5e-7] x [0, 1]):
// GST_INDEP reports collision (min_distance -1) below its distance_tolerance of 1e-6, which its
// contract allows (a gap within abs 1e-6 may be called contact); GST_LIBCCD answers the gap. At
// 3e-6 and at 1e-3 both measure the gap, well within 1e-6 (measured: within kPolygon).
TEST_CASE("GST_INDEP calls shapes closer than 1e-6 colliding, measures 1e-3 within 1e-6")
{
    const double gap = 5e-7;
    const peers::Answer i = indep().distance(peers::unitSquare(), peers::unitSquare(1 + gap, 0));
    REQUIRE(i.status == GJK2D_STATUS_OK);
    CHECK(i.distance == -1);
    const peers::Answer l = libccd().distance(peers::unitSquare(), peers::unitSquare(1 + gap, 0));
    CHECK(l.distance == within(gap, kPolygon));
    for (const double far : {3e-6, 1e-3})
        for (const peers::Plugin* p : {&libccd(), &indep()})
        {
            INFO(p->implementation().name << ", gap " << far);
            const peers::Answer j = p->distance(peers::unitSquare(), peers::unitSquare(1 + far, 0));
            REQUIRE(j.status == GJK2D_STATUS_OK);
            CHECK(j.distance == within(far, kPolygon));
        }
}

// The overlap clause (`zero`) through FCL: A = [10, 11]^2, B = [10.5, 11.5]^2 overlap by 0.5.
// FCL answers min_distance -1 ("in collision", DistanceResult's documentation), 0 or below as
// `zero` promises, and sets no nearest points: both are the origin, on neither shape, which `zero`
// does not judge. The adapter reports both as they are.
TEST_CASE("overlapping squares: FCL's -1 as it is, its nearest points the origin")
{
    for (const peers::Plugin* p : {&libccd(), &indep()})
    {
        INFO(p->implementation().name);
        const peers::Answer r =
            p->distance(peers::unitSquare(10, 10), peers::unitSquare(10.5, 10.5));
        REQUIRE(r.status == GJK2D_STATUS_OK);
        CHECK(r.distance == -1);
        CHECK((r.ax == 0 && r.ay == 0 && r.bx == 0 && r.by == 0));
    }
}

// A point at (3, 0.5) with radius 0.5 (an fcl::Sphere) and A: 2 - 0.5 = 1.5, the ball's nearest
// point at x = 2.5. The segment (-1, 3) .. (3, 3) with radius 0.5 (an fcl::Capsule rotated onto
// it) and A: 3 - 1 - 0.5 = 1.5, the square's point on its top edge y = 1.
TEST_CASE("a rounded point is a Sphere, a rounded segment a Capsule: distance minus the radius")
{
    for (const peers::Plugin* p : {&libccd(), &indep()})
    {
        INFO(p->implementation().name);
        const peers::Answer s = p->distance(peers::Shape{{0, 0}, 0.5, 3, 0.5}, peers::unitSquare());
        REQUIRE(s.status == GJK2D_STATUS_OK);
        CHECK(s.distance == within(1.5, kRounded));
        CHECK(s.ax == within(2.5, kRounded));
        CHECK(s.bx == within(1, kRounded));
        const peers::Answer c =
            p->distance(peers::Shape{{0, 0, 4, 0}, 0.5, -1, 3}, peers::unitSquare());
        REQUIRE(c.status == GJK2D_STATUS_OK);
        CHECK(c.distance == within(1.5, kRounded));
        CHECK(c.ay == within(2.5, kRounded));
        CHECK(c.by == within(1, kRounded));
    }
}

// FCL has no rounded polytope: a polygon (3 or more points) with radius > 0 is refused.
TEST_CASE("a rounded polygon is refused, the same polygon without radius answered")
{
    for (const peers::Plugin* p : {&libccd(), &indep()})
    {
        INFO(p->implementation().name);
        peers::Shape rounded = peers::unitSquare(3, 0);
        rounded.radius = 0.5;
        CHECK(p->distance(rounded, peers::unitSquare()).status == GJK2D_STATUS_REFUSED);
        CHECK(p->distance(peers::unitSquare(), rounded).status == GJK2D_STATUS_REFUSED);
        CHECK(p->distance(peers::unitSquare(3, 0), peers::unitSquare()).status == GJK2D_STATUS_OK);
    }
}

// (c, s) = (2, 0) is not a rotation: it scales A's points by 2, A = [0, 2]^2, and B = [5, 6] x
// [0, 1] is 3 away. The adapter applies it as given (FCL's Isometry would drop the scale: 4).
TEST_CASE("the case's (c, s) is applied as given: (2, 0) scales the square by 2")
{
    for (const peers::Plugin* p : {&libccd(), &indep()})
    {
        INFO(p->implementation().name);
        const peers::Answer r = p->distance(peers::unitSquare(0, 0, 2, 0), peers::unitSquare(5, 0));
        REQUIRE(r.status == GJK2D_STATUS_OK);
        CHECK(r.distance == within(3, kPolygon));
        CHECK(r.ax == within(2, kPolygon));
    }
}

// hard/extreme-scale/48-gap-1e180 (gjk-validate generate --family hard/extreme-scale; exact
// distance 1.46e172). The prism rule's e = radius + max (|x| + |y|) stays finite here (about 4e180;
// sqrt(x^2 + y^2) overflowed to h = inf, and GST_INDEP then answered -1, a false overlap made by
// the prisms). With the finite h GST_INDEP returns without writing its DistanceResult, as it did
// with prisms of half height 1: min_distance stays at its initial numeric max (1.8e308), the
// nearest points at the adapter's NaN presets (Eigen leaves them unwritten). FCL's own answer:
// "far apart" with no points, for shapes 1.46e172 apart. The same whatever the stack held before.
TEST_CASE("a huge case: GST_INDEP leaves its result unwritten (numeric max, NaN points), in every "
          "run")
{
    const peers::Shape a{{6.538098967619074e+179, 1.3121003390251404e+180, 6.55369169873577e+178,
                          1.4645066040429783e+180, -1.1633465828879966e+179,
                          1.4613490096669353e+180, -1.459739793133764e+180, 1.3503487370120538e+179,
                          -8.936515379395379e+179, -1.1620936319901263e+180,
                          1.1068483360807881e+180, -9.61229130690958e+179, 1.3675954503858125e+180,
                          -5.279747767249214e+179},
                         0,
                         5.619056201924275e+179,
                         2.2517228195368712e+180,
                         -0.9572434440300882,
                         -0.28928357862384013};
    const peers::Shape b{{6.069908577423192e+179, 1.2153222550364547e+180, 5.92775197598156e+179,
                          1.2223189641342053e+180, -1.3531436419967699e+180,
                          1.2020136893299825e+179},
                         0,
                         1.6544460974350955e+180,
                         3.2175387118142435e+180,
                         0.9995611920213605,
                         0.029621333610031296};
    for (unsigned char byte : {0x00, 0x3f})
    {
        peers::dirtyStack(byte);
        const peers::Answer r = indep().distance(a, b);
        REQUIRE(r.status == GJK2D_STATUS_OK);
        CHECK(r.distance == std::numeric_limits<double>::max());
        CHECK((std::isnan(r.ax) && std::isnan(r.ay) && std::isnan(r.bx) && std::isnan(r.by)));
    }
}

// fcl-0.7-libccd-signed: GST_LIBCCD with enable_signed_distance. Its contract: overlap
// `penetration` (distance_request.h:57-92), the distance tolerance as GST_LIBCCD's (none stated),
// and the depth clause FCL states for its EPA: within distance_tolerance, 1e-6
// (gjk_libccd-inl.h:2697-2700).
TEST_CASE("signed: a double variant with radii, its contract penetration, its depth within 1e-6")
{
    CHECK(signedLibccd().implementation().scalar == GJK2D_SCALAR_DOUBLE);
    CHECK((signedLibccd().implementation().accepts & GJK2D_ACCEPTS_RADIUS) != 0);
    const gjk2d_contract* c = signedLibccd().contract();
    REQUIRE(c != nullptr);
    CHECK(c->overlap == GJK2D_OVERLAP_PENETRATION);
    CHECK(std::string(c->overlap_source).find("distance_request.h:57-92") != std::string::npos);
    CHECK(std::string(c->overlap_source).find("FCL 0.7.0") != std::string::npos);
    CHECK((c->distance_abs_tolerance < 0 && c->distance_rel_tolerance < 0));
    const gjk2d_depth_contract* d = signedLibccd().depth();
    REQUIRE(d != nullptr);
    CHECK(d->abs_tolerance == 1e-6);
    CHECK(d->rel_tolerance < 0);
    CHECK(std::string(d->source).find("gjk_libccd-inl.h:2697-2700") != std::string::npos);
    for (const peers::Plugin* p : {&libccd(), &indep()}) // no depth answered: no clause stated
    {
        REQUIRE(p->depth() != nullptr);
        CHECK((p->depth()->abs_tolerance < 0 && p->depth()->rel_tolerance < 0));
    }
}

// Penetration pairs on A = [0, 10]^2 (depths derived in validation/plugins/bullet/tests/
// test_bullet.cpp): the segment (6, -5)-(6, 15) is 4 deep along x, pA on A's face x = 10, pB on
// the segment; the diamond (12, 5), (7, 10), (2, 5), (7, 0) 8 deep, pA (10, 5), pB (2, 5); A and
// A placed at (5, 0) 5 deep along x (where Bullet's EPA answers 5 / sqrt(2)). pA - pB is the
// translation of B that separates them. Held to FCL's stated 1e-6; measured: exact.
TEST_CASE("signed: a segment, a diamond and a square through a 10 x 10 square: depths 4, 8, 5")
{
    const double tol = 1e-6; // FCL's stated depth tolerance (the contract above)
    const peers::Shape a{{0, 0, 10, 0, 10, 10, 0, 10}, 0};
    const peers::Answer r = signedLibccd().distance(a, peers::Shape{{6, -5, 6, 15}, 0});
    REQUIRE(r.status == GJK2D_STATUS_OK);
    CHECK(r.distance == within(-4, tol));
    CHECK(r.ax == within(10, tol));
    CHECK(r.bx == within(6, tol));
    CHECK(r.ay == within(r.by, tol));
    CHECK((r.ay >= -tol && r.ay <= 10 + tol));
    const peers::Answer d = signedLibccd().distance(a, peers::Shape{{12, 5, 7, 10, 2, 5, 7, 0}, 0});
    REQUIRE(d.status == GJK2D_STATUS_OK);
    CHECK(d.distance == within(-8, tol));
    CHECK(d.ax == within(10, tol));
    CHECK(d.ay == within(5, tol));
    CHECK(d.bx == within(2, tol));
    CHECK(d.by == within(5, tol));
    const peers::Answer q =
        signedLibccd().distance(a, peers::Shape{{0, 0, 10, 0, 10, 10, 0, 10}, 0, 5, 0});
    REQUIRE(q.status == GJK2D_STATUS_OK);
    CHECK(q.distance == within(-5, tol));
    CHECK(q.ax - q.bx == within(5, tol));
    CHECK(q.ay == within(q.by, tol));
}

// Separated shapes: the signed request answers as the unsigned one (unit squares 3 apart).
TEST_CASE("signed: two unit squares 3 apart: distance 3, as without signed distance")
{
    const peers::Answer r = signedLibccd().distance(peers::unitSquare(), peers::unitSquare(4, 0));
    REQUIRE(r.status == GJK2D_STATUS_OK);
    CHECK(r.distance == within(3, kPolygon));
    CHECK(r.ax == within(1, kPolygon));
    CHECK(r.bx == within(4, kPolygon));
}

// Rounded shapes through FCL's Sphere and Capsule: a disc of radius 0.5 at (0.8, 0.5) in the unit
// square is freed by moving the square 0.7 to the left (its edge x = 1 to the disc's leftmost
// point x = 0.3; every other way is longer), depth 0.7, pA (0.3, 0.5) on the disc, pB (1, 0.5) on
// the square; the capsule around (0, 0.5)-(2, 0.5) of radius 0.25 leaves it by moving
// the square 0.75 up or down (along x: 2.25 or 1.25), depth 0.75. Curved: within kRounded, FCL's
// threshold (measured 4.6e-8 and 3e-9).
TEST_CASE("signed: a disc and a capsule in the unit square: depths 0.7 and 0.75")
{
    const peers::Answer r =
        signedLibccd().distance(peers::Shape{{0, 0}, 0.5, 0.8, 0.5}, peers::unitSquare());
    REQUIRE(r.status == GJK2D_STATUS_OK);
    CHECK(r.distance == within(-0.7, kRounded));
    CHECK(r.ax == within(0.3, kRounded));
    CHECK(r.bx == within(1, kRounded));
    const peers::Answer c =
        signedLibccd().distance(peers::Shape{{0, 0, 2, 0}, 0.25, 0, 0.5}, peers::unitSquare());
    REQUIRE(c.status == GJK2D_STATUS_OK);
    CHECK(c.distance == within(-0.75, kRounded));
    CHECK(std::abs(c.ay - c.by) == within(0.75, kRounded));
}
