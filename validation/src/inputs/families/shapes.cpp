// Sizes, shape kinds and poses: random pairs scaled tiny or huge, many vertices, rotations near
// quarter turns, rounded shapes, single points.
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

void genScaled(Rng& r, int i, Case& c, double k)
{
    randomPair(r, c, i % 4);
    scaleCase(c, k);
}

FamilyRow tinyScaleRow()
{
    return {{"tiny-scale", 40,
             "Random pairs scaled by 1e-12: squared quantities near 1e-24 (1e-48 for products of "
             "squares) test relative tolerances and underflow margins."},
            [](Rng& r, int i, Case& c, std::string& tag)
            {
                genScaled(r, i, c, 1e-12);
                tag = randomPairTag(i);
            },
            {{"max |coordinate|", M::MaxCoordinate, 0, 2e-11},
             {"overlapping fraction", M::OverlapFraction, 0.2, 0.8}}};
}

FamilyRow hugeScaleRow()
{
    return {{"huge-scale", 40,
             "Random pairs scaled by 1e9: squared quantities near 1e18 (1e36 for products) test "
             "overflow margins and absolute rounding."},
            [](Rng& r, int i, Case& c, std::string& tag)
            {
                genScaled(r, i, c, 1e9);
                tag = randomPairTag(i);
            },
            {{"max |coordinate|", M::MaxCoordinate, 1e9, kInf},
             {"overlapping fraction", M::OverlapFraction, 0.2, 0.8}}};
}

void genManyVertices(Rng& r, int i, Case& c, std::string& tag)
{
    static const int counts[] = {1000, 2000, 4000, 4000, 3000, 4096, 1024, 4000};
    static const double gaps[] = {1e-3, 1e-6, 1e-9, -1e-6};
    const int n = counts[i % 8];
    c.a = regularPolygon(n, 1, r.range(0, 1));
    c.b = i % 2 == 0 ? regularPolygon(n, 0.5, r.range(0, 1)) : randomPolygon(r);
    tag = fmt::format("n{}-{}", n, i % 2 == 0 ? "circles" : "circle-poly");
    randomPose(r, c.a);
    setPose(c.b, r.range(0, 2 * kPi), 0, 0);
    placeAtGap(c.a, c.b, gaps[i % 4], r);
}

FamilyRow manyVerticesRow()
{
    return {
        {"many-vertices", 8,
         "Polygons of 1000 to 4096 vertices approximating circles at gaps 1e-3..1e-9 and overlap: "
         "many nearly collinear support candidates, long runs of tiny progress, iteration "
         "limits."},
        genManyVertices,
        {{"max vertices", M::MaxVertices, 4000, kInf}}};
}

void genRotated(Rng& r, int i, Case& c, std::string& tag)
{
    c.a = randomPolygon(r);
    c.b = randomPolygon(r);
    for (ShapeIn* s : {&c.a, &c.b})
    {
        double t;
        if (i % 3 == 0)
            t = r.range(0, 2 * kPi);
        else
            t = r.integer(0, 3) * kPi / 2 + r.sign() * r.logUniform(-12, -1);
        setPose(*s, t, r.range(-4, 4), r.range(-4, 4));
    }
    tag = i % 3 == 0 ? "random-angle" : "near-quarter-turn";
    const double g = r.logUniform(-10, -2);
    placeAtGap(c.a, c.b, i % 4 == 3 ? -g : g, r);
}

FamilyRow rotatedRow()
{
    return {
        {"rotated", 40,
         "Rotations near multiples of a quarter turn (within 1e-12..1e-1) and random, in contact "
         "at small gaps: (c, s) with c^2 + s^2 != 1 in floating point and the local-frame "
         "mapping."},
        genRotated,
        {{"separated fraction", M::SeparatedFraction, 0.6, 0.85}}};
}

ShapeIn roundedShape(Rng& r, int kind)
{
    const double rad = r.logUniform(-3, 0), size = r.range(0.5, 2);
    switch (kind)
    {
    case 0:
        return poly({{0, 0}}, rad);
    case 1:
        return poly({{-size, 0}, {size, 0}}, rad);
    case 2:
        return poly({{-size, -size / 2}, {size, -size / 2}, {size, size / 2}, {-size, size / 2}},
                    rad);
    default:
    {
        ShapeIn s = polygonOnCircle(r, 3, size);
        s.radius = rad;
        return s;
    }
    }
}

