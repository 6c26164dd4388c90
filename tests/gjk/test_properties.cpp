// Properties of the core that a plausible one-line slip would break, each pinned directly (issue
// "Tests that catch plausible bugs: mutation testing of the core"; scripts/mutate.py and
// docs/testing.md list the slips these tests are measured against):
//   - the warm-start cache is validated at every boundary (count, each index, the search starts),
//     observable in an optimised build: the shapes' points sit between "poison" points that would
//     change the answer if an index one past either end were read;
//   - an exactly representable distance comes back exactly (the edge-height formula);
//   - each piece of the certified interval (outward rounding, the running error bounds, the support
//     scan's upper bound, containment from certified signs) is checked against exact values:
//     error-free transformations (two-sum, fma) for single operations and __int128 integer
//     arithmetic on dyadic inputs for the support scan and the orientations.
// Expected values come from the hand derivations in the comments or from that exact arithmetic,
// never from the library.
#include "gjk2d/distance.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using namespace gjk;

namespace
{
using I128 = __int128;

// A polygon whose points are stored between `pad` poison points on each side: reading index -1 or
// `count` (or further, up to pad) returns `poison` instead of faulting in a Release build.
template <class T> struct Guarded
{
    std::vector<Vec2<T>> storage;
    int count = 0;
    static constexpr int pad = 3;

    Guarded(std::initializer_list<Vec2<T>> pts, Vec2<T> poison)
    {
        storage.assign(pad, poison);
        storage.insert(storage.end(), pts.begin(), pts.end());
        storage.insert(storage.end(), pad, poison);
        count = int(pts.size());
    }
    Polygon<T> polygon(T radius = T(0)) const { return {storage.data() + pad, count, radius}; }
};

// d >= N / 2^k exactly, for an integer N (the exact value, scaled).
inline bool atLeast(double d, I128 N, int k)
{
    const double D = std::ldexp(d, k);
    REQUIRE(std::abs(D) < 0x1p125);
    return I128(std::ceil(D)) >= N;
}
} // namespace

// --- The warm-start cache --------------------------------------------------------------------

TEMPLATE_TEST_CASE("cache: every invalid field falls back to the cold start, at every boundary",
                   "[gjk][cache][properties]", float, double)
{
    using T = TestType;
    // A: triangle (2,0) (3,1) (3,-1); B: the origin. By hand the distance is 2 (vertex (2,0)), the
    // normal (-1, 0) from A to B. A's poison is B's point and B's poison is A's vertex (2,0): an
    // accepted out-of-range index puts w = 0 into the simplex, and the query answers 0.
    const Guarded<T> A({{2, 0}, {3, 1}, {3, -1}}, {0, 0});
    const Guarded<T> B({{0, 0}}, {2, 0});
    const DistanceInput<T> in{A.polygon(), B.polygon(), {}, {}};
    SimplexCache coldCache;
    const auto cold = distance(in, coldCache);
    REQUIRE(cold.distance == T(2));
    REQUIRE(cold.normal == Vec2<T>{-1, 0});

    auto check = [&](const SimplexCache& c)
    {
        SimplexCache cache = c;
        const auto out = distance(in, cache);
        CHECK(out.distance == T(2));
        CHECK(out.pointA == Vec2<T>{2, 0});
        CHECK(out.pointB == Vec2<T>{0, 0});
        CHECK(out.normal == Vec2<T>{-1, 0});
        // The cache written back is valid for these shapes again.
        CHECK(cache.count >= 1);
        CHECK(cache.count <= 3);
        for (int i = 0; i < std::min(std::max(cache.count, 0), 3); ++i)
        {
            CHECK(cache.indexA[i] >= 0);
            CHECK(cache.indexA[i] < A.count);
            CHECK(cache.indexB[i] >= 0);
            CHECK(cache.indexB[i] < B.count);
        }
    };

    SECTION("count outside [1, 3]")
    {
        for (int count : {-1, 0, 4, 5})
        {
            CAPTURE(count);
            SimplexCache c;
            c.count = count; // every index 0: valid, so only the count is wrong
            check(c);
        }
    }
    SECTION("an index equal to the count, or negative, in each slot")
    {
        // Slots before the bad one hold valid indices (0), so the loop must reach the bad slot.
        for (int count = 1; count <= 3; ++count)
            for (int bad : {A.count, -1})
            {
                CAPTURE(count, bad);
                SimplexCache c;
                c.count = count;
                c.indexA[count - 1] = bad;
                check(c);
            }
        for (int count = 1; count <= 3; ++count)
            for (int bad : {B.count, -1})
            {
                CAPTURE(count, bad);
                SimplexCache c;
                c.count = count;
                c.indexB[count - 1] = bad;
                check(c);
            }
    }
    SECTION("the largest valid index is accepted: a warm start from it")
    {
        SimplexCache c;
        c.count = 1;
        c.indexA[0] = A.count - 1; // (3, -1)
        c.indexB[0] = B.count - 1;
        SimplexCache cache = c;
        const auto out = distance(in, cache);
        CHECK(out.distance == T(2));
        // Warm from (3,-1): one support point (2,0), then the repeat: two, not the cold query's
        // one.
        CHECK(out.iterations == 2);
    }
}

