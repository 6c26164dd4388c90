// Degenerate input: implicit hulls (duplicate, collinear, interior points), nearly collinear
// segments, identical and nested shapes.
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

ShapeIn degenerateShape(Rng& r, int mode)
{
    switch (mode)
    {
    case 0: // every vertex repeated 1 to 3 times
    {
        ShapeIn base = randomPolygon(r), s;
        for (const auto& p : base.points)
            for (int k = r.integer(1, 3); k > 0; --k)
                s.points.push_back(p);
        std::rotate(s.points.begin(), s.points.begin() + r.integer(0, int(s.points.size()) - 1),
                    s.points.end());
        return s;
    }
    case 1: // square with exactly collinear points on its edges (dyadic quarters), shuffled
    {
        ShapeIn s;
        for (int k = 0; k < 8; ++k)
        {
            const double t = -1 + k / 4.0;
            s.points.push_back({t, -1});
            s.points.push_back({1, t});
            s.points.push_back({-t, 1});
            s.points.push_back({-1, -t});
        }
        r.shuffle(s.points);
        return s;
    }
    case 2: // all points collinear: a segment given by five points, shuffled
    {
        ShapeIn s = poly({{-1, -0.5}, {-0.5, -0.25}, {0, 0}, {0.25, 0.125}, {1, 0.5}});
        r.shuffle(s.points);
        return s;
    }
    case 3: // all points identical: a point
        return poly({{0.25, -0.5}, {0.25, -0.5}, {0.25, -0.5}, {0.25, -0.5}});
    default: // hull vertices plus interior points, shuffled
    {
        ShapeIn s = randomPolygon(r);
        const std::size_t n = s.points.size();
        for (std::size_t k = 0; k < n; ++k)
            s.points.push_back({0.5 * s.points[k][0], 0.5 * s.points[k][1]});
        r.shuffle(s.points);
        return s;
    }
    }
}

void genDegenerate(Rng& r, int i, Case& c, std::string& tag)
{
    static const char* modes[] = {"duplicates", "collinear", "all-collinear", "all-identical",
                                  "interior-shuffled"};
    const int ma = i % 5;
    c.a = degenerateShape(r, ma);
    tag = modes[ma];
    if (i % 2 == 1)
    {
        const int mb = (i / 2) % 5;
        c.b = degenerateShape(r, mb);
        tag += std::string("-") + modes[mb];
    }
    else
        c.b = randomPolygon(r);
    randomPose(r, c.a);
    setPose(c.b, r.range(0, 2 * kPi), 0, 0);
    const double g = r.logUniform(-9, -3);
    placeAtGap(c.a, c.b, i % 4 == 3 ? -g : g, r);
}

FamilyRow degenerateVerticesRow()
{
    return {
        {"degenerate-vertices", 32,
         "Duplicate vertices, exactly collinear vertices, all points collinear (a segment), all "
         "points identical (a point), interior points and shuffled order: the hull is implicit."},
        genDegenerate,
        {{"min hull vertices", M::MinHullVertices, 1, 1},
         {"max vertices", M::MaxVertices, 32, kInf},
         {"separated fraction", M::SeparatedFraction, 0.4, 1}}};
}

void genSegmentSegment(Rng& r, int i, Case& c, std::string& tag)
{
    static const double betas[] = {0, 1e-12, 1e-8, 1e-4};
    const double beta = betas[(i / 4) % 4];
    const double g = r.logUniform(-10, -1);
    c.a = poly({{-1, 0}, {1, 0}});
    switch (i % 4)
    {
    case 0: // end to end, nearly collinear
        c.b = poly({{1 + g, 0}, {3 + g, 2 * std::sin(beta)}});
        tag = "end-to-end";
        break;
    case 1: // side by side, nearly parallel
        c.b = poly({{-0.5, g}, {1.5, g + 2 * std::tan(beta)}});
        tag = "side-by-side";
        break;
    case 2: // crossing at a tiny angle
    {
        const double eps = r.logUniform(-12, -1);
        c.b = poly({{-1, -eps}, {1, eps}});
        tag = "crossing";
        break;
    }
    default: // perpendicular, approaching the interior of A
        c.b = poly({{0.25, g}, {0.25 + 2 * std::sin(beta), 1}});
        tag = "t-junction";
        break;
    }
    tag += fmt::format("-beta{:g}", beta);
    randomPose(r, c.a);
    // B's points are given in A's frame: same pose.
    c.b.c = c.a.c;
    c.b.s = c.a.s;
    c.b.px = c.a.px;
    c.b.py = c.a.py;
}

FamilyRow segmentSegmentRow()
{
    return {{"segment-segment", 40,
             "Segment against segment nearly collinear (end to end, side by side, crossing, "
             "T-junction) "
             "with angles 0 to 1e-4: zero-area triangles and collinear simplices (talk, 'Collinear "
             "vertices')."},
            genSegmentSegment,
            {{"separated fraction", M::SeparatedFraction, 0.7, 0.8},
             {"min positive distance", M::MinPositiveDistance, 0, 1e-9}}};
}

void genIdenticalNested(Rng& r, int i, Case& c, std::string& tag)
{
    const int mode = i % 6;
    static const char* modes[] = {"identical",   "reversed", "nested-half",
                                  "nested-tiny", "shifted",  "baked"};
    tag = modes[mode];
    c.a = mode == 2 || mode == 3 ? regularPolygon(r.integer(3, 32), r.range(0.5, 2), r.range(0, 1))
                                 : randomPolygon(r);
    randomPose(r, c.a);
    c.b = c.a;
    switch (mode)
    {
    case 1:
        std::reverse(c.b.points.begin(), c.b.points.end());
        break;
    case 2:
        for (auto& p : c.b.points)
            p = {0.5 * p[0], 0.5 * p[1]};
        break;
    case 3:
        c.b.points = {{0, 0}, {1e-3, 0}, {0, 1e-3}};
        break;
    case 4:
    {
        const double d = r.logUniform(-12, -6), t = r.range(0, 2 * kPi);
        c.b.px += d * std::cos(t);
        c.b.py += d * std::sin(t);
        break;
    }
    case 5:
        bake(c.b);
        break;
    default:
        break;
    }
}

FamilyRow identicalNestedRow()
{
    return {{"identical-nested", 24,
             "Identical shapes (same or reversed point order, baked transform), nested shapes and "
             "a copy shifted by 1e-12..1e-6: deep overlap, coincident support points, zero "
             "directions."},
            genIdenticalNested,
            {{"overlapping fraction", M::OverlapFraction, 1, 1}}};
}

} // namespace

std::vector<FamilyRow> degenerateFamilies()
{
    return {degenerateVerticesRow(), segmentSegmentRow(), identicalNestedRow()};
}

} // namespace gjkval::families
