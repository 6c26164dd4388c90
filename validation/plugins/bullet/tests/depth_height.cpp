// Bullet's penetration depth against the prisms' half height (docs/peers/prisms.md;
// validation/plugins/bullet/bullet.cpp, prismHalfHeight): Bullet 3.24 called through its own API
// only (a btConvexHullShape per prism, margin = radius, a btVoronoiSimplexSolver in zeroed storage,
// btGjkEpaPenetrationDepthSolver, btGjkPairDetector with identity transforms, as the adapter and
// direct_loop.cpp build them), on every overlapping case of a case file, once per half-height rule,
// its depth set against the 2D depth. Not a test: its figures go into docs/peers.md with the
// command. Its CTest (--check N --plugin P) checks that it runs and that, on the file's first N
// overlapping cases, the adapter's prepared queries answer bit for bit what this program answers at
// the adapter's rule (so that the figures are the adapter's).
//
//     cd build/release
//     validation/gjk-validate generate --family random:2000 --seed 1 --out /tmp/r.json
//     tests/plugins/bullet_depth_height_double /tmp/r.json
//     tests/plugins/bullet_depth_height_float /tmp/r.json
//
// --depths prints each overlapping case's brute-force 2D depth instead (name, depth), to set
// beside the exact side's.
//
// Columns, per rule: the overlapping cases answered within 1e-9 (relative, or absolute below a
// depth of 1) of the 2D depth; those short of it by more; those answered no penetration at all
// (depth 0 or less: Bullet's EPA ending on InvalidHull at a first face through the origin); the
// median and 10th percentile of (depth - 2D depth) / 2D depth over all, and the median over those
// answered a penetration; the largest |relative error|; the answers whose pair's x, y are closer
// than its depth (a pair tilted in z) by more than 1e-6 relative.
//
// The 2D depth, by brute force in double (no Bullet, no gjk2d): the cores' Minkowski difference
// M = hull{a_i - b_j} of the world points (the case's (c, s) and position applied in double to its
// numbers, rounded to btScalar first, as the adapter receives them); with the origin strictly
// inside M the cores' depth is the least distance from the origin to the line of an edge of M
// (each edge's line supports M, and the nearest boundary point lies on an edge), and the shapes'
// depth is that plus rA + rB; otherwise the cores are apart (or touch) at the distance d from the
// origin to M, and the depth is rA + rB - d where that is positive. Each number is a few rounding
// errors of double from the exact one (sums and products of the case's numbers, one square root):
// far below the errors measured, which are Bullet's.
//
// The half-height rules: h = 1, h = k (eA + eB) for k = 2 (FCL's rule), then powers of two to 2^20,
// among them the adapter's (bullet.cpp, kHeightFactor: 2^4 in float, 2^14 in double; e:
// bullet.cpp's extent). The 3D minimal translation of two prisms P x [-h, h], Q x [-h, h] is min(2D
// depth, 2h) in exact arithmetic (the Minkowski difference is M x [-2h, 2h], whose nearest face is
// an edge of M or a cap).
#include "direct_loop.hpp"

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>
#include <string>
#include <vector>

