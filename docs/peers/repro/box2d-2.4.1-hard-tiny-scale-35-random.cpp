// Box2D 2.4.1's b2Distance on one case: a standalone reproduction, with nothing of gjk2d in it.
// Written by gjk2d's `gjk-validate repro` (docs/peers.md, "Repro programs"):
//   gjk-validate repro --family hard/tiny-scale:40 --seed 1 hard/tiny-scale/35-random --variants box2d-2.4.1 --no-default-plugins --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-float.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-double.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-fcl.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-geos --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-jolt --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-planck --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-rapier --out /work/wt-issue55-runner/docs/peers/repro
// Build and run it against Debian's libbox2d-dev (Box2D 2.4.1; -O3 -ffp-contract=off as gjk2d
// builds its adapter, so that no a*b+c is fused in this file):
//   g++ box2d-2.4.1-hard-tiny-scale-35-random.cpp -std=c++17 -O3 -ffp-contract=off $(pkg-config --cflags --libs box2d) -o box2d-2.4.1-hard-tiny-scale-35-random && ./box2d-2.4.1-hard-tiny-scale-35-random
//
// The case: hard/tiny-scale/35-random (family hard/tiny-scale). Box2D computes in float: gjk-validate rounds the case's
// doubles to the nearest float and hands Box2D those. Each number below is the shortest decimal
// that reads back as that float, with the suffix f: the compiler reads it correctly rounded to the
// nearest float (without the f, read as a double first and then rounded to float, a decimal could
// be rounded twice), so Box2D gets the very bits gjk-validate gave it.
//
// The call, as gjk2d's adapter (validation/plugins/box2d-2.4/box2d.cpp) and Box2D itself make it:
// b2DistanceProxy::Set with each shape's points in its local frame and its radius, transforms with
// the case's position and (c, s) as given (world = R * local + p, R = [[c, -s], [s, c]]),
// useRadii = true, a b2SimplexCache with count = 0 (a cold start), then b2Distance.
#include <box2d/b2_distance.h>

#include <cstdio>

const b2Vec2 pointsA[] = {{1.0990034e-12f, 5.067042e-13f}, {5.6171463e-13f, 1.0719302e-12f}, {1.2165468e-13f, -1.2040589e-12f}, {1.0853664e-12f, -5.3529186e-13f}};
const float radiusA = 0.0f, pxA = -7.605138e-13f, pyA = 3.2415047e-12f, cA = -0.045490034f, sA = -0.9989648f;
const b2Vec2 pointsB[] = {{-8.686892e-13f, -2.6414195e-13f}, {-6.932139e-13f, -5.8638413e-13f}, {-4.751687e-13f, -7.736967e-13f}, {-1.991827e-13f, -8.8584316e-13f}, {-5.849901e-14f, -9.0607377e-13f}, {2.3558507e-13f, -8.768646e-13f}, {3.2984287e-13f, -8.459288e-13f}, {6.39581e-13f, -6.444594e-13f}};
const float radiusB = 0.0f, pxB = -2.1959702e-12f, pyB = -2.8311717e-12f, cB = 0.84321946f, sB = -0.53756946f;

// The exact answer for these float inputs (gjk2d's CGAL/GMP ground truth), correctly rounded to
// double. On overlap the shapes share points: no pair of nearest points is unique, and the exact
// side's witness is one common point.
const double exactDistance = 5.071234056572334e-12;
const bool exactOverlap = false;
const double exactA[2] = {-1.344624851937961e-12, 2.18161236302258e-12}, exactB[2] = {-3.0704604541473556e-12, -2.5869205697236778e-12};

int main()
{
    b2DistanceInput input;
    input.proxyA.Set(pointsA, int32(sizeof pointsA / sizeof pointsA[0]), radiusA);
    input.proxyB.Set(pointsB, int32(sizeof pointsB / sizeof pointsB[0]), radiusB);
    input.transformA.p.Set(pxA, pyA);
    input.transformA.q.c = cA; // as given, not recomputed from an angle
    input.transformA.q.s = sA;
    input.transformB.p.Set(pxB, pyB);
    input.transformB.q.c = cB;
    input.transformB.q.s = sB;
    input.useRadii = true;
    b2SimplexCache cache;
    cache.count = 0;
    b2DistanceOutput output;
    b2Distance(&output, &cache, &input);
    // Floats printed as the doubles they are: %.9g reads back as the float, %a is its bits.
    const double d = output.distance, ax = output.pointA.x, ay = output.pointA.y,
                 bx = output.pointB.x, by = output.pointB.y;
    std::printf("Box2D 2.4.1 b2Distance on hard/tiny-scale/35-random, useRadii = true, %d iterations:\n",
                output.iterations);
    std::printf("answer distance %.9g %a\n", d, d);
    std::printf("answer pointA %.9g %.9g %a %a\n", ax, ay, ax, ay);
    std::printf("answer pointB %.9g %.9g %a %a\n", bx, by, bx, by);
    std::printf("exact distance %.17g%s\n", exactDistance, exactOverlap ? " (the shapes overlap)" : "");
    std::printf("exact pointA %.17g %.17g%s\n", exactA[0], exactA[1], exactOverlap ? " (a common point)" : "");
    std::printf("exact pointB %.17g %.17g\n", exactB[0], exactB[1]);
    return 0;
}
