// Correct rounding of the doubles in Result, checked against exact midpoint comparisons: d is the
// nearest double to x iff x lies between the midpoints from d to its neighbours (on a midpoint: d
// has an even mantissa). For x = sqrt(q) - r, x >= m  <=>  q >= (m + r)^2 when m + r >= 0.
#include "support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace exact_test;
using exact::Options;
using exact::Result;

TEST_CASE("distance is sqrt(squared) correctly rounded where naive sqrt(double) is not")
{
    // Point vs point with random doubles: q = x^2 + y^2 has ~106 significant bits, so the double
    // q rounds once and std::sqrt rounds again; the double rounding is occasionally off by one ulp.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.5, 2.0);
    int naiveWrong = 0, squaredUp = 0;
    const int n = 20000;
    for (int k = 0; k < n; ++k)
    {
        const double x = u(rng), y = u(rng);
        const Result r = exact::distance(shape({{0, 0}}), shape({{x, y}}));
        const mpq_class q = squaredOf(r);
        REQUIRE(q == mpq_class(x) * mpq_class(x) + mpq_class(y) * mpq_class(y));
        REQUIRE(distanceRoundsTo(r.distance, q, 0));
        REQUIRE(rationalRoundsTo(r.squared, q));
        squaredUp += mpq_class(r.squared) > q;
        const double naive = std::sqrt(r.squared);
        if (naive != r.distance)
        {
            ++naiveWrong;
            CHECK_FALSE(distanceRoundsTo(naive, q, 0)); // the naive value really is wrong
        }
    }
    INFO("naive sqrt(double(q)) was off in " << naiveWrong << " of " << n << " cases");
    CHECK(naiveWrong >= 1);
    CHECK(squaredUp > n / 4); // rounding the squared value went up, not only down (truncation)
}

TEST_CASE("radius-subtracted distance is correctly rounded where naive double arithmetic is not")
{
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(-3.0, 3.0), rad(0.0, 1.0);
    int naiveWrong = 0, clamped = 0;
    const int n = 20000;
    for (int k = 0; k < n; ++k)
    {
        const Shape a = shape({{u(rng), u(rng)}}, rad(rng));
        const Shape b = shape({{u(rng), u(rng)}, {u(rng), u(rng)}}, rad(rng));
        const Result r = exact::distance(a, b);
        const mpq_class q = squaredOf(r), rr = radii(a, b);
        REQUIRE(distanceRoundsTo(r.distance, q, rr));
        REQUIRE(encloses(r.lower, r.upper, q, rr));
        clamped += r.distance == 0;
        const double naive = std::max(0.0, std::sqrt(r.squared) - a.radius - b.radius);
        if (naive != r.distance)
        {
            ++naiveWrong;
            CHECK_FALSE(distanceRoundsTo(naive, q, rr));
        }
    }
    INFO("naive was off in " << naiveWrong << " of " << n << " cases");
    CHECK(naiveWrong >= 1);
    CHECK(clamped >= 1);
}

TEST_CASE("squared: exact ties round to even")
{
    // dx = 1 + k 2^-27, dy = j 2^-27 with k, j odd: q = ((2^27 + k)^2 + j^2) 2^-54, and a sum of
    // two odd squares is 2 mod 8, so q in [1, 2) has its last bit at 2^-53: exactly halfway between
    // two doubles. The lower one is even here: 2 mod 8 means the bit above the tie bit is 0. (Every
    // dyadic squared distance has an odd part = 1 mod 4, a sum of two squares over one, so its ties
    // always go down; ties going up are tested on the distance below. Truncation would pass these
    // ties: squared values rounding up are counted in the first test case of this file.)
    int ties = 0;
    for (int k = 1; k < 40; k += 2)
        for (int j = 1; j < 40; j += 2)
        {
            const double dx = 1 + std::ldexp(k, -27), dy = std::ldexp(j, -27);
            const Result r = exact::distance(shape({{0, 0}}), shape({{dx, dy}}));
            const mpq_class q = squaredOf(r);
            REQUIRE(rationalRoundsTo(r.squared, q));
            const mpq_class at(r.squared), above(std::nextafter(r.squared, 4.0));
            REQUIRE(q == (at + above) / 2); // a tie indeed, resolved downwards to the even one
            ++ties;
        }
    CHECK(ties == 400);
}

TEST_CASE("distance: exact ties round to even")
{
    const double e52 = std::ldexp(1.0, -52), e51 = std::ldexp(1.0, -51);
    // sqrt(9) - 2^-52 = 3 - 2^-52: halfway between 3 - 2^-51 (odd) and 3 (even) -> 3
    Result r = exact::distance(shape({{0, 0}}, e52), shape({{3, 0}}));
    CHECK(r.distance == 3.0);
    CHECK(r.lower <= 3 - e52);
    CHECK(r.upper >= 3 - e52);
    // 3 - 3 * 2^-52: halfway between 3 - 2^-50 (even) and 3 - 2^-51 (odd) -> 3 - 2^-50
    r = exact::distance(shape({{0, 0}}, e52), shape({{3, 0}}, e51));
    CHECK(r.distance == 3 - 4 * e52);
    CHECK(distanceRoundsTo(r.distance, 9, mpq_class(e52) + mpq_class(e51)));
}

