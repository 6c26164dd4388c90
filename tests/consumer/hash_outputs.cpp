// A consumer of gjk2d/distance.hpp built with the user's flags, not the project's: it hashes every
// output bit of 40,000 queries so that builds with different compilers and flags can be compared
// (docs/gjk.md, "Compiler flags"; run by tests/consumer/flag_build.sh), and builds for other
// platforms too (docs/gjk.md, "The same bits on every platform"; tests/consumer/cross_build.sh):
// the hash reads every value in little-endian byte order (Hash), so a big-endian s390x prints the
// x86-64 hashes.
//
// Only the library's own arithmetic may differ between builds. Every input is made from integers
// by at most one floating-point operation (an int converted exactly, or one division of two exact
// ints, correctly rounded by IEEE 754 whatever the flags), and the random numbers come from
// std::mt19937_64's raw output (the engine is specified bit for bit; the distributions are not).
// Divisions give full-length mantissas: with small integer coordinates most products would be
// exact and a fused multiply-add could not change them.
//
// Per scalar type: 20,000 queries on random 3-8 point shapes (any order, interior points), half of
// them with Options::certify; variants of the search direction and the stopping rule; radii on a
// third; each pair queried cold and then warm from the cold query's cache after B moved. Hashed:
// distance, witness points, normal, iterations, simplex count, stop reason, range flags, the cache,
// the certified flag and interval. Output: one line per scalar type and field group, then "all".
// Then 15,000 correctly rounded double queries (runCorrect), and with -DGJK_HASH_BATCH (and
// gjk/src/batch.cpp linked) 15,000 batched queries per type (runBatch): one "all" line each.
//
// Besides the bits, every build checks what must hold whatever its bits (exit 1 otherwise): with
// the certified interval [lower, upper] as the truth (it contains the exact distance d*), each
// certified query of the reference variant (edge-perpendicular direction) has
// max(d - lower, upper - d) >= |d - d*| within the a-priori bound of docs/error-bound.md. With
// `--dump FILE` the certified intervals are written out (raw doubles, query order); with
// `--against FILE` (another build's dump) each interval must intersect that build's: both contain
// d*. This is how a build whose bits are not promised (Clang -ffp-contract=fast) is still tested.
#include "gjk2d/distance.hpp"
#ifdef GJK_HASH_BATCH
#include "gjk2d/batch.hpp"
#endif

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

