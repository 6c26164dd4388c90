// Route EdgeMerge: hulls of A and B (Andrew's monotone chain), the linear-time Minkowski difference
// Z = hull(A) - hull(B) by merging the two hulls' edge sequences by angle, then the
// predicate-located closest feature and one exact construction.
//
// Arithmetic: every input double is m * 2^e, so a transformed coordinate c*x - s*y + px is a dyadic
// rational, held exactly as a GMP integer times a power of two ("dyadic integers"): no division,
// no gcd. Each predicate is first evaluated in interval arithmetic (CGAL::Interval_nt, directed
// rounding, sound under overflow and underflow); only when the interval contains 0 does it fall
// back to the exact dyadic integers, which are computed lazily per input point.
//
// Also exact::PreparedShape (at the end): one shape's hull and intervals, kept for many
// point-to-shape distances (preparedPointDistance), with the decisions of the one-point route.
#include "internal.hpp"

#include <CGAL/Interval_nt.h>
#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <optional>
#include <vector>

namespace exact::detail
{
namespace
{

using I = CGAL::Interval_nt<false>; // needs the FPU in round-upward mode: see the Protector below

// Per-point and per-vertex arrays stored inline up to a shape of kInline points (Box2D's polygons
// have at most 8; the random family 3 to 8), on the heap beyond: a truth then allocates nothing
// here on the common path. 16 was slower than 8 in wall time, for fewer instructions: a prepared
// shape twice the memory (docs/speed.md, "Allocations, transforms and the fold").
constexpr std::size_t kInline = 8;
template <class T> using PointArray = boost::container::small_vector<T, kInline>;
template <class T> using VertexArray = boost::container::small_vector<T, 2 * kInline>; // Z, chains

// The interval of the product of two doubles, [RD(a b), RU(a b)], in the round-upward mode the
// Protector sets: CGAL's product of the point intervals I(a) and I(b), whose bounds are these same
// correctly rounded doubles, without its general case (fewer instructions a shape). The
// operands go through CGAL's own IA_opacify and IA_up, as in CGAL_IA_MUL: without them the
// compiler, which assumes round-to-nearest, may fold -((-a) b) into a b. A zero's sign may differ
// from CGAL's, which no comparison sees.
I product(double a, double b)
{
    const double up = CGAL::IA_up(CGAL::IA_opacify(a) * CGAL::IA_opacify(b));
    const double down = -CGAL::IA_up(CGAL::IA_opacify(-a) * CGAL::IA_opacify(b));
    return I(down, up);
}

// ---------------------------------------------------------------- exact dyadic integers

// v = m * 2^e exactly (m odd, or m = 0).
struct Dec
{
    long m;
    long e;
};

Dec decompose(double v)
{
    if (v == 0)
        return {0, 0};
    int k;
    const double f = std::frexp(v, &k); // |f| in [0.5, 1): exact
    long m = static_cast<long>(std::ldexp(f, 53));
    long e = k - 53;
    const int tz = __builtin_ctzl(static_cast<unsigned long>(m < 0 ? -m : m));
    return {m / (long(1) << tz), e + tz};
}

// A point or vector (x, y) * 2^e with GMP integers x, y.
struct E2
{
    mpz_class x, y;
    long e = 0;
};

// Accumulates term * 2^te into (v, ve); `set` tells whether v holds anything yet.
void accumulate(mpz_class& v, long& ve, bool& set, const mpz_class& term, long te)
{
    if (!set)
    {
        v = term;
        ve = te;
        set = true;
    }
    else if (te < ve)
    {
        v <<= static_cast<mp_bitcnt_t>(ve - te);
        v += term;
        ve = te;
    }
    else
    {
        mpz_class t = term;
        t <<= static_cast<mp_bitcnt_t>(te - ve);
        v += t;
    }
}

// The sign a product enters its sum with.
enum class Sign
{
    Plus,
    Minus
};

void addProduct(mpz_class& v, long& ve, bool& set, const Dec& a, const Dec& b, Sign sign)
{
    if (a.m == 0 || b.m == 0)
        return;
    mpz_class t(a.m);
    t *= b.m;
    if (sign == Sign::Minus)
        t = -t;
    accumulate(v, ve, set, t, a.e + b.e);
}

void addTerm(mpz_class& v, long& ve, bool& set, const Dec& a)
{
    if (a.m == 0)
        return;
    accumulate(v, ve, set, mpz_class(a.m), a.e);
}

struct DecShape
{
    Dec c, s, px, py;
};

// A shape's transform as dyadic integers: made only where an exact value is needed (a predicate
// the intervals left undecided, a construction), not with every shape (four frexp/ldexp pairs a
// shape).
DecShape decShapeOf(const Shape& s)
{
    return {decompose(s.c), decompose(s.s), decompose(s.px), decompose(s.py)};
}

// x' = c*x - s*y + px, y' = s*x + c*y + py, exactly.
E2 transformExact(const DecShape& t, const Point& p)
{
    const Dec x = decompose(p.x), y = decompose(p.y);
    E2 r;
    long ex = 0, ey = 0;
    bool sx = false, sy = false;
    addProduct(r.x, ex, sx, t.c, x, Sign::Plus);
    addProduct(r.x, ex, sx, t.s, y, Sign::Minus);
    addTerm(r.x, ex, sx, t.px);
    addProduct(r.y, ey, sy, t.s, x, Sign::Plus);
    addProduct(r.y, ey, sy, t.c, y, Sign::Plus);
    addTerm(r.y, ey, sy, t.py);
    if (!sx)
        ex = ey;
    if (!sy)
        ey = ex;
    r.e = std::min(ex, ey);
    r.x <<= static_cast<mp_bitcnt_t>(ex - r.e);
    r.y <<= static_cast<mp_bitcnt_t>(ey - r.e);
    return r;
}

// Shifted copies at a smaller common exponent e (e <= v.e).
mpz_class at(const mpz_class& v, long ve, long e)
{
    mpz_class r = v;
    r <<= static_cast<mp_bitcnt_t>(ve - e);
    return r;
}

E2 sub(const E2& a, const E2& b)
{
    E2 r;
    r.e = std::min(a.e, b.e);
    r.x = at(a.x, a.e, r.e) - at(b.x, b.e, r.e);
    r.y = at(a.y, a.e, r.e) - at(b.y, b.e, r.e);
    return r;
}

// Signs of cross and dot products: both terms carry 2^(a.e + b.e), no alignment needed.
int crossSignE(const E2& a, const E2& b)
{
    mpz_class l = a.x * b.y, r = a.y * b.x;
    return cmp(l, r);
}
int dotSignE(const E2& a, const E2& b)
{
    mpz_class d = a.x * b.x + a.y * b.y;
    return sgn(d);
}
int cmpCoord(const mpz_class& a, long ae, const mpz_class& b, long be)
{
    const long e = std::min(ae, be);
    return cmp(at(a, ae, e), at(b, be, e));
}

mpq_class toQ(const mpz_class& v, long e)
{
    mpq_class q(v);
    if (e > 0)
        mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    if (e < 0)
        mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    return q;
}
// num/den * 2^e; canonical (lowest terms) only when asked: the witness coordinates are left
// unreduced (see ExactResult), which saves a gcd each.
mpq_class toQ(const mpz_class& num, const mpz_class& den, long e, bool canonical = false)
{
    mpq_class q;
    mpz_set(mpq_numref(q.get_mpq_t()), num.get_mpz_t());
    mpz_set(mpq_denref(q.get_mpq_t()), den.get_mpz_t());
    if (canonical)
        q.canonicalize();
    if (e > 0)
        mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    if (e < 0)
        mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    return q;
}
QPoint toQ(const E2& p)
{
    return {toQ(p.x, p.e), toQ(p.y, p.e)};
}

// ---------------------------------------------------------------- filtered predicates

// Sign of an interval, or 2 when it is uncertain.
constexpr int kUnsure = 2;
int sign(const I& v)
{
    if (v.inf() > 0)
        return 1;
    if (v.sup() < 0)
        return -1;
    if (v.inf() == 0 && v.sup() == 0)
        return 0;
    return kUnsure;
}

// One input shape: interval and (lazily) exact transformed points.
struct Side
{
    const Shape* shape = nullptr;
    std::optional<DecShape> dec; // on the first exact value
    PointArray<I> ownX, ownY;    // init()'s intervals; from a prepared shape, x and y point there
    const I* x = nullptr;
    const I* y = nullptr;
    std::vector<E2> ex;
    std::vector<char> have;
    int exactDecisions = 0; // comparisons and orientations the intervals left to exact()

