// Starts and poses: every cold-start vertex pair of small pairs, and a float engine's
// rotations that are unit vectors only to float rounding.
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

// The cold-start sweep's pairs (points of A, points of B): every rotation of both point orders
// (na * nb cases) and kColdShuffles shuffled orders each.
constexpr int kColdPairs[][2] = {{3, 3}, {3, 4}, {4, 4}, {4, 5}, {5, 5}, {3, 6}, {6, 6}, {5, 8}};
constexpr int kColdShuffles = 3;
constexpr int kColdBlock = []
{
    int n = 0;
    for (const auto& p : kColdPairs)
        n += p[0] * p[1] + kColdShuffles;
    return n;
}();

void genColdStartSweep(Rng& r, int i, Case& c, std::string& tag)
{
    const int block = i / kColdBlock;
    int j = i % kColdBlock, p = 0;
    while (j >= kColdPairs[p][0] * kColdPairs[p][1] + kColdShuffles)
    {
        j -= kColdPairs[p][0] * kColdPairs[p][1] + kColdShuffles;
        ++p;
    }
    const int na = kColdPairs[p][0], nb = kColdPairs[p][1];
    const int pair = block * int(std::size(kColdPairs)) + p;
    Rng g = sharedRng(r, 0xc01d5eedULL + std::uint64_t(pair));
    c.a = polygonOnCircle(g, na, g.range(0.5, 2));
    c.b = polygonOnCircle(g, nb, g.range(0.5, 2));
    randomPose(g, c.a);
    setPose(c.b, g.range(0, 2 * kPi), 0, 0);
    const double gap = g.logUniform(-9, -3);
    placeAtGap(c.a, c.b, pair % 2 == 0 ? gap : -gap, g);
    // B re-expressed around A's origin (same translation): the cold start then begins at
    // vertex 0 of each shape (gjk::distance: the direction between the origins is zero).
    const auto wb = worldPoints(c.b);
    for (std::size_t k = 0; k < wb.size(); ++k)
    {
        const double dx = wb[k][0] - c.a.px, dy = wb[k][1] - c.a.py;
        c.b.points[k] = {c.b.c * dx + c.b.s * dy, -c.b.s * dx + c.b.c * dy};
    }
    c.b.px = c.a.px;
    c.b.py = c.a.py;
    if (j < na * nb)
    {
        const int ra = j % na, rb = j / na;
        std::rotate(c.a.points.begin(), c.a.points.begin() + ra, c.a.points.end());
        std::rotate(c.b.points.begin(), c.b.points.begin() + rb, c.b.points.end());
        tag = fmt::format("pair{}-{}x{}-start{}-{}", pair, na, nb, ra, rb);
    }
    else
    {
        r.shuffle(c.a.points);
        r.shuffle(c.b.points);
        tag = fmt::format("pair{}-{}x{}-shuffled{}", pair, na, nb, j - na * nb);
    }
}

FamilyRow coldStartSweepRow()
{
    return {{"cold-start-sweep", 200,
             "Eight small random pairs (3 to 8 points, gaps and overlaps of 1e-9 .. 1e-3) with "
             "both shapes at the same translation, so that the cold start begins at vertex 0 of "
             "each: every rotation of both point orders (every vertex pair is the start) and "
             "shuffled orders. A start on the far side, or on a vertex tied with the support, "
             "walks a different simplex path: repeated support points and degenerate simplices "
             "that one fixed start never shows."},
            genColdStartSweep,
            {{"shared origin fraction", M::SharedOriginFraction, 1, 1},
             {"distinct exact distances", M::DistinctDistances, 2, 8},
             {"separated fraction", M::SeparatedFraction, 0.45, 0.55},
             {"max vertices", M::MaxVertices, 8, 8},
             {"min vertices", M::MinVertices, 3, 3}}};
}

// A float engine's poses: (c, s) = (float(cos t), float(sin t)), a unit vector only to float
// rounding (|c^2 + s^2 - 1| up to ~1e-7 in double), and every other number rounded to float too,
// as an engine stores them. A's angles sweep the circle by the golden-ratio sequence
// t_i = 2 pi frac(i phi), evenly spread for any count; B's are random. A sits anywhere in a
// 100 m world; B at a gap, a penetration, near contact or overlapping (i mod 4).
void genFloatRotation(Rng& r, int i, Case& c, std::string& tag)
{
    static const char* tags[] = {"gap", "penetration", "near", "overlap"};
    const int mode = i % 4;
    tag = tags[mode];
    const double phi = (std::sqrt(5.0) - 1) / 2;
    const double t = 2 * kPi * std::fmod(double(i) * phi, 1.0);
    auto floatShape = [](ShapeIn& s)
    {
        for (auto& p : s.points)
            p = {roundToFloat(p[0]), roundToFloat(p[1])};
    };
    c.a = randomPolygon(r);
    c.b = randomPolygon(r);
    floatShape(c.a);
    floatShape(c.b);
    c.a.c = roundToFloat(std::cos(t));
    c.a.s = roundToFloat(std::sin(t));
    c.a.px = roundToFloat(r.range(-50, 50));
    c.a.py = roundToFloat(r.range(-50, 50));
    const double tb = r.range(0, 2 * kPi);
    c.b.c = roundToFloat(std::cos(tb));
    c.b.s = roundToFloat(std::sin(tb));
    const double gap = mode == 0   ? std::pow(10.0, r.range(-5, -1))
                       : mode == 1 ? -std::pow(10.0, r.range(-5, -1))
                       : mode == 2 ? r.range(-1e-3, 1e-3)
                                   : -r.range(0.2, 1.0);
    placeAtGap(c.a, c.b, gap, r);
    c.b.px = roundToFloat(c.b.px);
    c.b.py = roundToFloat(c.b.py);
}

FamilyRow floatRotationRow()
{
    return {
        {"float-rotation", 256,
         "A float engine's poses: rotations (float(cos t), float(sin t)) that are unit "
         "vectors only to float rounding, for angles sweeping the circle, every number a float, "
         "shapes in a 100 m world near contact. Inverting such a rotation by transposing it "
         "costs ~1e-7 relative in double: the double variants must still meet their bound."},
        genFloatRotation,
        {{"non-unit rotation fraction", M::NonUnitRotationFraction, 0.9, 1},
         {"separated fraction", M::SeparatedFraction, 0.3, 0.8},
         {"max |coordinate|", M::MaxCoordinate, 30, 100}}};
}

} // namespace

std::vector<FamilyRow> startAndPoseFamilies()
{
    return {coldStartSweepRow(), floatRotationRow()};
}

} // namespace gjkval::families