void genRounded(Rng& r, int i, Case& c, std::string& tag)
{
    static const char* kinds[] = {"disc", "capsule", "box", "triangle"};
    const int ka = i % 4, kb = (i / 4) % 4;
    c.a = roundedShape(r, ka);
    c.b = roundedShape(r, kb);
    tag = fmt::format("{}-{}", kinds[ka], kinds[kb]);
    randomPose(r, c.a);
    setPose(c.b, r.range(0, 2 * kPi), 0, 0);
    double g = r.logUniform(-10, -2);
    if (i % 4 == 1)
        g = -g;
    else if (i % 4 == 3)
        g = r.logUniform(-1, 0);
    placeAtGap(c.a, c.b, g, r);
}

FamilyRow roundedRow()
{
    return {{"rounded", 40,
             "Rounded shapes (discs, capsules, rounded boxes and triangles, radii 1e-3..1) at gaps "
             "and "
             "penetrations: the radius is applied after GJK, on the core distance."},
            genRounded,
            {{"rounded fraction", M::RadiusFraction, 1, 1},
             {"separated fraction", M::SeparatedFraction, 0.6, 0.85}}};
}

// A point inside a polygon (its vertex centroid).
void pointInside(Rng& r, Case& c)
{
    c.a = randomPolygon(r);
    randomPose(r, c.a);
    double x = 0, y = 0;
    for (const auto& p : c.a.points)
    {
        x += p[0];
        y += p[1];
    }
    const double n = double(c.a.points.size());
    c.b = c.a;
    c.b.points = {{x / n, y / n}};
}

// A point exactly on a vertex (same local point, same pose).
void pointOnVertex(Rng& r, Case& c)
{
    c.a = randomPolygon(r);
    randomPose(r, c.a);
    c.b = c.a;
    c.b.points = {c.a.points[std::size_t(r.integer(0, int(c.a.points.size()) - 1))]};
}

// A point exactly on an edge (dyadic).
void pointOnEdge(Rng& r, Case& c)
{
    c.a = poly({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
    randomPose(r, c.a);
    c.b = c.a;
    c.b.points = {{1, 0.375}};
}

// A point outside a polygon, near an edge.
void pointNearEdge(Rng& r, Case& c)
{
    c.a = randomPolygon(r);
    randomPose(r, c.a);
    c.b = poly({{0, 0}});
    placeAtGap(c.a, c.b, r.logUniform(-12, -2), r);
}

void pointSame(Rng& r, Case& c)
{
    c.a = poly({{r.range(-4, 4), r.range(-4, 4)}});
    c.b = c.a;
}

void pointPoint(Rng& r, Case& c)
{
    c.a = poly({{r.range(-4, 4), r.range(-4, 4)}});
    c.b = poly({{r.range(-4, 4), r.range(-4, 4)}});
    randomPose(r, c.a);
    randomPose(r, c.b);
}

// Two points one ulp apart.
void pointUlp(Rng& r, Case& c)
{
    const double x = r.range(-4, 4), y = r.range(-4, 4);
    c.a = poly({{x, y}});
    c.b = poly({{std::nextafter(x, kInf), y}});
}

// A point near a segment's endpoint region.
void pointNearSegment(Rng& r, Case& c)
{
    c.a = poly({{-1, 0}, {1, 0}});
    randomPose(r, c.a);
    c.b = poly({{0, 0}});
    placeAtGap(c.a, c.b, r.logUniform(-12, -2), r);
}

void genPoints(Rng& r, int i, Case& c, std::string& tag)
{
    static const struct
    {
        const char* tag;
        void (*make)(Rng&, Case&);
    } kinds[] = {{"inside", pointInside},   {"on-vertex", pointOnVertex},
                 {"on-edge", pointOnEdge},  {"near-edge", pointNearEdge},
                 {"point-same", pointSame}, {"point-point", pointPoint},
                 {"point-ulp", pointUlp},   {"near-segment", pointNearSegment}};
    kinds[i % 8].make(r, c);
    tag = kinds[i % 8].tag;
}

FamilyRow pointsRow()
{
    return {
        {"points", 16,
         "Single points: inside a polygon, exactly on a vertex or an edge, near an edge, point to "
         "point (identical, distinct, one ulp apart), near a segment: one-vertex simplices only."},
        genPoints,
        {{"min vertices", M::MinVertices, 1, 1, MakeupScope::EveryCase},
         {"overlapping fraction", M::OverlapFraction, 0.5, 0.5}}};
}

} // namespace

std::vector<FamilyRow> shapeFamilies()
{
    return {tinyScaleRow(), hugeScaleRow(), manyVerticesRow(),
            rotatedRow(),   roundedRow(),   pointsRow()};
}

} // namespace gjkval::families
