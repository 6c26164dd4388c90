// Sweeps and near-degenerate constructions, where published GJK implementations fail: one
// configuration over scales or offsets, very short contact edges, nearly tied supports, separations
// near zero.
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

// Boxes with near-parallel long edges (tilt 1e-9) at `gap`, B's pose relative to A's.
void nearParallelBoxes(Rng& g, Case& c, double gap, double px, double py)
{
    c.a = poly({{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}});
    c.b = poly({{-0.9, 0}, {0.9, 0}, {0.9, 0.6}, {-0.9, 0.6}});
    const double tilt = 1e-9, ca = std::cos(tilt), sa = std::sin(tilt);
    double minY = kInf;
    for (const auto& p : c.b.points)
        minY = std::min(minY, sa * p[0] + ca * p[1]);
    setPose(c.a, g.range(0, 2 * kPi), px, py);
    poseRelativeTo(c.a, c.b, tilt, {g.range(-0.05, 0.05), 0.5 + gap - minY});
}

// A triangle's vertex against a pentagon's edge at `gap` (negative: penetration).
void vertexAgainstEdge(Rng& g, Case& c, double gap, double px, double py)
{
    c.a = polygonOnCircle(g, 5, 1);
    c.b = poly({{0, 0}, {0.8, -0.3}, {0.5, 0.7}});
    setPose(c.a, g.range(0, 2 * kPi), px, py);
    setPose(c.b, g.range(0, 2 * kPi), 0, 0);
    placeAtGap(c.a, c.b, gap, g);
}

// Exact contact under a shared pose: A on the left of a generic segment P -> Q, B on its right
// sharing the segment (edge contact) or only the vertex P. Scaling every number by the same k
// keeps the shared points identical, so the contact stays exact.
void exactContact(Rng& g, Case& c, bool edge)
{
    const P2 P = {g.range(0.3, 0.7), g.range(-0.9, -0.5)},
             Q = {g.range(0.3, 0.7), g.range(0.5, 0.9)};
    const double len = std::hypot(Q[0] - P[0], Q[1] - P[1]);
    const P2 e = {(Q[0] - P[0]) / len, (Q[1] - P[1]) / len}, n = {e[1], -e[0]}; // n: right of P->Q
    auto at = [&](const P2& o, double t, double s) {
        return P2{o[0] + t * n[0] + s * e[0], o[1] + t * n[1] + s * e[1]};
    };
    c.a = poly({P, Q, at(Q, -1.2, 0.1), at(P, -1.0, -0.2)});
    if (edge)
        c.b = poly({Q, P, at(P, 0.8, -0.1), at(Q, 0.7, 0.2)});
    else
        c.b = poly({P, at(P, 0.9, -0.4), at(P, 0.6, 0.5)});
    randomPose(g, c.a);
    copyPose(c.a, c.b);
}

constexpr int kScaleSteps = 43; // 1e-12, 3.7e-12, 1e-11, ..., 3.7e8, 1e9

double sweepScale(int step)
{
    return (step % 2 == 1 ? 3.7 : 1.0) * std::pow(10.0, -12 + step / 2);
}

void genScaleSweep(Rng& r, int i, Case& c, std::string& tag)
{
    static const char* names[] = {"near-parallel-gap", "vertex-edge-gap", "touching",
                                  "overlapping"};
    const int config = i % 4, step = (i / 4) % kScaleSteps;
    const bool edge = step % 2 == 0; // the touching configuration alternates edge and vertex
    Rng g = sharedRng(r, 0x5ca1e5eeULL + std::uint64_t(config) * 2 + (config == 2 && !edge));
    switch (config)
    {
    case 0:
        nearParallelBoxes(g, c, 1e-6, g.range(-4, 4), g.range(-4, 4));
        break;
    case 1:
        vertexAgainstEdge(g, c, 1e-10, g.range(-4, 4), g.range(-4, 4));
        break;
    case 2:
        exactContact(g, c, edge);
        break;
    default:
        vertexAgainstEdge(g, c, -1e-7, g.range(-4, 4), g.range(-4, 4));
        break;
    }
    const double k = sweepScale(step);
    scaleCase(c, k);
    tag = fmt::format("{}{}-x{:g}", names[config], config == 2 ? (edge ? "-edge" : "-vertex") : "",
                      k);
}

