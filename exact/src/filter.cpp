// The filter of route EdgeMerge (docs/exact.md, "The filter"): the rounded outputs of finish()
// for a located closest feature, computed in double-double arithmetic with a rigorous bound on the
// absolute error of every quantity. A rounding is accepted only when the whole error interval lies
// strictly inside one double's rounding interval; then it is the correctly rounded value, the one
// finish() computes with GMP and MPFR. Otherwise the caller takes the GMP route.
//
// Runs in round-to-nearest (the caller's interval filters have restored it). Every V below holds
// an approximation h + l (h = RN(h + l), so |l| <= 2^-53 |h|) and a bound e >= |exact - (h + l)|.
// Overflow makes some h, l or e infinite or NaN, which every decision below refuses.
#include "expansion.hpp"
#include "internal.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

namespace exact::detail
{
namespace
{

constexpr double kU = 0x1p-53; // unit roundoff of round-to-nearest
// Relative error of one double-double operation's own rounding (at most 5 u^2 = 5 * 2^-106 for
// add and mul below, derivations beside them): 2^-98 is a margin of 50.
constexpr double kRel = 0x1p-98;
// What underflow can lose in one multiplication: a few 2^-1074 (a product's rounding and its fma
// error term); 2^-1000 is far above that and far below any value we round (see roundTo).
constexpr double kEta = 0x1p-1000;
// Each error bound is a short sum of nonnegative terms computed in round-to-nearest, so it is at
// most a few u below its exact value: inflating by 2^-20 covers that.
constexpr double kUp = 1 + 0x1p-20;

struct V
{
    double h = 0, l = 0, e = 0;
};

void twoSum(double a, double b, double& s, double& t) // s + t == a + b exactly (Knuth)
{
    s = a + b;
    const double bb = s - a;
    t = (a - (s - bb)) + (b - bb);
}

// Shewchuk's Grow-Expansion: x added to the expansion g[0..m) (nonoverlapping components of
// increasing magnitude, zeros anywhere among them), exactly.
void grow(double* g, int& m, double x)
{
    for (int j = 0; j < m; ++j)
    {
        double sum, err;
        twoSum(g[j], x, sum, err);
        g[j] = err;
        x = sum;
    }
    g[m++] = x;
}

// The exact sum of t[0..n) (n <= 8) as h + l, when it fits in two doubles: Shewchuk's
// GROW-EXPANSION (twoSum is exact, so the components' sum is the sum) leaves nonoverlapping
// components; at most two nonzero ones are added by twoSum, exactly. More: false (not decided
// here).
bool exactSum(const double* t, int n, double& h, double& l)
{
    double q[8];
    int m = 0;
    for (int i = 0; i < n; ++i)
        grow(q, m, t[i]);
    double big = 0, small = 0;
    int nonzero = 0;
    for (int j = 0; j < m; ++j)
        if (q[j] != 0)
        {
            small = big;
            big = q[j];
            ++nonzero;
        }
    if (nonzero > 2 || !std::isfinite(big))
        return false;
    twoSum(big, small, h, l);
    return true;
}

V exactly(double a)
{
    return {a, 0, 0};
}

bool isExact(const V& v)
{
    return v.l == 0 && v.e == 0;
}

double mag(const V& v) // >= |h + l|
{
    return std::fabs(v.h) * (1 + 0x1p-50);
}

V neg(const V& v)
{
    return {-v.h, -v.l, v.e};
}

// x + y: twoSum of the leading parts, the trailing parts added in (two roundings, each at most
// u (u |x.h| + u |y.h| + |twoSum error|) <= 3 u^2 (|x.h| + |y.h|)), renormalised exactly. Additions
// are exact under underflow, so no kEta.
V add(const V& x, const V& y)
{
    V r;
    double s, t;
    twoSum(x.h, y.h, s, t);
    if (x.e == 0 && y.e == 0)
    { // Exact inputs: keep the sum exact when it fits in two doubles (a transformed point of
      // float input does; values that are exactly doubles then round without a fallback).
        const double terms[4] = {x.h, x.l, y.h, y.l};
        if (exactSum(terms, 4, r.h, r.l))
            return r;
    }
    t += x.l + y.l;
    twoSum(s, t, r.h, r.l);
    r.e = ((x.e + y.e) + kRel * (std::fabs(x.h) + std::fabs(y.h))) * kUp;
    return r;
}

V sub(const V& x, const V& y)
{
    return add(x, neg(y));
}

// x * y: p + t = x.h * y.h exactly by fma (unless underflow), the cross terms x.h*y.l + x.l*y.h
// added with three roundings and x.l*y.l (<= u^2 |x.h y.h|) dropped: at most 5 u^2 |x.h y.h|.
// The inputs' errors propagate as |X| e_y + |Y| e_x + e_x e_y.
V mul(const V& x, const V& y)
{
    V r;
    if ((x.h == 0 && isExact(x)) || (y.h == 0 && isExact(y)))
        return r; // an exact zero factor (an edge of the other shape in along())
    const double p = x.h * y.h;
    double t = std::fma(x.h, y.h, -p);
    if (isExact(x) && isExact(y) && (p == 0 || std::fabs(p) >= 0x1p-960))
    { // p + t == x.h * y.h exactly: no underflow (|p| >= 2^-960 leaves t representable)
        twoSum(p, t, r.h, r.l);
        if (p == 0 && x.h != 0 && y.h != 0)
            r.e = kEta; // the product underflowed to zero
        return r;
    }
    if (x.e == 0 && y.e == 0)
    { // Exact inputs: the four partial products exactly (fma), their sum when it fits in two
      // doubles and no partial product can have underflowed (each nonzero one >= 2^-960).
        double terms[8];
        const double a[2] = {x.h, x.l}, b[2] = {y.h, y.l};
        bool fine = true;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
            {
                const double pp = a[i] * b[j];
                fine = fine && (pp == 0 ? a[i] == 0 || b[j] == 0 : std::fabs(pp) >= 0x1p-960);
                terms[4 * i + 2 * j] = pp;
                terms[4 * i + 2 * j + 1] = std::fma(a[i], b[j], -pp);
            }
        if (fine && exactSum(terms, 8, r.h, r.l))
            return r;
    }
    t += x.h * y.l + x.l * y.h;
    twoSum(p, t, r.h, r.l);
    r.e = (kRel * std::fabs(p) + mag(x) * y.e + mag(y) * x.e + x.e * y.e + kEta) * kUp;
    return r;
}

// x / y for y > 0 certainly (else NaN error, refused later). q1 = RN(X/Y); the residual
// R = X - q1 Y in double-double (error r.e); q2 = RN(r.h / y.h). X/Y - (q1 + q2) = (R - q2 Y)/Y,
// and |R - q2 Y| <= r.e + |r.l| + u |r.h| + |q2| |y.l| + ... <= r.e + 3 u |r.h| (1 + u), so the
// division's own error is at most (r.e + 4 u |r.h|) / |Y|. The inputs' errors propagate as
// (e_x + |X/Y| e_y) / (|Y| - e_y).
V div(const V& x, const V& y)
{
    const double ylow = y.h * (1 - 0x1p-50) - y.e; // < |Y| and < |y*|
    if (!(y.h > 0 && ylow > 0))
        return {0, 0, NAN};
    const V xh{x.h, x.l, 0}, yh{y.h, y.l, 0};
    const double q1 = x.h / y.h;
    const V r = sub(xh, mul(exactly(q1), yh));
    if (x.e == 0 && y.e == 0 && isExact(r) && r.h == 0)
        return exactly(q1); // x = q1 y exactly (an axis-aligned unit direction, t = 1/2)
    const double q2 = r.h / y.h;
    V out;
    twoSum(q1, q2, out.h, out.l);
    const double own = (r.e + 4 * kU * std::fabs(r.h) + kEta) / ylow;
    const double prop = (x.e + mag(out) * y.e) / ylow;
    out.e = (own + prop + kEta) * kUp;
    return out;
}

// sqrt(x) for x > 0 certainly. s1 = RN(sqrt(x.h)), |sqrt(X) - s1| = |d| <= 2 u s1; R = X - s1^2
// = d (2 s1 + d) in double-double; s2 = RN(r.h / (2 s1)). sqrt(X) - s1 - s2 = R/(2 s1 + d) - s2,
// |R/(2 s1 + d) - R/(2 s1)| <= |R| u / (s1 (1 - u)) and |R/(2 s1) - s2| <= (r.e + |r.l|) / (2 s1)
// + u |s2|. The input's error propagates as e_x / sqrt(X - e_x).
V sqrtV(const V& x)
{
    const double low = x.h * (1 - 0x1p-50) - x.e;
    if (!(x.h > 0 && low > 0))
        return {0, 0, NAN};
    const double s1 = std::sqrt(x.h);
    const V r = sub(V{x.h, x.l, 0}, mul(exactly(s1), exactly(s1)));
    if (x.e == 0 && isExact(r) && r.h == 0)
        return exactly(s1); // x = s1^2 exactly: a rational square root (axis-aligned distances)
    const double s2 = r.h / (2 * s1);
    V out;
    twoSum(s1, s2, out.h, out.l);
    const double R = std::fabs(r.h) * (1 + 0x1p-50) + r.e;
    const double own =
        (r.e + 2 * kU * std::fabs(r.h)) / (2 * s1) + kU * std::fabs(s2) + 1.01 * kU * R / s1;
    const double prop = x.e / (std::sqrt(low) * (1 - 0x1p-50));
    out.e = (own + prop + kEta) * kUp;
    return out;
}

// The correctly rounded (to nearest) double of the exact value, when the bound decides it: the
// value lies in [h + l - e, h + l + e], which must sit strictly inside the rounding interval of
// h, (h - gap below / 2, h + gap above / 2). Values below 2^-1000 or above 2^1000 are refused
// (subnormal results and overflow are the GMP route's). `side` returns the sign of exact - h
// (0: exactly h), or 2 when undecided.
bool roundTo(const V& v, double& out, int* side = nullptr)
{
    double h, l;
    twoSum(v.h, v.l, h, l);
    if (!std::isfinite(h) || !std::isfinite(l) || !std::isfinite(v.e))
        return false;
    if (v.e == 0 && l == 0)
    { // exactly the double h (zero and subnormals included)
        out = h == 0 ? 0.0 : h;
        if (side)
            *side = 0;
        return true;
    }
    const double a = std::fabs(h);
    if (!(a >= 0x1p-1000 && a <= 0x1p1000))
        return false;
    if (v.e == 0)
    { // exactly h + l, and h = RN(h + l) by twoSum, ties to even as MPFR's MPFR_RNDN
        out = h;
        if (side)
            *side = l > 0 ? 1 : l < 0 ? -1 : 0;
        return true;
    }
    // The gaps to h's neighbours, std::nextafter's without its calls (fewer instructions): |h| is
    // a normal double here, so its neighbours are its bit patterns +- 1.
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(a);
    const double away = std::bit_cast<double>(bits + 1) - a,
                 toward = a - std::bit_cast<double>(bits - 1);
    const double up = h > 0 ? away : toward, down = h > 0 ? toward : away;
    const double slack = 0x1p-50 * (std::fabs(l) + v.e); // covers the roundings of l +- e
    if (!(l + v.e + slack < up / 2 && l - v.e - slack > -down / 2))
        return false;
    out = h;
    if (side)
        *side = l - v.e - slack > 0 ? 1 : l + v.e + slack < 0 ? -1 : 2;
    return true;
}

struct P2
{
    V x, y;
};

P2 sub(const P2& a, const P2& b)
{
    return {sub(a.x, b.x), sub(a.y, b.y)};
}

// x' = c*x - s*y + px, y' = s*x + c*y + py of one input point, through the V operations: the
// general route, for products that may underflow.
P2 transformByOperations(const Shape& t, const Point& p)
{
    const V c = exactly(t.c), s = exactly(t.s), x = exactly(p.x), y = exactly(p.y);
    return {add(sub(mul(c, x), mul(s, y)), exactly(t.px)),
            add(add(mul(s, x), mul(c, y)), exactly(t.py))};
}

// The value of the expansion g[0..m) (m <= 5) as a V. At most two nonzero components: h + l
// exactly, e = 0 (exactSum()'s test). Else h + l = big + RN(small + rest) by twoSum, for the two
// largest nonzero components big and small and rest = RN(sum of the others) (at most three, so
// two roundings): the error is at most u |w| for w = RN(small + rest), plus 2 u (1 + u) times the
// others' magnitudes, so e = u (|w| + 3 sum|others|), inflated by kUp for its own rounding. That is
// about u^2 |value|. False when the value is not finite.
bool valueOf(const double* g, int m, V& out)
{
    double big = 0, small = 0, third = 0, rest = 0, restAbs = 0;
    int nonzero = 0;
    for (int j = 0; j < m; ++j)
        if (g[j] != 0)
        {
            rest += third;
            restAbs += std::fabs(third);
            third = small;
            small = big;
            big = g[j];
            ++nonzero;
        }
    if (!std::isfinite(big))
        return false;
    if (nonzero <= 2)
    {
        twoSum(big, small, out.h, out.l);
        out.e = 0;
        return true;
    }
    rest += third;
    restAbs += std::fabs(third);
    const double w = small + rest;
    twoSum(big, w, out.h, out.l);
    out.e = kU * (std::fabs(w) + 3 * restAbs) * kUp;
    return true;
}

// a*b + c*d + e for doubles, in the steps transformByOperations() takes, so exactly where it is
// exact: the products split exactly by fma (a*b = p + t when the product cannot have underflowed:
// p == 0 with a zero factor, or |p| >= 2^-960, mul()'s test), their four parts summed as one
// expansion; when that fits in two doubles (add()'s exact route), renormalised and e added as a
// second expansion, else e added to the first. Where the sum is not exact its bound is about u^2
// of it, inside the 2^-98 relative bound of the operations this replaces, in fewer instructions.
// False when a product may have underflowed
// or a value is not finite: the caller takes transformByOperations().
bool productSum(double a, double b, double c, double d, double e, V& out)
{
    const double p1 = a * b, p2 = c * d;
    const auto fine = [](double p, double x, double y)
    { return p == 0 ? x == 0 || y == 0 : std::fabs(p) >= 0x1p-960; };
    if (!fine(p1, a, b) || !fine(p2, c, d))
        return false;
    // A pair (x, y) with x = RN(x + y) is already the expansion that growing x by y would give
    // (twoSum(x, y) returns it unchanged; a zero's sign aside, which valueOf() ignores): the fma
    // product (p1, t1), and below the renormalised (h, l).
    double g[5] = {std::fma(a, b, -p1), p1};
    int m = 2;
    grow(g, m, p2);
    grow(g, m, std::fma(c, d, -p2));
    V products;
    if (!valueOf(g, m, products))
        return false;
    if (products.e == 0)
    { // add()'s exactSum({h, l, e, 0}): the zero's pass renormalises, as there
        g[0] = products.l;
        g[1] = products.h;
        m = 2;
        grow(g, m, e);
        grow(g, m, 0);
    }
    else
        grow(g, m, e);
    return valueOf(g, m, out);
}

P2 transform(const Shape& t, const Point& p)
{
    P2 r;
    if (productSum(t.c, p.x, -t.s, p.y, t.px, r.x) && productSum(t.s, p.x, t.c, p.y, t.py, r.y))
        return r;
    return transformByOperations(t, p);
}

V cross(const P2& a, const P2& b)
{
    return sub(mul(a.x, b.y), mul(a.y, b.x));
}
V dot(const P2& a, const P2& b)
{
    return add(mul(a.x, b.x), mul(a.y, b.y));
}

// a + t (b - a)
P2 along(const P2& a, const P2& b, const V& t)
{
    const P2 d = sub(b, a);
    return {add(a.x, mul(t, d.x)), add(a.y, mul(t, d.y))};
}

// What finish() rounds, in double-double: the hull points wa, wb, z = wa - wb, q = |z|^2 and
// s = sqrt(q) (separated only).
struct Construction
{
    P2 wa, wb, z;
    V q, s;
};

Construction construct(const Feature& f, const P2* a, const P2* b)
{
    Construction c;
    if (f.kind == Feature::Vertex)
    {
        c.wa = a[0];
        c.wb = b[0];
        c.z = sub(a[0], b[0]);
        c.q = dot(c.z, c.z);
        if (!f.overlap)
            c.s = sqrtV(c.q);
        return c;
    }
    const P2 zs[3] = {sub(a[0], b[0]), sub(a[1], b[1]),
                      f.kind == Feature::Triangle ? sub(a[2], b[2]) : P2{}};
    if (f.kind == Feature::Edge)
    {
        const P2 d = sub(zs[1], zs[0]);
        const V L = dot(d, d);
        const V t = div(neg(dot(zs[0], d)), L);
        c.wa = along(a[0], a[1], t);
        c.wb = along(b[0], b[1], t);
        if (!f.overlap)
        {
            c.z = along(zs[0], zs[1], t);
            // C = P x Q = P x (Q - P): the same value, and exact more often (an axis-aligned
            // edge). sqrt(q) = |C| / sqrt(L): exact when L is a square and C / sqrt(L) a double
            // (a vertex at a double's distance from an axis-aligned edge: the engine families).
            const V C = cross(zs[0], d);
            c.q = div(mul(C, C), L);
            c.s = std::fabs(C.h) * (1 - 0x1p-50) > C.e ? div(C.h < 0 ? neg(C) : C, sqrtV(L))
                                                       : sqrtV(c.q);
        }
        return c;
    }
    const V l[3] = {cross(zs[1], zs[2]), cross(zs[2], zs[0]), cross(zs[0], zs[1])};
    const V den = add(add(l[0], l[1]), l[2]);
    V nx, ny;
    for (int t = 0; t < 3; ++t)
    {
        nx = add(nx, mul(l[t], a[t].x));
        ny = add(ny, mul(l[t], a[t].y));
    }
    c.wa = {div(nx, den), div(ny, den)};
    c.wb = c.wa;
    return c;
}

// Correctly rounded w + rho * z / s (rho a radius with its sign).
bool roundShifted(const V& w, double rho, const V& zc, const V& s, double& out)
{
    if (rho == 0)
        return roundTo(w, out);
    return roundTo(add(w, mul(exactly(rho), div(zc, s))), out);
}

// Correctly rounded value of v with its tight enclosure (finish.cpp's roundSigned()): roundTo()
// and the side of the exact value, which must be known (a double's neighbour, or the double).
bool roundEnclosed(const V& v, double& value, double& lower, double& upper)
{
    int side = 2;
    if (!roundTo(v, value, &side) || side == 2)
        return false;
    lower = side < 0 ? std::nextafter(value, -HUGE_VAL) : value;
    upper = side > 0 ? std::nextafter(value, HUGE_VAL) : value;
    return true;
}

// Correctly rounded max(0, sqrt(q) - rA - rB) with its tight enclosure (finish.cpp). With
// `signedOut` (Options::penetration), also sqrt(q) - rA - rB unclamped, when decided (else
// `signedOut->hasSigned` stays false: the caller's GMP rounds it).
bool roundDistance(const V& s, double rA, double rB, Result& r, Result* signedOut = nullptr)
{
    const V d = sub(s, add(exactly(rA), exactly(rB)));
    if (signedOut)
        signedOut->hasSigned = roundEnclosed(d, signedOut->signedDistance, signedOut->signedLower,
                                             signedOut->signedUpper);
    double h, l;
    twoSum(d.h, d.l, h, l);
    const bool exactNonPositive = d.e == 0 && (h < 0 || (h == 0 && l <= 0));
    if (exactNonPositive || (h < 0 && (std::fabs(l) + d.e) * kUp < -h * (1 - 0x1p-50)))
    { // sqrt(q) <= rA + rB: clamped
        r.distance = r.lower = r.upper = 0;
        return true;
    }
    int side = 2;
    if (!roundTo(d, r.distance, &side) || r.distance <= 0 || side == 2)
        return false;
    r.lower = side < 0 ? std::nextafter(r.distance, -HUGE_VAL) : r.distance;
    r.upper = side > 0 ? std::nextafter(r.distance, HUGE_VAL) : r.distance;
    return true;
}

// ---------------------------------------------------------------- point to shape
//
// filteredPointDistance (docs/exact.md, "Point to shape"): max(0, dist(p, hull(B)) - r) for a
// query point p, what exact::pointToShapeDistance measures for the runner's witness checks. A
// witness point lies about u R from its shape (R the coordinates' magnitude), so its distance is
// about u R: filteredFinish()'s double-double world points, each within about 2^-98 R (absolute),
// leave that difference a relative error of about 2^-45, far from enough to round it correctly.
// Here nothing is rounded until the value is formed:
//  1. the coordinate differences z = p - w_i (six doubles a coordinate: p, the translation, two
//     TwoProducts), the edge vector d = w_i - w_j (four TwoProducts), the cross product C = z x d,
//     the squared lengths q = |z|^2 and L = |d|^2, and with a radius the numerators q - r^2 and
//     C^2 - r^2 L are exact expansions (expansion.hpp);
//  2. toV() turns each into a V within a relative few 2^-100 (its bound e derived there);
//  3. the few V operations after that (sqrtV, add, mul, div: own errors at most a relative 2^-98
//     each, plus the propagated bounds of their inputs, derived above, with no cancellation left:
//     every operand is positive) leave the value within a relative 2^-95 or so; roundTo() accepts
//     the rounding only when the whole interval lies inside one double's rounding interval, so a
//     value within that of a midpoint goes to GMP (about 1 value in 2^42);
//  4. the clamp max(0, .) is the exact sign of the numerator, and a distance that is a single
//     coordinate difference (axis-aligned) stays exact to the end (axisDistance).
// The result is then the correctly rounded value of the same exact real that finish() rounds with
// MPFR (sqrt of the located feature's squared distance, minus 0 and r): the GMP route's bit for
// bit. Refused (false: the GMP route): a product that could lose bits to underflow, overflow
// (expansion.hpp), inputs that scaling to [1/2, 1) would cut, a scaled result outside roundTo()'s
// [2^-1000, 2^1000] or a result below 2^-1022 once scaled back.

// An expansion as a V, with h + l within a relative few 2^-100 of its value. The two largest
// components would not do: nonoverlapping components may have few bits each (a top component
// 2^-58 may be followed by one just below it), so what they leave can be a relative 2^-53. Instead
// h is the expansion's components summed in double (increasing magnitude: within a relative n u of
// the value, n <= kMax), the exact remainder E - h is formed (one more exact add), l is its sum the
// same way, and E - h - l is formed exactly too: its components' magnitudes summed bound the error
// rigorously, and it is about (n u)^2 of the value. That bound is a sum of at most kMax = 64
// nonnegative doubles in round-to-nearest, at most a relative 64 u < 2^-46 below its exact value:
// 1 + 2^-40 covers that. Two components or fewer: exact (e = 0), which keeps sqrtV's and div's
// exact shortcuts (axis-aligned edges, exact vertices).
double estimate(const Expansion& x)
{
    double s = 0;
    for (int i = 0; i < x.n; ++i)
        s += x.c[i];
    return s;
}

V toV(const Expansion& x)
{
    if (!x.ok)
        return {0, 0, NAN};
    V v;
    if (x.n <= 2)
    {
        twoSum(x.n == 2 ? x.c[1] : x.n == 1 ? x.c[0] : 0.0, x.n == 2 ? x.c[0] : 0.0, v.h, v.l);
        return v;
    }
    Expansion r = x;
    const double h = estimate(r);
    r.add(-h);
    const double l = estimate(r);
    r.add(-l);
    if (!r.ok)
        return {0, 0, NAN};
    double rest = 0;
    for (int i = 0; i < r.n; ++i)
        rest += std::fabs(r.c[i]);
    twoSum(h, l, v.h, v.l);
    v.e = rest * (1 + 0x1p-40);
    return v;
}

// Multiplies v[0..n) by 2^k, with k chosen so that the largest magnitude lands in [1/2, 1), when
// no value loses a bit (one pushed into the subnormal range would: refused). The formulas below
// are homogeneous in the scaled values (the rotation (c, s) is not scaled): the exact differences
// and products then stay far from overflow, and products of values within 2^450 of the largest
// stay above expansion.hpp's 2^-960 underflow limit. The result is scaled back by 2^-k, exactly
// (a power of two; both roundings see the same significand while the result is a normal double).
bool scaleToUnit(double* v, int n, int& k)
{
    double m = 0;
    for (int i = 0; i < n; ++i)
        m = std::fmax(m, std::fabs(v[i]));
    k = 0;
    if (m == 0)
        return true;
    int e;
    std::frexp(m, &e); // m = f 2^e, f in [1/2, 1)
    k = -e;
    if (k >= -1000 && k <= 1000)
    { // 2^k and 2^-k are normal doubles: a product by either is exact unless it leaves the normal
      // range, and multiplying back tells (the same test as ldexp's below, without a call each)
        const double up = std::ldexp(1.0, k), down = std::ldexp(1.0, -k);
        for (int i = 0; i < n; ++i)
        {
            const double s = v[i] * up;
            if (s * down != v[i])
                return false;
            v[i] = s;
        }
        return true;
    }
    for (int i = 0; i < n; ++i)
    {
        const double s = std::ldexp(v[i], k);
        if (std::ldexp(s, -k) != v[i])
            return false;
        v[i] = s;
    }
    return true;
}

// |a| - r exactly, for a distance that is one coordinate difference a (a point level with a vertex,
// or off an axis-aligned edge: the engine families' boxes): an expansion of the exact value, so
// values that are doubles or midpoints between two (where a bound would never decide) are decided
// too, ties to even as MPFR's.
V axisDistance(Expansion a, double r, bool& clamped)
{
    if (a.sign() < 0)
        a.negate();
    a.add(-r);
    clamped = a.ok && a.sign() <= 0;
    return toV(a);
}

// max(0, |z| - r) for the vertex z = (zx, zy) != 0, exact expansions of its coordinates. Without a
// radius sqrt(q), q = |z|^2 exact. With one, sqrt(q) - r = (q - r^2) / (sqrt(q) + r): the
// numerator exactly, its sign decides the clamp, and the quotient has no cancellation left (a
// witness point on a rounded shape's arc is about u R from it, where sqrt(q) - r in
// double-double would lose all of its digits). `clamped`: the exact value is <= 0.
V vertexDistance(const Expansion& zx, const Expansion& zy, double r, bool& clamped)
{
    if (zx.n == 0 || zy.n == 0)
        return axisDistance(zx.n == 0 ? zy : zx, r, clamped);
    Expansion q;
    q.addProduct(zx, zx);
    q.addProduct(zy, zy);
    if (r == 0)
        return sqrtV(toV(q));
    Expansion num = q;
    num.addProduct(-r, r);
    clamped = num.ok && num.sign() <= 0;
    return div(toV(num), add(sqrtV(toV(q)), exactly(r)));
}

// The same for the inside of an edge: z the vertex z_i, d = z_j - z_i the edge vector, the
// distance |C| / sqrt(L) with C = z x d and L = |d|^2 both exact. The cross product is where the
// double-double construction of filteredFinish() fails a witness point: C is about |z| |d| u when
// the point lies about u R off the edge, so an absolute error of 2^-98 |z| |d| in its factors is a
// relative 2^-45 of C; exactly, C keeps all of its digits. With a radius: |C| / sqrt(L) - r =
// (C^2 - r^2 L) / (sqrt(L) (|C| + r sqrt(L))), the numerator exactly (its sign decides the clamp).
V edgeDistance(const Expansion& zx, const Expansion& zy, const Expansion& dx, const Expansion& dy,
               double r, bool& clamped)
{
    if (dx.n == 0 || dy.n == 0) // |C| / sqrt(L) = |zx dy| / |dy| = |zx| (dx = 0), or |zy|
        return axisDistance(dx.n == 0 ? zx : zy, r, clamped);
    Expansion C;
    C.addProduct(zx, dy);
    C.addProduct(zy, dx, -1);
    if (!C.ok || C.sign() == 0)
        return {0, 0, NAN}; // refused, or on the edge's line (an overlap, which locate() says)
    if (C.sign() < 0)
        C.negate();
    C.compress();
    Expansion L;
    L.addProduct(dx, dx);
    L.addProduct(dy, dy);
    L.compress();
    const V sL = sqrtV(toV(L));
    if (r == 0)
        return div(toV(C), sL);
    Expansion rr, num;
    rr.addProduct(r, r);
    num.addProduct(C, C);
    num.addProduct(L, rr, -1);
    clamped = num.ok && num.sign() <= 0;
    return div(toV(num), mul(sL, add(toV(C), mul(exactly(r), sL))));
}

} // namespace

bool filteredPointDistance(const Feature& f, Point p, const Shape& B, const Point* bs, double& out)
{
    if (f.overlap)
    { // p in hull(B): max(0, 0 - radius)
        out = 0;
        return true;
    }
    const bool edge = f.kind == Feature::Edge;
    // p, B's translation, the feature's one or two points of B, the radius: scaled together.
    double v[9] = {
        p.x, p.y, B.px, B.py, bs[0].x, bs[0].y, edge ? bs[1].x : 0, edge ? bs[1].y : 0, B.radius};
    int k = 0;
    if (!scaleToUnit(v, 9, k))
        return false;
    const double c = B.c, s = B.s, r = v[8];
    // z = p - w_i, w_i = (c x - s y + px, s x + c y + py): six terms a coordinate, exactly.
    Expansion zx, zy;
    zx.add(v[0]);
    zx.add(-v[2]);
    zx.addProduct(-c, v[4]);
    zx.addProduct(s, v[5]);
    zy.add(v[1]);
    zy.add(-v[3]);
    zy.addProduct(-s, v[4]);
    zy.addProduct(-c, v[5]);
    if (!zx.ok || !zy.ok) // a refused product leaves the expansion incomplete: its n means nothing
        return false;
    zx.compress();
    zy.compress();
    bool clamped = false;
    V value;
    if (!edge)
        value = vertexDistance(zx, zy, r, clamped);
    else
    { // d = z_j - z_i = w_i - w_j: the translation cancels, four products a coordinate
        Expansion dx, dy;
        dx.addProduct(c, v[4]);
        dx.addProduct(-s, v[5]);
        dx.addProduct(-c, v[6]);
        dx.addProduct(s, v[7]);
        dy.addProduct(s, v[4]);
        dy.addProduct(c, v[5]);
        dy.addProduct(-s, v[6]);
        dy.addProduct(-c, v[7]);
        if (!dx.ok || !dy.ok)
            return false;
        dx.compress();
        dy.compress();
        value = edgeDistance(zx, zy, dx, dy, r, clamped);
    }
    if (clamped)
    {
        out = 0;
        return true;
    }
    double scaled;
    if (!roundTo(value, scaled) || !(scaled > 0))
        return false;
    out = std::ldexp(scaled, -k);
    return std::isfinite(out) && out >= 0x1p-1022;
}

// ---------------------------------------------------------------- exact predicate signs
//
// zSignExact (internal.hpp): the sign of PointLocator's predicates on Z = {p} - hull(B) where its
// intervals leave it undecided (a witness point on or within about u R of B's boundary, where the
// predicate's exact value is about u R^2 and no filter of double or double-double width decides).
// Z vertex k = p - w_k, w_k = (c x - s y + px, s x + c y + py) for B's point k, so each coordinate
// is an exact six-term expansion (filteredPointDistance's z), the cross z_i x z_j and the dot
// z_i . (z_j - z_i) exact expansions of their products, whose sign is that of the largest
// component. Both are homogeneous of degree 2 in (p, B's translation, B's points) with (c, s)
// fixed, so scaling those by a power of two together (scaleToUnit, exact or refused) keeps the
// sign and keeps every product above expansion.hpp's underflow limit. Refused (kZUnsure): the
// caller's GMP route, whose sign this equals wherever it answers.
namespace
{
void zVertex(Point p, double tx, double ty, double c, double s, Point b, Expansion& zx,
             Expansion& zy)
{
    zx.add(p.x);
    zx.add(-tx);
    zx.addProduct(-c, b.x);
    zx.addProduct(s, b.y);
    zy.add(p.y);
    zy.add(-ty);
    zy.addProduct(-s, b.x);
    zy.addProduct(-c, b.y);
    zx.compress();
    zy.compress();
}

// z = p - w for one point b of B (scaled values), each coordinate as a V without expansions: the
// six terms (p, the translation, the two products as p + e by fma) summed by cascaded twoSum,
// whose errors q are exact and summed in double (Ogita, Rump and Oishi's Sum2): h + l is the
// cascade's sum plus that double sum, within gamma_5 sum|q| <= 6 u sum|q| of the exact value
// (recursive summation of five q), inflated by kUp for the bound's own rounding. A product below
// the subnormal range's reach leaves its fma error term inexact by at most 2^-1075: 2^-1070 a
// coordinate covers both products' (the values are scaled to [1/2, 1), so that is far below any
// decided value).
V zFastCoordinate(const double (&t)[6])
{
    double sum = t[0], low = 0, spread = 0;
    for (int i = 1; i < 6; ++i)
    {
        double q;
        twoSum(sum, t[i], sum, q);
        low += q;
        spread += std::fabs(q);
    }
    V v;
    twoSum(sum, low, v.h, v.l);
    v.e = (6 * kU * spread + 0x1p-1070) * kUp;
    return v;
}

void zFast(Point p, double tx, double ty, double c, double s, Point b, V& x, V& y)
{
    const double cx = c * b.x, sy = s * b.y, sx = s * b.x, cy = c * b.y;
    const double tX[6] = {p.x, -tx, -cx, -std::fma(c, b.x, -cx), sy, std::fma(s, b.y, -sy)};
    const double tY[6] = {p.y, -ty, -sx, -std::fma(s, b.x, -sx), -cy, -std::fma(c, b.y, -cy)};
    x = zFastCoordinate(tX);
    y = zFastCoordinate(tY);
}

// The sign of a V when its error bound decides it (|h + l| >= |h| (1 - 2^-50) > e), else kZUnsure.
int decidedSign(const V& v)
{
    if (!std::isfinite(v.h) || !(std::fabs(v.h) * (1 - 0x1p-50) > v.e))
        return v.h == 0 && v.l == 0 && v.e == 0 ? 0 : kZUnsure;
    return v.h > 0 ? 1 : -1;
}
} // namespace

int zSignExact(ZPredicate kind, Point p, const Shape& B, Point bi, Point bj)
{
    double v[8] = {p.x, p.y, B.px, B.py, bi.x, bi.y, bj.x, bj.y};
    int k = 0;
    if (!scaleToUnit(v, 8, k))
        return kZUnsure;
    const Point ps{v[0], v[1]};
    // First in double-double with an error bound (zFast, then the V operations above): the sign of
    // a value about u R^2 is decided at once, as the bound is about 2^-98 R^2; only a value closer
    // to 0 than that (or exactly 0) takes the exact expansions.
    {
        V Xi, Yi, Xj, Yj;
        zFast(ps, v[2], v[3], B.c, B.s, {v[4], v[5]}, Xi, Yi);
        int sgn;
        if (kind == ZPredicate::IsZero)
        { // a coordinate certainly nonzero
            const int sx = decidedSign(Xi), sy = decidedSign(Yi);
            sgn = (sx == 1 || sx == -1 || sy == 1 || sy == -1) ? 1 : kZUnsure;
        }
        else
        {
            zFast(ps, v[2], v[3], B.c, B.s, {v[6], v[7]}, Xj, Yj);
            sgn = decidedSign(kind == ZPredicate::Cross
                                  ? sub(mul(Xi, Yj), mul(Yi, Xj))
                                  : add(mul(Xi, sub(Xj, Xi)), mul(Yi, sub(Yj, Yi))));
        }
        if (sgn != kZUnsure && sgn != 0)
            return sgn;
    }
    Expansion xi, yi;
    zVertex(ps, v[2], v[3], B.c, B.s, {v[4], v[5]}, xi, yi);
    if (kind == ZPredicate::IsZero)
        return !xi.ok || !yi.ok ? kZUnsure : (xi.n == 0 && yi.n == 0 ? 0 : 1);
    Expansion xj, yj;
    zVertex(ps, v[2], v[3], B.c, B.s, {v[6], v[7]}, xj, yj);
    Expansion r;
    if (kind == ZPredicate::Cross) // z_i x z_j
    {
        r.addProduct(xi, yj);
        r.addProduct(yi, xj, -1);
    }
    else // z_i . (z_j - z_i) = z_i . z_j - |z_i|^2
    {
        r.addProduct(xi, xj);
        r.addProduct(yi, yj);
        r.addProduct(xi, xi, -1);
        r.addProduct(yi, yi, -1);
    }
    return r.ok ? r.sign() : kZUnsure;
}

bool filteredFinish(const Feature& f, const Shape& A, const Shape& B, const Point* as,
                    const Point* bs, Result& r, bool penetration)
{
    const int count = f.kind == Feature::Vertex ? 1 : f.kind == Feature::Edge ? 2 : 3;
    P2 a[3], b[3];
    for (int t = 0; t < count; ++t)
    {
        a[t] = transform(A, as[t]);
        b[t] = transform(B, bs[t]);
    }
    const Construction c = construct(f, a, b);
    r.overlap = f.overlap;
    if (f.overlap)
    { // squared == 0: the hull points themselves
        r.squared = r.distance = r.lower = r.upper = 0;
        r.fallbacks.witness = !(roundTo(c.wa.x, r.witnessA.x) && roundTo(c.wa.y, r.witnessA.y) &&
                                roundTo(c.wb.x, r.witnessB.x) && roundTo(c.wb.y, r.witnessB.y));
        return !r.fallbacks.witness;
    }
    r.fallbacks.squared = !roundTo(c.q, r.squared) || !(r.squared > 0);
    if (r.fallbacks.squared)
        return false;
    const V& s = c.s;
    r.fallbacks.distance = !roundDistance(s, A.radius, B.radius, r, penetration ? &r : nullptr);
    if (r.fallbacks.distance)
        return false;
    r.fallbacks.witness = !(roundShifted(c.wa.x, -A.radius, c.z.x, s, r.witnessA.x) &&
                            roundShifted(c.wa.y, -A.radius, c.z.y, s, r.witnessA.y) &&
                            roundShifted(c.wb.x, B.radius, c.z.x, s, r.witnessB.x) &&
                            roundShifted(c.wb.y, B.radius, c.z.y, s, r.witnessB.y));
    return !r.fallbacks.witness;
}

// ---------------------------------------------------------------- penetration depth
//
// filteredDepth (docs/exact.md, "Penetration depth", "The filter"): the signed distance and the
// penetration pair of overlapping cores, in the double-double operations above, for the closest
// edge P -> Q of Z (D = Q - P) the caller chose (edge_merge.cpp: interval enclosures of every
// edge's squared line distance C^2 / L, C = P x D, L = |D|^2, and exact comparisons among the
// edges whose enclosures reach the least): the signed value -(C / sqrt(L) + rA + rB), the foot
// parameter t = -(P . D) / L, the hull points a + t (a' - a) and b + t (b' - b), and the pair moved
// by the radii along N / sqrt(L), N = (D.y, -D.x): each rounded by roundTo() as above, so equal
// to penetration.cpp's MPFR roundings of the same reals wherever decided.

bool filteredDepth(int count, const Shape& A, const Shape& B, const Point* as, const Point* bs,
                   Result& r)
{
    const double rA = A.radius, rB = B.radius;
    const V radii = add(exactly(rA), exactly(rB)); // exact: two doubles' sum
    P2 a[2], b[2], z[2];
    for (int t = 0; t < count; ++t)
    {
        a[t] = transform(A, as[t]);
        b[t] = transform(B, bs[t]);
        z[t] = sub(a[t], b[t]);
    }
    if (count == 1)
    { // Z = {O}: depth 0, n = (1, 0)
        return roundEnclosed(neg(radii), r.signedDistance, r.signedLower, r.signedUpper) &&
               roundTo(add(a[0].x, exactly(rA)), r.penetrationA.x) &&
               roundTo(a[0].y, r.penetrationA.y) &&
               roundTo(sub(b[0].x, exactly(rB)), r.penetrationB.x) &&
               roundTo(b[0].y, r.penetrationB.y);
    }
    const P2 d = sub(z[1], z[0]);
    const V L = dot(d, d);
    const V C = cross(z[0], d); // >= 0: O is inside or on the edge's left
    V depth;
    if (isExact(C) && C.h == 0)
        depth = exactly(0);
    else if (std::fabs(C.h) * (1 - 0x1p-50) > C.e && C.h > 0)
        depth = div(C, sqrtV(L));
    else
        return false; // within its bound of 0 (touching): the GMP route
    if (!roundEnclosed(neg(add(depth, radii)), r.signedDistance, r.signedLower, r.signedUpper))
        return false;
    const V t = div(neg(dot(z[0], d)), L);
    const P2 wa = along(a[0], a[1], t), wb = along(b[0], b[1], t);
    const V s = sqrtV(L), nx = d.y, ny = neg(d.x);
    return roundShifted(wa.x, rA, nx, s, r.penetrationA.x) &&
           roundShifted(wa.y, rA, ny, s, r.penetrationA.y) &&
           roundShifted(wb.x, -rB, nx, s, r.penetrationB.x) &&
           roundShifted(wb.y, -rB, ny, s, r.penetrationB.y);
}

} // namespace exact::detail