TEMPLATE_TEST_CASE("cache: the binary search's start is validated at every boundary",
                   "[gjk][cache][properties]", float, double)
{
    using T = TestType;
    // A regular 20-gon (more than 16 points: SupportStrategy::BinarySearch gallops from
    // SimplexCache::searchA), radius 1 around (4, 0), against the origin, its vertex 0 at (3, 0):
    // the closest one, so the warm start's first search direction (-1, 0) has its maximum at the
    // vertex a start of 20 wraps to. Its poison is the origin (a read one to three past either end
    // puts w = 0 into the simplex). A start outside [0, 20) must fall back to indexA[0].
    std::vector<Vec2<T>> ring;
    for (int i = 0; i < 20; ++i)
    {
        const double t = 3.14159265358979323846 * (1 + i / 10.0);
        ring.push_back({T(4 + std::cos(t)), T(std::sin(t))});
    }
    Guarded<T> A({}, {0, 0});
    A.storage.assign(Guarded<T>::pad, {0, 0});
    A.storage.insert(A.storage.end(), ring.begin(), ring.end());
    A.storage.insert(A.storage.end(), Guarded<T>::pad, {0, 0});
    A.count = 20;
    const Guarded<T> B({{0, 0}}, {4, 0});
    const DistanceInput<T> in{A.polygon(), B.polygon(), {}, {}};
    Options o;
    o.support = SupportStrategy::BinarySearch;
    SimplexCache coldCache;
    const auto cold = distance(in, coldCache, o);
    // The closest vertex is index 0, (4 + cos(pi), sin(pi)) = (3, 1.2e-16), about 3 away.
    REQUIRE(cold.distance > T(2.9));
    REQUIRE(coldCache.count == 1);
    REQUIRE(coldCache.indexA[0] == 0);
    for (int start : {-3, -2, 20, 21, 22})
    {
        for (int which = 0; which < 2; ++which)
        {
            CAPTURE(start, which);
            SimplexCache c = coldCache;
            (which ? c.searchB : c.searchA) = start;
            const auto out = distance(in, c, o);
            CHECK(out.distance == cold.distance);
            CHECK(out.pointA == cold.pointA);
        }
    }
}

// --- Exactly representable distances ---------------------------------------------------------