FamilyRow scaleSweepRow()
{
    return {
        {"scale-sweep", 172,
         "The same four configurations (near-parallel edges at a gap of 1e-6, a vertex at 1e-10 "
         "from an edge, exact edge or vertex contact, a 1e-7 overlap; sizes ~1) scaled by "
         "1e-12, 3.7e-12, 1e-11, ... 1e9 (factors that are not powers of two, so every number "
         "rounds): an absolute tolerance (an epsilon on squared lengths, on the duality gap or "
         "on the overlap test) is right at one scale only and gives false overlaps below it or "
         "lost accuracy above it; the error must stay proportional to the scale."},
        genScaleSweep,
        {{"overlapping fraction", M::OverlapFraction, 0.5, 0.5},
         {"min positive distance", M::MinPositiveDistance, 0, 2e-22},
         {"max distance", M::MaxDistance, 0.9e3, 1.1e3},
         {"smallest case scale", M::MinScale, 0, 1e-11},
         {"max |coordinate|", M::MaxCoordinate, 1e9, kInf}}};
}

constexpr int kOffsetSteps = 19; // 10^0, 10^0.5, ..., 10^9

void genOffsetSweep(Rng& r, int i, Case& c, std::string& tag)
{
    const int config = i % 2, step = (i / 4) % kOffsetSteps;
    const bool baked = (i / 2) % 2 == 1;
    const double offset = std::pow(10.0, step / 2.0), gap = 1e-5;
    Rng g = sharedRng(r, 0x0ff5e75eULL + std::uint64_t(config));
    if (config == 0)
        nearParallelBoxes(g, c, gap, g.range(-1, 1), g.range(-1, 1));
    else
        vertexAgainstEdge(g, c, gap, g.range(-1, 1), g.range(-1, 1));
    moveFar(c, offset, g.range(0, 2 * kPi), baked);
    tag = fmt::format("{}-off{:g}-{}", config == 0 ? "near-parallel" : "vertex-edge", offset,
                      baked ? "coords" : "transform");
}

FamilyRow offsetSweepRow()
{
    return {
        {"offset-sweep", 76,
         "A fixed gap of 1e-5 (near-parallel edges, and a vertex against an edge) moved by "
         "offsets 1, 10^0.5, ... 1e9, the offset in the transforms (A's local frame cancels it "
         "before the gap is rounded) or baked into the coordinates (then the input itself "
         "carries ulp(offset)): a computation in world coordinates loses a small gap to a large "
         "common offset (at 1e9 the gap is ~80 ulps of the coordinates)."},
        genOffsetSweep,
        {{"separated fraction", M::SeparatedFraction, 1, 1},
         {"min positive distance", M::MinPositiveDistance, 0.9e-5, 1.1e-5},
         {"max distance", M::MaxDistance, 0.9e-5, 1.1e-5},
         {"smallest case scale", M::MinScale, 0, 10},
         {"max |coordinate|", M::MaxCoordinate, 7e8, kInf}}};
}

void genShortContactEdge(Rng& r, int i, Case& c, std::string& tag)
{
    static const char* partners[] = {"short-edge", "long-edge", "vertex"};
    static const char* gapNames[] = {"gap-l",    "gap-l/10",     "gap-l/1000",
                                     "touching", "overlap-l/10", "overlap-l/1000"};
    static const double gapFactor[] = {1, 0.1, 1e-3, 0, -0.1, -1e-3};
    const int partner = i % 3, gm = (i / 3) % 6, li = (i / 18) % 7;
    const double ell = std::pow(10.0, -(3 + li));
    // A's short edge P -> Q has direction (-1, 3) and length ~ell; s is a multiple of 2^-52 so
    // that P, Q, their midpoint M and every point below on the line 3x + y = 3 are exact.
    const double s = std::ldexp(std::nearbyint(std::ldexp(ell / std::sqrt(10.0), 52)), -52);
    const P2 P = {1, 0}, Q = {1 - s, 3 * s}, M = {1 - s / 2, 1.5 * s};
    c.a = poly({{0.5, -1}, P, Q, {-0.5, 1}, {-1, 0}});
    switch (partner)
    {
    case 0: // A reflected through M: B's own short edge is Q -> P, exactly
        c.b = c.a;
        for (auto& p : c.b.points)
            p = {(2 - s) - p[0], 3 * s - p[1]};
        break;
    case 1: // a box whose long edge (0.75, 0.75)-(1.25, -0.75) contains A's short edge
        c.b = poly({{1.25, -0.75}, {2, -0.5}, {1.5, 1}, {0.75, 0.75}});
        break;
    default: // a triangle's vertex at the midpoint of A's short edge
        c.b = poly({M, {M[0] + 1.2, M[1] + 0.9}, {M[0] + 0.3, M[1] + 1.1}});
        break;
    }
    // Touching in A's frame; B then moved by the gap along the short edge's normal (3, 1)/sqrt(10).
    const double gap = gapFactor[gm] * ell, nx = 3 / std::sqrt(10.0), ny = 1 / std::sqrt(10.0);
    randomPose(r, c.a);
    poseRelativeTo(c.a, c.b, 0, {gap * nx, gap * ny});
    tag = fmt::format("{}-l1e-{}-{}", partners[partner], 3 + li, gapNames[gm]);
}

