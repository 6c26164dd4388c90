// A user of the installed SDK (tests/plugins/plugin_ci.py, step sdk): every query the SDK declares,
// called through the installed headers (gjk2d/...) and libraries, each checked against a value
// derived by hand. Prints one line per check and "sdk_consumer: all N checks passed"; exits 1 when
// a check fails.
//
// The shapes, by hand: A is the unit square [0, 1]^2 at the origin.
// - B, the same square at (2, 0): B's left edge x = 2 faces A's right edge x = 1, so the distance
//   is exactly 1, the witness points share their y in [0, 1], and the normal is (1, 0).
// - C, the same square at (2, 2): the closest points are the corners (1, 1) and (2, 2), so the
//   distance is sqrt(2), whose correctly rounded double is std::sqrt(2.0) (IEEE square roots are
//   correctly rounded), and sqrt(2) is no double: a certified interval around it is not a point.
// - The batch: B at (2 + k, 0) for k = 0 .. 9, distance 1 + k exactly, in double and in float.
// - The exact side: the triangles (0, 0), (1, 0), (0, 1) and (3, 0), (4, 0), (3, 1), 2 apart.
#include <gjk2d/batch.hpp>
#include <gjk2d/correct_fallback.hpp>
#include <gjk2d/distance.hpp>
#include <gjk2d/exact.hpp>
#include <gjk2d/plugin.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <vector>

namespace
{

int g_checks = 0, g_failures = 0;

void check(bool ok, const char* what)
{
    ++g_checks;
    if (!ok)
        ++g_failures;
    std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
}

template <class T> bool sameBits(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class T> struct Squares
{
    gjk::Vec2<T> square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

    gjk::DistanceInput<T> at(T x, T y) const
    {
        gjk::DistanceInput<T> in;
        in.proxyA = {square, 4, T(0)};
        in.proxyB = {square, 4, T(0)};
        in.transformA = {{0, 0}, {1, 0}};
        in.transformB = {{x, y}, {1, 0}};
        return in;
    }
};

// The batch in SIMD lanes: pair k is 1 + k apart, and each answer is distance()'s, bit for bit.
// The widest lanes this CPU runs, named: BatchIsa::Best would run double's four-point squares in
// the scalar loop, where lanes lose (gjk2d/batch.hpp), and leave the lanes untested here.
template <class T> void checkBatch(const Squares<T>& s, const char* what)
{
    std::vector<gjk::DistanceInput<T>> inputs;
    for (int k = 0; k < 10; ++k)
        inputs.push_back(s.at(T(2 + k), T(0)));
    std::vector<gjk::SimplexCache> caches(inputs.size());
    std::vector<gjk::DistanceOutput<T>> outputs(inputs.size());
    gjk::BatchStats stats;
    gjk::distanceBatchLanes(std::span<const gjk::DistanceInput<T>>(inputs), caches, outputs,
                            gjk::referenceOptions, gjk::bestBatchIsa(), &stats);
    bool exact = true, same = true;
    for (std::size_t k = 0; k < inputs.size(); ++k)
    {
        exact = exact && outputs[k].distance == T(1 + int(k));
        gjk::SimplexCache cache;
        const gjk::DistanceOutput<T> one = gjk::distance(inputs[k], cache);
        same = same && sameBits(one.distance, outputs[k].distance) &&
               sameBits(one.pointA, outputs[k].pointA) && sameBits(one.pointB, outputs[k].pointB);
    }
    std::printf("%s: %s lanes, %llu queries\n", what, gjk::batchIsaName(stats.isa),
                static_cast<unsigned long long>(stats.queries));
    check(exact && stats.queries == inputs.size(), "distanceBatchLanes: distances 1 .. 10");
    check(same, "distanceBatchLanes: distance()'s bits, pair by pair");
}

} // namespace

int main()
{
    const Squares<double> s;

    // The plain query.
    gjk::SimplexCache cache;
    const gjk::DistanceOutput<double> plain = gjk::distance(s.at(2, 0), cache);
    check(plain.distance == 1, "distance: 1");
    check(plain.pointA.x == 1 && plain.pointB.x == 2 && plain.pointA.y == plain.pointB.y &&
              plain.pointA.y >= 0 && plain.pointA.y <= 1,
          "distance: witness points on x = 1 and x = 2, at one y in [0, 1]");
    check(plain.normal.x == 1 && plain.normal.y == 0, "distance: normal (1, 0)");
    const Squares<float> f;
    check(gjk::distance(f.at(2, 0)).distance == 1.0f, "distance (float): 1");

    // The certified query: the interval holds the answer; around sqrt(2) it is not a point.
    gjk::Options certify;
    certify.certify = true;
    const gjk::DistanceOutput<double> apart = gjk::distance(s.at(2, 0), certify);
    check(apart.certified && apart.lower <= 1 && 1 <= apart.upper, "certify: 1 in [lower, upper]");
    const gjk::DistanceOutput<double> corner = gjk::distance(s.at(2, 2), certify);
    check(corner.certified && corner.lower < corner.upper && corner.lower * corner.lower <= 2 &&
              corner.upper * corner.upper >= 2,
          "certify: sqrt(2) in [lower, upper], lower < upper");

    // The correctly rounded query, completed by the exact side when its stages cannot decide.
    gjk::Options rounded;
    rounded.correctlyRounded = true;
    const gjk::DistanceInput<double> diagonal = s.at(2, 2);
    gjk::DistanceOutput<double> correct = gjk::distance(diagonal, rounded);
    exact::completeCorrectlyRounded(diagonal, rounded, correct);
    check(correct.distance == std::sqrt(2.0), "correctly rounded: sqrt(2) rounded to nearest");
    check(correct.path != gjk::CorrectPath::NeedsExact, "correctly rounded: decided");

    // The batch in SIMD lanes, double and float.
    checkBatch(s, "batch (double)");
    checkBatch(f, "batch (float)");

    // The exact side on its own.
    const exact::Shape a{{{0, 0}, {1, 0}, {0, 1}}, 0}, b{{{3, 0}, {4, 0}, {3, 1}}, 0};
    check(exact::distance(a, b).distance == 2, "exact::distance: 2");

    // The plugin ABI's header: its version constant is visible.
    check(GJK2D_PLUGIN_ABI_VERSION >= 1, "gjk2d/plugin.h: GJK2D_PLUGIN_ABI_VERSION");

    if (g_failures != 0)
    {
        std::printf("sdk_consumer: %d of %d checks failed\n", g_failures, g_checks);
        return 1;
    }
    std::printf("sdk_consumer: all %d checks passed\n", g_checks);
    return 0;
}
