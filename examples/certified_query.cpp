// A certified query: Options::certify adds an interval [lower, upper] of doubles that provably
// contains the exact distance between the shapes as given (gjk2d/certify.hpp).
//
// The answer, by hand (the CTest "example: certified_query" checks it): A is the box [-1, 1]^2 at
// the origin, B the same box at (3, 3). Their closest points are the corners (1, 1) and (2, 2),
// so the exact distance is sqrt(2) = 1.41421356237309504880..., whose nearest double is
// 1.4142135623730951 (the query's answer: sqrt(1 + 1), correctly rounded). sqrt(2) is not a
// double, so the interval cannot be a single point; the program checks, exactly, that
// lower <= sqrt(2) <= upper, i.e. lower^2 <= 2 <= upper^2 (squares split into a rounded part and
// its exact error with std::fma, which -ffp-contract=off does not touch).
#include "gjk2d/distance.hpp"

#include <cmath>
#include <cstdio>

// x^2 compared with 2, exactly: -1, 0 or +1. x^2 = p + e exactly, with p = RN(x^2).
static int compareSquareWith2(double x)
{
    const double p = x * x;
    const double e = std::fma(x, x, -p);
    if (p != 2)
        return p < 2 ? -1 : 1;
    return e < 0 ? -1 : (e > 0 ? 1 : 0);
}

int main()
{
    using V = gjk::Vec2<double>;
    const V box[] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    gjk::DistanceInput<double> in;
    in.proxyA = {box, 4, 0.0};
    in.proxyB = {box, 4, 0.0};
    in.transformA = {{0, 0}, {1, 0}};
    in.transformB = {{3, 3}, {1, 0}};

    // [snippet: certified-query]
    gjk::Options options;   // the reference variant ...
    options.certify = true; // ... plus the certified interval: one more scan of each shape
    const gjk::DistanceOutput<double> out = gjk::distance(in, options);

    std::printf("distance %.17g\n", out.distance); // sqrt(2), rounded: 1.4142135623730951
    if (out.certified)                             // false only when the bounds overflowed
        std::printf("certified [%.17g, %.17g], width %.3g\n", out.lower, out.upper,
                    out.upper - out.lower);
    // [end snippet]

    const bool holdsAnswer = out.lower <= out.distance && out.distance <= out.upper;
    const bool lowerBelow = out.lower <= 0 || compareSquareWith2(out.lower) <= 0;
    const bool upperAbove = compareSquareWith2(out.upper) >= 0;
    std::printf("interval contains the answer: %s\n", holdsAnswer ? "yes" : "no");
    std::printf("interval contains sqrt(2): %s\n", lowerBelow && upperAbove ? "yes" : "no");
    return out.certified && holdsAnswer && lowerBelow && upperAbove ? 0 : 1;
}
