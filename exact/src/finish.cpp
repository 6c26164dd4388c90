// Correct rounding of the exact results to doubles (GMP + MPFR, no CGAL).
//
// Everything irrational here has the form  w + rho * zc / sqrt(q)  or  sqrt(q) - r  with rational
// w, zc, q and dyadic rho, r. Each is enclosed in an MPFR interval computed with directed rounding
// at increasing precision until both ends round to the same double (Ziv's strategy). That can only
// loop forever if the exact value is a midpoint between two doubles, which needs it to be rational:
// those cases (sqrt(q) rational, or rho*zc == 0) are computed as exact rationals instead.
#include "internal.hpp"

#include <mpfr.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace exact::detail
{
namespace
{

constexpr mpfr_prec_t kStartPrecision = 64;
constexpr mpfr_prec_t kMaxPrecision = mpfr_prec_t(1) << 24; // never reached in practice

struct Mp
{
    mpfr_t v;
    explicit Mp(mpfr_prec_t p) { mpfr_init2(v, p); }
    ~Mp() { mpfr_clear(v); }
    Mp(const Mp&) = delete;
    Mp& operator=(const Mp&) = delete;
};

// A closed interval [lo, hi] of MPFR numbers.
struct Iv
{
    Mp lo, hi;
    explicit Iv(mpfr_prec_t p) : lo(p), hi(p) {}
};

void setQ(Iv& r, const mpq_class& q)
{
    mpfr_set_q(r.lo.v, q.get_mpq_t(), MPFR_RNDD);
    mpfr_set_q(r.hi.v, q.get_mpq_t(), MPFR_RNDU);
}

// r = a / b with b > 0 (b.lo > 0).
void divPos(Iv& r, const Iv& a, const Iv& b)
{
    if (mpfr_sgn(a.lo.v) >= 0)
    {
        mpfr_div(r.lo.v, a.lo.v, b.hi.v, MPFR_RNDD);
        mpfr_div(r.hi.v, a.hi.v, b.lo.v, MPFR_RNDU);
    }
    else if (mpfr_sgn(a.hi.v) <= 0)
    {
        mpfr_div(r.lo.v, a.lo.v, b.lo.v, MPFR_RNDD);
        mpfr_div(r.hi.v, a.hi.v, b.hi.v, MPFR_RNDU);
    }
    else
    {
        mpfr_div(r.lo.v, a.lo.v, b.lo.v, MPFR_RNDD);
        mpfr_div(r.hi.v, a.hi.v, b.lo.v, MPFR_RNDU);
    }
}

// Rounded-to-nearest doubles of both ends; true when they agree (then `out` is the answer for
// every value in the interval, since rounding is monotonic).
bool agree(const Iv& v, double& out)
{
    const double a = mpfr_get_d(v.lo.v, MPFR_RNDN);
    const double b = mpfr_get_d(v.hi.v, MPFR_RNDN);
    if (a != b)
        return false;
    out = a == 0 ? 0.0 : a; // no -0
    return true;
}

bool sqrtIsRational(const mpq_class& q, mpq_class& root)
{
    if (!mpz_perfect_square_p(q.get_num_mpz_t()) || !mpz_perfect_square_p(q.get_den_mpz_t()))
        return false;
    mpz_class n, d;
    mpz_sqrt(n.get_mpz_t(), q.get_num_mpz_t());
    mpz_sqrt(d.get_mpz_t(), q.get_den_mpz_t());
    root = mpq_class(n, d);
    root.canonicalize();
    return true;
}

QPoint canonical(const QPoint& p)
{
    QPoint c = p;
    c.x.canonicalize();
    c.y.canonicalize();
    return c;
}

[[noreturn]] void precisionExhausted()
{
    throw std::logic_error(
        "exact: rounding did not converge (value is a midpoint between doubles?)");
}

// Enclosure of a rational by doubles (any valid one; tight to one ulp).
void encloseQ(const mpq_class& q, double& lower, double& upper)
{
    Iv v(kStartPrecision);
    setQ(v, q);
    lower = mpfr_get_d(v.lo.v, MPFR_RNDD);
    upper = mpfr_get_d(v.hi.v, MPFR_RNDU);
}

// Enclosures of sqrt(q), q > 0 and irrational sqrt, computed once per precision and shared by the
// distance and the four witness coordinates.
class SqrtEnclosure
{
  public:
    explicit SqrtEnclosure(const mpq_class& q) : q_(q) {}
    const Iv& at(mpfr_prec_t p)
    {
        if (!iv_ || prec_ != p)
        {
            iv_ = std::make_unique<Iv>(p);
            prec_ = p;
            setQ(*iv_, q_);
            mpfr_sqrt(iv_->lo.v, iv_->lo.v, MPFR_RNDD);
            mpfr_sqrt(iv_->hi.v, iv_->hi.v, MPFR_RNDU);
        }
        return *iv_;
    }

  private:
    const mpq_class& q_;
    std::unique_ptr<Iv> iv_;
    mpfr_prec_t prec_ = 0;
};

// Correctly rounded w + rho * zc / sqrt(q); q > 0. `root` is sqrt(q) when rational (then exact).
double roundShifted(const mpq_class& w, double rho, const mpq_class& zc, const mpq_class* root,
                    SqrtEnclosure& sq)
{
    if (rho == 0 || sgn(zc) == 0)
        return roundToDouble(w);
    if (root)
        return roundToDouble(w + mpq_class(rho) * zc / *root);
    for (mpfr_prec_t p = kStartPrecision; p <= kMaxPrecision; p *= 2)
    {
        const Iv& s = sq.at(p);
        Iv t(p), zi(p);
        setQ(zi, zc);
        divPos(t, zi, s);
        Iv& v = zi; // reuse
        if (rho > 0)
        {
            mpfr_mul_d(v.lo.v, t.lo.v, rho, MPFR_RNDD);
            mpfr_mul_d(v.hi.v, t.hi.v, rho, MPFR_RNDU);
        }
        else
        {
            mpfr_mul_d(v.lo.v, t.hi.v, rho, MPFR_RNDD);
            mpfr_mul_d(v.hi.v, t.lo.v, rho, MPFR_RNDU);
        }
        setQ(t, w);
        mpfr_add(v.lo.v, v.lo.v, t.lo.v, MPFR_RNDD);
        mpfr_add(v.hi.v, v.hi.v, t.hi.v, MPFR_RNDU);
        double out;
        if (agree(v, out))
            return out;
    }
    precisionExhausted();
}

// Correctly rounded max(0, sqrt(q) - rA - rB) and an enclosure.
void roundDistanceImpl(const mpq_class& q, double rA, double rB, const mpq_class* root,
                       SqrtEnclosure* shared, double& value, double& lower, double& upper)
{
    value = lower = upper = 0;
    if (sgn(q) <= 0)
        return;
    if (rA != 0 || rB != 0)
    {
        const mpq_class r = mpq_class(rA) + mpq_class(rB); // mpq from double is exact
        if (cmp(q, r * r) <= 0)
            return; // sqrt(q) <= r exactly: clamped to 0
    }
    if (root)
    {
        const mpq_class v = *root - mpq_class(rA) - mpq_class(rB);
        value = roundToDouble(v);
        encloseQ(v, lower, upper);
        if (lower < 0)
            lower = 0;
        return;
    }
    // sqrt(q) - rA - rB is irrational and > 0 here.
    SqrtEnclosure local(q);
    SqrtEnclosure& sq = shared ? *shared : local;
    for (mpfr_prec_t p = kStartPrecision; p <= kMaxPrecision; p *= 2)
    {
        const Iv& s = sq.at(p);
        Iv v(p);
        mpfr_sub_d(v.lo.v, s.lo.v, rA, MPFR_RNDD);
        mpfr_sub_d(v.lo.v, v.lo.v, rB, MPFR_RNDD);
        mpfr_sub_d(v.hi.v, s.hi.v, rA, MPFR_RNDU);
        mpfr_sub_d(v.hi.v, v.hi.v, rB, MPFR_RNDU);
        double out;
        if (agree(v, out))
        {
            // The value is irrational, so the tight enclosure is two adjacent doubles: go on
            // until the interval says which two (the filter, filter.cpp, gives the same ones).
            lower = mpfr_get_d(v.lo.v, MPFR_RNDD);
            upper = mpfr_get_d(v.hi.v, MPFR_RNDU);
            if (std::isfinite(upper) && upper != std::nextafter(lower, HUGE_VAL))
                continue;
            value = out;
            if (lower < 0)
                lower = 0;
            return;
        }
    }
    precisionExhausted();
}

// Correctly rounded sigma sqrt(q) - rA - rB (sigma = +1 or -1, q >= 0), unclamped, with its tight
// enclosure: the signed distance (Options::penetration). The same scheme as roundDistanceImpl():
// an exact rational when sqrt(q) is one (the only way the value can be a double or a midpoint),
// else an MPFR interval refined until both ends round alike and the enclosing doubles are adjacent.
void roundSignedImpl(const mpq_class& q, int sigma, double rA, double rB, double& value,
                     double& lower, double& upper)
{
    mpq_class root;
    if (sgn(q) == 0 || sqrtIsRational(q, root))
    {
        if (sgn(q) == 0)
            root = 0;
        const mpq_class v = (sigma > 0 ? root : mpq_class(-root)) - mpq_class(rA) - mpq_class(rB);
        value = roundToDouble(v);
        encloseQ(v, lower, upper);
        return;
    }
    SqrtEnclosure sq(q);
    for (mpfr_prec_t p = kStartPrecision; p <= kMaxPrecision; p *= 2)
    {
        const Iv& s = sq.at(p);
        Iv v(p);
        if (sigma > 0)
        {
            mpfr_set(v.lo.v, s.lo.v, MPFR_RNDD);
            mpfr_set(v.hi.v, s.hi.v, MPFR_RNDU);
        }
        else
        {
            mpfr_neg(v.lo.v, s.hi.v, MPFR_RNDD);
            mpfr_neg(v.hi.v, s.lo.v, MPFR_RNDU);
        }
        mpfr_sub_d(v.lo.v, v.lo.v, rA, MPFR_RNDD);
        mpfr_sub_d(v.lo.v, v.lo.v, rB, MPFR_RNDD);
        mpfr_sub_d(v.hi.v, v.hi.v, rA, MPFR_RNDU);
        mpfr_sub_d(v.hi.v, v.hi.v, rB, MPFR_RNDU);
        double out;
        if (!agree(v, out))
            continue;
        lower = mpfr_get_d(v.lo.v, MPFR_RNDD);
        upper = mpfr_get_d(v.hi.v, MPFR_RNDU);
        // Irrational, so strictly between two adjacent doubles (or beyond +-DBL_MAX, then one end
        // is infinite): refine until the interval says which two.
        if (std::isfinite(upper) && std::isfinite(lower) &&
            upper != std::nextafter(lower, HUGE_VAL))
            continue;
        value = out;
        return;
    }
    precisionExhausted();
}

} // namespace

void roundSigned(const mpq_class& q, int sigma, double rA, double rB, double& value, double& lower,
                 double& upper)
{
    roundSignedImpl(q, sigma, rA, rB, value, lower, upper);
}

void roundPair(const QPoint& a, const QPoint& b, const QPoint& n, double rA, double rB, Point& pA,
               Point& pB)
{
    const QPoint ac = canonical(a), bc = canonical(b), nc = canonical(n);
    const mpq_class q = nc.x * nc.x + nc.y * nc.y; // > 0
    mpq_class root;
    const mpq_class* rootp = sqrtIsRational(q, root) ? &root : nullptr;
    SqrtEnclosure sq(q);
    pA = {roundShifted(ac.x, rA, nc.x, rootp, sq), roundShifted(ac.y, rA, nc.y, rootp, sq)};
    pB = {roundShifted(bc.x, -rB, nc.x, rootp, sq), roundShifted(bc.y, -rB, nc.y, rootp, sq)};
}

double roundToDouble(const mpq_class& q)
{
    if (sgn(q) == 0)
        return 0.0;
    {
        // One correctly rounded conversion at 53 bits (MPFR's exponent range is far wider than a
        // double's): when the result is a normal double, it is the answer.
        Mp v(53);
        mpfr_set_q(v.v, q.get_mpq_t(), MPFR_RNDN);
        const mpfr_exp_t e = mpfr_get_exp(v.v); // v = m * 2^e with m in [1/2, 1)
        if (e >= -1021 && e <= 1024)
            return mpfr_get_d(v.v, MPFR_RNDN);
    }
    // Subnormal or overflowing: enclose and round both ends with mpfr_get_d, which rounds
    // correctly into the subnormal range and to infinity.
    for (mpfr_prec_t p = kStartPrecision; p <= kMaxPrecision; p *= 2)
    {
        Iv v(p);
        // An exact conversion leaves lo == hi; otherwise lo < q < hi and q is not a midpoint
        // (midpoints have 54 significant bits), so a large enough p separates them.
        setQ(v, q);
        double out;
        if (agree(v, out))
            return out;
    }
    precisionExhausted();
}

void roundDistance(const mpq_class& q, double rA, double rB, double& value, double& lower,
                   double& upper)
{
    mpq_class root;
    const bool rational = sgn(q) > 0 && sqrtIsRational(q, root);
    roundDistanceImpl(q, rA, rB, rational ? &root : nullptr, nullptr, value, lower, upper);
}

std::string toString(const mpq_class& q)
{
    if (q.get_den() == 1)
        return q.get_num().get_str();
    return q.get_num().get_str() + "/" + q.get_den().get_str();
}

// mpfr_set_q only divides numerator by denominator, so the unreduced coordinates of ExactResult
// round correctly as they are; mpq arithmetic and strings get reduced copies.
Result finish(const ExactResult& e, double rA, double rB, bool exactWitnesses)
{
    Result r;
    r.overlap = e.overlap;
    r.squaredNum = e.squared.get_num().get_str();
    r.squaredDen = e.squared.get_den().get_str();
    r.squared = roundToDouble(e.squared);
    if (sgn(e.squared) == 0)
    {
        r.witnessA = {roundToDouble(e.wa.x), roundToDouble(e.wa.y)};
        r.witnessB = {roundToDouble(e.wb.x), roundToDouble(e.wb.y)};
    }
    else
    {
        mpq_class root;
        const mpq_class* rootp = sqrtIsRational(e.squared, root) ? &root : nullptr;
        SqrtEnclosure sq(e.squared);
        roundDistanceImpl(e.squared, rA, rB, rootp, &sq, r.distance, r.lower, r.upper);
        // z = wa - wb points from B's point to A's: A's point moves by rA along -z/|z| (toward B),
        // B's by rB along z/|z| (toward A).
        if (rootp)
        { // exact rational path: needs reduced fractions
            const QPoint wa = canonical(e.wa), wb = canonical(e.wb), z = canonical(e.z);
            r.witnessA = {roundShifted(wa.x, -rA, z.x, rootp, sq),
                          roundShifted(wa.y, -rA, z.y, rootp, sq)};
            r.witnessB = {roundShifted(wb.x, rB, z.x, rootp, sq),
                          roundShifted(wb.y, rB, z.y, rootp, sq)};
        }
        else
        {
            r.witnessA = {roundShifted(e.wa.x, -rA, e.z.x, rootp, sq),
                          roundShifted(e.wa.y, -rA, e.z.y, rootp, sq)};
            r.witnessB = {roundShifted(e.wb.x, rB, e.z.x, rootp, sq),
                          roundShifted(e.wb.y, rB, e.z.y, rootp, sq)};
        }
    }
    if (exactWitnesses)
    {
        r.hasExactWitnesses = true;
        const QPoint wa = canonical(e.wa), wb = canonical(e.wb);
        r.exactWitnessA = {toString(wa.x), toString(wa.y)};
        r.exactWitnessB = {toString(wb.x), toString(wb.y)};
    }
    return r;
}

} // namespace exact::detail