TEMPLATE_TEST_CASE("an exactly representable distance comes back exactly",
                   "[gjk][numerics][properties]", float, double)
{
    using T = TestType;
    // The origin against a horizontal segment (x1, h)-(x2, h), x1 < 0 < x2, at integer height h:
    // the distance is h. The library's height formula |cross(w1, e)| / |e| is exact here
    // (cross = h (x2 - x1), |e| = x2 - x1, both integers), while |u w1 + v w2| from the barycentric
    // weights u = x2 / (x2 - x1), v = -x1 / (x2 - x1) (rounded) is not: docs/gjk.md's claim that
    // the height is the more accurate formula. Also the segment as B (w = -B), vertical segments,
    // and the normal (exactly the axis; the witness points come from the rounded weights and are
    // not claimed exact).
    int checked = 0;
    for (int h = 1; h <= 9; ++h)
        for (int x1 = -13; x1 <= -1; ++x1)
            for (int x2 = 1; x2 <= 13; ++x2)
                for (int vertical = 0; vertical < 2; ++vertical)
                    for (int segmentIsB = 0; segmentIsB < 2; ++segmentIsB)
                    {
                        CAPTURE(h, x1, x2, vertical, segmentIsB);
                        auto pt = [&](int along, int across) {
                            return vertical ? Vec2<T>{T(across), T(along)}
                                            : Vec2<T>{T(along), T(across)};
                        };
                        const Vec2<T> seg[2] = {pt(x1, h), pt(x2, h)};
                        const Vec2<T> origin[1] = {{0, 0}};
                        DistanceInput<T> in{{seg, 2, T(0)}, {origin, 1, T(0)}, {}, {}};
                        if (segmentIsB)
                            std::swap(in.proxyA, in.proxyB);
                        const auto out = distance(in);
                        REQUIRE(out.distance == T(h));
                        const Vec2<T> axis = pt(0, 1);
                        CHECK(out.normal == (segmentIsB ? axis : T(-1) * axis));
                        ++checked;
                    }
    CHECK(checked == 9 * 13 * 13 * 4);
}

// --- The certified interval's pieces against exact values --------------------------------------

TEST_CASE("certify: up and down round outwards by at least one ulp, at most two",
          "[gjk][certify][properties]")
{
    using certify::down;
    using certify::up;
    const double mx = std::numeric_limits<double>::max();
    const double tiny = std::numeric_limits<double>::denorm_min();
    const double xs[] = {0.0, tiny,        3 * tiny, 0x1p-1022, 0x1.8p-1000,         0.1,   0.5,
                         1.0, 1 + 0x1p-52, 1.5,      3.0,       0x1.fffffffffffffp0, 1e300, mx / 4};
    for (double x0 : xs)
        for (double x : {x0, -x0})
        {
            CAPTURE(x);
            const double next = std::nextafter(x, mx), prev = std::nextafter(x, -mx);
            CHECK(up(x) >= next);
            CHECK(up(x) <= std::nextafter(next, mx));
            CHECK(down(x) <= prev);
            CHECK(down(x) >= std::nextafter(prev, -mx));
        }
    // Past the range: up(max) is inf (still above), infinities stay.
    CHECK(up(mx) > mx);
    CHECK(up(std::numeric_limits<double>::infinity()) == std::numeric_limits<double>::infinity());
}

TEST_CASE("certify: hi and lo enclose v +- e exactly, and round outwards",
          "[gjk][certify][properties]")
{
    using certify::Bounded;
    // v + e and v - e are exact in long double (64-bit significand) for these dyadic pairs: the
    // enclosure is checked against the exact ends. Where v +- e is not a double the ends must round
    // outwards (e = 2^-60 at v = 1: to nearest, 1 + 2^-60 is 1).
    const Bounded cases[] = {{1, 0x1p-60},         {1, 0x1p-54}, {1, 3 * 0x1p-53}, {-1, 0x1p-60},
                             {0x1p-900, 0x1p-960}, {1e10, 0.25}, {0, 0x1p-1074},   {3, 0}};
    for (const Bounded& a : cases)
    {
        CAPTURE(a.v, a.e);
        const long double top = (long double)a.v + (long double)a.e;
        const long double bottom = (long double)a.v - (long double)a.e;
        REQUIRE(top - (long double)a.v == (long double)a.e); // exact in long double
        CHECK((long double)certify::hi(a) >= top);
        CHECK((long double)certify::lo(a) <= bottom);
        CHECK(certify::hi(a) > a.v);
        CHECK(certify::lo(a) < a.v);
    }
}

