// The constructions the family generators share: polygons (on a circle, regular, random), poses
// (random, relative, shared, baked into the points), and one shape placed at a chosen gap from
// another.
#include "inputs/families/construct.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gjkval::families
{

ShapeIn poly(std::vector<P2> pts, double radius)
{
    ShapeIn s;
    s.points = std::move(pts);
    s.radius = radius;
    return s;
}

ShapeIn polygonOnCircle(Rng& r, int n, double radius)
{
    // The sorted angles are kept in the points' first coordinates: one allocation, not two.
    ShapeIn s;
    s.points.resize(static_cast<std::size_t>(n));
    for (auto& q : s.points)
        q[0] = r.range(0, 2 * kPi);
    std::sort(s.points.begin(), s.points.end(),
              [](const auto& p, const auto& q) { return p[0] < q[0]; });
    for (auto& q : s.points)
    {
        const double a = q[0];
        q = {radius * std::cos(a), radius * std::sin(a)};
    }
    return s;
}

ShapeIn regularPolygon(int n, double radius, double phase)
{
    ShapeIn s;
    for (int i = 0; i < n; ++i)
    {
        const double a = phase + 2 * kPi * i / n;
        s.points.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    return s;
}

ShapeIn randomPolygon(Rng& r)
{
    return polygonOnCircle(r, r.integer(3, 8), r.range(0.5, 2));
}

void setPose(ShapeIn& s, double angle, double px, double py)
{
    s.c = std::cos(angle);
    s.s = std::sin(angle);
    s.px = px;
    s.py = py;
}

void randomPose(Rng& r, ShapeIn& s)
{
    setPose(s, r.range(0, 2 * kPi), r.range(-4, 4), r.range(-4, 4));
}

void poseRelativeTo(const ShapeIn& a, ShapeIn& b, double relAngle, P2 relP)
{
    const double rc = std::cos(relAngle), rs = std::sin(relAngle);
    b.c = a.c * rc - a.s * rs;
    b.s = a.s * rc + a.c * rs;
    b.px = a.c * relP[0] - a.s * relP[1] + a.px;
    b.py = a.s * relP[0] + a.c * relP[1] + a.py;
}

void copyPose(const ShapeIn& a, ShapeIn& b)
{
    b.c = a.c;
    b.s = a.s;
    b.px = a.px;
    b.py = a.py;
}

void sharedPose(Case& c, double cc, double ss, double px, double py)
{
    for (ShapeIn* s : {&c.a, &c.b})
    {
        s->c = cc;
        s->s = ss;
        s->px = px;
        s->py = py;
    }
}

void bake(ShapeIn& s)
{
    s.points = worldPoints(s);
    s.c = 1;
    s.s = 0;
    s.px = s.py = 0;
}

void moveFar(Case& c, double offset, double phi, bool baked)
{
    const double ox = offset * std::cos(phi), oy = offset * std::sin(phi);
    for (ShapeIn* s : {&c.a, &c.b})
    {
        s->px += ox;
        s->py += oy;
        if (baked)
            bake(*s);
    }
}

void placeAtGap(const ShapeIn& a, ShapeIn& b, double gap, Rng& r)
{
    const auto h = convexHull(worldPoints(a));
    P2 n, p;
    if (h.size() >= 2)
    {
        std::size_t i = std::size_t(r.integer(0, int(h.size()) - 1));
        P2 p0 = h[i], p1 = h[(i + 1) % h.size()];
        if (h.size() == 2 && (r.next() & 1))
            std::swap(p0, p1);
        const double ex = p1[0] - p0[0], ey = p1[1] - p0[1], len = std::hypot(ex, ey);
        n = {ey / len, -ex / len}; // right perpendicular: outward for a counter-clockwise hull
        const double t = r.range(0.2, 0.8);
        p = {p0[0] + t * ex, p0[1] + t * ey};
    }
    else
    {
        const double t = r.range(0, 2 * kPi);
        n = {std::cos(t), std::sin(t)};
        p = h[0];
    }
    double best = kInf;
    P2 rk{};
    for (const auto& q : b.points)
    {
        const P2 rq = {b.c * q[0] - b.s * q[1], b.s * q[0] + b.c * q[1]};
        const double d = n[0] * rq[0] + n[1] * rq[1];
        if (d < best)
        {
            best = d;
            rk = rq;
        }
    }
    const double off = gap + a.radius + b.radius;
    b.px = p[0] + off * n[0] - rk[0];
    b.py = p[1] + off * n[1] - rk[1];
}

void randomPair(Rng& r, Case& c, int mode)
{
    c.a = randomPolygon(r);
    c.b = randomPolygon(r);
    randomPose(r, c.a);
    randomPose(r, c.b);
    if (mode == 0)
        placeAtGap(c.a, c.b, r.logUniform(-9, -2), r);
    else if (mode == 1)
        placeAtGap(c.a, c.b, -r.logUniform(-9, -2), r);
    else if (mode == 2)
    {
        c.b.px = c.a.px + r.range(-1, 1);
        c.b.py = c.a.py + r.range(-1, 1);
    }
}

std::string randomPairTag(int mode)
{
    static const char* tags[] = {"gap", "penetration", "deep-overlap", "random"};
    return tags[mode % 4];
}

Rng sharedRng(const Rng& r, std::uint64_t key)
{
    return Rng(mix64(r.family ^ mix64(key)));
}

} // namespace gjkval::families
