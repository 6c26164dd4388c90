// Scales the types strain at: a tiny shape beside a large one, pairs scaled from 1e-300 to
// 1e300, and inputs outside float's and double's safe ranges.
#include "inputs/families/construct.hpp"
#include "inputs/families/rows.hpp"

#include "gjk2d/math.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace gjkval::families
{
namespace
{

void genMixedScale(Rng& r, int i, Case& c, std::string& tag)
{
    static const double gapFactor[] = {10, 1, 1e-2, -1e-2};
    const int ei = i % 4, li = (i / 4) % 4, gi = (i / 16) % 4;
    const bool swap = (i / 64) % 2 == 1;
    const double eps = std::pow(10.0, -(6 + 2 * ei)), L = std::pow(10.0, 2 * li);
    ShapeIn big = randomPolygon(r), tiny = randomPolygon(r);
    randomPose(r, big);
    scaleShape(big, L);
    scaleShape(tiny, eps);
    setPose(tiny, r.range(0, 2 * kPi), 0, 0);
    placeAtGap(big, tiny, gapFactor[gi] * eps, r);
    c.a = swap ? tiny : big;
    c.b = swap ? big : tiny;
    tag = fmt::format("{}-L1e{}-eps1e-{}-gap{:g}eps", swap ? "tiny-big" : "big-tiny", 2 * li,
                      6 + 2 * ei, gapFactor[gi]);
}

FamilyRow mixedScaleRow()
{
    return {{"mixed-scale", 128,
             "A tiny polygon (size 1e-6 .. 1e-12) near contact (gaps 10, 1, 0.01 times its size, "
             "overlap 0.01) with a large one (size and position 1 .. 1e6), either one as A (the "
             "compute frame): the Minkowski difference has the large shape's coordinates while the "
             "answer is on the tiny one's scale, so tolerances relative to one shape fail and the "
             "error must follow the larger scale."},
            genMixedScale,
            {{"min size ratio", M::MinSizeRatio, 1e5, kInf},
             {"max size ratio", M::MaxSizeRatio, 1e17, kInf},
             {"separated fraction", M::SeparatedFraction, 0.5, 0.95},
             {"max distance", M::MaxDistance, 0, 1e-4}}};
}

// Scales 1e-300 .. 1e300 in steps of 10x: a random pair (gap, penetration, deep overlap, random
// placement) scaled as a whole. Outside Tolerances<T>'s safe range the query reruns rescaled by a
// power of two ("any finite input gets an answer"): every case here must be answered
// within its bound, none flagged outOfRange. Float variants see the cases that fit in float.
void genExtremeScale(Rng& r, int i, Case& c, std::string& tag)
{
    const int e = -300 + 10 * (i % 61), mode = (i / 61) % 4;
    randomPair(r, c, mode);
    scaleCase(c, std::pow(10.0, e));
    tag = fmt::format("{}-1e{}", randomPairTag(mode), e);
}

FamilyRow extremeScaleRow()
{
    return {
        {"extreme-scale", 244,
         "A random pair (at a gap, penetrating, deeply overlapping, placed at random) scaled by "
         "1e-300, 1e-290, ... 1e300: outside the type's safe range the query must rescale itself "
         "by a power of two (exact) and answer within its bound, never flag a finite input whose "
         "extent fits in the exponent range (hostile-input hardening: two separated shapes at "
         "1e-300 were "
         "answered 0 and flagged)."},
        genExtremeScale,
        {{"max |coordinate|", M::MaxCoordinate, 1e299, kInf},
         {"smallest case scale", M::MinScale, 0, 1e-299},
         {"separated fraction", M::SeparatedFraction, 0.2, 0.8}}};
}

// Whether the range-gap mode also runs at double's scale (size 1e160, gap 0.3 maxCoordinate of
// double); a switch so that the mode can be isolated when investigating
// (validation/cases/range-overflow.json keeps one such input).
constexpr bool kRangeGapInDouble = true;

// The range-gap mode's A: a random polygon of size k, counter-clockwise with distinct vertices, a
// random vertex made vertex 0.
ShapeIn rangeGapA(Rng& r, double k)
{
    ShapeIn a = polygonOnCircle(r, r.integer(3, 8), 1);
    a.points = convexHull(a.points); // counter-clockwise, distinct vertices (at size 1: the
    scaleShape(a, k);                // hull's products would overflow at 1e160)
    const std::size_t ia = std::size_t(r.integer(0, int(a.points.size()) - 1));
    std::rotate(a.points.begin(), a.points.begin() + std::ptrdiff_t(ia), a.points.end());
    return a;
}

// The range-gap mode's B: a random polygon of size k turned at random, its extreme vertex along
// -n moved to `target` and made vertex 0.
ShapeIn rangeGapB(Rng& r, double k, P2 n, P2 target)
{
    ShapeIn b = randomPolygon(r);
    scaleShape(b, k);
    const double t = r.range(0, 2 * kPi), ct = std::cos(t), st = std::sin(t);
    std::size_t ib = 0;
    double best = kInf;
    for (std::size_t j = 0; j < b.points.size(); ++j)
    {
        auto& q = b.points[j];
        q = {ct * q[0] - st * q[1], st * q[0] + ct * q[1]};
        if (const double v = n[0] * q[0] + n[1] * q[1]; v < best)
        {
            best = v;
            ib = j;
        }
    }
    const P2 shift = {target[0] - b.points[ib][0], target[1] - b.points[ib][1]};
    for (auto& q : b.points)
        q = {q[0] + shift[0], q[1] + shift[1]};
    std::rotate(b.points.begin(), b.points.begin() + std::ptrdiff_t(ib), b.points.end());
    return b;
}

// Shapes of size ~k, both at the same translation (so the cold start is the vertex pair (0, 0)),
// B's vertex 0 at a gap g from A's edge 0 -> 1, at a distance g from A's vertex 0 along that edge;
// g = 0.3 maxCoordinate of float (of double for 1e160). Every support point of the walk stays in
// range (|w| ~ 0.42 maxCoordinate) while dot(d, point) with the shapes' own points (|d| ~ g,
// |point| ~ k) overflows.
void rangeGap(Rng& r, Case& c, double k)
{
    const double g = 0.3 * (k > 1e100 ? double(gjk::Tolerances<double>::maxCoordinate)
                                      : double(gjk::Tolerances<float>::maxCoordinate));
    c.a = rangeGapA(r, k);
    const P2 a0 = c.a.points[0], a1 = c.a.points[1];
    const double len = std::hypot(a1[0] - a0[0], a1[1] - a0[1]);
    const P2 e = {(a1[0] - a0[0]) / len, (a1[1] - a0[1]) / len}, n = {e[1], -e[0]};
    const P2 target = {a0[0] + g * e[0] + g * n[0], a0[1] + g * e[1] + g * n[1]};
    c.b = rangeGapB(r, k, n, target);
    setPose(c.a, r.range(0, 2 * kPi), r.range(-4, 4) * k, r.range(-4, 4) * k);
    copyPose(c.a, c.b);
}

// Shapes of size ~1 at a small gap, at a common offset k in the transforms.
void rangeOffset(Rng& r, Case& c, double k)
{
    randomPair(r, c, 0);
    const double phi = r.range(0, 2 * kPi);
    for (ShapeIn* s : {&c.a, &c.b})
    {
        s->px += k * std::cos(phi);
        s->py += k * std::sin(phi);
    }
}

// A pair at a small gap scaled by k, its transforms baked into the coordinates.
void rangeBaked(Rng& r, Case& c, double k)
{
    randomPair(r, c, 0);
    scaleCase(c, k);
    bake(c.a);
    bake(c.b);
}

void genRange(Rng& r, int i, Case& c, std::string& tag)
{
    // Outside float's safe range (above 2.3e18, below 4.4e-16) and double's (1.7e153, 1.5e-146).
    static const double scales[] = {1e19,    3.3e21, 1e24,    4.4e27, 1e30,  1e-20,
                                    3.3e-23, 1e-25,  4.4e-28, 1e-30,  1e160, 1e-160};
    const int si = i % 12, mode = (i / 12) % 6;
    const double k = scales[si];
    if (mode == 5 && k > 1 && (k < 1e100 || kRangeGapInDouble))
    {
        rangeGap(r, c, k);
        tag = "range-gap";
    }
    else if (mode < 4 || mode == 5)
    {
        randomPair(r, c, mode % 4); // mode 5 below 1: a second penetration
        scaleCase(c, k);
        tag = randomPairTag(mode % 4);
    }
    else if (k > 1)
    {
        rangeOffset(r, c, k);
        tag = "offset";
    }
    else
    {
        rangeBaked(r, c, k);
        tag = "gap-baked";
    }
    tag += fmt::format("-x{:g}", k);
}

FamilyRow rangeRow()
{
    return {
        {"range", 72,
         "Inputs outside float's safe range (coordinates 1e19 .. 1e30, 1e-20 .. 1e-30: squared "
         "lengths overflow or underflow in float) and double's (1e160, 1e-160): random pairs "
         "scaled, a common offset, baked coordinates, and shapes of size 1e19..1e30 (and 1e160) "
         "starting (vertex 0 of each, same translation) at a vertex pair 0.4 times the type's "
         "maxCoordinate apart: the support points stay in range while dot(d, point) with the "
         "shapes' own points overflows. GJK must not return inf, NaN or a silently wrong "
         "distance: since the hostile-input hardening it reruns such queries rescaled by a power "
         "of two and they are "
         "judged within their bound (outOfRange only for inputs that cannot be rescaled)."},
        genRange,
        {{"max |coordinate|", M::MaxCoordinate, 1e160, kInf},
         {"smallest case scale", M::MinScale, 0, 1e-158},
         {"outside float's safe range", M::OutsideFloatRangeFraction, 1, 1}}};
}

} // namespace

std::vector<FamilyRow> scaleFamilies()
{
    return {mixedScaleRow(), extremeScaleRow(), rangeRow()};
}

} // namespace gjkval::families
