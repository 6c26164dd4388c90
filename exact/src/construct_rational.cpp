// The exact construction step of the CGAL routes, in plain GMP rationals (mpq_class, canonical
// after every operation). EdgeMerge does the same construction in dyadic integers (edge_merge.cpp);
// the tests compare both with == on every case.
#include "internal.hpp"

namespace exact::detail
{

ExactResult construct(const Feature& f, const QPoint* zs, const QPoint* as, const QPoint* bs)
{
    ExactResult r;
    r.overlap = f.overlap;
    if (f.kind == Feature::Vertex)
    {
        r.z = zs[0];
        r.squared = zs[0].x * zs[0].x + zs[0].y * zs[0].y;
        r.wa = as[0];
        r.wb = bs[0];
        return r;
    }
    if (f.kind == Feature::Edge)
    {
        const QPoint &P = zs[0], &Q = zs[1];
        const mpq_class dx = Q.x - P.x, dy = Q.y - P.y;
        const mpq_class L = dx * dx + dy * dy;
        const mpq_class t = -(P.x * dx + P.y * dy) / L; // closest point P + t (Q - P), 0 < t < 1
        if (f.overlap)
        {
            r.squared = 0;
            r.z = {0, 0};
        }
        else
        {
            const mpq_class C = P.x * Q.y - P.y * Q.x;
            r.squared = C * C / L;
            r.z = {P.x + t * dx, P.y + t * dy};
        }
        r.wa = {as[0].x + t * (as[1].x - as[0].x), as[0].y + t * (as[1].y - as[0].y)};
        r.wb = {bs[0].x + t * (bs[1].x - bs[0].x), bs[0].y + t * (bs[1].y - bs[0].y)};
        return r;
    }
    // Triangle: O = sum l_t zs[t] = sum l_t (as[t] - bs[t]) with barycentric l_t, so
    // sum l_t as[t] = sum l_t bs[t] is a common point of both hulls.
    const mpq_class l0 = zs[1].x * zs[2].y - zs[1].y * zs[2].x;
    const mpq_class l1 = zs[2].x * zs[0].y - zs[2].y * zs[0].x;
    const mpq_class l2 = zs[0].x * zs[1].y - zs[0].y * zs[1].x;
    const mpq_class den = l0 + l1 + l2;
    r.squared = 0;
    r.z = {0, 0};
    r.wa = {(l0 * as[0].x + l1 * as[1].x + l2 * as[2].x) / den,
            (l0 * as[0].y + l1 * as[1].y + l2 * as[2].y) / den};
    r.wb = r.wa;
    return r;
}

} // namespace exact::detail