TEST_CASE("cancellation: sqrt(q) barely above the radii")
{
    // (0,0) vs (1,1), radius just below sqrt(2): the exact value is about 1e-16, far below the
    // rounding error of sqrt(2.0) - r in doubles.
    const double r2 = std::sqrt(2.0); // RN(sqrt 2) > sqrt 2
    for (double rad : {r2, std::nextafter(r2, 0.0), std::nextafter(std::nextafter(r2, 0.0), 0.0)})
    {
        const Result r = exact::distance(shape({{0, 0}}, rad), shape({{1, 1}}));
        CHECK(distanceRoundsTo(r.distance, 2, mpq_class(rad)));
        CHECK(encloses(r.lower, r.upper, 2, mpq_class(rad)));
    }
    const Result above = exact::distance(shape({{0, 0}}, r2), shape({{1, 1}}));
    CHECK(above.distance == 0.0); // sqrt(2) - RN(sqrt(2)) < 0: clamped
    const Result below = exact::distance(shape({{0, 0}}, std::nextafter(r2, 0.0)), shape({{1, 1}}));
    CHECK(below.distance > 0.0);
    CHECK(below.distance < 1e-15);
}

TEST_CASE("witnesses on rounded surfaces are correctly rounded")
{
    // witness A = wa + rA z/|z|, witness B = wb - rB z/|z| with z = wb - wa, checked coordinate by
    // coordinate with exact comparisons (sign of w + a/sqrt(q) - m).
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-2.0, 2.0), rad(0.0, 1.0), angle(0, 6.283185307179586);
    Options o;
    o.exactWitnesses = true;
    int checked = 0;
    for (int k = 0; k < 1500; ++k)
    {
        Shape a, b;
        for (Shape* s : {&a, &b})
        {
            const int n = 1 + k % 5;
            for (int i = 0; i < n; ++i)
                s->points.push_back({u(rng), u(rng)});
            s->radius = rad(rng);
            const double t = angle(rng);
            s->c = std::cos(t);
            s->s = std::sin(t);
            s->px = 2 * u(rng);
        }
        const Result r = exact::distance(a, b, o);
        const mpq_class q = squaredOf(r);
        const Q2 wa = exactPoint(r.exactWitnessA), wb = exactPoint(r.exactWitnessB);
        if (sgn(q) == 0)
        {
            CHECK(r.witnessA.x == r.witnessB.x);
            CHECK(r.witnessA.y == r.witnessB.y);
            CHECK(rationalRoundsTo(std::fabs(r.witnessA.x), abs(wa.x)));
            continue;
        }
        const mpq_class zx = wb.x - wa.x, zy = wb.y - wa.y, ra(a.radius), rb(b.radius);
        auto check = [&](double d, const mpq_class& w, const mpq_class& shift) {
            return roundsToSigned(d,
                                  [&](const mpq_class& m) { return cmpShifted(w, shift, q, m); });
        };
        CHECK(check(r.witnessA.x, wa.x, ra * zx));
        CHECK(check(r.witnessA.y, wa.y, ra * zy));
        CHECK(check(r.witnessB.x, wb.x, -rb * zx));
        CHECK(check(r.witnessB.y, wb.y, -rb * zy));
        ++checked;
    }
    CHECK(checked > 500);
}

TEST_CASE("exact witness strings are in lowest terms")
{
    Options o;
    o.exactWitnesses = true;
    // Triangle (0,0), (3,0), (0,3) and point (7,7) scaled by c = 1/2 to (7/2, 7/2): against the
    // edge x + y = 3 the foot is (7/2, 7/2) - 2 (1,1) = (3/2, 3/2), squared 2^2 + 2^2 = 8.
    Shape b = shape({{7, 7}});
    b.c = 0.5;
    const Result r = exact::distance(shape({{0, 0}, {3, 0}, {0, 3}}), b, o);
    for (const std::string& s : {r.exactWitnessA.x, r.exactWitnessA.y, r.exactWitnessB.x,
                                 r.exactWitnessB.y, r.squaredNum + "/" + r.squaredDen})
    {
        mpq_class q(s, 10);
        mpq_class c = q;
        c.canonicalize();
        CHECK(q == c);
        CHECK(mpz_cmp(q.get_num_mpz_t(), c.get_num_mpz_t()) == 0);
        CHECK(mpz_cmp(q.get_den_mpz_t(), c.get_den_mpz_t()) == 0);
    }
    CHECK(r.squaredNum == "8");
    CHECK(r.squaredDen == "1");
    CHECK(r.exactWitnessA.x == "3/2");
    CHECK(r.exactWitnessB.y == "7/2");
}
