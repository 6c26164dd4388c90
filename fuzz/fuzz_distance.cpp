// libFuzzer target: gjk::distance in float and double, every Options combination, cold and warm.
//
// The fuzz bytes decode into one query (the layout is below, at `decode`; fuzz/make_corpus.py
// writes seeds in it): the options, then two shapes of 1 to 20 points each with a radius, a
// rotation (c, s) and a translation. Numbers are finite values of every magnitude (small
// integers, m * 2^e down to the subnormals and up to the overflow threshold, raw bit patterns,
// repeats and neighbours of the previous value). Inputs that break the query's preconditions
// (a NaN or infinite number, a value that overflows when rounded to float, a rotation (0, 0),
// points out of convex order for the binary-search support) are skipped; a negative radius is
// used as its magnitude.
//
// Invariants, checked on the cold query and on a warm repeat from the cold query's cache
// (docs/fuzzing.md); a broken one aborts with a message naming it:
//  - no sanitizer report (ASan, UBSan) and no GJK contract assert (GJK2D_CHECKED);
//  - the distance is finite and >= 0, or out.outOfRange is set (also when the exact distance is
//    beyond the largest T: docs/gjk.md, "Rescaling");
//  - the witness points and the normal are finite, or out.outOfRange is set;
//  - 1 <= out.simplexCount <= 3 and 0 <= out.iterations <= the iteration limit
//    (gjk::iterationLimit: Options::maxIterations, or defaultMaxIterations when it is 0);
//  - when out.certified: lower <= upper and the exact distance (exact::distance, the exact side)
//    lies in [lower, upper];
//  - the warm/cold promise of docs/gjk.md ("Warm start"): warmRepeatsCold.
#include "gjk2d/distance.hpp"

#include <gjk2d/correct_fallback.hpp> // exact::shapeOf
#include <gjk2d/exact.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <type_traits>
#include <vector>

namespace
{

constexpr int kMaxPoints = 20;

// Reads the fuzz bytes front to back; past the end every byte is 0.
class Reader
{
  public:
    Reader(const std::uint8_t* data, std::size_t size) : p_(data), n_(size) {}
    std::uint8_t byte()
    {
        if (n_ == 0)
            return 0;
        --n_;
        return *p_++;
    }
    std::uint16_t u16()
    {
        const std::uint16_t lo = byte();
        return std::uint16_t(lo | (byte() << 8));
    }
    std::uint64_t u64()
    {
        std::uint64_t v = 0;
        for (int i = 0; i < 8; ++i)
            v |= std::uint64_t(byte()) << (8 * i);
        return v;
    }

