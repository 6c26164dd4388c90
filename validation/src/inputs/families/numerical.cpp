// The talk's numerical issues: its single-precision example, near-parallel closest edges,
// shapes far from the origin, slivers.
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

void genTalkSegment(Rng& r, int i, Case& c, std::string& tag)
{
    // Talk, "Numerical issues": segment A B against the origin, single precision.
    P2 p0 = {0.021119118, 79.584320}, p1 = {0.020964622, -31.515678};
    ShapeIn seg = poly({p0, p1}), origin = poly({{0, 0}});
    static const int scales[] = {-8, -4, -1, 1, 4, 8};
    if (i == 0)
        tag = "original";
    else if (i == 1)
    {
        tag = "swapped";
        std::swap(seg, origin);
    }
    else if (i <= 7)
    {
        const int k = scales[i - 2];
        tag = fmt::format("scale2^{}", k);
        for (auto& p : seg.points)
            p = {std::ldexp(p[0], k), std::ldexp(p[1], k)};
    }
    else if (i == 8)
    {
        tag = "mirror-x";
        for (auto& p : seg.points)
            p[0] = -p[0];
    }
    else if (i == 9)
    {
        tag = "rot90";
        for (auto& p : seg.points)
            p = {-p[1], p[0]};
    }
    else if (i == 10)
    {
        tag = "float-input";
        for (auto& p : seg.points)
            p = {roundToFloat(p[0]), roundToFloat(p[1])};
    }
    else if (i == 11)
    {
        tag = "offset1e3";
        seg.px = origin.px = 1000.5;
        seg.py = origin.py = -250.25;
    }
    else
    {
        tag = "jitter";
        for (auto& p : seg.points)
            p = {p[0] * (1 + r.range(-1e-3, 1e-3)), p[1] * (1 + r.range(-1e-3, 1e-3))};
    }
    c.a = seg;
    c.b = origin;
}

FamilyRow talkSegmentRow()
{
    return {
        {"talk-segment", 16,
         "The talk's single-precision example: segment (0.021119118, 79.584320)-(0.020964622, "
         "-31.515678) against the origin. With d = -P the search direction has dot(d, edge) = "
         "3.2e-6 in float and may pick a wrong support point; scaled, mirrored, rotated, swapped, "
         "offset and jittered copies."},
        genTalkSegment,
        {{"separated fraction", M::SeparatedFraction, 1, 1}}};
}

void genNearParallel(Rng& r, int i, Case& c, std::string& tag)
{
    const int gi = i % 12;
    static const double tilts[] = {0, 1e-9, 1e-6, 1e-3};
    const double g = std::pow(10.0, -(1 + gi)), alpha = tilts[(i / 12) % 4];
    tag = fmt::format("gap1e-{}-tilt{:g}", gi + 1, alpha);
    c.a = poly({{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}});
    c.b = poly({{-0.9, 0}, {0.9, 0}, {0.9, 0.6}, {-0.9, 0.6}});
    const double ca = std::cos(alpha), sa = std::sin(alpha);
    double minY = kInf;
    for (const auto& p : c.b.points)
        minY = std::min(minY, sa * p[0] + ca * p[1]);
    randomPose(r, c.a);
    poseRelativeTo(c.a, c.b, alpha, {r.range(-0.05, 0.05), 0.5 + g - minY});
}

FamilyRow nearParallelRow()
{
    return {{"near-parallel", 48,
             "Near-parallel closest edges at gaps 1e-1 down to 1e-12 and tilts 0 to 1e-3: the "
             "edge-versus-vertex decision and the edge distance lose relative accuracy as the gap "
             "shrinks."},
            genNearParallel,
            {{"separated fraction", M::SeparatedFraction, 1, 1},
             {"min positive distance", M::MinPositiveDistance, 0, 2e-12},
             {"max distance", M::MaxDistance, 0.09, 0.2}}};
}

void genFarFromOrigin(Rng& r, int i, Case& c, std::string& tag)
{
    const int oi = i % 4, gi = (i / 4) % 5;
    const bool coords = (i / 20) % 2 == 1;
    const double offset = std::pow(10.0, 3 + 2 * oi), gap = std::pow(10.0, -(1 + gi));
    tag = fmt::format("off1e{}-gap1e-{}-{}", 3 + 2 * oi, 1 + gi, coords ? "coords" : "transform");
    c.a = randomPolygon(r);
    c.b = randomPolygon(r);
    setPose(c.a, r.range(0, 2 * kPi), 0, 0);
    setPose(c.b, r.range(0, 2 * kPi), 0, 0);
    placeAtGap(c.a, c.b, gap, r);
    moveFar(c, offset, r.range(0, 2 * kPi), coords);
}

FamilyRow farFromOriginRow()
{
    return {
        {"far-from-origin", 40,
         "Shapes at offsets 1e3 to 1e9 with gaps 1e-1 to 1e-5, the offset in the transforms (A's "
         "local frame cancels it) or baked into the coordinates (nothing can): absolute rounding "
         "grows with the coordinates, not with the gap."},
        genFarFromOrigin,
        {{"separated fraction", M::SeparatedFraction, 1, 1},
         {"max |coordinate|", M::MaxCoordinate, 7e8, kInf}}};
}

ShapeIn sliverShape(int kind, double w)
{
    if (kind == 0)
        return poly({{-1, -w / 2}, {1, -w / 2}, {1, w / 2}, {-1, w / 2}});
    return poly({{-1, 0}, {1, -w / 2}, {1, w / 2}});
}

void genSliver(Rng& r, int i, Case& c, std::string& tag)
{
    const int ai = i % 8, kind = (i / 8) % 5;
    const double aspect = std::pow(10.0, 1 + ai), w = 2 / aspect;
    static const char* kinds[] = {"rect-poly", "tri-poly", "rect-rect", "tri-tri", "poly-rect"};
    tag = fmt::format("aspect1e{}-{}", 1 + ai, kinds[kind]);
    switch (kind)
    {
    case 0:
        c.a = sliverShape(0, w);
        c.b = randomPolygon(r);
        break;
    case 1:
        c.a = sliverShape(1, w);
        c.b = randomPolygon(r);
        break;
    case 2:
        c.a = sliverShape(0, w);
        c.b = sliverShape(0, w);
        break;
    case 3:
        c.a = sliverShape(1, w);
        c.b = sliverShape(1, w);
        break;
    default:
        c.a = randomPolygon(r);
        c.b = sliverShape(0, w);
        break;
    }
    randomPose(r, c.a);
    setPose(c.b, r.range(0, 2 * kPi), 0, 0);
    double g = std::pow(10.0, -(2 + (i * 3) % 7));
    if (i % 5 == 4)
        g = -std::min(g, w / 4);
    placeAtGap(c.a, c.b, g, r);
}

FamilyRow sliverRow()
{
    return {
        {"sliver", 40,
         "Slivers (rectangles and wedges) with aspect ratios 1e1 to 1e8 against polygons and each "
         "other: nearly degenerate simplices, tiny cross products, long edges with tiny normals."},
        genSliver,
        {{"max aspect ratio", M::MaxAspect, 0.99e8, kInf},
         {"separated fraction", M::SeparatedFraction, 0.7, 1}}};
}

} // namespace

std::vector<FamilyRow> numericalFamilies()
{
    return {talkSegmentRow(), nearParallelRow(), farFromOriginRow(), sliverRow()};
}

} // namespace gjkval::families