namespace
{

// FNV-1a, 64 bits, over each value's bytes in little-endian order whatever the platform's order
// (a big-endian s390x prints the x86-64 hash): a float or double as its IEEE bits, an integer or
// bool as its two's-complement bytes. On a little-endian machine these are the bytes in memory,
// so the hashes are those of the memcpy this replaced.
struct Hash
{
    std::uint64_t h = 0xcbf29ce484222325ull;
    template <class V> void add(const V& v)
    {
        static_assert(std::is_arithmetic_v<V> && sizeof(V) <= 8);
        std::uint64_t bits = 0;
        if constexpr (std::is_same_v<V, float>)
            bits = std::bit_cast<std::uint32_t>(v);
        else if constexpr (std::is_same_v<V, double>)
            bits = std::bit_cast<std::uint64_t>(v);
        else
        {
            static_assert(std::is_integral_v<V>);
            bits = std::uint64_t(v); // two's complement (C++20): the low bytes are v's
        }
        for (std::size_t i = 0; i < sizeof(V); ++i)
            h = (h ^ ((bits >> (8 * i)) & 0xff)) * 0x100000001b3ull;
    }
};

struct Hashes
{
    Hash distance, witness, normal, steps, cache, interval, all;
};

template <class T> struct Shape
{
    std::vector<gjk::Vec2<T>> points;
    T radius = 0;
};

struct Source
{
    std::mt19937_64 rng;
    explicit Source(std::uint64_t seed) : rng(seed) {}
    // Uniform in [lo, hi] from the raw 64-bit output (the modulo bias does not matter here).
    long long between(long long lo, long long hi)
    {
        return lo + (long long)(rng() % std::uint64_t(hi - lo + 1));
    }
    // One correctly rounded division of two exact integers.
    template <class T> T ratio(long long num, long long den) { return T(num) / T(den); }
    // (Function arguments are evaluated in an unspecified order, GCC's differs from Clang's: each
    // draw is its own statement.)
    template <class T> T coordinate(int range)
    {
        const long long num = between(-range * 97, range * 97);
        const long long den = between(7, 97);
        return ratio<T>(num, den);
    }
};

template <class T> Shape<T> randomShape(Source& src)
{
    Shape<T> s;
    const int n = int(src.between(3, 8));
    for (int i = 0; i < n; ++i)
        s.points.push_back({src.coordinate<T>(4), src.coordinate<T>(4)});
    if (src.between(0, 2) == 0)
        s.radius = src.ratio<T>(src.between(0, 64), 128);
    return s;
}

// A rotation (c, s) = (m^2 - n^2, 2mn) / (m^2 + n^2) from Euclid's formula: integer arithmetic,
// then one division each. A unit rotation to within rounding (both of isUnitRotation's branches
// occur), any quadrant.
template <class T> gjk::Transform<T> randomTransform(Source& src, int range)
{
    const long long m = src.between(1, 40), n = src.between(0, 40);
    long long a = m * m - n * n, b = 2 * m * n;
    const long long r = m * m + n * n;
    if (src.between(0, 1))
        a = -a;
    if (src.between(0, 1))
        b = -b;
    gjk::Transform<T> xf;
    xf.q = {src.ratio<T>(a, r), src.ratio<T>(b, r)};
    xf.p = {src.coordinate<T>(range), src.coordinate<T>(range)};
    return xf;
}

template <class T>
void hashOutput(Hashes& h, const gjk::DistanceOutput<T>& o, const gjk::SimplexCache& c)
{
    h.distance.add(o.distance);
    h.witness.add(o.pointA.x), h.witness.add(o.pointA.y), h.witness.add(o.pointB.x),
        h.witness.add(o.pointB.y);
    h.normal.add(o.normal.x), h.normal.add(o.normal.y);
    h.steps.add(o.iterations), h.steps.add(o.simplexCount), h.steps.add(std::uint8_t(o.stop));
    h.steps.add(o.outOfRange), h.steps.add(o.rescaled);
    h.cache.add(c.count), h.cache.add(c.edgeBase), h.cache.add(c.searchA), h.cache.add(c.searchB);
    for (int i = 0; i < 3; ++i)
        h.cache.add(c.indexA[i]), h.cache.add(c.indexB[i]);
    h.interval.add(o.certified), h.interval.add(o.lower), h.interval.add(o.upper);
    // "all" in a fixed field order, independent of the groups above.
    for (const Hash* g : {&h.distance, &h.witness, &h.normal, &h.steps, &h.cache, &h.interval})
        h.all.add(g->h);
}

struct Counts
{
    int queries = 0, certified = 0, apart = 0, broken = 0, bounded = 0, beyondBound = 0,
        disjoint = 0, unmatched = 0; // unmatched: intervals with none left in the --against dump
    double worstRatio = 0;           // largest max(d - lower, upper - d) / bound
};

std::FILE* dumpFile = nullptr;    // --dump
std::FILE* againstFile = nullptr; // --against

// The a-priori bound of docs/error-bound.md (validation/src/evaluate/bounds.cpp, errorBound) for
// the reference variant, its metrics in world lengths evaluated in double (their own rounding,
// ~1e-16 relative, is far below the bound's first-order slack):
//   u (4 A + 43 B + 10.2 D + 1.5 B~ + 5 W + 6.5 d + 3.5 (rA + rB)) [+ 16 u W with DualityGap]
template <class T>
double errorBound(const gjk::DistanceInput<T>& in, const gjk::Options& o, double d)
{
    auto world = [](const gjk::Transform<T>& xf, gjk::Vec2<T> v)
    {
        const double c = xf.q.c, s = xf.q.s;
        return std::pair{c * double(v.x) - s * double(v.y) + double(xf.p.x),
                         s * double(v.x) + c * double(v.y) + double(xf.p.y)};
    };
    const double sizeA = std::hypot(double(in.transformA.q.c), double(in.transformA.q.s));
    const double sizeB = std::hypot(double(in.transformB.q.c), double(in.transformB.q.s));
    const double pAx = in.transformA.p.x, pAy = in.transformA.p.y;
    double A = 0, B = 0, Bm = 0, W = 0;
    for (int i = 0; i < in.proxyA.count; ++i)
        A = std::max(
            A, sizeA * std::hypot(double(in.proxyA.points[i].x), double(in.proxyA.points[i].y)));
    for (int j = 0; j < in.proxyB.count; ++j)
    {
        B = std::max(
            B, sizeB * std::hypot(double(in.proxyB.points[j].x), double(in.proxyB.points[j].y)));
        const auto [bx, by] = world(in.transformB, in.proxyB.points[j]);
        Bm = std::max(Bm, std::hypot(bx - pAx, by - pAy));
        for (int i = 0; i < in.proxyA.count; ++i)
        {
            const auto [ax, ay] = world(in.transformA, in.proxyA.points[i]);
            W = std::max(W, std::hypot(ax - bx, ay - by));
        }
    }
    const double D = std::hypot(double(in.transformB.p.x) - pAx, double(in.transformB.p.y) - pAy);
    const double u = double(std::numeric_limits<T>::epsilon()) / 2;
    double terms = 4 * A + 43 * B + 10.2 * D + 1.5 * Bm + 5 * W + 6.5 * d;
    if (o.stopping == gjk::StoppingRule::DualityGap)
        terms += 16 * W;
    return u * (terms + 3.5 * (double(in.proxyA.radius) + double(in.proxyB.radius))) +
           double(std::numeric_limits<T>::denorm_min());
}

template <class T> void run(const char* name, std::uint64_t seed, int pairs)
{
    Source src(seed);
    Hashes h;
    Counts n;
    for (int i = 0; i < pairs; ++i)
    {
        const Shape<T> a = randomShape<T>(src), b = randomShape<T>(src);
        gjk::DistanceInput<T> in{{a.points.data(), int(a.points.size()), a.radius},
                                 {b.points.data(), int(b.points.size()), b.radius},
                                 randomTransform<T>(src, 2),
                                 randomTransform<T>(src, 12)};
        gjk::Options o;
        o.certify = (i & 1) != 0;
        o.stopping =
            (i >> 1) % 3 == 2 ? gjk::StoppingRule::DualityGap : gjk::StoppingRule::RepeatedSupport;
        o.direction = (i >> 1) % 4 == 3 ? gjk::SearchDirection::ClosestPoint
                                        : gjk::SearchDirection::EdgePerpendicular;
        gjk::SimplexCache cache;
        for (int pass = 0; pass < 2; ++pass) // cold, then warm after B moved
        {
            if (pass == 1) // one addition of two exact values: the same rounding in every build
                in.transformB.p = {in.transformB.p.x + src.ratio<T>(src.between(-64, 64), 1024),
                                   in.transformB.p.y + src.ratio<T>(src.between(-64, 64), 1024)};
            const gjk::DistanceOutput<T> out = gjk::distance(in, cache, o);
            hashOutput(h, out, cache);
            ++n.queries;
            n.apart += out.distance > T(0);
            if (o.certify)
            {
                const double interval[2] = {out.lower, out.upper};
                if (dumpFile && std::fwrite(interval, sizeof interval, 1, dumpFile) != 1)
                {
                    std::printf("%s BROKEN: writing the interval dump failed\n", name);
                    std::exit(1);
                }
                double other[2];
                if (againstFile && std::fread(other, sizeof other, 1, againstFile) != 1)
                    ++n.unmatched; // a short dump: a comparison that cannot be made is a failure
                else if (againstFile &&
                         !(std::max(interval[0], other[0]) <= std::min(interval[1], other[1])))
                    ++n.disjoint;
            }
            if (out.certified)
            {
                ++n.certified;
                const double d = double(out.distance);
                if (!(out.lower <= out.upper))
                    ++n.broken;
                if (o.direction == gjk::SearchDirection::EdgePerpendicular && !out.outOfRange &&
                    out.stop != gjk::StopReason::IterationLimit)
                {
                    const double error = std::max(d - out.lower, out.upper - d); // >= |d - d*|
                    const double ratio = error / errorBound(in, o, out.upper);
                    ++n.bounded;
                    n.worstRatio = std::max(n.worstRatio, ratio);
                    n.beyondBound += !(ratio <= 1);
                }
            }
        }
    }
    const std::pair<const char*, const Hash*> groups[] = {{"distance", &h.distance},
                                                          {"witness", &h.witness},
                                                          {"normal", &h.normal},
                                                          {"steps", &h.steps},
                                                          {"cache", &h.cache},
                                                          {"interval", &h.interval},
                                                          {"all", &h.all}};
    for (const auto& [group, hash] : groups)
        std::printf("%s %-8s %016llx\n", name, group, (unsigned long long)hash->h);
    std::printf("%s queries %d certified %d apart %d\n", name, n.queries, n.certified, n.apart);
    // The worst ratio goes to stderr: it is a measurement, and its bits may differ between builds.
    std::fprintf(stderr, "%s bound checked on %d queries, worst error / bound %.3g\n", name,
                 n.bounded, n.worstRatio);
    if (n.broken || n.beyondBound || n.disjoint || n.unmatched)
    {
        std::printf(
            "%s BROKEN: %d inverted certified intervals, %d errors beyond the bound, %d intervals "
            "disjoint from the other build's, %d missing from it (its dump is shorter)\n",
            name, n.broken, n.beyondBound, n.disjoint, n.unmatched);
        std::fflush(stdout);
        std::exit(1);
    }
}

// --- The correctly rounded query (Options::correctlyRounded, gjk2d/correct.hpp), double only
// ------
//
// Its stages differ by platform: the extended stage runs where long double is the x87 80-bit
// format (x86) and is skipped elsewhere (binary128 on aarch64, riscv64 and s390x), and what no
// stage decides (CorrectPath::NeedsExact) needs exact arithmetic (GMP), not linked here. So each
// query runs twice: with this platform's stages, and with the portable ones -- on x86 with the x87
// precision control lowered to 53 bits, which makes the extended stage step aside
// (correct::extendedPrecisionOn), elsewhere the same stages again. The portable run is the same
// computation on every platform: its decided answers (with their path) are hashed, its undecided
// ones counted. A decided answer is the correctly rounded one, so the two runs' answers must agree
// wherever both decided (exit 1 otherwise); what only one run decided is printed to stderr. One
// pair in 25 is two integer boxes in exact contact (box, below): no stage decides exact touching,
// so the count of undecided queries is not 0 by construction.
class PortableStages
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  public:
    PortableStages()
    {
        __asm__ volatile("fnstcw %0" : "=m"(saved) : : "memory");
        const unsigned short lowered = (saved & ~0x0300) | 0x0200; // precision control 53 bits
        __asm__ volatile("fldcw %0" : : "m"(lowered) : "memory");
    }
    ~PortableStages()
    {
        __asm__ volatile("fldcw %0" : : "m"(saved) : "memory");
    }
    PortableStages(const PortableStages&) = delete;
    PortableStages& operator=(const PortableStages&) = delete;