    void init(const Shape& s)
    {
        shape = &s;
        const std::size_t n = s.points.size();
        ownX.resize(n);
        ownY.resize(n);
        const I px(s.px), py(s.py);
        for (std::size_t i = 0; i < n; ++i)
        {
            const double x = s.points[i].x, y = s.points[i].y;
            ownX[i] = product(s.c, x) - product(s.s, y) + px;
            ownY[i] = product(s.s, x) + product(s.c, y) + py;
        }
        x = ownX.data();
        y = ownY.data();
    }
    void init(const PreparedData& d); // the prepared shape's intervals and hull counts
    const E2& exact(int i)
    {
        if (ex.empty())
        { // exact values are rarely needed for more than a few points: allocate late
            ex.resize(shape->points.size());
            have.assign(shape->points.size(), 0);
        }
        if (!have[i])
        {
            if (!dec)
                dec = decShapeOf(*shape);
            ex[i] = transformExact(*dec, shape->points[i]);
            have[i] = 1;
        }
        return ex[i];
    }

    int cmpX(int i, int j)
    {
        if (x[i].sup() < x[j].inf())
            return -1;
        if (x[i].inf() > x[j].sup())
            return 1;
        if (x[i].is_point() && x[j].is_point())
            return 0; // equal points: exactly equal
        ++exactDecisions;
        const E2 &a = exact(i), &b = exact(j);
        return cmpCoord(a.x, a.e, b.x, b.e);
    }
    int cmpY(int i, int j)
    {
        if (y[i].sup() < y[j].inf())
            return -1;
        if (y[i].inf() > y[j].sup())
            return 1;
        if (y[i].is_point() && y[j].is_point())
            return 0;
        ++exactDecisions;
        const E2 &a = exact(i), &b = exact(j);
        return cmpCoord(a.y, a.e, b.y, b.e);
    }
    int cmpXY(int i, int j)
    {
        const int c = cmpX(i, j);
        return c != 0 ? c : cmpY(i, j);
    }
    int cmpYX(int i, int j)
    {
        const int c = cmpY(i, j);
        return c != 0 ? c : cmpX(i, j);
    }
    int orient(int i, int j, int k)
    {
        const int s = sign((x[j] - x[i]) * (y[k] - y[i]) - (y[j] - y[i]) * (x[k] - x[i]));
        if (s != kUnsure)
            return s;
        ++exactDecisions;
        const E2& p = exact(i);
        return crossSignE(sub(exact(j), p), sub(exact(k), p));
    }

