#include "evaluate/witness_filter.hpp"

#include <algorithm>
#include <cmath>

// Error analysis (the standard model of IEEE 754 binary64, round to nearest, -ffp-contract=off).
// u = 2^-53. For a sum or difference z of two doubles, |fl(z) - z| <= u |fl(z)| (a result in the
// subnormal range is exact). For a product, |fl(z) - z| <= u |fl(z)| + 2^-1075 (the second term:
// underflow). Every bound below is a sum of such terms, evaluated in double with coefficients
// rounded up so that its own rounding (a few ulps of a positive sum) is covered: 5u for a true
// 4u + 2u^2, 1.01 for 1 + u, and eta = 2^-1060 for the handful of underflow terms 2^-1075.
// Overflow: an infinite or NaN quantity makes its comparison false (the bound is then infinite
// or NaN too), so it falls back to the exact route.
namespace gjkval
{
namespace
{
constexpr double u = 0x1p-53;
constexpr double eta = 0x1p-1060;

// The world point of local (x, y) as the exact side builds it, rounded: X = fl(fl(fl(c x) -
// fl(s y)) + px). With P1 = fl(c x), P2 = fl(s y), D = fl(P1 - P2):
//   |X_exact - X| <= |c x - P1| + |s y - P2| + |(P1 - P2) - D| + |(D + px) - X|
//                 <= u (|P1| + |P2| + |D| + |X|) + 2 * 2^-1075,
// returned in `err` (rounded up as above).
double worldCoordinate(double c, double x, double s, double y, double p, double& err)
{
    const double p1 = c * x, p2 = s * y;
    const double d = p1 - p2;
    const double w = d + p;
    err = 1.01 * u * (std::abs(p1) + std::abs(p2) + std::abs(d) + std::abs(w)) + eta;
    return w;
}

double cross(exact::Point o, exact::Point a, exact::Point b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// orientation(A, B, P) > 0 for certain, A and B rounded shape points (each coordinate within delta
// of the exact one), P exact. With e = fl(B - A), f = fl(P - A) and O = fl(fl(ex fy) - fl(ey fx)):
// the exact e and f satisfy |ex_exact - ex| <= u|ex| + 2 delta and |fx_exact - fx| <= u|fx| + delta
// (two rounded points, one). Writing a = |ex|, b = |fy|,
//   |ex_exact fy_exact - ex fy| <= (u a + 2 delta)((1 + u) b + delta) + a (u b + delta)
//                               = (2u + u^2) ab + (1 + u) a delta + 2 (1 + u) b delta + 2 delta^2,
// the same for ey fx, and the evaluation of O adds (2u + u^2)(|ex fy| + |ey fx|) + 2 * 2^-1075:
//   |O_exact - O| <= (4u + 2u^2) S + (1 + u) delta (|ex| + |ey|) + 2 (1 + u) delta (|fx| + |fy|)
//                    + 4 delta^2 + 2^-1074,   S = |ex fy| + |ey fx|.
// O above that bound is positive for certain.
bool certainlyLeft(exact::Point a, exact::Point b, exact::Point p, double delta)
{
    const double ex = b.x - a.x, ey = b.y - a.y, fx = p.x - a.x, fy = p.y - a.y;
    const double o = ex * fy - ey * fx;
    const double s = std::abs(ex * fy) + std::abs(ey * fx);
    const double bound = 5 * u * s + 1.01 * delta * (std::abs(ex) + std::abs(ey)) +
                         2.02 * delta * (std::abs(fx) + std::abs(fy)) + 4 * delta * delta + eta;
    return o > bound;
}

// An upper bound of dist(P, segment AB) (A, B rounded shape points within delta, P exact): the
// distance from P to the point X(t) = A + t (B - A) of the exact segment, for the double t in
// [0, 1] that the rounded points make closest. With f = fl(P - A), e = fl(B - A), g = fl(f -
// fl(t e)) per coordinate:
//   |g_exact - g| <= (u |f| + delta) + t (u |e| + 2 delta) + (u |t e| + 2^-1075) + u |g|
//                 <= u (|f| + 2 |e| + |g|) + 3 delta + 2^-1075,
// and |P - X(t)| <= sqrt((|gx| + errx)^2 + (|gy| + erry)^2). Rounding that sum of squares and its
// root loses at most a relative 6u, covered by the factor 1 + 2^-49 (16u); squares that underflow
// lose at most 2^-1073 in all, at most 2^-536 after the root, covered by 2^-530.
double segmentDistanceAbove(exact::Point a, exact::Point b, exact::Point p, double delta)
{
    const double ex = b.x - a.x, ey = b.y - a.y, fx = p.x - a.x, fy = p.y - a.y;
    const double ee = ex * ex + ey * ey;
    double t = ee > 0 ? (fx * ex + fy * ey) / ee : 0;
    t = std::isnan(t) ? 0 : std::clamp(t, 0.0, 1.0);
    const double gx = fx - t * ex, gy = fy - t * ey;
    const double errx =
        1.01 * (u * (std::abs(fx) + 2 * std::abs(ex) + std::abs(gx)) + 3 * delta) + eta;
    const double erry =
        1.01 * (u * (std::abs(fy) + 2 * std::abs(ey) + std::abs(gy)) + 3 * delta) + eta;
    const double hx = std::abs(gx) + errx, hy = std::abs(gy) + erry;
    return std::sqrt(hx * hx + hy * hy) * (1 + 0x1p-49) + 0x1p-530;
}

// Andrew's monotone chain on the rounded points (floating-point turns: it only chooses
// certificates, see FilterShape).
std::vector<exact::Point> roughHull(std::vector<exact::Point> pts)
{
    std::sort(pts.begin(), pts.end(),
              [](exact::Point a, exact::Point b)
              { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (pts.size() < 3)
    {
        if (pts.size() == 2 && pts[0].x == pts[1].x && pts[0].y == pts[1].y)
            pts.pop_back();
        return pts;
    }
    std::vector<exact::Point> h(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
        while (k >= 2 && !(cross(h[k - 2], h[k - 1], pts[i]) > 0))
            --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, lo = k + 1; i-- > 0;)
    {
        while (k >= lo && !(cross(h[k - 2], h[k - 1], pts[i]) > 0))
            --k;
        h[k++] = pts[i];
    }
    h.resize(k > 1 ? k - 1 : k);
    return h;
}
} // namespace

FilterShape filterShape(const exact::Shape& s)
{
    FilterShape f;
    f.radius = s.radius;
    std::vector<exact::Point> world;
    world.reserve(s.points.size());
    double delta = 0;
    for (const exact::Point& q : s.points)
    {
        double ex = 0, ey = 0;
        const double x = worldCoordinate(s.c, q.x, s.s, q.y, s.px, ex);
        const double y = worldCoordinate(s.s, q.x, -s.c, q.y, s.py, ey); // s x - (-c) y + py
        delta = std::max({delta, ex, ey});
        world.push_back({x, y});
    }
    f.delta = delta;
    f.usable = std::isfinite(delta) && std::isfinite(s.radius);
    for (const exact::Point& w : world)
        f.usable = f.usable && std::isfinite(w.x) && std::isfinite(w.y);
    if (f.usable)
        f.hull = roughHull(std::move(world));
    return f;
}

bool certainlyOnShape(const FilterShape& f, exact::Point p)
{
    if (!f.usable || !std::isfinite(p.x) || !std::isfinite(p.y))
        return false;
    const std::vector<exact::Point>& h = f.hull;
    const std::size_t m = h.size();
    // Strictly left of every edge of the closed chain h: strictly inside the hull of its points,
    // distance 0. (Were p outside that hull, a line would separate it from every h_i: seen from p,
    // all h_i lie within an open half-turn, each edge turns strictly counter-clockwise by less than
    // a half-turn, and the chain could not return to its start.) Any closed chain of the shape's
    // points will do, so a rough hull that is wrong costs a fallback, never a wrong 0.
    bool inside = m >= 3;
    for (std::size_t i = 0; i < m && inside; ++i)
        inside = certainlyLeft(h[i], h[(i + 1) % m], p, f.delta);
    if (inside)
        return true;
    // Within the radius of a segment of the shape's points (any such segment lies in the hull).
    // Radii below 2^-500 are left to the exact route (the bound's 2^-530 would not be small).
    if (!(f.radius >= 0x1p-500) || m == 0)
        return false;
    for (std::size_t i = 0; i < m; ++i)
        if (segmentDistanceAbove(h[i], h[(i + 1) % m], p, f.delta) <= f.radius)
            return true;
    return false;
}

} // namespace gjkval