  private:
    unsigned short saved = 0;
#endif
};

// An axis-aligned box [0, w] x [0, h] of integer sides 2 to 9, counter-clockwise from the origin.
Shape<double> box(Source& src)
{
    const double w = double(src.between(2, 9));
    const double h = double(src.between(2, 9));
    return {{{0, 0}, {w, 0}, {w, h}, {0, h}}, 0};
}

void runCorrect(const char* name, std::uint64_t seed, int pairs)
{
    Source src(seed);
    Hash h;
    int queries = 0, decided = 0, disagree = 0, onlyHere = 0, onlyPortable = 0;
    int paths[int(gjk::CorrectPath::Exact) + 1] = {}; // this platform's stages
    for (int i = 0; i < pairs; ++i)
    {
        const bool touching = i % 25 == 24;
        const Shape<double> a = touching ? box(src) : randomShape<double>(src);
        const Shape<double> b = touching ? box(src) : randomShape<double>(src);
        gjk::DistanceInput<double> in{{a.points.data(), int(a.points.size()), a.radius},
                                      {b.points.data(), int(b.points.size()), b.radius},
                                      randomTransform<double>(src, 2),
                                      randomTransform<double>(src, 12)};
        if (touching) // B's left edge on A's right edge, overlapping it by at least 1
        {
            const long long ha = (long long)a.points[2].y, hb = (long long)b.points[2].y;
            in.transformA = {};
            in.transformB = {};
            const double dy = double(src.between(1 - hb, ha - 1));
            in.transformB.p = {a.points[1].x, dy};
        }
        gjk::Options o;
        o.correctlyRounded = true; // any plain options name the features: both directions
        o.direction = i % 4 == 3 ? gjk::SearchDirection::ClosestPoint
                                 : gjk::SearchDirection::EdgePerpendicular;
        gjk::SimplexCache here, portable;
        for (int pass = 0; pass < 3; ++pass) // cold, warm after B moved, warm repeat
        {
            if (pass == 1)
                in.transformB.p = {
                    in.transformB.p.x + src.ratio<double>(src.between(-64, 64), 1024),
                    in.transformB.p.y + src.ratio<double>(src.between(-64, 64), 1024)};
            const gjk::DistanceOutput<double> outHere = gjk::distance(in, here, o);
            gjk::DistanceOutput<double> outPortable;
            {
                const PortableStages lowered;
                outPortable = gjk::distance(in, portable, o);
            }
            ++queries;
            ++paths[int(outHere.path)];
            const bool decidedHere = outHere.path != gjk::CorrectPath::NeedsExact;
            const bool decidedPortable = outPortable.path != gjk::CorrectPath::NeedsExact;
            h.add(decidedPortable);
            if (decidedPortable)
                h.add(std::uint8_t(outPortable.path)), h.add(outPortable.distance);
            decided += decidedPortable;
            onlyHere += decidedHere && !decidedPortable;
            onlyPortable += decidedPortable && !decidedHere;
            disagree += decidedHere && decidedPortable &&
                        std::bit_cast<std::uint64_t>(outHere.distance) !=
                            std::bit_cast<std::uint64_t>(outPortable.distance);
        }
    }
    std::printf("%s all      %016llx\n", name, (unsigned long long)h.h);
    std::printf("%s queries %d decided %d undecided %d (portable stages)\n", name, queries, decided,
                queries - decided);
    using P = gjk::CorrectPath;
    std::fprintf(stderr,
                 "%s this platform's stages: Double %d, Extended %d, DoubleDouble %d, NeedsExact "
                 "%d; decided only by them %d, only by the portable ones %d\n",
                 name, paths[int(P::Double)], paths[int(P::Extended)], paths[int(P::DoubleDouble)],
                 paths[int(P::NeedsExact)], onlyHere, onlyPortable);
    if (disagree)
    {
        std::printf("%s BROKEN: %d decided answers differ between this platform's stages and the "
                    "portable ones\n",
                    name, disagree);
        std::fflush(stdout);
        std::exit(1);
    }
}

