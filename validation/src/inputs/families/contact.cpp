// Exact contact (a vertex, an edge) and separations of one ulp: the overlap decision at the
// boundary.
#include "inputs/families/construct.hpp"
#include "inputs/families/rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace gjkval::families
{
namespace
{

// A shared pose for exact-contact families: a quarter turn (exact) or a rounded random rotation,
// and a dyadic translation.
void contactPose(Rng& r, int i, Case& c, double scale, std::string& tag)
{
    static const double quarter[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const double px = r.integer(-(1 << 20), 1 << 20) * scale / 4;
    const double py = r.integer(-(1 << 20), 1 << 20) * scale / 4;
    if ((i / 2) % 2 == 0)
    {
        const int k = (i / 4) % 4;
        sharedPose(c, quarter[k][0], quarter[k][1], px, py);
        tag += fmt::format("-rot{}", 90 * k);
    }
    else
    {
        const double t = r.range(0, 2 * kPi);
        sharedPose(c, std::cos(t), std::sin(t), px, py);
        tag += "-rot";
    }
}

void genTouchingVertex(Rng& r, int i, Case& c, std::string& tag)
{
    const double S = std::ldexp(1.0, (i * 7) % 21 - 10);
    const bool vv = i % 2 == 0;
    c.a = poly({{0, 0}, {S, 0}, {S, S}, {0, S}});
    if (vv)
        c.b = poly({{S, S}, {2 * S, 1.5 * S}, {1.5 * S, 2 * S}});
    else
    {
        const double t = r.integer(1, 7) / 8.0 * S;
        c.b = poly({{S, t}, {2 * S, t - S / 2}, {2 * S, t + S / 2}});
    }
    tag = fmt::format("{}-s2^{}", vv ? "vertex-vertex" : "vertex-edge", (i * 7) % 21 - 10);
    if (i % 3 == 0)
        std::swap(c.a, c.b);
    contactPose(r, i, c, S, tag);
}

FamilyRow touchingVertexRow()
{
    return {
        {"touching-vertex", 24,
         "Exact contact at a vertex (vertex on vertex, vertex inside an edge) with dyadic "
         "coordinates and a shared pose: the true distance is exactly 0, so any positive answer "
         "is "
         "rounding; tests the overlap decision at the boundary."},
        genTouchingVertex,
        {{"overlapping fraction", M::OverlapFraction, 1, 1}}};
}

void genTouchingEdge(Rng& r, int i, Case& c, std::string& tag)
{
    const double S = std::ldexp(1.0, (i * 5) % 17 - 8);
    auto sc = [S](std::vector<P2> v)
    {
        for (auto& p : v)
            p = {p[0] * S, p[1] * S};
        return poly(std::move(v));
    };
    switch (i % 4)
    {
    case 0:
    {
        // Every x0 + len reaches x >= 0 and every x0 <= 2: the top edges always meet, as the
        // make-up check (overlapping fraction 1) requires.
        static const double x0s[] = {-0.5, 0, 0.5, 1, 1.5}, lens[] = {0.5, 1, 3};
        const double x0 = x0s[r.integer(0, 4)], x1 = x0 + lens[r.integer(0, 2)];
        c.a = sc({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
        c.b = sc({{x0, 2}, {x1, 2}, {x1, 3}, {x0, 3}});
        tag = "box-on-box";
        break;
    }
    case 1:
        c.a = sc({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
        c.b = sc({{2, 0}, {3, 0}, {3, 2}, {2, 2}});
        tag = "shared-edge";
        break;
    case 2:
        c.a = sc({{0, 0}, {4, 0}, {0, 4}});
        c.b = sc({{1, 3}, {3, 1}, {4, 4}});
        tag = "slanted";
        break;
    default:
        c.a = sc({{0, 0}, {4, 0}, {0, 4}});
        c.b = sc({{3, 1}, {5, -1}, {5, 3}});
        tag = "slanted-partial";
        break;
    }
    if (i % 3 == 1)
        std::swap(c.a, c.b);
    contactPose(r, i, c, S, tag);
}

FamilyRow touchingEdgeRow()
{
    return {
        {"touching-edge", 24,
         "Exact contact along an edge (shared, partial, slanted), dyadic and exactly "
         "representable: "
         "the origin lies on an edge of the Minkowski difference (talk, termination cases 3b and "
         "4)."},
        genTouchingEdge,
        {{"overlapping fraction", M::OverlapFraction, 1, 1}}};
}

void genUlpGap(Rng& r, int i, Case& c, std::string& tag)
{
    static const double mags[] = {0.5, 1, 3, 1000, 1048576.5, 1e6, 1e9, 1e-6};
    const double X = mags[i % 8];
    const bool apart = (i / 8) % 2 == 0;
    const bool vertex = (i / 16) % 2 == 0;
    const double Xp = std::nextafter(X, apart ? kInf : -kInf);
    const double w = X / 2, h = X / 2;
    c.a = poly({{X - w, -h}, {X, -h}, {X, h}, {X - w, h}});
    if (vertex)
        c.b = poly({{Xp, 0}, {X + w, -h}, {X + w, h}});
    else
        c.b = poly({{Xp, -h / 2}, {X + w, -h / 2}, {X + w, h / 2}, {Xp, h / 2}});
    tag = fmt::format("x{:g}-{}-{}", X, apart ? "gap" : "overlap", vertex ? "vertex" : "edge");
    if (i % 3 == 0)
    {
        const double px = r.integer(-1000, 1000), py = r.integer(-1000, 1000);
        sharedPose(c, 1, 0, px, py);
        tag += "-shifted";
    }
}

FamilyRow ulpGapRow()
{
    return {{"ulp-gap", 32,
             "Gaps and overlaps of exactly one ulp of the contact coordinate at magnitudes 1e-6 to "
             "1e9: "
             "the smallest nonzero separation the input can express."},
            genUlpGap,
            {{"separated fraction", M::SeparatedFraction, 0.5, 0.5},
             {"max distance", M::MaxDistance, 0, 2.5e-7}}};
}

} // namespace

std::vector<FamilyRow> contactFamilies()
{
    return {touchingVertexRow(), touchingEdgeRow(), ulpGapRow()};
}

} // namespace gjkval::families
