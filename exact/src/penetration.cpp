// The signed distance and the penetration pair (Options::penetration), in plain GMP rationals from
// the whole of Z = hull(A) - hull(B) with its provenance: every route hands the same polygon (the
// same vertices, maybe from another first vertex), and nothing here depends on where it starts, so
// all routes give the same bits. The derivation is in docs/exact.md, "Penetration depth":
//
//   For O inside the convex polygon Z, the depth (O's distance to Z's boundary) is the least
//   distance from O to the line of an edge, cross(P, Q)^2 / |Q - P|^2 squared for the edge P -> Q,
//   and the foot of the perpendicular on that line lies on the edge itself.
#include "internal.hpp"

namespace exact::detail
{
namespace
{

// 0 for directions with angle in [0, pi), 1 for [pi, 2 pi).
int halfOf(const QPoint& n)
{
    return (sgn(n.y) > 0 || (sgn(n.y) == 0 && sgn(n.x) > 0)) ? 0 : 1;
}

// true when nonzero direction n has a smaller angle in [0, 2 pi) than m.
bool angleLess(const QPoint& n, const QPoint& m)
{
    const int hn = halfOf(n), hm = halfOf(m);
    if (hn != hm)
        return hn < hm;
    return sgn(n.x * m.y - n.y * m.x) > 0; // same half plane: n turns left to m
}

} // namespace

// Edge P -> Q of a counterclockwise Z with O inside or on it: cross(P, Q) >= 0 is twice the area of
// (O, P, Q), so O's distance to the edge's line is cross(P, Q) / |Q - P|; the outward normal is
// (dy, -dx) for D = Q - P. A segment (k = 2) is the two edges P -> Q and Q -> P, O on both lines.
Depth deepest(const Polygon& poly)
{
    const std::size_t k = poly.z.size();
    Depth best;
    if (k == 1)
    { // Z = {O}: both shapes are one point, the same; every direction is a normal, the least is +x
        best.squared = 0;
        best.normal = {1, 0};
        best.a = poly.a[0];
        best.b = poly.b[0];
        return best;
    }
    std::size_t bestEdge = 0;
    mpq_class bestT;
    for (std::size_t e = 0; e < k; ++e)
    {
        const std::size_t g = e + 1 == k ? 0 : e + 1;
        const QPoint &P = poly.z[e], &Q = poly.z[g];
        const mpq_class dx = Q.x - P.x, dy = Q.y - P.y;
        const mpq_class C = P.x * Q.y - P.y * Q.x;
        const mpq_class L = dx * dx + dy * dy;
        const mpq_class d2 = C * C / L;
        const QPoint n{dy, -dx};
        const int c = e == 0 ? -1 : cmp(d2, best.squared);
        if (c < 0 || (c == 0 && angleLess(n, best.normal)))
        {
            best.squared = d2;
            best.normal = n;
            bestEdge = e;
            bestT = -(P.x * dx + P.y * dy) / L; // foot P + t (Q - P), 0 <= t <= 1
        }
    }
    const std::size_t e = bestEdge, g = e + 1 == k ? 0 : e + 1;
    auto along = [&](const QPoint& p, const QPoint& q) -> QPoint {
        return {p.x + bestT * (q.x - p.x), p.y + bestT * (q.y - p.y)};
    };
    best.a = along(poly.a[e], poly.a[g]);
    best.b = along(poly.b[e], poly.b[g]);
    return best;
}

void finishSigned(const ExactResult& e, double rA, double rB, Result& r)
{
    r.hasSigned = true;
    if (!e.overlap)
    { // sqrt(squared) - rA - rB, unclamped; the pair is the witnesses on the rounded surfaces
        mpq_class q = e.squared;
        q.canonicalize();
        roundSigned(q, 1, rA, rB, r.signedDistance, r.signedLower, r.signedUpper);
        r.depthSquaredNum.clear();
        r.depthSquaredDen.clear();
        r.penetrationA = r.witnessA;
        r.penetrationB = r.witnessB;
        return;
    }
    const Depth d = deepest(e.polygon);
    roundSigned(d.squared, -1, rA, rB, r.signedDistance, r.signedLower, r.signedUpper);
    r.depthSquaredNum = d.squared.get_num().get_str();
    r.depthSquaredDen = d.squared.get_den().get_str();
    roundPair(d.a, d.b, d.normal, rA, rB, r.penetrationA, r.penetrationB);
}

} // namespace exact::detail