#ifdef GJK_HASH_BATCH
// --- The batch's portable fallback (gjk::distanceBatchLanes, gjk/src/batch.cpp)
// ----------------------
//
// Built with -DGJK_HASH_BATCH and gjk/src/batch.cpp linked (tests/consumer/cross_build.sh; the
// flag matrix builds the header-only program). The batch's SIMD lanes exist only with GCC on
// x86-64 (GJK_BATCH_LANES); elsewhere, and with BatchIsa::Scalar anywhere, it is the portable loop
// over gjk::distance. This runs the pairs with Scalar, hashed, and again with Best (the widest
// lanes here, the same loop elsewhere), whose outputs and caches batch.hpp promises bit for bit
// equal: its hash must be the same (exit 1 otherwise). Half the pairs with the reference options,
// half certified (the lanes end those in the scalar finishQuery); cold, warm after B moved, and a
// warm repeat.
template <class T> void runBatch(const char* name, std::uint64_t seed, int pairs)
{
    Source src(seed);
    std::vector<Shape<T>> shapes;
    std::vector<gjk::Transform<T>> transforms;
    std::vector<gjk::Vec2<T>> moves; // B's move before the second pass
    for (int i = 0; i < pairs; ++i)
    {
        shapes.push_back(randomShape<T>(src));
        shapes.push_back(randomShape<T>(src));
        transforms.push_back(randomTransform<T>(src, 2));
        transforms.push_back(randomTransform<T>(src, 12));
        const T dx = src.ratio<T>(src.between(-64, 64), 1024);
        const T dy = src.ratio<T>(src.between(-64, 64), 1024);
        moves.push_back({dx, dy});
    }
    const std::size_t half = std::size_t(pairs) / 2;
    gjk::Options certified;
    certified.certify = true;
    auto hashBatch = [&](gjk::BatchIsa isa, gjk::BatchIsa& ran)
    {
        std::vector<gjk::DistanceInput<T>> inputs;
        for (int i = 0; i < pairs; ++i)
        {
            const Shape<T>&a = shapes[2 * i], &b = shapes[2 * i + 1];
            inputs.push_back({{a.points.data(), int(a.points.size()), a.radius},
                              {b.points.data(), int(b.points.size()), b.radius},
                              transforms[2 * i],
                              transforms[2 * i + 1]});
        }
        std::vector<gjk::SimplexCache> caches(inputs.size());
        std::vector<gjk::DistanceOutput<T>> outputs(inputs.size());
        Hashes h;
        for (int pass = 0; pass < 3; ++pass) // cold, warm after B moved, warm repeat
        {
            for (std::size_t k = 0; pass == 1 && k < inputs.size(); ++k)
                inputs[k].transformB.p = {inputs[k].transformB.p.x + moves[k].x,
                                          inputs[k].transformB.p.y + moves[k].y};
            for (const auto& [begin, end, options] :
                 {std::tuple{std::size_t(0), half, gjk::referenceOptions},
                  std::tuple{half, inputs.size(), certified}})
            {
                gjk::BatchStats stats;
                gjk::distanceBatchLanes(
                    std::span<const gjk::DistanceInput<T>>(inputs.data() + begin, end - begin),
                    std::span(caches.data() + begin, end - begin),
                    std::span(outputs.data() + begin, end - begin), options, isa, &stats);
                ran = stats.isa;
            }
            for (std::size_t k = 0; k < inputs.size(); ++k)
                hashOutput(h, outputs[k], caches[k]);
        }
        return h.all.h;
    };
    gjk::BatchIsa portable = gjk::BatchIsa::Scalar, best = gjk::BatchIsa::Scalar;
    const std::uint64_t hashPortable = hashBatch(gjk::BatchIsa::Scalar, portable);
    const std::uint64_t hashBest = hashBatch(gjk::BatchIsa::Best, best);
    std::printf("%s all      %016llx\n", name, (unsigned long long)hashPortable);
    std::printf("%s queries %d\n", name, 3 * pairs);
    std::fprintf(stderr, "%s ran %s (hashed) and %s\n", name, gjk::batchIsaName(portable),
                 gjk::batchIsaName(best));
    if (portable != gjk::BatchIsa::Scalar || hashBest != hashPortable)
    {
        std::printf("%s BROKEN: the batch with %s (%016llx) differs from the portable loop\n", name,
                    gjk::batchIsaName(best), (unsigned long long)hashBest);
        std::fflush(stdout);
        std::exit(1);
    }
}
#endif

} // namespace