    // Convex hull, counterclockwise, no repeated or collinear vertices, starting at the
    // lexicographically smallest point; a single point or a segment's two ends when degenerate.
    PointArray<int> hull()
    {
        const int n = static_cast<int>(shape->points.size());
        PointArray<int> idx(n);
        std::iota(idx.begin(), idx.end(), 0);
        std::sort(idx.begin(), idx.end(), [this](int a, int b) { return cmpXY(a, b) < 0; });
        idx.erase(
            std::unique(idx.begin(), idx.end(), [this](int a, int b) { return cmpXY(a, b) == 0; }),
            idx.end());
        const int m = static_cast<int>(idx.size());
        // Copied, not moved: GCC 12 misreads the inline buffer's move (-Wstringop-overread).
        if (m <= 2)
            return PointArray<int>(idx.begin(), idx.end());
        VertexArray<int> h(2 * m);
        int k = 0;
        for (int i = 0; i < m; ++i)
        {
            while (k >= 2 && orient(h[k - 2], h[k - 1], idx[i]) <= 0)
                --k;
            h[k++] = idx[i];
        }
        for (int i = m - 2, t = k + 1; i >= 0; --i)
        {
            while (k >= t && orient(h[k - 2], h[k - 1], idx[i]) <= 0)
                --k;
            h[k++] = idx[i];
        }
        return PointArray<int>(h.begin(), h.begin() + (k - 1));
    }
};

// Half-plane class of a nonzero vector for angle ordering in [pi, 3*pi): 0 for angles in [pi,
// 2*pi).
int half(int sy, int sx)
{
    return (sy < 0 || (sy == 0 && sx < 0)) ? 0 : 1;
}

} // namespace

// What PreparedShape keeps: the shape; its hull as Side::hull() gives it, with the exact decisions
// that took (Solver's side, from prepared data: the same hull and the same counts); Z = {p} -
// hull(shape) as Solver's merge() builds it for a one-point A, less the point: hull vertex indices
// from the lowest (then leftmost) one, counterclockwise (merge()'s order, so the same Z vertex
// numbers); and every point's interval world coordinates (Side::init()'s, moved from it).
struct PreparedData
{
    Shape shape;
    PointArray<int> hull;
    int hullExact = 0;
    PointArray<int> z;
    PointArray<I> x, y; // by point index: Z vertex k is p - (x, y)[z[k]]
};

namespace
{

void Side::init(const PreparedData& d)
{
    shape = &d.shape;
    x = d.x.data();
    y = d.y.data();
    exactDecisions = d.hullExact;
}

class Solver
{
  public:
    Solver(const Shape& a, const Shape& b) : a_(a), b_(b) {}
    // From prepared shapes (exact::PreparedShape): their hulls and intervals, not made again.
    Solver(const PreparedData& a, const PreparedData& b)
        : a_(a.shape), b_(b.shape), preparedA_(&a), preparedB_(&b)
    {
    }

    ExactResult run(bool wantPolygon = false)
    {
        const Feature f = locateFeature();
        ExactResult e = build(f);
        if (wantPolygon && f.overlap)
            e.polygon = polygon();
        return e;
    }

    // The filtered result (Options::filter): the rounded outputs in double-double where the bound
    // decides them, with the exact squared distance from the feature; else build() and finish().
    Result runFiltered(const Options& options)
    {
        const Feature f = locateFeature();
        Result r;
        if (!options.exactWitnesses)
        {
            const int ids[3] = {f.i, f.j, f.l};
            Point as[3], bs[3];
            for (int t = 0; t < 3; ++t)
            {
                as[t] = a_.points[za[ids[t]]];
                bs[t] = b_.points[zb[ids[t]]];
            }
            if (filteredFinish(f, a_, b_, as, bs, r, options.penetration))
            {
                if (options.squaredRational)
                {
                    const mpq_class q = squared(f);
                    r.squaredNum = q.get_num().get_str();
                    r.squaredDen = q.get_den().get_str();
                }
                if (options.penetration)
                    filteredSigned(f, options, r);
                r.fallbacks = counts(r.fallbacks);
                return r;
            }
        }
        Fallbacks undecided = r.fallbacks;
        ExactResult e = build(f);
        if (options.penetration && f.overlap)
            e.polygon = polygon();
        r = finish(e, a_.radius, b_.radius, options.exactWitnesses);
        if (options.penetration)
        {
            finishSigned(e, a_.radius, b_.radius, r);
            undecided.depth = true;
        }
        r.fallbacks = counts(undecided);
        r.fallbacks.gmp = true;
        return r;
    }

