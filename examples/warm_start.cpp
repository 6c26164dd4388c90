// A warm-started loop: shape B moves towards shape A over eight frames, and the SimplexCache that
// each query leaves behind starts the next one from the last frame's simplex. The same queries
// run cold beside it, to show what the warm start saves (iterations = support points computed).
//
// The distances, by hand (the CTest "example: warm_start" checks them):
// - A and B are the same 12-gon, an octagon-like rounded box whose right and left edges are the
//   vertical segments x = 5 and x = -5 for y in [-2, 2]; every point has |x| <= 5.
// - At frame k, B is translated by (14 - k/2, 3 - 3k/4): B's left edge is x = 9 - k/2 for
//   y in [1 - 3k/4, 5 - 3k/4], which overlaps A's right edge's y range [-2, 2] for k = 0 .. 7.
// - A lies in x <= 5 and B in x >= 9 - k/2, so the distance is at least 4 - k/2, and the
//   overlapping edges attain it: distance 4 - k/2 = 4, 3.5, ..., 0.5, exact in double.
#include "gjk2d/distance.hpp"

#include <cstdio>

int main()
{
    using V = gjk::Vec2<double>;
    // Counter-clockwise from (-5, -2): A's first point is on its far side from B, and a cold start
    // begins there (indexA = indexB = 0), so it has a way to go.
    const V shape[] = {{-5, -2}, {-4, -4}, {-2, -5}, {2, -5}, {4, -4}, {5, -2},
                       {5, 2},   {4, 4},   {2, 5},   {-2, 5}, {-4, 4}, {-5, 2}};
    const gjk::Polygon<double> polygon = {shape, 12, 0.0};

    int coldTotal = 0, warmTotal = 0;
    // [snippet: warm-start]
    gjk::SimplexCache cache; // carried from frame to frame: the last frame's simplex, as indices
    for (int k = 0; k < 8; ++k)
    {
        gjk::DistanceInput<double> in;
        in.proxyA = polygon;
        in.proxyB = polygon;
        in.transformA = {{0, 0}, {1, 0}};
        in.transformB = {{14 - 0.5 * k, 3 - 0.75 * k}, {1, 0}}; // B moves towards A

        const gjk::DistanceOutput<double> warm = gjk::distance(in, cache); // updates cache
        const gjk::DistanceOutput<double> cold = gjk::distance(in);        // a fresh cache
        std::printf("frame %d  distance %g  iterations cold %d warm %d\n", k, warm.distance,
                    cold.iterations, warm.iterations);
        coldTotal += cold.iterations;
        warmTotal += warm.iterations;
    }
    // [end snippet]
    std::printf("support points over 8 frames: cold %d, warm %d\n", coldTotal, warmTotal);
    return 0;
}