int main(int argc, char** argv)
{
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string_view arg = argv[i];
        std::FILE*& f = arg == "--dump" ? dumpFile : againstFile;
        if ((arg != "--dump" && arg != "--against") ||
            !(f = std::fopen(argv[i + 1], arg == "--dump" ? "wb" : "rb")))
        {
            std::fprintf(stderr, "usage: hash_outputs [--dump FILE] [--against FILE]\n");
            return 2;
        }
    }
    // 10,000 pairs per type, each queried cold and warm: 20,000 queries per type, 40,000 in all.
    run<float>("float ", 20260601, 10000);
    run<double>("double", 20260602, 10000);
    // 5,000 pairs, each queried cold, warm after a move and warm again, with both stage sets.
    runCorrect("double-correct", 20260603, 5000);
#ifdef GJK_HASH_BATCH
    runBatch<float>("float-batch", 20260604, 5000);
    runBatch<double>("double-batch", 20260605, 5000);
#endif
    if (dumpFile && std::fclose(dumpFile) != 0)
    {
        std::printf("BROKEN: writing the interval dump failed\n");
        return 1;
    }
    if (againstFile && std::fgetc(againstFile) != EOF) // a longer dump: another sequence of queries
    {
        std::printf("BROKEN: the --against dump holds more intervals than this build computed\n");
        return 1;
    }
    return 0;
}
