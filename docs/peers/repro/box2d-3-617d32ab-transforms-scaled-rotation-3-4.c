/* Box2D v3's b2ShapeDistance on one case: a standalone reproduction, with nothing of gjk2d in it.
 * Written by gjk2d's `gjk-validate repro` (docs/peers.md, "Repro programs"):
 *   gjk-validate repro /work/wt-issue55-runner/build/release/validation/cases/transforms.json transforms/scaled-rotation-3-4 --variants box2d-3-617d32ab --no-default-plugins --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d3.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-float.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-double.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-fcl.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-geos --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-jolt --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-planck --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-rapier --out /work/wt-issue55-runner/docs/peers/repro
 * Build and run it with the Box2D v3 sources the variant box2d-3-617d32ab was built from (BOX2D3 names
 * the tree, with include/ and src/; -O2 -ffp-contract=off as gjk2d builds them, so that no a*b+c
 * is fused):
//   cc -std=c17 -O2 -ffp-contract=off -I"${BOX2D3:?a Box2D v3 source tree}/include" box2d-3-617d32ab-transforms-scaled-rotation-3-4.c "$BOX2D3/src/distance.c" "$BOX2D3/src/math_functions.c" "$BOX2D3/src/core.c" -lm -o box2d-3-617d32ab-transforms-scaled-rotation-3-4 && ./box2d-3-617d32ab-transforms-scaled-rotation-3-4
 *
 * The case: transforms/scaled-rotation-3-4 (family file:transforms.json). Box2D computes in float: gjk-validate rounds the case's
 * doubles to the nearest float and hands Box2D those. Each number below is the shortest decimal
 * that reads back as that float, with the suffix f: the compiler reads it correctly rounded to the
 * nearest float (without the f, read as a double first and then rounded to float, a decimal could
 * be rounded twice), so Box2D gets the very bits gjk-validate gave it.
 *
 * The call, as gjk2d's adapter (validation/plugins/box2d-v3/box2d3.c) makes it and Box2D calls
 * itself (b2TimeOfImpact): proxies from b2MakeProxy in each shape's local frame, world transforms
 * with the case's position and (c, s) as given (world = R * local + p, R = [[c, -s], [s, c]]),
 * input.transform = b2InvMulTransforms(xfA, xfB) (B in A's frame), useRadii = true, a zeroed
 * b2SimplexCache (a cold start), no simplex capture; the answer's points mapped to the world with
 * b2TransformPoint(xfA, .). */
#include "box2d/collision.h"
#include "box2d/math_functions.h"

#include <stdbool.h>
#include <stdio.h>
#include <string.h>

static const b2Vec2 pointsA[] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
static const float radiusA = 0.0f;
static const b2Transform xfA = {{0.0f, 0.0f}, {3.0f, 4.0f}};
static const b2Vec2 pointsB[] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
static const float radiusB = 0.25f;
static const b2Transform xfB = {{12.0f, 1.0f}, {0.6f, 0.8f}};

/* The exact answer for these float inputs (gjk2d's CGAL/GMP ground truth), correctly rounded to
 * double. On overlap the shapes share points: no pair of nearest points is unique, and the exact
 * side's witness is one common point. */
static const double exactDistance = 3.35555123909501;
static const bool exactOverlap = false;
static const double exactA[2] = {7, 1}, exactB[2] = {10.35038487589771, 0.8138675161398726};

int main(void)
{
    b2DistanceInput in;
    memset(&in, 0, sizeof in);
    in.proxyA = b2MakeProxy(pointsA, (int)(sizeof pointsA / sizeof pointsA[0]), radiusA);
    in.proxyB = b2MakeProxy(pointsB, (int)(sizeof pointsB / sizeof pointsB[0]), radiusB);
    in.transform = b2InvMulTransforms(xfA, xfB);
    in.useRadii = true;
    b2SimplexCache cache = {0};
    b2DistanceOutput o = b2ShapeDistance(&in, &cache, NULL, 0);
    b2Vec2 wa = b2TransformPoint(xfA, o.pointA), wb = b2TransformPoint(xfA, o.pointB);
    /* Floats printed as the doubles they are: %.9g reads back as the float, %a is its bits. */
    const double d = o.distance, ax = wa.x, ay = wa.y, bx = wb.x, by = wb.y;
    printf("Box2D v3 b2ShapeDistance on transforms/scaled-rotation-3-4, useRadii = true, %d iterations:\n", o.iterations);
    printf("answer distance %.9g %a\n", d, d);
    printf("answer pointA %.9g %.9g %a %a\n", ax, ay, ax, ay);
    printf("answer pointB %.9g %.9g %a %a\n", bx, by, bx, by);
    printf("exact distance %.17g%s\n", exactDistance, exactOverlap ? " (the shapes overlap)" : "");
    printf("exact pointA %.17g %.17g%s\n", exactA[0], exactA[1], exactOverlap ? " (a common point)" : "");
    printf("exact pointB %.17g %.17g\n", exactB[0], exactB[1]);
    return 0;
}