FamilyRow shortContactEdgeRow()
{
    return {
        {"short-contact-edge", 126,
         "Contact along a very short edge (length 1e-3 .. 1e-9 of the shape's size, exact "
         "coordinates on the line 3x + y = 3) against a short edge, a long edge or a vertex, at "
         "gaps of the edge length, a tenth and a thousandth of it, exact touching, and overlaps "
         "of a tenth and a thousandth: the simplex edge is tiny next to its distance from the "
         "origin, so an absolute tolerance on edge lengths or barycentric weights, or a "
         "division by the squared edge length, turns a short-edge contact into a false overlap "
         "or a wrong Voronoi region."},
        genShortContactEdge,
        {{"separated fraction", M::SeparatedFraction, 0.5, 0.5},
         {"min positive distance", M::MinPositiveDistance, 0.9e-12, 1.1e-12},
         {"max distance", M::MaxDistance, 0.9e-3, 1.1e-3},
         {"shortest edge / diameter", M::MinEdgeRatio, 0, 1e-9}}};
}

void genNearTiedSupport(Rng& r, int i, Case& c, std::string& tag)
{
    static const int ns[] = {6, 32, 256, 2048};
    static const double widths[] = {1, 0.1, 1e-2, 1e-4};
    static const double deltas[] = {0, 1e-15, 1e-12, 1e-9, 1e-6, 1e-3};
    const int kind = i % 3, ni = (i / 3) % 4, di = (i / 12) % 6;
    const double gap = (i / 72) % 2 == 0 ? 1e-5 : 1e-11, delta = deltas[di];
    double lateral = 0;
    if (kind == 2)
    {
        // Boxes facing each other with parallel edges (x = w), B turned by delta.
        const double w = widths[ni];
        c.a = poly({{-w, -1}, {w, -1}, {w, 1}, {-w, 1}});
        c.b = c.a;
        tag = fmt::format("boxes-w{:g}", w);
    }
    else
    {
        // Regular n-gons: A's edge faces +x; B's edge (kind 0) or, half a vertex angle further,
        // its vertex (kind 1) faces -x. The vertex is kept inside A's facing edge.
        const int n = ns[ni];
        c.a = regularPolygon(n, 1, kPi / n);
        c.b = regularPolygon(n, 1, kind == 0 ? kPi + kPi / n : kPi);
        if (kind == 1)
            lateral = r.range(-0.5, 0.5) * std::sin(kPi / n) + std::sin(delta);
        tag = fmt::format("{}gon-{}", n, kind == 0 ? "edge-edge" : "edge-vertex");
    }
    double maxA = -kInf, minB = kInf;
    const double cd = std::cos(delta), sd = std::sin(delta);
    for (const auto& p : c.a.points)
        maxA = std::max(maxA, p[0]);
    for (const auto& p : c.b.points)
        minB = std::min(minB, cd * p[0] - sd * p[1]);
    randomPose(r, c.a);
    poseRelativeTo(c.a, c.b, delta, {maxA + gap - minB, lateral});
    tag += fmt::format("-rot{:g}-gap{:g}", delta, gap);
}

FamilyRow nearTiedSupportRow()
{
    return {{"near-tied-support", 144,
             "Several vertices nearly tied along the search directions: regular 6- to 2048-gons "
             "facing each other edge to edge or, half a vertex angle further, edge to vertex, and "
             "boxes with parallel facing edges, B turned by 0, 1e-15 .. 1e-3, gaps 1e-5 and 1e-11: "
             "the support point flips between nearly tied vertices from one rounding to the next, "
             "which repeats support points (a degenerate simplex, NaN from a zero-length edge) or "
             "cycles until the iteration limit, and the binary-search support must resolve the "
             "ties like the linear scan."},
            genNearTiedSupport,
            {{"separated fraction", M::SeparatedFraction, 1, 1},
             {"min positive distance", M::MinPositiveDistance, 0.9e-11, 1.1e-11},
             {"max distance", M::MaxDistance, 0.9e-5, 1.1e-5},
             {"max vertices", M::MaxVertices, 2048, kInf},
             {"min vertices", M::MinVertices, 4, 4}}};
}