    // Options::penetration after filteredFinish() decided the rest: separated, the signed
    // distance filteredFinish() rounded where it could; overlapping, filteredDepth(). What they
    // leave undecided, the GMP route (penetration.cpp) rounds, with Fallbacks::depth.
    void filteredSigned(const Feature& f, const Options& options, Result& r)
    {
        if (!f.overlap)
        {
            if (r.hasSigned)
            {
                r.penetrationA = r.witnessA;
                r.penetrationB = r.witnessB;
                return;
            }
            ExactResult e;
            e.squared = squared(f);
            finishSigned(e, a_.radius, b_.radius, r);
            r.fallbacks.depth = true;
            return;
        }
        const int k = static_cast<int>(za.size());
        const int chosen = closestEdge(r.fallbacks.depthTies);
        const int ids[2] = {chosen, chosen + 1 == k ? 0 : chosen + 1};
        const int count = k == 1 ? 1 : 2;
        Point as[2], bs[2];
        for (int t = 0; t < count; ++t)
        {
            as[t] = a_.points[za[ids[t]]];
            bs[t] = b_.points[zb[ids[t]]];
        }
        Result s;
        if (filteredDepth(count, a_, b_, as, bs, s))
        {
            r.hasSigned = true;
            r.signedDistance = s.signedDistance;
            r.signedLower = s.signedLower;
            r.signedUpper = s.signedUpper;
            r.penetrationA = s.penetrationA;
            r.penetrationB = s.penetrationB;
            if (options.squaredRational)
            {
                const mpq_class q = k == 1 ? mpq_class(0) : edgeExact(chosen).squared;
                r.depthSquaredNum = q.get_num().get_str();
                r.depthSquaredDen = q.get_den().get_str();
            }
        }
        else
        {
            ExactResult e;
            e.overlap = true;
            e.polygon = polygon();
            finishSigned(e, a_.radius, b_.radius, r);
            r.fallbacks.depth = true;
        }
    }

    // The closest edge of Z to O (inside or on Z), as penetration.cpp's deepest() chooses it: each
    // edge's squared line distance C^2 / L (C = P x Q, L = |Q - P|^2) enclosed from merge()'s
    // interval vertices; the least upper end m, and every edge whose enclosure starts at or below m
    // is a candidate; one candidate is the answer, several (near or exact ties) are compared
    // exactly (edgeExact: the least squared distance, then the least outward-normal angle), each
    // comparison counted in `exactCount`. Z a point (k = 1): 0.
    int closestEdge(int& exactCount)
    {
        const int k = static_cast<int>(za.size());
        if (k == 1)
            return 0;
        VertexArray<double> lo(k), hi(k);
        double least = HUGE_VAL;
        {
            I::Protector protect; // round upward for the intervals
            for (int e = 0; e < k; ++e)
            {
                const int g = e + 1 == k ? 0 : e + 1;
                const I dx = zx[g] - zx[e], dy = zy[g] - zy[e];
                const I C = zx[e] * zy[g] - zy[e] * zx[g];
                const I L = CGAL::square(dx) + CGAL::square(dy);
                if (L.inf() > 0)
                {
                    const I dd = CGAL::square(C) / L;
                    lo[e] = dd.inf();
                    hi[e] = dd.sup();
                }
                else
                { // an edge too short for its interval: a candidate, decided exactly
                    lo[e] = 0;
                    hi[e] = HUGE_VAL;
                }
                least = std::min(least, hi[e]);
            }
        }
        VertexArray<int> near;
        for (int e = 0; e < k; ++e)
            if (!(lo[e] > least)) // NaN ends too
                near.push_back(e);
        if (near.size() == 1)
            return near[0];
        int best = near[0];
        EdgeExact b = edgeExact(best);
        for (std::size_t t = 1; t < near.size(); ++t)
        {
            EdgeExact c = edgeExact(near[t]);
            ++exactCount;
            const int o = cmp(c.squared, b.squared);
            if (o < 0 || (o == 0 && angleLess(c, b)))
            {
                best = near[t];
                b = std::move(c);
            }
        }
        return best;
    }

    // Edge e of Z (vertex e to e + 1), exactly: its squared line distance from O and its outward
    // normal (D.y, -D.x) up to a positive power of two.
    struct EdgeExact
    {
        mpq_class squared;
        mpz_class nx, ny;
    };
    EdgeExact edgeExact(int e)
    {
        const int k = static_cast<int>(za.size());
        const E2 &P = z(e), &Q = z(e + 1 == k ? 0 : e + 1);
        const E2 D = sub(Q, P);
        const mpz_class px = at(P.x, P.e, D.e), py = at(P.y, P.e, D.e);
        const mpz_class qx = at(Q.x, Q.e, D.e), qy = at(Q.y, Q.e, D.e);
        const mpz_class C = px * qy - py * qx;
        return {toQ(C * C, D.x * D.x + D.y * D.y, 2 * D.e, true), D.y, -D.x};
    }