TEST_CASE("certify: the running error bound of each operation covers its exact error",
          "[gjk][certify][properties]")
{
    using namespace certify;
    // Exact errors from error-free transformations: two-sum for + and -, fma for * (exact when the
    // product does not underflow; the exponents below keep it normal). The bound e must cover
    // |exact - v| for every pair; the counters make sure the pairs did round.
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> mant(1.0, 2.0);
    std::uniform_int_distribution<int> ex(-40, 40);
    auto draw = [&] { return std::ldexp(mant(rng), ex(rng)) * (rng() & 1 ? 1 : -1); };
    auto twoSumError = [](double a, double b, double s)
    {
        const double bb = s - a;
        return (a - (s - bb)) + (b - bb);
    };
    int roundedSums = 0, roundedProducts = 0;
    for (int k = 0; k < 20000; ++k)
    {
        const double a = draw(), b = draw();
        const Bounded s = exactly(a) + exactly(b);
        const double es = twoSumError(a, b, s.v);
        CHECK(std::abs(es) <= s.e);
        roundedSums += es != 0;
        const Bounded d = exactly(a) - exactly(b);
        CHECK(std::abs(twoSumError(a, -b, d.v)) <= d.e);
        const Bounded p = exactly(a) * exactly(b);
        const double ep = std::fma(a, b, -p.v);
        CHECK(std::abs(ep) <= p.e);
        roundedProducts += ep != 0;
        const Bounded q = mulExact(a, b);
        CHECK(std::abs(std::fma(a, b, -q.v)) <= q.e);
    }
    CHECK(roundedSums > 10000);
    CHECK(roundedProducts > 10000);

    // Products of uncertain factors: every corner (a.v +- a.e)(b.v +- b.e), exact in small
    // integers, lies within the bound. By hand: (0 +- 1)(0 +- 1) reaches 1 with v = 0, which only
    // the a.e b.e term covers; (2 +- 1)(3 +- 1) reaches 12 = 6 + 2*1 + 3*1 + 1*1.
    const Bounded pairs[][2] = {
        {{0, 1}, {0, 1}}, {{2, 1}, {3, 1}}, {{-5, 2}, {7, 3}}, {{4, 0}, {-9, 2}}};
    for (const auto& pr : pairs)
    {
        const Bounded p = pr[0] * pr[1];
        for (int sa : {-1, 1})
            for (int sb : {-1, 1})
            {
                const double corner = (pr[0].v + sa * pr[0].e) * (pr[1].v + sb * pr[1].e); // exact
                CHECK(std::abs(corner - p.v) <= p.e);
            }
    }
    // Sums of uncertain values: the input errors add.
    const Bounded s = Bounded{1, 0.5} + Bounded{2, 0.25};
    CHECK(s.e >= 0.75);
    const Bounded d = Bounded{1, 0.5} - Bounded{2, 0.25};
    CHECK(d.e >= 0.75);
}