// Closest points of two convex hulls that are apart (double; vertex against edge, both ways).
void closestPoints(const std::vector<P2>& a, const std::vector<P2>& b, P2& pa, P2& pb)
{
    const auto ha = convexHull(a), hb = convexHull(b);
    double best = kInf;
    auto consider = [&](const P2& p, const P2& q0, const P2& q1, bool pOnA)
    {
        const double ex = q1[0] - q0[0], ey = q1[1] - q0[1], ee = ex * ex + ey * ey;
        const double t =
            ee > 0 ? std::clamp(((p[0] - q0[0]) * ex + (p[1] - q0[1]) * ey) / ee, 0.0, 1.0) : 0;
        const P2 q = {q0[0] + t * ex, q0[1] + t * ey};
        const double d = std::hypot(p[0] - q[0], p[1] - q[1]);
        if (d < best)
        {
            best = d;
            pa = pOnA ? p : q;
            pb = pOnA ? q : p;
        }
    };
    for (const auto& p : ha)
        for (std::size_t j = 0; j < hb.size(); ++j)
            consider(p, hb[j], hb[(j + 1) % hb.size()], true);
    for (const auto& p : hb)
        for (std::size_t j = 0; j < ha.size(); ++j)
            consider(p, ha[j], ha[(j + 1) % ha.size()], false);
}

constexpr int kSeparationLevels = 15; // 1e-3 .. 1e-15, 0 up to rounding, exact contact

void genNearZeroSeparation(Rng& r, int i, Case& c, std::string& tag)
{
    const int level = i % kSeparationLevels;
    c.a = randomPolygon(r);
    c.b = randomPolygon(r);
    setPose(c.a, r.range(0, 2 * kPi), r.range(-1, 1), r.range(-1, 1));
    if (level == kSeparationLevels - 1)
    {
        // Exactly 0: B is given in A's frame (shared pose), rotated at random, and its support
        // vertex along -n is put exactly on A's support vertex along n (a random direction n):
        // the shapes touch at that one point.
        const double t = r.range(0, 2 * kPi), tb = r.range(0, 2 * kPi);
        const double nx = std::cos(t), ny = std::sin(t), cb = std::cos(tb), sb = std::sin(tb);
        for (auto& p : c.b.points)
            p = {cb * p[0] - sb * p[1], sb * p[0] + cb * p[1]};
        std::size_t ia = 0, ib = 0;
        for (std::size_t k = 0; k < c.a.points.size(); ++k)
            if (nx * c.a.points[k][0] + ny * c.a.points[k][1] >
                nx * c.a.points[ia][0] + ny * c.a.points[ia][1])
                ia = k;
        for (std::size_t k = 0; k < c.b.points.size(); ++k)
            if (nx * c.b.points[k][0] + ny * c.b.points[k][1] <
                nx * c.b.points[ib][0] + ny * c.b.points[ib][1])
                ib = k;
        const double sx = c.a.points[ia][0] - c.b.points[ib][0];
        const double sy = c.a.points[ia][1] - c.b.points[ib][1];
        for (auto& p : c.b.points)
            p = {p[0] + sx, p[1] + sy};
        c.b.points[ib] = c.a.points[ia];
        copyPose(c.a, c.b);
        tag = "exact-contact";
        return;
    }
    // B starts 5 away in a random direction, then moves along the separating direction (from
    // the closest points, in double) until the separation is the target.
    const double target = level < kSeparationLevels - 2 ? std::pow(10.0, -(3 + level)) : 0;
    const double theta = r.range(0, 2 * kPi);
    setPose(c.b, r.range(0, 2 * kPi), c.a.px + 5 * std::cos(theta), c.a.py + 5 * std::sin(theta));
    P2 pa{}, pb{};
    closestPoints(worldPoints(c.a), worldPoints(c.b), pa, pb);
    const double dx = pb[0] - pa[0], dy = pb[1] - pa[1], d = std::hypot(dx, dy);
    c.b.px -= (d - target) * (dx / d);
    c.b.py -= (d - target) * (dy / d);
    tag = target > 0 ? fmt::format("sep1e-{}", 3 + level) : "sep0";
}

FamilyRow nearZeroSeparationRow()
{
    return {{"near-zero-separation", 180,
             "Random polygons in random directions, B moved along the separating direction "
             "(closest points in double) to a separation of 1e-3, 1e-4, ... 1e-15 (sizes ~1) or 0, "
             "plus exact vertex contacts: the overlap decision near zero, where a rounded "
             "orientation or containment test, or a tolerance, must not report a false overlap "
             "beyond the bound, nor a false separation of touching shapes."},
            genNearZeroSeparation,
            {{"overlapping fraction", M::OverlapFraction, 0.05, 0.5},
             {"min positive distance", M::MinPositiveDistance, 0, 1e-12},
             {"max distance", M::MaxDistance, 0.99e-3, 1.01e-3},
             {"near-touching fraction (0 < d <= 1e-2)", M::NearTouchingFraction, 0.5, 0.95}}};
}

} // namespace

std::vector<FamilyRow> sweepFamilies()
{
    return {scaleSweepRow(), offsetSweepRow(), shortContactEdgeRow(), nearTiedSupportRow(),
            nearZeroSeparationRow()};
}

} // namespace gjkval::families
