// libFuzzer target: the default route's filter (exact/src/filter.cpp) against the GMP route
// (exact::Options::filter = false) on hostile inputs: extreme scales, collinear and duplicate
// points, tiny edges, exact and inexact rotations, radii. Both results must agree bit for bit,
// the squared rational included (docs/fuzzing.md, "fuzz_truth"); a difference aborts. So must the
// same truth of the shapes prepared (exact::PreparedShape, the runner's path), counts included.
// Then the point-to-shape distance (exact::pointToShapeDistance, one-shot and on a PreparedShape,
// decided in floating point where its bound allows) against the GMP route on the truth's witness
// points and the shapes' points.
//
// Layout (`decode`): per shape, byte 0: count (1 + b % 8) and transform kind (b / 8 % 4:
// identity, quarter turn, (cos, sin) of a number, any finite (c, s)); byte 1: point kind (b % 4:
// free, collinear along one direction, duplicates of the previous point, neighbours of the
// previous point a few ulps apart) and whether it has a radius (b & 4); then numbers, each a
// selector byte and up to 8 bytes (`number`).
#include <gjk2d/exact.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace
{

struct Reader
{
    const std::uint8_t* data;
    std::size_t size, at = 0;
    std::uint8_t byte() { return at < size ? data[at++] : 0; }
    std::uint64_t word()
    {
        std::uint64_t w = 0;
        for (int k = 0; k < 8; ++k)
            w = w << 8 | byte();
        return w;
    }
};

// A finite double: a small integer, a small fraction, m * 2^e over the whole exponent range, raw
// bits, or a neighbour of the previous number.
double number(Reader& r, double previous)
{
    const std::uint8_t sel = r.byte();
    switch (sel % 5)
    {
    case 0:
        return double(std::int8_t(r.byte()));
    case 1:
        return double(std::int8_t(r.byte())) / double(1 + r.byte());
    case 2:
    {
        const double m = double(std::int32_t(r.word() >> 32)) / 2147483648.0;
        const int hi = r.byte(), lo = r.byte();
        return std::ldexp(m, int(std::int16_t(hi << 8 | lo)) % 1100);
    }
    case 3:
    {
        const double v = std::bit_cast<double>(r.word());
        return std::isfinite(v) ? v : 0.0;
    }
    default:
    {
        double v = previous;
        for (int k = r.byte() % 4; k >= 0; --k)
            v = std::nextafter(v, sel & 8 ? HUGE_VAL : -HUGE_VAL);
        return std::isfinite(v) ? v : previous;
    }
    }
}

exact::Shape shape(Reader& r)
{
    exact::Shape s;
    const std::uint8_t head = r.byte(), kind = r.byte();
    const int count = 1 + head % 8;
    double prev = 0;
    const double dx = number(r, prev), dy = number(r, dx);
    for (int i = 0; i < count; ++i)
    {
        exact::Point p;
        switch (kind % 4)
        {
        case 0:
            p.x = number(r, prev);
            p.y = number(r, p.x);
            break;
        case 1: // collinear: i * (dx, dy), exact when the products are
            p = {double(i) * dx, double(i) * dy};
            break;
        case 2:
            p = i % 2 && !s.points.empty() ? s.points.back() : exact::Point{dx, dy};
            break;
        default:
            p = s.points.empty() ? exact::Point{dx, dy} : s.points.back();
            p.x = std::nextafter(p.x, r.byte() & 1 ? HUGE_VAL : -HUGE_VAL);
            p.y = std::nextafter(p.y, r.byte() & 1 ? HUGE_VAL : -HUGE_VAL);
        }
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            p = {0, 0};
        prev = p.y;
        s.points.push_back(p);
    }
    switch (head / 8 % 4)
    {
    case 0:
        break;
    case 1:
        s.c = 0, s.s = r.byte() & 1 ? 1 : -1;
        break;
    case 2:
    {
        const double t = number(r, 0);
        s.c = std::cos(t), s.s = std::sin(t);
        break;
    }
    default:
        s.c = number(r, 1), s.s = number(r, 0);
    }
    s.px = number(r, prev), s.py = number(r, s.px);
    if (kind & 4)
        s.radius = std::fabs(number(r, 0));
    return s;
}

bool same(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    Reader r{data, size};
    const exact::Shape a = shape(r), b = shape(r);
    exact::Options gmp;
    gmp.filter = false;
    exact::Result f, e;
    try
    {
        f = exact::distance(a, b);
        e = exact::distance(a, b, gmp);
    }
    catch (const std::invalid_argument&)
    {
        return 0; // refused input (a product overflowed to a non-finite value is not refused)
    }
    const bool ok = f.overlap == e.overlap && f.squaredNum == e.squaredNum &&
                    f.squaredDen == e.squaredDen && same(f.squared, e.squared) &&
                    same(f.distance, e.distance) && same(f.lower, e.lower) &&
                    same(f.upper, e.upper) && same(f.witnessA.x, e.witnessA.x) &&
                    same(f.witnessA.y, e.witnessA.y) && same(f.witnessB.x, e.witnessB.x) &&
                    same(f.witnessB.y, e.witnessB.y) && e.fallbacks.gmp;
    if (!ok)
        std::abort();
    // The runner's truth: the same call on prepared shapes (the hulls made once), bit for bit,
    // fallback counts included.
    {
        const exact::PreparedShape pa(a), pb(b);
        const exact::Result p = exact::distance(pa, pb);
        const bool same_ =
            p.overlap == f.overlap && p.squaredNum == f.squaredNum &&
            p.squaredDen == f.squaredDen && same(p.squared, f.squared) &&
            same(p.distance, f.distance) && same(p.lower, f.lower) && same(p.upper, f.upper) &&
            same(p.witnessA.x, f.witnessA.x) && same(p.witnessA.y, f.witnessA.y) &&
            same(p.witnessB.x, f.witnessB.x) && same(p.witnessB.y, f.witnessB.y) &&
            p.fallbacks.hull == f.fallbacks.hull && p.fallbacks.merge == f.fallbacks.merge &&
            p.fallbacks.feature == f.fallbacks.feature && p.fallbacks.gmp == f.fallbacks.gmp;
        if (!same_)
            std::abort();
    }
    // exact::pointToShapeDistance's own filter (filteredPointDistance) against its GMP route, on
    // the truth's witness points (on or within a rounding of each rounded surface: what the
    // runner's witness checks measure) and a point of each shape, against both shapes.
    const exact::Point probes[] = {f.witnessA, f.witnessB, a.points[0], b.points.back()};
    // The one-shot call and a prepared shape (exact::PreparedShape, made once per shape) alike.
    for (const exact::Shape* s : {&a, &b})
    {
        const exact::PreparedShape prepared(*s);
        for (const exact::Point& p : probes)
        {
            if (!std::isfinite(p.x) || !std::isfinite(p.y))
                continue;
            exact::Shape q;
            q.points = {p};
            const double d = exact::distance(q, *s, gmp).distance;
            if (!same(exact::pointToShapeDistance(*s, p), d) ||
                !same(exact::pointToShapeDistance(prepared, p), d))
                std::abort();
        }
    }
    return 0;
}