    // Outward normals (up to positive factors) by angle in [0, 2 pi), as penetration.cpp's.
    static int halfOf(const EdgeExact& n)
    {
        return (sgn(n.ny) > 0 || (sgn(n.ny) == 0 && sgn(n.nx) > 0)) ? 0 : 1;
    }
    static bool angleLess(const EdgeExact& n, const EdgeExact& m)
    {
        const int hn = halfOf(n), hm = halfOf(m);
        if (hn != hm)
            return hn < hm;
        return cmp(n.nx * m.ny, n.ny * m.nx) > 0;
    }

    // The whole of Z with its provenance, exactly (Options::penetration with overlapping cores).
    Polygon polygon()
    {
        Polygon p;
        const std::size_t k = za.size();
        p.z.reserve(k);
        p.a.reserve(k);
        p.b.reserve(k);
        for (std::size_t t = 0; t < k; ++t)
        {
            p.z.push_back(toQ(z(static_cast<int>(t))));
            p.a.push_back(toQ(A.exact(za[t])));
            p.b.push_back(toQ(B.exact(zb[t])));
        }
        return p;
    }

    // pointDistance(): a_ is the query point (one point, identity, no radius).
    double runPoint(bool& gmp)
    {
        const Feature f = locateFeature();
        const Point bs[2] = {b_.points[zb[f.i]], b_.points[zb[f.j]]};
        double d = 0;
        gmp = !filteredPointDistance(f, a_.points[0], b_, bs, d);
        return gmp ? finish(build(f), a_.radius, b_.radius, false).distance : d;
    }

    // ---- locate() interface: Z vertex k is A point za[k] minus B point zb[k].
    int orientO(int i, int j)
    {
        const int s = sign(zx[i] * zy[j] - zy[i] * zx[j]);
        if (s != kUnsure)
            return s;
        ++featureExact;
        return crossSignE(z(i), z(j));
    }
    int dotSign(int i, int j)
    {
        const int s = sign(zx[i] * (zx[j] - zx[i]) + zy[i] * (zy[j] - zy[i]));
        if (s != kUnsure)
            return -s;
        ++featureExact;
        const E2& p = z(i);
        return -dotSignE(p, sub(z(j), p));
    }
    bool isZero(int i)
    {
        const int sx = sign(zx[i]), sy = sign(zy[i]);
        if ((sx != 0 && sx != kUnsure) || (sy != 0 && sy != kUnsure))
            return false;
        if (sx == 0 && sy == 0)
            return true;
        ++featureExact;
        const E2& p = z(i);
        return sgn(p.x) == 0 && sgn(p.y) == 0;
    }

  private:
    const Shape& a_;
    const Shape& b_;
    const PreparedData* preparedA_ = nullptr;
    const PreparedData* preparedB_ = nullptr;
    Side A, B;
    int mergeExact = 0, featureExact = 0; // predicates the intervals left to exact integers

    Feature locateFeature()
    {
        I::Protector protect; // round upward for the interval filters; restored at the end of scope
        if (preparedA_ && preparedB_)
        { // the same intervals, hulls and hull counts as below, made by PreparedShape
            A.init(*preparedA_);
            B.init(*preparedB_);
            ha = &preparedA_->hull;
            hb = &preparedB_->hull;
        }
        else
        {
            A.init(a_);
            B.init(b_);
            ownHa = A.hull();
            ownHb = B.hull();
            ha = &ownHa;
            hb = &ownHb;
        }
        merge();
        return locate(static_cast<int>(za.size()), *this);
    }

    Fallbacks counts(Fallbacks f) const
    {
        f.hull = A.exactDecisions + B.exactDecisions;
        f.merge = mergeExact;
        f.feature = featureExact;
        return f;
    }

    // The exact squared distance of the located feature alone (what build() puts in `squared`).
    mpq_class squared(const Feature& f)
    {
        if (f.overlap)
            return 0;
        if (f.kind == Feature::Vertex)
        {
            const E2& p = z(f.i);
            return toQ(mpz_class(p.x * p.x + p.y * p.y), 2 * p.e);
        }
        const E2 &P = z(f.i), &Q = z(f.j);
        const E2 D = sub(Q, P);
        const mpz_class px = at(P.x, P.e, D.e), py = at(P.y, P.e, D.e);
        const mpz_class qx = at(Q.x, Q.e, D.e), qy = at(Q.y, Q.e, D.e);
        const mpz_class C = px * qy - py * qx;
        return toQ(C * C, D.x * D.x + D.y * D.y, 2 * D.e, true);
    }
    PointArray<int> ownHa, ownHb;        // the hulls made here, without prepared shapes
    const PointArray<int>* ha = nullptr; // A's hull: ownHa or the prepared one
    const PointArray<int>* hb = nullptr;
    VertexArray<int> za, zb; // per Z vertex: index of the A point and of the B point
    VertexArray<I> zx, zy;
    std::vector<E2> zex;
    std::vector<char> zhave;

