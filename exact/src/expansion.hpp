// Floating-point expansions (Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
// Robust Geometric Predicates", 1997): a number held exactly as a sum of doubles, the components
// nonoverlapping, in increasing magnitude, zeros eliminated. Used by the point-to-shape filter
// (filter.cpp, filteredPointDistance) to form differences, cross products and squared lengths of
// world coordinates with no rounding error at all.
//
// Exact as long as nothing overflows and no product loses bits to underflow; `ok` turns false
// when that cannot be guaranteed (then the caller takes the GMP route), and when the expansion
// would need more than kMax components (a nonoverlapping expansion of n added terms has at most
// n components; the filter's largest, C^2 - r^2 L, stays far below kMax in practice).
#pragma once

#include <cmath>

namespace exact::detail
{

struct Expansion
{
    static constexpr int kMax = 64;
    double c[kMax];
    int n = 0;
    bool ok = true;

    // Adds b exactly: GROW-EXPANSION-ZEROELIM (Shewchuk, section 2.3, figure 7). Each step is
    // Knuth's TwoSum, exact unless it overflows; the output index never passes the input index,
    // so the expansion is updated in place.
    void add(double b)
    {
        if (b == 0 || !ok)
            return;
        double q = b;
        int k = 0;
        for (int i = 0; i < n; ++i)
        {
            const double s = q + c[i];
            const double bb = s - q;
            const double err = (q - (s - bb)) + (c[i] - bb);
            q = s;
            if (err != 0)
                c[k++] = err;
        }
        if (!std::isfinite(q) || k >= kMax)
        {
            ok = false;
            return;
        }
        if (q != 0)
            c[k++] = q;
        n = k;
    }

    // Adds a * b exactly: the product as p + t by fma (TwoProduct). t is exact when a * b does not
    // overflow and no bits fall below the subnormal range: |p| >= 2^-960 leaves 2^-1074 below
    // p's last bit by more than 53 bits (a p of 2^-960 has its last bit at 2^-1012). A nonzero
    // product below that, or zero from nonzero factors, is refused.
    void addProduct(double a, double b)
    {
        if (a == 0 || b == 0)
            return;
        const double p = a * b;
        if (!std::isfinite(p) || !(std::fabs(p) >= 0x1p-960))
        {
            ok = false;
            return;
        }
        add(std::fma(a, b, -p));
        add(p);
    }

    // Adds sign * x * y exactly (every pair of components, TwoProduct each).
    void addProduct(const Expansion& x, const Expansion& y, double sign = 1)
    {
        ok = ok && x.ok && y.ok;
        for (int i = 0; i < x.n && ok; ++i)
            for (int j = 0; j < y.n && ok; ++j)
                addProduct(sign * x.c[i], y.c[j]);
    }

    // The same value in as few components as COMPRESS gives (Shewchuk, section 2.8, figure 15;
    // his Theorem 23: the result is nonoverlapping, largest last, no zeros). Each step is
    // Dekker's FastTwoSum, exact for |a| >= |b|, which the order of the components guarantees.
    // A product of expansions costs the product of their lengths in TwoProducts, so the sums
    // of a few terms here are compressed before they are multiplied.
    void compress()
    {
        if (n < 2 || !ok)
            return;
        double g[kMax];
        double q = c[n - 1];
        int bottom = n - 1;
        for (int i = n - 2; i >= 0; --i)
        {
            const double s = q + c[i];
            const double small = c[i] - (s - q);
            if (small != 0)
            {
                g[bottom--] = s;
                q = small;
            }
            else
                q = s;
        }
        g[bottom] = q;
        int top = 0;
        for (int i = bottom + 1; i < n; ++i)
        {
            const double s = g[i] + q;
            const double small = q - (s - g[i]);
            if (small != 0)
                c[top++] = small;
            q = s;
        }
        c[top++] = q;
        n = top;
    }

    void negate()
    {
        for (int i = 0; i < n; ++i)
            c[i] = -c[i];
    }

    // The exact sign: that of the largest component (nonoverlapping components, Shewchuk's
    // Lemma 11: the largest outweighs the sum of the others).
    int sign() const { return n == 0 ? 0 : c[n - 1] > 0 ? 1 : -1; }
};

} // namespace exact::detail
