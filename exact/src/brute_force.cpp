// Independent brute force, in plain GMP rationals with no hull construction, for the tests.
//   overlap:  the hulls are disjoint iff some direction strictly separates the point sets; when
//   they
//             are, the closest pair gives such a direction, and it is either the normal of a hull
//             edge (a pair of points of one set) or the difference of two points (one per set).
//             So: try the normals of all intra-set pairs and all inter-set differences.
//   distance: when disjoint, the closest pair is a vertex of one hull and a point of an edge (or a
//             vertex) of the other; every hull edge is a segment between two input points and every
//             such segment lies in the hull, so the minimum over (point, point-pair segment) of the
//             exact squared point-to-segment distance is the distance between the hulls.
#include "internal.hpp"

#include <vector>

namespace exact
{
namespace
{

using detail::QPoint;

std::vector<QPoint> transformed(const Shape& s)
{
    std::vector<QPoint> out;
    const mpq_class c(s.c), sn(s.s), px(s.px), py(s.py); // mpq from double: exact
    for (const Point& p : s.points)
    {
        const mpq_class x(p.x), y(p.y);
        out.push_back({c * x - sn * y + px, sn * x + c * y + py});
    }
    return out;
}

mpq_class dot(const mpq_class& dx, const mpq_class& dy, const QPoint& p)
{
    return dx * p.x + dy * p.y;
}

// true if direction (dx, dy) strictly separates the sets (in either order)
bool separates(const mpq_class& dx, const mpq_class& dy, const std::vector<QPoint>& a,
               const std::vector<QPoint>& b)
{
    if (sgn(dx) == 0 && sgn(dy) == 0)
        return false;
    mpq_class minA = dot(dx, dy, a[0]), maxA = minA, minB = dot(dx, dy, b[0]), maxB = minB;
    for (const QPoint& p : a)
    {
        mpq_class v = dot(dx, dy, p);
        if (v < minA)
            minA = v;
        if (v > maxA)
            maxA = v;
    }
    for (const QPoint& p : b)
    {
        mpq_class v = dot(dx, dy, p);
        if (v < minB)
            minB = v;
        if (v > maxB)
            maxB = v;
    }
    return maxA < minB || maxB < minA;
}

bool disjoint(const std::vector<QPoint>& a, const std::vector<QPoint>& b)
{
    for (const auto* s : {&a, &b})
        for (std::size_t i = 0; i < s->size(); ++i)
            for (std::size_t j = i + 1; j < s->size(); ++j)
            {
                const QPoint &p = (*s)[i], &q = (*s)[j];
                if (separates(p.y - q.y, q.x - p.x, a, b))
                    return true;
            }
    for (const QPoint& p : a)
        for (const QPoint& q : b)
            if (separates(q.x - p.x, q.y - p.y, a, b))
                return true;
    return false;
}

// Closest point of segment [p, q] to x and its squared distance.
mpq_class pointSegment(const QPoint& x, const QPoint& p, const QPoint& q, QPoint& closest)
{
    const mpq_class dx = q.x - p.x, dy = q.y - p.y;
    const mpq_class l = dx * dx + dy * dy;
    if (sgn(l) == 0)
    {
        closest = p;
    }
    else
    {
        mpq_class t = ((x.x - p.x) * dx + (x.y - p.y) * dy) / l;
        if (sgn(t) < 0)
            t = 0;
        if (t > 1)
            t = 1;
        closest = {p.x + t * dx, p.y + t * dy};
    }
    const mpq_class ex = x.x - closest.x, ey = x.y - closest.y;
    return ex * ex + ey * ey;
}

} // namespace

Result bruteForce(const Shape& sa, const Shape& sb)
{
    validateShape(sa, "shape A");
    validateShape(sb, "shape B");
    const std::vector<QPoint> a = transformed(sa), b = transformed(sb);
    detail::ExactResult e;
    e.overlap = !disjoint(a, b);
    if (e.overlap)
    {
        e.squared = 0;
        e.z = e.wa = e.wb = {0, 0};
        return detail::finish(e, sa.radius, sb.radius, false);
    }
    bool first = true;
    QPoint c;
    for (const QPoint& x : a)
        for (std::size_t i = 0; i < b.size(); ++i)
            for (std::size_t j = i; j < b.size(); ++j)
            {
                const mpq_class d = pointSegment(x, b[i], b[j], c);
                if (first || d < e.squared)
                {
                    first = false;
                    e.squared = d;
                    e.wa = x;
                    e.wb = c;
                }
            }
    for (const QPoint& x : b)
        for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t j = i; j < a.size(); ++j)
            {
                const mpq_class d = pointSegment(x, a[i], a[j], c);
                if (d < e.squared)
                {
                    e.squared = d;
                    e.wa = c;
                    e.wb = x;
                }
            }
    e.z = {e.wa.x - e.wb.x, e.wa.y - e.wb.y}; // finish()'s z = wa - wb
    return detail::finish(e, sa.radius, sb.radius, false);
}

// Overlap: the depth is the least over unit directions n of h_Z(n) = max_i n.a_i - min_j n.b_j
// (O inside Z: the distance from O to Z's supporting line of normal n), and that least is taken at
// a normal of an edge of Z, which is an edge of hull(A) or of hull(B), so perpendicular to a pair
// of distinct input points of A or of B (docs/exact.md, "Penetration depth"). Every such normal,
// both signs, is a candidate; with no candidate (each shape a single point, the same one: Z = {O})
// the depth is 0.
Result bruteForceSigned(const Shape& sa, const Shape& sb)
{
    Result r = bruteForce(sa, sb);
    r.hasSigned = true;
    if (!r.overlap)
    {
        mpq_class q(r.squaredNum + "/" + r.squaredDen, 10);
        q.canonicalize();
        detail::roundSigned(q, 1, sa.radius, sb.radius, r.signedDistance, r.signedLower,
                            r.signedUpper);
        r.penetrationA = r.witnessA;
        r.penetrationB = r.witnessB;
        return r;
    }
    const std::vector<QPoint> a = transformed(sa), b = transformed(sb);
    bool any = false;
    mpq_class best = 0;
    auto tryNormal = [&](const mpq_class& nx, const mpq_class& ny)
    {
        mpq_class hi = dot(nx, ny, a[0]), lo = dot(nx, ny, b[0]);
        for (const QPoint& p : a)
            if (const mpq_class v = dot(nx, ny, p); v > hi)
                hi = v;
        for (const QPoint& p : b)
            if (const mpq_class v = dot(nx, ny, p); v < lo)
                lo = v;
        mpq_class h = hi - lo;
        if (sgn(h) < 0)
            h = 0;
        const mpq_class v = h * h / (nx * nx + ny * ny);
        if (!any || v < best)
            best = v;
        any = true;
    };
    for (const auto* s : {&a, &b})
        for (std::size_t i = 0; i < s->size(); ++i)
            for (std::size_t j = i + 1; j < s->size(); ++j)
            {
                const QPoint &p = (*s)[i], &q = (*s)[j];
                if (p.x == q.x && p.y == q.y)
                    continue;
                tryNormal(p.y - q.y, q.x - p.x);
                tryNormal(q.y - p.y, p.x - q.x);
            }
    detail::roundSigned(best, -1, sa.radius, sb.radius, r.signedDistance, r.signedLower,
                        r.signedUpper);
    r.depthSquaredNum = best.get_num().get_str();
    r.depthSquaredDen = best.get_den().get_str();
    return r; // the penetration pair left at 0 on overlap (as the overlap witnesses)
}

} // namespace exact