  private:
    const std::uint8_t* p_;
    std::size_t n_;
};

// One number: a tag byte, then its payload. Exponent ranges cover each type's subnormals and its
// overflow threshold (the overflowing values are skipped as non-finite).
template <class T> double number(Reader& r, double previous)
{
    constexpr bool isFloat = std::is_same_v<T, float>;
    switch (r.byte() % 8)
    {
    case 0:
        return 0.0;
    case 1:
        return double(std::int8_t(r.byte())); // small integers
    case 2:
        return double(std::int8_t(r.byte())) / 64.0; // small fractions
    case 3:
    case 4:
    {
        // m * 2^e, m a 16-bit integer: exact, every magnitude.
        const double m = double(std::int16_t(r.u16()));
        const int e = isFloat ? -165 + r.u16() % 293 : -1090 + r.u16() % 2099;
        return std::ldexp(m, e);
    }
    case 5:
        return std::bit_cast<double>(r.u64()); // any bit pattern (NaN and inf are skipped)
    case 6:
        return previous; // a repeated coordinate
    default:             // a neighbour of the previous value
        return r.byte() & 1 ? std::nextafter(T(previous), std::numeric_limits<T>::infinity())
                            : std::nextafter(T(previous), -std::numeric_limits<T>::infinity());
    }
}

template <class T> struct Query
{
    std::vector<gjk::Vec2<T>> pointsA, pointsB;
    gjk::DistanceInput<T> input;
    gjk::Options options;
    bool trace = false;
};

// A double as a T, false when it is not finite there.
template <class T> bool toT(double v, T& out)
{
    out = T(v);
    return std::isfinite(out);
}

// Points in convex order for SupportStrategy::BinarySearch: (x_i * 2^ex, x_i^2 * 2^ey) for
// strictly increasing small integers x_i (a parabola: convex, no repeated point), optionally
// reversed and rotated cyclically. False when a scaled value is not exact in T.
template <class T> bool convexPoints(Reader& r, int count, std::vector<gjk::Vec2<T>>& out)
{
    constexpr bool isFloat = std::is_same_v<T, float>;
    const int ex = isFloat ? -120 + r.byte() % 230 : -1000 + r.u16() % 2000;
    const int ey = isFloat ? -120 + r.byte() % 230 : -1000 + r.u16() % 2000;
    const bool reversed = r.byte() & 1;
    const int shift = r.byte() % count;
    int x = std::int8_t(r.byte());
    std::vector<gjk::Vec2<T>> pts;
    for (int i = 0; i < count; ++i)
    {
        const T px = T(std::ldexp(double(x), ex)), py = T(std::ldexp(double(x) * x, ey));
        if (!std::isfinite(px) || !std::isfinite(py) || std::ldexp(double(px), -ex) != x ||
            std::ldexp(double(py), -ey) != double(x) * x)
            return false;
        pts.push_back({px, py});
        x += 1 + r.byte() % 8;
    }
    if (reversed)
        std::reverse(pts.begin(), pts.end());
    std::rotate(pts.begin(), pts.begin() + shift, pts.end());
    out = pts;
    return true;
}

// One shape: count, points, radius, rotation, translation.
template <class T>
bool decodeShape(Reader& r, bool convex, std::vector<gjk::Vec2<T>>& points, gjk::Polygon<T>& poly,
                 gjk::Transform<T>& xf)
{
    const int count = 1 + r.byte() % kMaxPoints;
    double prev = 0;
    if (convex)
    {
        if (!convexPoints(r, count, points))
            return false;
    }
    else
    {
        points.clear();
        for (int i = 0; i < count; ++i)
        {
            gjk::Vec2<T> p;
            prev = number<T>(r, prev);
            if (!toT(prev, p.x))
                return false;
            prev = number<T>(r, prev);
            if (!toT(prev, p.y))
                return false;
            points.push_back(p);
        }
    }
    T radius = T(0);
    if (r.byte() & 1 && !toT(std::abs(number<T>(r, prev)), radius))
        return false;
    switch (r.byte() % 4)
    {
    case 0:
        xf.q = {T(1), T(0)};
        break; // identity
    case 1:    // unit-ish: (cos, sin) of an angle, rounded to T
    {
        const double angle = r.u16() * (6.283185307179586 / 65536.0);
        xf.q = {T(std::cos(angle)), T(std::sin(angle))};
        break;
    }
    case 2: // arbitrary finite (c, s) != (0, 0), used as given (a rotation times |q|)
        if (!toT(number<T>(r, 1.0), xf.q.c) || !toT(number<T>(r, 0.0), xf.q.s))
            return false;
        if (xf.q.c == T(0) && xf.q.s == T(0)) // no transform: the query's precondition
            return false;
        break;
    default: // an exact quarter turn
    {
        static const T cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
        const int k = r.byte() % 4;
        xf.q = {cs[k][0], cs[k][1]};
        break;
    }
    }
    if (!toT(number<T>(r, prev), xf.p.x) || !toT(number<T>(r, prev), xf.p.y))
        return false;
    poly = {points.data(), count, radius};
    return true;
}

// Layout: byte 0 = option bits (0 direction, 1 stopping, 2 frame, 3 support, 4 certify,
// 5 !useRadii, 6 double, 7 trace); byte 1 = maxIterations (< 192: automatic, else byte - 191);
// then shape A, then shape B.
template <class T> bool decode(Reader& r, std::uint8_t bits, Query<T>& q)
{
    gjk::Options& o = q.options;
    o.direction =
        bits & 1 ? gjk::SearchDirection::ClosestPoint : gjk::SearchDirection::EdgePerpendicular;
    o.stopping = bits & 2 ? gjk::StoppingRule::DualityGap : gjk::StoppingRule::RepeatedSupport;
    o.frame = bits & 4 ? gjk::Frame::World : gjk::Frame::LocalA;
    o.support = bits & 8 ? gjk::SupportStrategy::BinarySearch : gjk::SupportStrategy::Linear;
    o.certify = bits & 16;
    o.useRadii = !(bits & 32);
    q.trace = bits & 128;
    const std::uint8_t limit = r.byte();
    o.maxIterations = limit < 192 ? 0 : limit - 191;
    const bool convex = o.support == gjk::SupportStrategy::BinarySearch;
    return decodeShape(r, convex, q.pointsA, q.input.proxyA, q.input.transformA) &&
           decodeShape(r, convex, q.pointsB, q.input.proxyB, q.input.transformB);
}

template <class T> void describe(const char* label, const gjk::DistanceOutput<T>& out)
{
    std::fprintf(stderr,
                 "  %s: distance %a, pointA (%a, %a), pointB (%a, %a), normal (%a, %a), stop %s, "
                 "iterations %d, simplexCount %d, outOfRange %d, rescaled %d, certified %d "
                 "[%.17g, %.17g]\n",
                 label, double(out.distance), double(out.pointA.x), double(out.pointA.y),
                 double(out.pointB.x), double(out.pointB.y), double(out.normal.x),
                 double(out.normal.y), gjk::stopReasonName(out.stop), out.iterations,
                 out.simplexCount, int(out.outOfRange), int(out.rescaled), int(out.certified),
                 out.lower, out.upper);
}

template <class T>
[[noreturn]] void finding(const gjk::DistanceOutput<T>& out, const char* which, const char* what)
{
    std::fprintf(stderr, "fuzz_distance: FINDING (%s, %s query): %s\n",
                 std::is_same_v<T, float> ? "float" : "double", which, what);
    describe("output", out);
    std::abort();
}

template <class T> bool sameBits(T a, T b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

template <class T> bool sameBits(gjk::Vec2<T> a, gjk::Vec2<T> b)
{
    return sameBits(a.x, b.x) && sameBits(a.y, b.y);
}

// The warm/cold promise as docs/gjk.md ("Warm start", "The promise, stated exactly") states it: a
// query warm-started from the cache a query left behind, on the same input and options, returns
// that query's distance, witness points and normal bit for bit, unless that query stopped at the
// iteration limit, or either of the two left the safe range (rescaled or outOfRange).
template <class T>
bool warmRepeatsCold(const gjk::DistanceOutput<T>& cold, const gjk::DistanceOutput<T>& warm)
{
    if (cold.stop == gjk::StopReason::IterationLimit || cold.rescaled || cold.outOfRange ||
        warm.rescaled || warm.outOfRange)
        return true;
    return sameBits(cold.distance, warm.distance) && sameBits(cold.pointA, warm.pointA) &&
           sameBits(cold.pointB, warm.pointB) && sameBits(cold.normal, warm.normal);
}

template <class T>
void checkOutput(const Query<T>& q, const gjk::DistanceOutput<T>& out, const char* which)
{
    const bool r = q.options.useRadii;
    auto truth = [&]
    {
        return exact::distance(exact::shapeOf(q.input.proxyA, q.input.transformA, r),
                               exact::shapeOf(q.input.proxyB, q.input.transformB, r));
    };
    if (!out.outOfRange && !(std::isfinite(out.distance) && out.distance >= T(0)))
        finding(out, which, "distance is negative or not finite and outOfRange is not set");
    auto finite = [](gjk::Vec2<T> v) { return std::isfinite(v.x) && std::isfinite(v.y); };
    if (!out.outOfRange && !(finite(out.pointA) && finite(out.pointB) && finite(out.normal)))
        finding(out, which,
                "a witness point or the normal is not finite and outOfRange is not set");
    if (out.simplexCount < 1 || out.simplexCount > 3)
        finding(out, which, "simplexCount outside 1..3");
    const int limit = gjk::iterationLimit(q.options, q.input.proxyA.count, q.input.proxyB.count);
    if (out.iterations < 0 || out.iterations > limit)
        finding(out, which, "iterations outside 0..the iteration limit");
    if (out.certified && !q.options.certify)
        finding(out, which, "certified without Options::certify");
    if (!out.certified)
        return;
    if (!(out.lower <= out.upper))
        finding(out, which, "certified interval with lower > upper (or NaN)");
    const exact::Result exactResult = truth();
    // exactResult.lower and .upper are the doubles enclosing the exact value (equal when it is a
    // double), so [out.lower, out.upper] contains it exactly when it contains both.
    if (!(out.lower <= exactResult.lower && exactResult.upper <= out.upper))
    {
        std::fprintf(stderr, "certified [%.17g, %.17g], exact in [%.17g, %.17g]\n", out.lower,
                     out.upper, exactResult.lower, exactResult.upper);
        finding(out, which, "the certified interval does not contain the exact distance");
    }
}

template <class T> void run(Reader& r, std::uint8_t bits)
{
    Query<T> q;
    if (!decode(r, bits, q))
        return; // a precondition does not hold: not a query
    gjk::Trace<T> trace;
    gjk::SimplexCache cache;
    const gjk::DistanceOutput<T> cold =
        gjk::distance(q.input, cache, q.options, q.trace ? &trace : nullptr);
    checkOutput(q, cold, "cold");
    const gjk::DistanceOutput<T> warm =
        gjk::distance(q.input, cache, q.options, q.trace ? &trace : nullptr);
    checkOutput(q, warm, "warm");
    if (!warmRepeatsCold(cold, warm))
    {
        describe("cold", cold);
        finding(warm, "warm",
                "a warm repeat does not give the cold answer's bits (warmRepeatsCold)");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    Reader r(data, size);
    const std::uint8_t bits = r.byte();
    try
    {
        if (bits & 64)
            run<double>(r, bits);
        else
            run<float>(r, bits);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "fuzz_distance: FINDING: exception: %s\n", e.what());
        std::abort();
    }
    return 0;
}