TEMPLATE_TEST_CASE("certify: the support scan's upper bound is above the exact maximum",
                   "[gjk][certify][properties]", float, double)
{
    using T = TestType;
    // supportUpper bounds max_i n . (Q x_i + p) from above. Inputs on a dyadic grid so that the
    // exact value is an integer over 2^32: c, s, nx, ny = k / 2^16 (|k| < 2^15 in double, < 2^21
    // in float, so that m = Q^T n has enough bits for m . x to round), point coordinates
    // and the translation integers below 2^(digits - 2) (exact in T). The points are chosen so that
    // m . x (m = Q^T n) nearly cancels, and p so that n . p nearly cancels: the rounded dot
    // products are then off by many units of their (small) result, which only the scan's own error
    // term and the translation's error bound cover (the final up() adds a few ulps of the small
    // result). The exact value: 2^32 n.(Qx + p) = NX (C X - S Y) + NY (S X + C Y) + 2^16 (NX PX +
    // NY PY) in __int128 (at most ~2^83).
    constexpr int bits = std::numeric_limits<T>::digits - 2;
    const std::int64_t range = std::int64_t(1) << bits;
    std::mt19937_64 rng(99);
    const std::int64_t smallRange =
        std::numeric_limits<T>::digits < 53 ? std::int64_t(1) << 21 : 30000;
    auto small = [&] { return std::int64_t(rng() % std::uint64_t(2 * smallRange)) - smallRange; };
    auto big = [&] { return std::int64_t(rng() % std::uint64_t(range)) - range / 2; };
    int scanRoundedDown = 0, trials = 0;
    for (int k = 0; k < 3000; ++k)
    {
        const std::int64_t C = small(), S = small(), NX = small(), NY = small();
        const I128 MX = I128(C) * NX + I128(S) * NY; // 2^32 m
        const I128 MY = I128(C) * NY - I128(S) * NX;
        if (MX == 0 || MY == 0)
            continue;
        // Points with m . x ~ 0: Y = -MX X / MY rounded, then within the range.
        std::vector<Vec2<T>> pts;
        for (int j = 0; j < 4; ++j)
        {
            const std::int64_t X = big() / 4;
            const I128 Y = -(I128(X) * MX) / MY + I128(rng() % 5) - 2;
            if (Y >= range || Y <= -range)
                continue;
            pts.push_back({T(X), T(std::int64_t(Y))});
        }
        if (pts.empty())
            continue;
        const std::int64_t PX = big();
        const I128 PYw = NY != 0 ? -(I128(PX) * NX) / NY : 0;
        if (PYw >= range || PYw <= -range)
            continue;
        const std::int64_t PY = std::int64_t(PYw);
        Transform<T> xf;
        xf.q = {T(std::ldexp(double(C), -16)), T(std::ldexp(double(S), -16))};
        xf.p = {T(PX), T(PY)};
        const double nx = std::ldexp(double(NX), -16), ny = std::ldexp(double(NY), -16);
        I128 best = 0;
        bool first = true;
        for (const auto& v : pts)
        {
            const I128 X = I128(std::int64_t(v.x)), Y = I128(std::int64_t(v.y));
            const I128 val =
                I128(NX) * (I128(C) * X - I128(S) * Y) + I128(NY) * (I128(S) * X + I128(C) * Y);
            if (first || val > best)
                best = val;
            first = false;
            // How the scan itself rounds: m (exact here: integers of at most 45 bits over 2^32)
            // times x.
            const double mx = std::ldexp(double(MX), -32), my = std::ldexp(double(MY), -32);
            scanRoundedDown += !atLeast(mx * double(v.x) + my * double(v.y), val, 32);
        }
        const I128 exact = best + (I128(1) << 16) * (I128(NX) * PX + I128(NY) * PY);
        const double upper = certify::supportUpper(xf, pts.data(), int(pts.size()),
                                                   certify::exactly(nx), certify::exactly(ny));
        ++trials;
        CAPTURE(k, C, S, NX, NY, PX, PY);
        CHECK(atLeast(upper, exact, 32));
    }
    CHECK(trials > 1000);
    // The inputs do exercise the scan's rounding: its plain dot product was below the exact value.
    CHECK(scanRoundedDown > 100);
}