    const E2& z(int k)
    {
        if (zex.empty())
        {
            zex.resize(za.size());
            zhave.assign(za.size(), 0);
        }
        if (!zhave[k])
        {
            zex[k] = sub(A.exact(za[k]), B.exact(zb[k]));
            zhave[k] = 1;
        }
        return zex[k];
    }

    // Compares the directions of edge vectors u = A[i2] - A[i1] and w = B[j1] - B[j2] (an edge of
    // -B) by angle in [pi, 3*pi): -1 if u comes first, 1 if w does, 0 if they point the same way.
    int cmpAngle(int i1, int i2, int j1, int j2)
    {
        const I ux = A.x[i2] - A.x[i1], uy = A.y[i2] - A.y[i1];
        const I wx = B.x[j1] - B.x[j2], wy = B.y[j1] - B.y[j2];
        int sux = sign(ux), suy = sign(uy), swx = sign(wx), swy = sign(wy);
        int sc = sign(ux * wy - uy * wx);
        if (sux == kUnsure || suy == kUnsure || swx == kUnsure || swy == kUnsure || sc == kUnsure)
        {
            ++mergeExact;
            const E2 u = sub(A.exact(i2), A.exact(i1));
            const E2 w = sub(B.exact(j1), B.exact(j2));
            sux = sgn(u.x);
            suy = sgn(u.y);
            swx = sgn(w.x);
            swy = sgn(w.y);
            sc = crossSignE(u, w);
        }
        const int hu = half(suy, sux), hw = half(swy, swx);
        if (hu != hw)
            return hu < hw ? -1 : 1;
        return -sc; // cross(u, w) > 0: u has the smaller angle
    }

    // Minkowski difference Z = hull(A) + hull(-B): both edge sequences start at their highest (then
    // rightmost) vertex, so edge angles increase through [pi, 3*pi) in each; merge them. Z's first
    // vertex is its highest-rightmost one, where locate()'s fan starts (docs/exact.md,
    // "Witnesses").
    void merge()
    {
        const PointArray<int>& ha = *this->ha;
        const PointArray<int>& hb = *this->hb;
        const int na = static_cast<int>(ha.size()), nb = static_cast<int>(hb.size());
        // Highest-rightmost vertex of -B is the lowest-leftmost vertex of B.
        int sa = 0, sb = 0;
        for (int t = 1; t < na; ++t)
            if (A.cmpYX(ha[t], ha[sa]) > 0)
                sa = t;
        for (int t = 1; t < nb; ++t)
            if (B.cmpYX(hb[t], hb[sb]) < 0)
                sb = t;
        const int ea = na >= 2 ? na : 0, eb = nb >= 2 ? nb : 0; // edge counts
        auto av = [&](int t) { return ha[(sa + t) % na]; };
        auto bv = [&](int t) { return hb[(sb + t) % nb]; };
        za.reserve(na + nb);
        zb.reserve(na + nb);
        int i = 0, j = 0;
        do
        {
            za.push_back(av(i));
            zb.push_back(bv(j));
            if (i == ea)
            {
                ++j;
            }
            else if (j == eb)
            {
                ++i;
            }
            else
            {
                const int c = cmpAngle(av(i), av(i + 1), bv(j), bv(j + 1));
                if (c <= 0)
                    ++i;
                if (c >= 0)
                    ++j;
            }
        } while (i < ea || j < eb);
        const std::size_t k = za.size();
        zx.resize(k);
        zy.resize(k);
        for (std::size_t t = 0; t < k; ++t)
        {
            zx[t] = A.x[za[t]] - B.x[zb[t]];
            zy[t] = A.y[za[t]] - B.y[zb[t]];
        }
    }

    // The one exact construction, in dyadic integers, for each kind of closest feature.
    ExactResult build(const Feature& f)
    {
        if (f.kind == Feature::Vertex)
            return buildAtVertex(f);
        if (f.kind == Feature::Edge)
            return buildOnEdge(f);
        return buildInTriangle(f);
    }

    ExactResult buildAtVertex(const Feature& f)
    {
        ExactResult r;
        r.overlap = f.overlap;
        const E2& p = z(f.i);
        r.z = toQ(p);
        mpz_class n = p.x * p.x + p.y * p.y;
        r.squared = toQ(n, 2 * p.e);
        r.wa = toQ(A.exact(za[f.i]));
        r.wb = toQ(B.exact(zb[f.i]));
        return r;
    }

