// The exact side (exact/include/gjk2d/exact.hpp, CGAL and GMP behind it): the exact distance of a
// pair, and a float GJK answer's error in ulps against it (the error measure of gjk-validate: the
// absolute error over the spacing of floats at the exact value).
//
// The pairs and their answers, by hand (the CTest "example: exact_distance" checks them):
// - one_query's pair (see one_query.cpp): hull distance 3, squared 9, minus the radii 2.25. Every
//   step of the float query is exact on these small dyadic numbers: 0 ulps.
// - certified_query's pair: two boxes [-1, 1]^2, at the origin and at (3, 3): squared distance 2,
//   distance sqrt(2). The float query's answer is sqrtf(2), correctly rounded: sqrt(2) * 2^23 =
//   11863283.2030..., so it is 11863283 * 2^-23, 0.2030 ulps (of 2^-23) below the exact value.
#include "gjk2d/distance.hpp"
#include "gjk2d/exact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

// The float query for the same shapes and transforms (all of them floats exactly).
static float floatDistance(const exact::Shape& a, const exact::Shape& b)
{
    std::vector<gjk::Vec2<float>> pa, pb;
    for (const exact::Point& p : a.points)
        pa.push_back({float(p.x), float(p.y)});
    for (const exact::Point& p : b.points)
        pb.push_back({float(p.x), float(p.y)});
    gjk::DistanceInput<float> in;
    in.proxyA = {pa.data(), int(pa.size()), float(a.radius)};
    in.proxyB = {pb.data(), int(pb.size()), float(b.radius)};
    in.transformA = {{float(a.px), float(a.py)}, {float(a.c), float(a.s)}};
    in.transformB = {{float(b.px), float(b.py)}, {float(b.c), float(b.s)}};
    return gjk::distance(in).distance;
}

// Spacing of floats at x > 0 (subnormal spacing below FLT_MIN), as validation/ measures ulps.
static double floatUlp(double x)
{
    int e = 0;
    std::frexp(x, &e);
    return std::ldexp(1.0, std::max(e, -125) - 24);
}

static void report(const char* name, const exact::Shape& a, const exact::Shape& b)
{
    // [snippet: exact-distance]
    const exact::Result r = exact::distance(a, b); // the default route, edge merge
    std::printf("%s: exact squared hull distance %s/%s, distance %.17g\n", name,
                r.squaredNum.c_str(), r.squaredDen.c_str(), r.distance); // correctly rounded

    const float f = floatDistance(a, b); // the same pair, a float gjk::distance query
    const double ulps = std::abs(double(f) - r.distance) / floatUlp(r.distance);
    std::printf("%s: float GJK %.9g, error %.4f ulps\n", name, f, ulps);
    // [end snippet]
}

int main()
{
    // [snippet: exact-shapes]
    exact::Shape a, b; // points, radius, translation, rotation (c, s)
    a.points = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    a.radius = 0.25;
    a.px = -2, a.py = 1;
    b.points = {{0, -1}, {1, 1}, {-1, 1}};
    b.radius = 0.5;
    b.px = 3, b.py = 1;
    b.c = 0, b.s = -1; // the same doubles the float side used
    // [end snippet]
    report("one_query", a, b);

    exact::Shape box;
    box.points = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    exact::Shape moved = box;
    moved.px = 3, moved.py = 3;
    report("certified_query", box, moved);
    return 0;
}
