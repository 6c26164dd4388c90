// Shared pieces of the two CGAL routes (included by cgal_hull.cpp and cgal_minkowski.cpp only).
#pragma once

#include "internal.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace exact::detail::cg
{

// Exactness is chosen by this one typedef: lazy exact constructions over GMP rationals, with
// interval-filtered predicates.
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = K::FT;
using P2 = K::Point_2;

// x' = c*x - s*y + px, y' = s*x + c*y + py, exactly (FT(double) is exact).
inline P2 transform(const Shape& s, const Point& p)
{
    const FT c(s.c), sn(s.s), x(p.x), y(p.y);
    return P2(c * x - sn * y + FT(s.px), sn * x + c * y + FT(s.py));
}

inline std::vector<P2> transformAll(const Shape& s)
{
    std::vector<P2> out;
    out.reserve(s.points.size());
    for (const Point& p : s.points)
        out.push_back(transform(s, p));
    return out;
}

template <class NT> // a template so that the untaken branches below are not instantiated
mpq_class toMpq(const NT& v)
{
    using ET = std::decay_t<decltype(CGAL::exact(v))>;
    const ET& e = CGAL::exact(v);
    if constexpr (std::is_same_v<ET, mpq_class>)
    {
        return e;
    }
    else if constexpr (std::is_same_v<ET, CGAL::Gmpq>)
    {
        mpq_class q;
        mpq_set(q.get_mpq_t(), e.mpq());
        return q;
    }
    else
    {
        mpq_class q;
        mpq_set(q.get_mpq_t(), e.backend().data()); // boost::multiprecision gmp_rational
        return q;
    }
}

inline QPoint toQ(const P2& p)
{
    return {toMpq(p.x()), toMpq(p.y())};
}

// Rotates a counterclockwise vertex list so that it starts at its largest vertex in (x, y) order:
// the first vertex of Z, where locate()'s fan starts (docs/exact.md, "Witnesses").
template <class T, class Point> void startAtLargestXY(std::vector<T>& v, Point&& point)
{
    if (v.empty())
        return;
    const K::Less_xy_2 less;
    std::size_t best = 0;
    for (std::size_t k = 1; k < v.size(); ++k)
        if (less(point(v[best]), point(v[k])))
            best = k;
    std::rotate(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(best), v.end());
}

// locate() predicates on a vector of Z vertices, evaluated by the kernel's filtered predicates.
struct KernelPredicates
{
    const std::vector<P2>& z;
    int orientO(int i, int j) const
    {
        return static_cast<int>(CGAL::orientation(z[i], z[j], P2(CGAL::ORIGIN)));
    }
    int dotSign(int i, int j) const
    {
        // angle(p, q, r) is the sign of (p - q) . (r - q).
        switch (CGAL::angle(P2(CGAL::ORIGIN), z[i], z[j]))
        {
        case CGAL::ACUTE:
            return 1;
        case CGAL::RIGHT:
            return 0;
        default:
            return -1;
        }
    }
    bool isZero(int i) const { return z[i] == P2(CGAL::ORIGIN); }
};

// Locates the closest feature of Z and constructs the exact result; provenance(k, a, b) gives the
// A and B points whose difference a - b is Z vertex k.
// With wantPolygon and overlapping cores, also the whole of Z with its provenance
// (ExactResult::polygon, for the penetration depth).
template <class Provenance>
ExactResult solve(const std::vector<P2>& z, Provenance&& provenance, bool wantPolygon = false)
{
    KernelPredicates pr{z};
    const Feature f = locate(static_cast<int>(z.size()), pr);
    const int ids[3] = {f.i, f.j, f.l};
    const int count = f.kind == Feature::Vertex ? 1 : f.kind == Feature::Edge ? 2 : 3;
    QPoint zs[3], as[3], bs[3];
    for (int t = 0; t < count; ++t)
    {
        P2 a, b;
        provenance(ids[t], a, b);
        as[t] = toQ(a);
        bs[t] = toQ(b);
        zs[t] = {as[t].x - bs[t].x, as[t].y - bs[t].y};
    }
    ExactResult r = construct(f, zs, as, bs);
    if (wantPolygon && f.overlap)
    {
        Polygon& poly = r.polygon;
        for (std::size_t k = 0; k < z.size(); ++k)
        {
            P2 a, b;
            provenance(static_cast<int>(k), a, b);
            poly.a.push_back(toQ(a));
            poly.b.push_back(toQ(b));
            const QPoint& qa = poly.a.back();
            const QPoint& qb = poly.b.back();
            poly.z.push_back({qa.x - qb.x, qa.y - qb.y});
        }
    }
    return r;
}

} // namespace exact::detail::cg
