// ExactSum (validation/src/statistics/exact_sum.hpp): the sum of a histogram's values, exact and
// rounded once, so that shards, chunks and ranks merge to the same bits in any order. The expected
// values come from GMP's exact rationals, and the rounding is checked against the midpoints to the
// neighbouring doubles, never against the accumulator itself.
#include "statistics/exact_sum.hpp"
#include "statistics/stats.hpp"

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace gjkval;

namespace
{
mpq_class exactOf(double v)
{
    mpq_class q;
    mpq_set_d(q.get_mpq_t(), v); // exact: a double is a dyadic rational
    return q;
}

// d is the double nearest to q (ties to even), checked with exact rationals.
bool correctlyRounded(double d, const mpq_class& q)
{
    const double below = std::nextafter(d, -INFINITY), above = std::nextafter(d, INFINITY);
    const mpq_class lo = (exactOf(below) + exactOf(d)) / 2, hi = (exactOf(d) + exactOf(above)) / 2;
    if (q > lo && q < hi)
        return true;
    if (q == lo || q == hi) // a tie: d must be the even one
    {
        int e = 0;
        const double m = std::frexp(d, &e);
        return std::fmod(std::ldexp(m, 53), 2.0) == 0;
    }
    return false;
}
} // namespace

TEST_CASE("exact sum: small cases by hand", "[stats][exact-sum]")
{
    ExactSum s;
    CHECK(s.value() == 0);
    s.add(0.0);
    s.add(1.0);
    s.add(0.5);
    CHECK(s.value() == 1.5);
    // 1 + 2^-60 + 2^-60 ... : naive summation keeps 1 each time; 2^10 of them make 1 + 2^-50.
    ExactSum t;
    t.add(1.0);
    for (int i = 0; i < 1024; ++i)
        t.add(std::ldexp(1.0, -60));
    CHECK(t.value() == 1.0 + std::ldexp(1.0, -50));
    // A tie: 1 + 2^-53 lies halfway between 1 and 1 + 2^-52: ties to even gives 1; one more
    // subnormal above the tie rounds up.
    ExactSum tie;
    tie.add(1.0);
    tie.add(std::ldexp(1.0, -53));
    CHECK(tie.value() == 1.0);
    tie.add(std::numeric_limits<double>::denorm_min());
    CHECK(tie.value() == 1.0 + std::ldexp(1.0, -52));
    // Subnormals add exactly: 3 smallest subnormals are 3 * 2^-1074.
    ExactSum sub;
    for (int i = 0; i < 3; ++i)
        sub.add(std::numeric_limits<double>::denorm_min());
    CHECK(sub.value() == 3 * std::numeric_limits<double>::denorm_min());
    // Beyond the largest double: +inf.
    ExactSum big;
    big.add(std::numeric_limits<double>::max());
    big.add(std::numeric_limits<double>::max());
    CHECK(big.value() == INFINITY);
    CHECK_THROWS_AS(big.add(-1.0), std::logic_error);
    CHECK_THROWS_AS(big.add(NAN), std::logic_error);
}

TEST_CASE("exact sum: correctly rounded and independent of order and merges", "[stats][exact-sum]")
{
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 40; ++trial)
    {
        // Values across the whole range, from subnormals to 1e300, in one sum: the hard case for
        // any floating-point accumulation.
        const int lo = trial % 4 == 0 ? -1074 : -60, hi = trial % 4 == 0 ? 1000 : 60;
        std::uniform_int_distribution<int> expo(lo, hi);
        std::uniform_real_distribution<double> frac(1.0, 2.0);
        std::vector<double> values(500);
        mpq_class exact = 0;
        for (double& v : values)
        {
            v = std::ldexp(frac(rng), expo(rng));
            exact += exactOf(v);
        }
        ExactSum whole;
        for (double v : values)
            whole.add(v);
        INFO("trial " << trial);
        CHECK(correctlyRounded(whole.value(), exact));

        // Shuffled, cut into pieces, merged in another order: the same state and the same bits.
        std::shuffle(values.begin(), values.end(), rng);
        std::vector<ExactSum> pieces(7);
        for (std::size_t i = 0; i < values.size(); ++i)
            pieces[(i * 5) % pieces.size()].add(values[i]);
        ExactSum merged;
        for (std::size_t k = pieces.size(); k-- > 0;)
            merged.merge(pieces[k]);
        CHECK(merged == whole);
        CHECK(merged.value() == whole.value());
        CHECK(ExactSum::fromJson(merged.toJson()) == whole);
    }
}

TEST_CASE("histogram merge: the same statistics in any order, ties to the earlier case",
          "[stats][exact-sum]")
{
    Hist a(-40, 40, 10), b(-40, 40, 10), whole(-40, 40, 10);
    const double values[] = {0.1, 0.7, 3.0, 1e-17, 0.2, 3.0}; // 3.0 at cases 2 (a) and 5 (b)
    for (int i = 0; i < 6; ++i)
    {
        const std::string name = "c" + std::to_string(i);
        whole.add(values[i], name, std::uint64_t(i));
        (i % 2 == 0 ? a : b).add(values[i], name, std::uint64_t(i));
    }
    Hist ab = a, ba = b;
    ab.merge(b);
    ba.merge(a);
    for (const Hist* h : {&ab, &ba})
    {
        CHECK(h->toJson() == whole.toJson());
        CHECK(h->maxCase == "c2"); // the earlier of the two, whichever side merges into which
    }
    mpq_class exact = 0;
    for (double v : values)
        exact += exactOf(v);
    CHECK(correctlyRounded(whole.sum(), exact));
}