TEST_CASE("certify: containment needs certified orientation signs, not rounded ones",
          "[gjk][certify][properties]")
{
    // A triangle A and a point b whose Minkowski difference W_i = A_i - b rounds (the coordinates
    // need 61 bits) so that the three rounded orientations cross(W_i, W_i+1) are all positive: the
    // origin looks strictly inside. Exactly (__int128), b lies outside A: one orientation is
    // negative and the distance is positive, so an upper end of 0 would be wrong. Found by a random
    // search over A near (-2^60,-2^60) (2^60,2^60) (-2^60,2^60) on the 2^8 grid and b in
    // [-256, 256]^2 (this work, scratch program; the first hit).
    const std::int64_t ax[3] = {-1152921504606847488LL, 1152921504606847232LL,
                                -1152921504606845952LL};
    const std::int64_t ay[3] = {-1152921504606848000LL, 1152921504606848000LL,
                                1152921504606848000LL};
    const std::int64_t bx = -211, by = -125;
    std::vector<Vec2<double>> a;
    for (int i = 0; i < 3; ++i)
    {
        REQUIRE(std::int64_t(double(ax[i])) == ax[i]); // exact doubles
        REQUIRE(std::int64_t(double(ay[i])) == ay[i]);
        a.push_back({double(ax[i]), double(ay[i])});
    }
    const std::vector<Vec2<double>> b = {{double(bx), double(by)}};
    int roundedPositive = 0, exactNegative = 0;
    for (int i = 0; i < 3; ++i)
    {
        const int j = (i + 1) % 3;
        const double wxi = a[i].x - b[0].x, wyi = a[i].y - b[0].y, wxj = a[j].x - b[0].x,
                     wyj = a[j].y - b[0].y;
        roundedPositive += wxi * wyj - wyi * wxj > 0;
        const I128 exi = I128(ax[i]) - bx, eyi = I128(ay[i]) - by, exj = I128(ax[j]) - bx,
                   eyj = I128(ay[j]) - by;
        exactNegative += exi * eyj - eyi * exj < 0;
    }
    REQUIRE(roundedPositive == 3); // what a rounded-sign test would call containment
    REQUIRE(exactNegative >= 1);   // the origin is outside: the distance is positive

    const DistanceInput<double> in{{a.data(), 3, 0.0}, {b.data(), 1, 0.0}, {}, {}};
    Simplex<double> s;
    s.count = 3;
    for (int i = 0; i < 3; ++i)
    {
        s.v[i] = {};
        s.v[i].indexA = i;
        s.v[i].indexB = 0;
        s.v[i].a = 1.0 / 3;
    }
    DistanceOutput<double> out;
    certifyDistance(in, s, true, Vec2<double>{}, out);
    REQUIRE(out.certified);
    CHECK(out.upper > 0);
    CHECK(out.lower == 0);

    // The containment the certificate does claim: b well inside (exact orientations all positive
    // by hand: b = (0, 2^59) is inside the triangle), so upper is exactly 0.
    const std::vector<Vec2<double>> inside = {{0, 0x1p59}};
    const DistanceInput<double> in2{{a.data(), 3, 0.0}, {inside.data(), 1, 0.0}, {}, {}};
    DistanceOutput<double> out2;
    certifyDistance(in2, s, true, Vec2<double>{}, out2);
    CHECK(out2.certified);
    CHECK(out2.upper == 0);
}

// --- Support points ------------------------------------------------------------------------------

TEMPLATE_TEST_CASE("support: ties keep the lowest index", "[gjk][support][properties]", float,
                   double)
{
    using T = TestType;
    // support.hpp, findSupport: a repeated support point is recognised by its index, so among tied
    // vertices the scan must return the same one every time, the lowest index. The unit square
    // (0,0) (1,0) (1,1) (0,1) and a point twice: along +x vertices 1 and 2 tie (value 1), along +y
    // vertices 2 and 3, along (1, 1) only vertex 2, along -x vertices 0 and 3, along -y 0 and 1.
    const Vec2<T> square[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 1}};
    const Polygon<T> p{square, 5, T(0)};
    CHECK(findSupport(p, Vec2<T>{1, 0}) == 1);
    CHECK(findSupport(p, Vec2<T>{0, 1}) == 2);
    CHECK(findSupport(p, Vec2<T>{1, 1}) == 2); // not the repeated point 4
    CHECK(findSupport(p, Vec2<T>{-1, 0}) == 0);
    CHECK(findSupport(p, Vec2<T>{0, -1}) == 0);
    CHECK(findSupport(p, Vec2<T>{-1, 1}) == 3);
}
