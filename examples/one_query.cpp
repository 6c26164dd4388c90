// One GJK distance query: a rounded box and a rounded triangle, each with its own transform.
//
// The answer, by hand (the CTest "example: one_query" checks the printed values against it):
// - A is the box [-1, 1]^2 grown by radius 0.25, placed at (-2, 1): its core's right edge is
//   x = -1 for y in [0, 2].
// - B is the triangle (0, -1), (1, 1), (-1, 1) grown by radius 0.5, turned a quarter turn
//   clockwise, (c, s) = (0, -1), which maps (x, y) to (y, -x): apex (-1, 0), base corners (1, -1)
//   and (1, 1); then placed at (3, 1): apex (2, 1), corners (4, 0) and (4, 2).
// - The apex (2, 1) is the closest point of B's core; it faces A's right edge at (-1, 1), 3 away.
//   Minus both radii: distance 3 - 0.25 - 0.5 = 2.25; the witness points move along the normal
//   (1, 0): pointA = (-1 + 0.25, 1) = (-0.75, 1), pointB = (2 - 0.5, 1) = (1.5, 1).
// Every number above is a small dyadic rational, so the double query computes them exactly.
#include "gjk2d/distance.hpp"

#include <cstdio>

int main()
{
    // [snippet: one-query]
    using V = gjk::Vec2<double>;
    const V box[] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}; // any order; the shape is their hull
    const V triangle[] = {{0, -1}, {1, 1}, {-1, 1}};

    gjk::DistanceInput<double> in;
    in.proxyA = {box, 4, 0.25}; // a view: points, count, radius
    in.proxyB = {triangle, 3, 0.5};
    in.transformA = {{-2, 1}, {1, 0}}; // position, rotation as (cos, sin)
    in.transformB = {{3, 1}, {0, -1}}; // a quarter turn clockwise, used as given

    gjk::SimplexCache cache; // value-initialised: a cold start
    const gjk::DistanceOutput<double> out = gjk::distance(in, cache);

    std::printf("distance %g\n", out.distance);                   // 2.25
    std::printf("pointA (%g, %g)\n", out.pointA.x, out.pointA.y); // (-0.75, 1), on A's surface
    std::printf("pointB (%g, %g)\n", out.pointB.x, out.pointB.y); // (1.5, 1), on B's surface
    std::printf("normal (%g, %g)\n", out.normal.x, out.normal.y); // (1, 0), from A towards B
    std::printf("iterations %d, stop: %s\n", out.iterations, gjk::stopReasonName(out.stop));
    // [end snippet]
    return out.outOfRange ? 1 : 0;
}