    ExactResult buildOnEdge(const Feature& f)
    {
        ExactResult r;
        r.overlap = f.overlap;
        const E2 &P = z(f.i), &Q = z(f.j);
        const E2 D = sub(Q, P);
        const mpz_class px = at(P.x, P.e, D.e), py = at(P.y, P.e, D.e);
        const mpz_class qx = at(Q.x, Q.e, D.e), qy = at(Q.y, Q.e, D.e);
        const mpz_class L = D.x * D.x + D.y * D.y;
        const mpz_class C = px * qy - py * qx;
        const mpz_class T = -(px * D.x + py * D.y); // t = T / L, closest point P + t (Q - P)
        if (f.overlap)
        {
            r.squared = 0;
            r.z = {0, 0};
        }
        else
        {
            r.squared = toQ(C * C, L, 2 * D.e, true);
            r.z = {toQ(px * L + T * D.x, L, D.e), toQ(py * L + T * D.y, L, D.e)};
        }
        r.wa = along(A, za[f.i], za[f.j], T, L);
        r.wb = along(B, zb[f.i], zb[f.j], T, L);
        return r;
    }

    // Triangle (overlap): barycentric coordinates of O in (V0, V1, V2), with equal weights on
    // the A and B points: sum l_t (a_t - b_t) = O, so sum l_t a_t = sum l_t b_t is in both
    // hulls.
    ExactResult buildInTriangle(const Feature& f)
    {
        ExactResult r;
        r.overlap = f.overlap;
        const E2 &V0 = z(f.i), &V1 = z(f.j), &V2 = z(f.l);
        const long e = std::min({V0.e, V1.e, V2.e});
        E2 v[3];
        const E2* src[3] = {&V0, &V1, &V2};
        for (int t = 0; t < 3; ++t)
        {
            v[t].x = at(src[t]->x, src[t]->e, e);
            v[t].y = at(src[t]->y, src[t]->e, e);
        }
        mpz_class l[3];
        l[0] = v[1].x * v[2].y - v[1].y * v[2].x;
        l[1] = v[2].x * v[0].y - v[2].y * v[0].x;
        l[2] = v[0].x * v[1].y - v[0].y * v[1].x;
        const mpz_class den = l[0] + l[1] + l[2]; // twice the triangle's area, > 0
        const int ia[3] = {za[f.i], za[f.j], za[f.l]};
        long ea = LONG_MAX;
        for (int t = 0; t < 3; ++t)
            ea = std::min(ea, A.exact(ia[t]).e);
        mpz_class nx = 0, ny = 0;
        for (int t = 0; t < 3; ++t)
        {
            const E2& a = A.exact(ia[t]);
            nx += l[t] * at(a.x, a.e, ea);
            ny += l[t] * at(a.y, a.e, ea);
        }
        r.squared = 0;
        r.z = {0, 0};
        r.wa = {toQ(nx, den, ea), toQ(ny, den, ea)};
        r.wb = r.wa;
        return r;
    }

    // Point s[i1] + (T/L) (s[i2] - s[i1]) of a side, exactly.
    static QPoint along(Side& s, int i1, int i2, const mpz_class& T, const mpz_class& L)
    {
        const E2& p = s.exact(i1);
        if (i1 == i2)
            return toQ(p);
        const E2 d = sub(s.exact(i2), p);
        const mpz_class px = at(p.x, p.e, d.e), py = at(p.y, p.e, d.e);
        return {toQ(px * L + T * d.x, L, d.e), toQ(py * L + T * d.y, L, d.e)};
    }
};

} // namespace

namespace
{
// Side::init()'s intervals of a one-point identity shape {p}, built the same way (the same
// operations, so the same bits).
void pointIntervals(Point p, I& x, I& y)
{
    const I c(1.0), sn(0.0), px(0.0), py(0.0);
    const I px_(p.x), py_(p.y);
    x = c * px_ - sn * py_ + px;
    y = sn * px_ + c * py_ + py;
}

// Solver's locate() interface for Z = {p} - hull(B) from prepared data: the same interval
// predicates (Z vertex intervals p - w_k as merge() forms them), and the same exact fallbacks, on
// exact values made only when an interval leaves a sign undecided.
class PointLocator
{
  public:
    PointLocator(const PreparedData& d, Point p) : d_(d), p_(p) { pointIntervals(p, px_, py_); }

    I zx(int k) const { return px_ - d_.x[d_.z[k]]; }
    I zy(int k) const { return py_ - d_.y[d_.z[k]]; }

    // Where an interval leaves a sign undecided: the exact sign by expansions (zSignExact, in
    // round-to-nearest), then, where those refuse, GMP.
    int orientO(int i, int j)
    {
        const int s = sign(zx(i) * zy(j) - zy(i) * zx(j));
        if (s != kUnsure)
            return s;
        const int e = expansionSign(ZPredicate::Cross, i, j);
        return e != kZUnsure ? e : crossSignE(z(i), z(j));
    }
    int dotSign(int i, int j)
    {
        const I xi = zx(i), yi = zy(i);
        const int s = sign(xi * (zx(j) - xi) + yi * (zy(j) - yi));
        if (s != kUnsure)
            return -s;
        const int e = expansionSign(ZPredicate::Dot, i, j);
        if (e != kZUnsure)
            return -e;
        const E2& q = z(i);
        return -dotSignE(q, sub(z(j), q));
    }
    bool isZero(int i)
    {
        const int sx = sign(zx(i)), sy = sign(zy(i));
        if ((sx != 0 && sx != kUnsure) || (sy != 0 && sy != kUnsure))
            return false;
        if (sx == 0 && sy == 0)
            return true;
        const int e = expansionSign(ZPredicate::IsZero, i, i);
        if (e != kZUnsure)
            return e == 0;
        const E2& q = z(i);
        return sgn(q.x) == 0 && sgn(q.y) == 0;
    }

