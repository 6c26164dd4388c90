// The speed targets' `random` distribution, shared by gjk_bench and the GJK tests: 3 to 8 points
// on a circle of radius 0.5 to 2 (sorted by angle, so in convex order), placed in [-4, 4]^2 with a
// random rotation. Generated in double; `converted` rounds a shape to float or double.
#pragma once

#include "gjk2d/math.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace gjk::bench
{
template <class T> struct ShapeData
{
    std::vector<Vec2<T>> points;
    Transform<T> xf;
};

inline ShapeData<double> randomShape(std::mt19937_64& rng)
{
    std::uniform_int_distribution<int> count(3, 8);
    std::uniform_real_distribution<double> radius(0.5, 2.0), angle(0.0, 2 * M_PI), pos(-4.0, 4.0);
    ShapeData<double> s;
    const int n = count(rng);
    const double r = radius(rng);
    std::vector<double> angles(n);
    for (auto& t : angles)
        t = angle(rng);
    std::sort(angles.begin(), angles.end());
    for (double t : angles)
        s.points.push_back({r * std::cos(t), r * std::sin(t)});
    const double q = angle(rng);
    s.xf = {{pos(rng), pos(rng)}, {std::cos(q), std::sin(q)}};
    return s;
}

template <class T> ShapeData<T> converted(const ShapeData<double>& s)
{
    ShapeData<T> out;
    for (auto v : s.points)
        out.points.push_back({T(v.x), T(v.y)});
    out.xf = {{T(s.xf.p.x), T(s.xf.p.y)}, {T(s.xf.q.c), T(s.xf.q.s)}};
    return out;
}
} // namespace gjk::bench
