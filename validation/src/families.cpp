#include "families.hpp"

#include "geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

namespace gjkval
{
namespace
{
constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Deterministic generator (SplitMix64); distributions written out so that every platform agrees.
struct Rng
{
    std::uint64_t state;
    explicit Rng(std::uint64_t seed) : state(seed) {}
    std::uint64_t next()
    {
        state += 0x9e3779b97f4a7c15ULL;
        std::uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    double range(double a, double b) { return a + (b - a) * uniform(); }
    int integer(int lo, int hi) { return lo + int(next() % std::uint64_t(hi - lo + 1)); }
    double logUniform(double e0, double e1) { return std::pow(10.0, range(e0, e1)); }
    double sign() { return (next() & 1) ? 1.0 : -1.0; }
    template <class V> void shuffle(V& v)
    {
        for (std::size_t i = v.size(); i > 1; --i)
            std::swap(v[i - 1], v[std::size_t(next() % i)]);
    }
};

// --- Shape helpers ---------------------------------------------------------------------------

ShapeIn poly(std::vector<P2> pts, double radius = 0)
{
    ShapeIn s;
    s.points = std::move(pts);
    s.radius = radius;
    return s;
}

// n points on a circle at sorted random angles: a convex polygon, counter-clockwise.
ShapeIn polygonOnCircle(Rng& r, int n, double radius)
{
    std::vector<double> angles(static_cast<std::size_t>(n));
    for (auto& a : angles)
        a = r.range(0, 2 * kPi);
    std::sort(angles.begin(), angles.end());
    ShapeIn s;
    for (double a : angles)
        s.points.push_back({radius * std::cos(a), radius * std::sin(a)});
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

// The rotation is stored as the two doubles (cos t, sin t), computed once.
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

// Compose: world pose of a shape given relative to A's pose (rel first, then A's).
void poseRelativeTo(const ShapeIn& a, ShapeIn& b, double relAngle, P2 relP)
{
    const double rc = std::cos(relAngle), rs = std::sin(relAngle);
    b.c = a.c * rc - a.s * rs;
    b.s = a.s * rc + a.c * rs;
    b.px = a.c * relP[0] - a.s * relP[1] + a.px;
    b.py = a.s * relP[0] + a.c * relP[1] + a.py;
}

// Moves B (keeping its rotation) so that its extreme vertex along -n sits at the signed gap `gap`
// (negative: penetration) from a point inside a random edge of hull(A), n the edge's outward
// normal: B is then in the half plane beyond that edge's line, and the distance between the
// rounded shapes is `gap` up to the rounding of this construction.
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
    std::size_t k = 0;
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
        ++k;
    }
    const double off = gap + a.radius + b.radius;
    b.px = p[0] + off * n[0] - rk[0];
    b.py = p[1] + off * n[1] - rk[1];
}

void scaleShape(ShapeIn& s, double k)
{
    for (auto& p : s.points)
        p = {p[0] * k, p[1] * k};
    s.radius *= k;
    s.px *= k;
    s.py *= k;
}

void scaleCase(Case& c, double k)
{
    scaleShape(c.a, k);
    scaleShape(c.b, k);
}

// Points replaced by their world coordinates (rounded), identity transform.
void bake(ShapeIn& s)
{
    s.points = worldPoints(s);
    s.c = 1;
    s.s = 0;
    s.px = s.py = 0;
}

// The same rigid map for both shapes: exact contact in local coordinates stays exact contact for
// the exact side (an affine map preserves incidence in rational arithmetic).
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

// A random pair: random polygons and poses; mode 0 places B at a small gap, mode 1 at a small
// penetration, mode 2 within [-1, 1]^2 of A's position (deep overlap), otherwise independent.
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

// --- The random family -----------------------------------------------------------------------

void genRandom(Rng& r, int, Case& c, std::string&)
{
    // 10% near contact (gap 1e-9 .. 1e-2), 10% shallow penetration, 20% deep overlap, 60%
    // independent positions.
    const double u = r.uniform();
    randomPair(r, c, u < 0.1 ? 0 : (u < 0.2 ? 1 : (u < 0.4 ? 2 : 3)));
}

// --- The hard sub-families -------------------------------------------------------------------

using Gen = std::function<void(Rng&, int, Case&, std::string&)>;

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
            p = {double(float(p[0])), double(float(p[1]))};
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
    const double phi = r.range(0, 2 * kPi);
    const double ox = offset * std::cos(phi), oy = offset * std::sin(phi);
    for (ShapeIn* s : {&c.a, &c.b})
    {
        s->px += ox;
        s->py += oy;
        if (coords)
            bake(*s);
    }
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

// A shared pose for exact-contact families: a quarter turn (exact) or a rounded random rotation,
// and a dyadic translation.
void contactPose(Rng& r, int i, Case& c, double scale, std::string& tag)
{
    static const double quarter[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    const double px = r.integer(-(1 << 20), 1 << 20) * scale / 4;
    const double py = r.integer(-(1 << 20), 1 << 20) * scale / 4;
    if ((i / 2) % 2 == 0)
    {
        const int k = (i / 4) % 4;
        sharedPose(c, quarter[k][0], quarter[k][1], px, py);
        tag += fmt::format("-rot{}", 90 * k);
    }
    else
    {
        const double t = r.range(0, 2 * kPi);
        sharedPose(c, std::cos(t), std::sin(t), px, py);
        tag += "-rot";
    }
}

void genTouchingVertex(Rng& r, int i, Case& c, std::string& tag)
{
    const double S = std::ldexp(1.0, (i * 7) % 21 - 10);
    const bool vv = i % 2 == 0;
    c.a = poly({{0, 0}, {S, 0}, {S, S}, {0, S}});
    if (vv)
        c.b = poly({{S, S}, {2 * S, 1.5 * S}, {1.5 * S, 2 * S}});
    else
    {
        const double t = r.integer(1, 7) / 8.0 * S;
        c.b = poly({{S, t}, {2 * S, t - S / 2}, {2 * S, t + S / 2}});
    }
    tag = fmt::format("{}-s2^{}", vv ? "vertex-vertex" : "vertex-edge", (i * 7) % 21 - 10);
    if (i % 3 == 0)
        std::swap(c.a, c.b);
    contactPose(r, i, c, S, tag);
}

void genTouchingEdge(Rng& r, int i, Case& c, std::string& tag)
{
    const double S = std::ldexp(1.0, (i * 5) % 17 - 8);
    auto sc = [S](std::vector<P2> v)
    {
        for (auto& p : v)
            p = {p[0] * S, p[1] * S};
        return poly(std::move(v));
    };
    switch (i % 4)
    {
    case 0:
    {
        static const double x0s[] = {-1, -0.5, 0, 0.5, 1}, lens[] = {0.5, 1, 3};
        const double x0 = x0s[r.integer(0, 4)], x1 = x0 + lens[r.integer(0, 2)];
        c.a = sc({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
        c.b = sc({{x0, 2}, {x1, 2}, {x1, 3}, {x0, 3}});
        tag = "box-on-box";
        break;
    }
    case 1:
        c.a = sc({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
        c.b = sc({{2, 0}, {3, 0}, {3, 2}, {2, 2}});
        tag = "shared-edge";
        break;
    case 2:
        c.a = sc({{0, 0}, {4, 0}, {0, 4}});
        c.b = sc({{1, 3}, {3, 1}, {4, 4}});
        tag = "slanted";
        break;
    default:
        c.a = sc({{0, 0}, {4, 0}, {0, 4}});
        c.b = sc({{3, 1}, {5, -1}, {5, 3}});
        tag = "slanted-partial";
        break;
    }
    if (i % 3 == 1)
        std::swap(c.a, c.b);
    contactPose(r, i, c, S, tag);
}

void genUlpGap(Rng& r, int i, Case& c, std::string& tag)
{
    static const double mags[] = {0.5, 1, 3, 1000, 1048576.5, 1e6, 1e9, 1e-6};
    const double X = mags[i % 8];
    const bool apart = (i / 8) % 2 == 0;
    const bool vertex = (i / 16) % 2 == 0;
    const double Xp = std::nextafter(X, apart ? kInf : -kInf);
    const double w = X / 2, h = X / 2;
    c.a = poly({{X - w, -h}, {X, -h}, {X, h}, {X - w, h}});
    if (vertex)
        c.b = poly({{Xp, 0}, {X + w, -h}, {X + w, h}});
    else
        c.b = poly({{Xp, -h / 2}, {X + w, -h / 2}, {X + w, h / 2}, {Xp, h / 2}});
    tag = fmt::format("x{:g}-{}-{}", X, apart ? "gap" : "overlap", vertex ? "vertex" : "edge");
    if (i % 3 == 0)
    {
        const double px = r.integer(-1000, 1000), py = r.integer(-1000, 1000);
        sharedPose(c, 1, 0, px, py);
        tag += "-shifted";
    }
}

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

std::string scaledTag(int i)
{
    static const char* tags[] = {"gap", "penetration", "deep-overlap", "random"};
    return tags[i % 4];
}

void genScaled(Rng& r, int i, Case& c, double k)
{
    randomPair(r, c, i % 4);
    scaleCase(c, k);
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

void genPoints(Rng& r, int i, Case& c, std::string& tag)
{
    switch (i % 8)
    {
    case 0: // inside a polygon (its vertex centroid)
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
        tag = "inside";
        break;
    }
    case 1: // exactly on a vertex (same local point, same pose)
        c.a = randomPolygon(r);
        randomPose(r, c.a);
        c.b = c.a;
        c.b.points = {c.a.points[std::size_t(r.integer(0, int(c.a.points.size()) - 1))]};
        tag = "on-vertex";
        break;
    case 2: // exactly on an edge (dyadic)
        c.a = poly({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
        randomPose(r, c.a);
        c.b = c.a;
        c.b.points = {{1, 0.375}};
        tag = "on-edge";
        break;
    case 3: // outside near an edge
        c.a = randomPolygon(r);
        randomPose(r, c.a);
        c.b = poly({{0, 0}});
        placeAtGap(c.a, c.b, r.logUniform(-12, -2), r);
        tag = "near-edge";
        break;
    case 4: // identical points
        c.a = poly({{r.range(-4, 4), r.range(-4, 4)}});
        c.b = c.a;
        tag = "point-same";
        break;
    case 5: // two distinct points
        c.a = poly({{r.range(-4, 4), r.range(-4, 4)}});
        c.b = poly({{r.range(-4, 4), r.range(-4, 4)}});
        randomPose(r, c.a);
        randomPose(r, c.b);
        tag = "point-point";
        break;
    case 6: // one ulp apart
    {
        const double x = r.range(-4, 4), y = r.range(-4, 4);
        c.a = poly({{x, y}});
        c.b = poly({{std::nextafter(x, kInf), y}});
        tag = "point-ulp";
        break;
    }
    default: // point near a segment's endpoint region
        c.a = poly({{-1, 0}, {1, 0}});
        randomPose(r, c.a);
        c.b = poly({{0, 0}});
        placeAtGap(c.a, c.b, r.logUniform(-12, -2), r);
        tag = "near-segment";
        break;
    }
}

// --- THE table: every hard sub-family, its size, why it is here, and its make-up ---------------

struct HardEntry
{
    HardSubFamilyInfo info;
    Gen gen;
    std::vector<MakeupSpec> makeup;
};

using M = MakeupMetric;

const std::vector<HardEntry>& hardTable()
{
    static const std::vector<HardEntry> table = {
        {{"talk-segment", 16,
          "The talk's single-precision example: segment (0.021119118, 79.584320)-(0.020964622, "
          "-31.515678) against the origin. With d = -P the search direction has dot(d, edge) = "
          "3.2e-6 in float and may pick a wrong support point; scaled, mirrored, rotated, swapped, "
          "offset and jittered copies."},
         genTalkSegment,
         {{"separated fraction", M::SeparatedFraction, 1, 1}}},
        {{"near-parallel", 48,
          "Near-parallel closest edges at gaps 1e-1 down to 1e-12 and tilts 0 to 1e-3: the "
          "edge-versus-vertex decision and the edge distance lose relative accuracy as the gap "
          "shrinks."},
         genNearParallel,
         {{"separated fraction", M::SeparatedFraction, 1, 1},
          {"min positive distance", M::MinPositiveDistance, 0, 2e-12},
          {"max distance", M::MaxDistance, 0.09, 0.2}}},
        {{"far-from-origin", 40,
          "Shapes at offsets 1e3 to 1e9 with gaps 1e-1 to 1e-5, the offset in the transforms (A's "
          "local frame cancels it) or baked into the coordinates (nothing can): absolute rounding "
          "grows with the coordinates, not with the gap."},
         genFarFromOrigin,
         {{"separated fraction", M::SeparatedFraction, 1, 1},
          {"max |coordinate|", M::MaxCoordinate, 7e8, kInf}}},
        {{"sliver", 40,
          "Slivers (rectangles and wedges) with aspect ratios 1e1 to 1e8 against polygons and each "
          "other: nearly degenerate simplices, tiny cross products, long edges with tiny normals."},
         genSliver,
         {{"max aspect ratio", M::MaxAspect, 0.99e8, kInf},
          {"separated fraction", M::SeparatedFraction, 0.7, 1}}},
        {{"touching-vertex", 24,
          "Exact contact at a vertex (vertex on vertex, vertex inside an edge) with dyadic "
          "coordinates and a shared pose: the true distance is exactly 0, so any positive answer "
          "is "
          "rounding; tests the overlap decision at the boundary."},
         genTouchingVertex,
         {{"overlapping fraction", M::OverlapFraction, 1, 1}}},
        {{"touching-edge", 24,
          "Exact contact along an edge (shared, partial, slanted), dyadic and exactly "
          "representable: "
          "the origin lies on an edge of the Minkowski difference (talk, termination cases 3b and "
          "4)."},
         genTouchingEdge,
         {{"overlapping fraction", M::OverlapFraction, 1, 1}}},
        {{"ulp-gap", 32,
          "Gaps and overlaps of exactly one ulp of the contact coordinate at magnitudes 1e-6 to "
          "1e9: "
          "the smallest nonzero separation the input can express."},
         genUlpGap,
         {{"separated fraction", M::SeparatedFraction, 0.5, 0.5},
          {"max distance", M::MaxDistance, 0, 2.5e-7}}},
        {{"degenerate-vertices", 32,
          "Duplicate vertices, exactly collinear vertices, all points collinear (a segment), all "
          "points identical (a point), interior points and shuffled order: the hull is implicit."},
         genDegenerate,
         {{"min hull vertices", M::MinHullVertices, 1, 1},
          {"max vertices", M::MaxVertices, 32, kInf},
          {"separated fraction", M::SeparatedFraction, 0.4, 1}}},
        {{"segment-segment", 40,
          "Segment against segment nearly collinear (end to end, side by side, crossing, "
          "T-junction) "
          "with angles 0 to 1e-4: zero-area triangles and collinear simplices (talk, 'Collinear "
          "vertices')."},
         genSegmentSegment,
         {{"separated fraction", M::SeparatedFraction, 0.7, 0.8},
          {"min positive distance", M::MinPositiveDistance, 0, 1e-9}}},
        {{"identical-nested", 24,
          "Identical shapes (same or reversed point order, baked transform), nested shapes and "
          "a copy shifted by 1e-12..1e-6: deep overlap, coincident support points, zero "
          "directions."},
         genIdenticalNested,
         {{"overlapping fraction", M::OverlapFraction, 1, 1}}},
        {{"tiny-scale", 40,
          "Random pairs scaled by 1e-12: squared quantities near 1e-24 (1e-48 for products of "
          "squares) test relative tolerances and underflow margins."},
         [](Rng& r, int i, Case& c, std::string& tag)
         {
             genScaled(r, i, c, 1e-12);
             tag = scaledTag(i);
         },
         {{"max |coordinate|", M::MaxCoordinate, 0, 2e-11},
          {"overlapping fraction", M::OverlapFraction, 0.2, 0.8}}},
        {{"huge-scale", 40,
          "Random pairs scaled by 1e9: squared quantities near 1e18 (1e36 for products) test "
          "overflow margins and absolute rounding."},
         [](Rng& r, int i, Case& c, std::string& tag)
         {
             genScaled(r, i, c, 1e9);
             tag = scaledTag(i);
         },
         {{"max |coordinate|", M::MaxCoordinate, 1e9, kInf},
          {"overlapping fraction", M::OverlapFraction, 0.2, 0.8}}},
        {{"many-vertices", 8,
          "Polygons of 1000 to 4096 vertices approximating circles at gaps 1e-3..1e-9 and overlap: "
          "many nearly collinear support candidates, long runs of tiny progress, iteration "
          "limits."},
         genManyVertices,
         {{"max vertices", M::MaxVertices, 4000, kInf}}},
        {{"rotated", 40,
          "Rotations near multiples of a quarter turn (within 1e-12..1e-1) and random, in contact "
          "at small gaps: (c, s) with c^2 + s^2 != 1 in floating point and the local-frame "
          "mapping."},
         genRotated,
         {{"separated fraction", M::SeparatedFraction, 0.6, 0.85}}},
        {{"rounded", 40,
          "Rounded shapes (discs, capsules, rounded boxes and triangles, radii 1e-3..1) at gaps "
          "and "
          "penetrations: the radius is applied after GJK, on the core distance."},
         genRounded,
         {{"rounded fraction", M::RadiusFraction, 1, 1},
          {"separated fraction", M::SeparatedFraction, 0.6, 0.85}}},
        {{"points", 16,
          "Single points: inside a polygon, exactly on a vertex or an edge, near an edge, point to "
          "point (identical, distinct, one ulp apart), near a segment: one-vertex simplices only."},
         genPoints,
         {{"min vertices", M::MinVertices, 1, 1},
          {"overlapping fraction", M::OverlapFraction, 0.5, 0.5}}},
    };
    return table;
}

std::vector<MakeupSpec> randomMakeup()
{
    return {
        {"overlapping fraction", M::OverlapFraction, 0.2, 0.8, true},
        {"near-touching fraction (0 < d <= 1e-2)", M::NearTouchingFraction, 0.05, 1, true},
        {"min vertices", M::MinVertices, 3, 8},
        {"max vertices", M::MaxVertices, 3, 8},
        {"max |coordinate|", M::MaxCoordinate, 0, 16},
    };
}

const char* kRandomReason =
    "Realistic mix: 3 to 8 vertices on circles of radius 0.5 to 2 at random angles, random "
    "positions "
    "in [-4, 4]^2 and rotations; 10% placed at a gap of 1e-9..1e-2, 10% at a penetration of that "
    "size, 20% within [-1, 1]^2 of each other (deep overlap), the rest independent.";

std::uint64_t familySeed(std::uint64_t seed, const std::string& name)
{
    return mix64(seed ^ hashString(name));
}

GeneratedFamily generate(const std::string& name, const std::string& reason, int count,
                         std::uint64_t seed, const Gen& gen, std::vector<MakeupSpec> makeup)
{
    GeneratedFamily f;
    f.name = name;
    f.reason = reason;
    f.seed = familySeed(seed, name);
    f.makeup = std::move(makeup);
    f.cases.resize(std::size_t(count));
    for (int i = 0; i < count; ++i)
    {
        Rng r(mix64(f.seed + std::uint64_t(i)));
        std::string tag;
        Case& c = f.cases[std::size_t(i)];
        gen(r, i, c, tag);
        c.name = name + "/" + std::to_string(i) + (tag.empty() ? "" : "-" + tag);
    }
    return f;
}

} // namespace

const std::vector<HardSubFamilyInfo>& hardSubFamilies()
{
    static const std::vector<HardSubFamilyInfo> infos = []
    {
        std::vector<HardSubFamilyInfo> v;
        for (const auto& e : hardTable())
            v.push_back(e.info);
        return v;
    }();
    return infos;
}

std::vector<GeneratedFamily> generateFamilies(const std::string& spec, std::uint64_t seed)
{
    std::string name = spec;
    int count = -1;
    if (const auto colon = spec.find(':'); colon != std::string::npos)
    {
        name = spec.substr(0, colon);
        const std::string n = spec.substr(colon + 1);
        std::size_t used = 0;
        long v = -1;
        try
        {
            v = std::stol(n, &used);
        }
        catch (...)
        {
            used = 0;
        }
        if (used != n.size() || v < 0 || v > 100000000)
            throw InputError(
                fmt::format("--family {}: the count '{}' is not a number in 0..1e8", spec, n));
        count = int(v);
    }
    std::vector<GeneratedFamily> out;
    if (name == "random")
    {
        out.push_back(generate("random", kRandomReason, count < 0 ? kDefaultRandomCount : count,
                               seed, genRandom, randomMakeup()));
        return out;
    }
    const bool all = name == "hard";
    for (const auto& e : hardTable())
    {
        const std::string full = "hard/" + e.info.name;
        if (all || name == full)
            out.push_back(generate(full, e.info.reason, count < 0 ? e.info.count : count, seed,
                                   e.gen, e.makeup));
    }
    if (out.empty())
    {
        std::string known = "random, hard";
        for (const auto& e : hardTable())
            known += ", hard/" + e.info.name;
        throw InputError(fmt::format("unknown family '{}' (known: {})", name, known));
    }
    return out;
}

std::vector<MakeupResult> evaluateMakeup(const std::vector<MakeupSpec>& specs,
                                         const std::vector<const Case*>& cases,
                                         const std::vector<const exact::Result*>& truths)
{
    std::vector<MakeupResult> out;
    const double n = double(cases.size());
    for (const auto& s : specs)
    {
        double v = 0;
        switch (s.metric)
        {
        case M::OverlapFraction:
        case M::SeparatedFraction:
        {
            double k = 0;
            for (auto* t : truths)
                k += exactIsZero(*t) ? 1 : 0;
            v = n > 0 ? k / n : 0;
            if (s.metric == M::SeparatedFraction)
                v = n > 0 ? 1 - v : 0;
            break;
        }
        case M::NearTouchingFraction:
        {
            double k = 0;
            for (auto* t : truths)
                k += (!exactIsZero(*t) && t->distance <= 1e-2) ? 1 : 0;
            v = n > 0 ? k / n : 0;
            break;
        }
        case M::MinPositiveDistance:
            v = kInf;
            for (auto* t : truths)
                if (!exactIsZero(*t))
                    v = std::min(v, t->distance);
            break;
        case M::MaxDistance:
            for (auto* t : truths)
                v = std::max(v, t->distance);
            break;
        case M::MaxCoordinate:
            for (auto* c : cases)
                v = std::max(v, maxAbsWorldCoordinate(*c));
            break;
        case M::MinVertices:
            v = kInf;
            for (auto* c : cases)
                v = std::min({v, double(c->a.points.size()), double(c->b.points.size())});
            break;
        case M::MinHullVertices:
            v = kInf;
            for (auto* c : cases)
                v = std::min({v, double(convexHull(c->a.points).size()),
                              double(convexHull(c->b.points).size())});
            break;
        case M::MaxVertices:
            for (auto* c : cases)
                v = std::max({v, double(c->a.points.size()), double(c->b.points.size())});
            break;
        case M::MaxAspect:
            for (auto* c : cases)
                for (const ShapeIn* sh : {&c->a, &c->b})
                    if (const double a = aspectRatio(*sh); std::isfinite(a))
                        v = std::max(v, a);
            break;
        case M::RadiusFraction:
        {
            double k = 0;
            for (auto* c : cases)
                k += (c->a.radius > 0 || c->b.radius > 0) ? 1 : 0;
            v = n > 0 ? k / n : 0;
            break;
        }
        }
        const bool skipped = s.statistical && cases.size() < kMinCasesForStatistics;
        const bool inRange = v >= s.min && v <= s.max;
        out.push_back({s.check, v, s.min, s.max, skipped || inRange, skipped});
    }
    return out;
}

} // namespace gjkval