  private:
    // The exact Z vertices, allocated on the first undecided predicate only.
    struct Exact
    {
        DecShape dec; // the shape's transform (decShapeOf)
        E2 p;
        std::vector<E2> z;
        std::vector<char> have;
    };
    const PreparedData& d_;
    Point p_;
    I px_, py_;
    std::unique_ptr<Exact> exact_;

    int expansionSign(ZPredicate kind, int i, int j) const
    {
        CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST); // expansions need it
        const std::vector<Point>& b = d_.shape.points;
        return zSignExact(kind, p_, d_.shape, b[d_.z[i]], b[d_.z[j]]);
    }

    const E2& z(int k)
    {
        if (!exact_)
        {
            exact_ = std::make_unique<Exact>();
            exact_->dec = decShapeOf(d_.shape);
            const Dec one = decompose(1.0), zero = decompose(0.0);
            exact_->p = transformExact({one, zero, zero, zero}, p_);
            exact_->z.resize(d_.z.size());
            exact_->have.assign(d_.z.size(), 0);
        }
        if (!exact_->have[k])
        {
            exact_->z[k] = sub(exact_->p, transformExact(exact_->dec, d_.shape.points[d_.z[k]]));
            exact_->have[k] = 1;
        }
        return exact_->z[k];
    }
};
} // namespace

double preparedPointDistance(const PreparedData& d, Point p, bool& gmp)
{
    Feature f;
    {
        I::Protector protect; // round upward for the interval predicates only
        PointLocator loc(d, p);
        f = locate(static_cast<int>(d.z.size()), loc);
    }
    const Point bs[2] = {d.shape.points[d.z[f.i]], d.shape.points[d.z[f.j]]};
    double out = 0;
    if (filteredPointDistance(f, p, d.shape, bs, out))
    {
        gmp = false;
        return out;
    }
    // The GMP route, rare: Solver::runPoint() from the start (the same feature, the same undecided
    // filter, then the construction).
    Shape q;
    q.points = {p};
    return pointDistance(q, d.shape, gmp);
}

ExactResult edgeMerge(const Shape& a, const Shape& b, bool wantPolygon)
{
    return Solver(a, b).run(wantPolygon);
}

double pointDistance(const Shape& point, const Shape& shape, bool& gmp)
{
    return Solver(point, shape).runPoint(gmp);
}

Result edgeMergeResult(const Shape& a, const Shape& b, const Options& options)
{
    if (options.filter)
        return Solver(a, b).runFiltered(options);
    const ExactResult e = edgeMerge(a, b, options.penetration);
    Result r = finish(e, a.radius, b.radius, options.exactWitnesses);
    if (options.penetration)
        finishSigned(e, a.radius, b.radius, r);
    r.fallbacks.gmp = true;
    return r;
}

Result edgeMergeResult(const PreparedData& a, const PreparedData& b, const Options& options)
{
    Solver solver(a, b);
    if (options.filter)
        return solver.runFiltered(options);
    const ExactResult e = solver.run(options.penetration);
    Result r = finish(e, a.shape.radius, b.shape.radius, options.exactWitnesses);
    if (options.penetration)
        finishSigned(e, a.shape.radius, b.shape.radius, r);
    r.fallbacks.gmp = true;
    return r;
}

} // namespace exact::detail

namespace exact
{

PreparedShape::PreparedShape(const Shape& shape, const char* name)
    : PreparedShape(Shape(shape), name)
{
}

PreparedShape::PreparedShape(Shape&& shape, const char* name)
    : data_(std::make_unique<detail::PreparedData>())
{
    validateShape(shape, name);
    detail::PreparedData& d = *data_;
    d.shape = std::move(shape);
    detail::Side side;
    {
        detail::I::Protector protect; // as Solver::locateFeature()
        side.init(d.shape);
        detail::PointArray<int> h = side.hull();
        d.hull = h;
        d.hullExact = side.exactDecisions;
        // merge()'s start on B: the lowest (then leftmost) hull vertex, the first one found.
        const int n = static_cast<int>(h.size());
        int sb = 0;
        for (int t = 1; t < n; ++t)
            if (side.cmpYX(h[t], h[sb]) < 0)
                sb = t;
        std::rotate(h.begin(), h.begin() + sb, h.end());
        d.z = std::move(h);
    }
    d.x = std::move(side.ownX); // every point's intervals, read through z
    d.y = std::move(side.ownY);
}

PreparedShape::PreparedShape(PreparedShape&&) noexcept = default;
PreparedShape& PreparedShape::operator=(PreparedShape&&) noexcept = default;
PreparedShape::~PreparedShape() = default;

const Shape& PreparedShape::shape() const
{
    return data_->shape;
}

int PreparedShape::hullSize() const
{
    return static_cast<int>(data_->z.size());
}

} // namespace exact