namespace
{

#ifdef BT_USE_DOUBLE_PRECISION
const char* const kVariant = "bullet-3.24-double";
#else
const char* const kVariant = "bullet-3.24-float";
#endif

struct P
{
    double x, y;
};

// The case's shape as the adapter receives it: each number rounded to btScalar.
struct Shape
{
    std::vector<P> local;
    double radius, px, py, c, s;
};

Shape scalarShape(const directloop::Shape& s)
{
    Shape out{{},
              double(btScalar(s.radius)),
              double(btScalar(s.px)),
              double(btScalar(s.py)),
              double(btScalar(s.c)),
              double(btScalar(s.s))};
    for (std::size_t i = 0; i + 1 < s.points.size(); i += 2)
        out.local.push_back({double(btScalar(s.points[i])), double(btScalar(s.points[i + 1]))});
    return out;
}

std::string fmt(int p)
{
    return "h = 2^" + std::to_string(p) + " (eA + eB)";
}

std::vector<P> world(const Shape& s)
{
    std::vector<P> w;
    for (const P& p : s.local)
        w.push_back({s.c * p.x - s.s * p.y + s.px, s.s * p.x + s.c * p.y + s.py});
    return w;
}

double cross(const P& o, const P& a, const P& b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The convex hull, counter-clockwise, collinear points dropped (Andrew's monotone chain).
std::vector<P> hull(std::vector<P> p)
{
    std::sort(p.begin(), p.end(),
              [](const P& a, const P& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end(),
                        [](const P& a, const P& b) { return a.x == b.x && a.y == b.y; }),
            p.end());
    if (p.size() < 3)
        return p;
    std::vector<P> h(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0)
            --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;)
    {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0)
            --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

double segmentDistance(const P& a, const P& b)
{
    const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? -(a.x * dx + a.y * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(a.x + t * dx, a.y + t * dy);
}

// The shapes' 2D penetration depth (> 0 on overlap, <= 0: apart by minus it); see the header.
double depth2d(const Shape& a, const Shape& b)
{
    std::vector<P> d;
    for (const P& p : world(a))
        for (const P& q : world(b))
            d.push_back({p.x - q.x, p.y - q.y});
    const std::vector<P> m = hull(d);
    const double radii = a.radius + b.radius;
    if (m.size() >= 3)
    {
        double inner = INFINITY;
        bool inside = true;
        for (std::size_t i = 0; i < m.size(); ++i)
        {
            const P& u = m[i];
            const P& v = m[(i + 1) % m.size()];
            const double c = cross(u, v, P{0, 0}); // > 0: the origin left of u v (inside)
            inside = inside && c > 0;
            inner = std::min(inner, c / std::hypot(v.x - u.x, v.y - u.y));
        }
        if (inside)
            return inner + radii;
    }
    double apart = INFINITY;
    for (std::size_t i = 0; i < m.size(); ++i)
        apart = std::min(apart, segmentDistance(m[i], m[(i + 1) % m.size()]));
    return radii - apart;
}

double extent(const Shape& s)
{
    double e = 0;
    for (const P& p : s.local)
        e = std::max(e, std::abs(p.x) + std::abs(p.y));
    return s.radius + e;
}

// Bullet's answer on the two prisms of half height h: its depth (minus its distance) and the
// length of its pair's x, y separation.
struct Answer
{
    bool ok;
    double depth, xy;
};

Answer bullet(const Shape& a, const Shape& b, double h, directloop::Answer* raw = nullptr)
{
    btConvexHullShape ha, hb;
    for (auto [s, hull] : {std::pair{&a, &ha}, std::pair{&b, &hb}})
    {
        const btScalar c = btScalar(s->c), sn = btScalar(s->s);
        for (const P& p : s->local)
        {
            const btScalar x = btScalar(p.x), y = btScalar(p.y);
            const btScalar wx = c * x - sn * y + btScalar(s->px);
            const btScalar wy = sn * x + c * y + btScalar(s->py);
            hull->addPoint(btVector3(wx, wy, -btScalar(h)), false);
            hull->addPoint(btVector3(wx, wy, btScalar(h)), false);
        }
        hull->recalcLocalAabb();
        hull->setMargin(btScalar(s->radius));
    }
    alignas(btVoronoiSimplexSolver) unsigned char storage[sizeof(btVoronoiSimplexSolver)] = {};
    auto* simplex = new (storage) btVoronoiSimplexSolver;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector detector(&ha, &hb, simplex, &epa);
    btGjkPairDetector::ClosestPointInput input;
    input.m_transformA.setIdentity();
    input.m_transformB.setIdentity();
    btPointCollector result;
    detector.getClosestPoints(input, result, nullptr);
    simplex->~btVoronoiSimplexSolver();
    const btVector3 onB = result.m_pointInWorld;
    const btVector3 onA = onB + result.m_normalOnBInWorld * result.m_distance;
    if (raw != nullptr)
        *raw = directloop::Answer{result.m_hasResult ? GJK2D_STATUS_OK : GJK2D_STATUS_ERROR,
                                  double(result.m_distance),
                                  double(onA.x()),
                                  double(onA.y()),
                                  double(onB.x()),
                                  double(onB.y())};
    return {result.m_hasResult, -double(result.m_distance),
            std::hypot(double(onA.x() - onB.x()), double(onA.y() - onB.y()))};
}

double quantile(std::vector<double> v, double q)
{
    if (v.empty())
        return NAN;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

// The adapter's rule (bullet.cpp, prismHalfHeight): k (eA + eB) in double, rounded to btScalar.
constexpr double kAdapterFactor = sizeof(btScalar) == sizeof(double) ? 16384 : 16;
double halfHeight(double k, const Shape& a, const Shape& b)
{
    const double h = k * (extent(a) + extent(b));
    return double(btScalar(h == 0 ? 1.0 : h));
}

struct Overlapping
{
    const directloop::Case* c;
    Shape a, b;
    double depth; // the 2D depth, > 0
};

// One rule's row of the table (the header's columns).
void row(const char* name, double k, const std::vector<Overlapping>& cases)
{
    std::vector<double> rel, relAnswered;
    int exactish = 0, shortCount = 0, none = 0, tilted = 0;
    double maxRel = 0;
    for (const Overlapping& o : cases)
    {
        const Answer ans = bullet(o.a, o.b, k == 0 ? 1.0 : halfHeight(k, o.a, o.b));
        const double err = ans.ok ? ans.depth - o.depth : -o.depth, e = err / o.depth;
        rel.push_back(e);
        if (ans.ok && ans.depth > 0)
            relAnswered.push_back(e);
        const double slack = 1e-9 * std::max(1.0, o.depth);
        exactish += std::abs(err) <= slack;
        shortCount += err < -slack && ans.depth > 0;
        none += !(ans.depth > 0);
        tilted += ans.depth > 0 && std::abs(ans.xy - ans.depth) > 1e-6 * std::max(1.0, ans.depth);
        maxRel = std::max(maxRel, std::abs(e));
    }
    std::printf("%-30s %6d %6d %5d %11.3e %11.3e %11.3e %10.3e %6d\n", name, exactish, shortCount,
                none, quantile(rel, 0.5), quantile(rel, 0.1), quantile(relAnswered, 0.5), maxRel,
                tilted);
}

// --check N --plugin P: the adapter's answers on the first N overlapping cases, bit for bit this
// program's at the adapter's rule. Returns the number that differ.
int checkAdapter(const std::vector<Overlapping>& cases, std::size_t n, const std::string& plugin)
{
    n = std::min(n, cases.size());
    std::vector<const directloop::Case*> first;
    for (std::size_t k = 0; k < n; ++k)
        first.push_back(cases[k].c);
    directloop::PluginSide adapter(plugin, kVariant);
    adapter.prepare(first);
    int differ = 0;
    for (std::size_t k = 0; k < n; ++k)
    {
        directloop::Answer mine;
        bullet(cases[k].a, cases[k].b, halfHeight(kAdapterFactor, cases[k].a, cases[k].b), &mine);
        const directloop::Answer theirs = adapter.answer(k);
        if (theirs.status != mine.status || !directloop::sameBits(theirs.distance, mine.distance) ||
            !directloop::sameBits(theirs.ax, mine.ax) || !directloop::sameBits(theirs.by, mine.by))
        {
            ++differ;
            std::printf("%s: this program %.17g, the adapter %.17g\n", first[k]->name.c_str(),
                        mine.distance, theirs.distance);
        }
    }
    std::printf("--check: %d of %zu overlapping cases differ from the adapter\n", differ, n);
    return differ;
}

} // namespace

int main(int argc, char** argv)
{
    const char* usage =
        "usage: bullet_depth_height_{float,double} CASES.json [--depths | --check N "
        "--plugin gjk2d-bullet-{float,double}.so]\n";
    const bool depths = argc == 3 && std::string(argv[2]) == "--depths";
    if (argc != 2 && argc != 6 && !depths)
    {
        std::fprintf(stderr, "%s", usage);
        return 2;
    }
    const std::vector<directloop::Case> all = directloop::readCases(argv[1]);
    std::vector<Overlapping> cases;
    for (const directloop::Case& c : all)
    {
        if (c.a.count() < 1 || c.b.count() < 1)
            continue;
        const Shape a = scalarShape(c.a), b = scalarShape(c.b);
        const double d = depth2d(a, b);
        if (d > 0)
            cases.push_back({&c, a, b, d});
    }
    if (argc == 6)
        return checkAdapter(cases, std::size_t(std::atoi(argv[3])), argv[5]) == 0 ? 0 : 1;
    if (depths) // the brute-force 2D depths, to set beside the exact side's
    {
        for (const Overlapping& o : cases)
            std::printf("%s %.17g\n", o.c->name.c_str(), o.depth);
        return 0;
    }
    std::printf("%s: %zu overlapping cases of %s (2D depth > 0 by brute force)\n", kVariant,
                cases.size(), argv[1]);
    std::printf("%-30s %6s %6s %5s %11s %11s %11s %10s %6s\n", "half height", "within", "short",
                "none", "median rel", "p10 rel", "med answ.", "max |rel|", "tilted");
    row("h = 1", 0, cases);
    for (int p : {1, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20})
    {
        const double k = std::ldexp(1.0, p);
        const std::string name =
            fmt(p) + (k == kAdapterFactor ? " (adapter)" : "") + (p == 1 ? " (before)" : "");
        row(name.c_str(), k, cases);
    }
    return 0;
}
