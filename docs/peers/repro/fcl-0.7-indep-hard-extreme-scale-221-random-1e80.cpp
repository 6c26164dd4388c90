// FCL's fcl::distance on one case: a standalone reproduction, with nothing of gjk2d in it.
// Written by gjk2d's `gjk-validate repro` (docs/peers.md, "Repro programs"):
//   gjk-validate repro --family hard/extreme-scale:244 --seed 1 hard/extreme-scale/221-random-1e80 --variants fcl-0.7-indep --no-default-plugins --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-float.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-double.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-fcl.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-geos --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-jolt --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-planck --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-rapier --out /work/wt-issue55-runner/docs/peers/repro
// Build and run it against Debian's libfcl-dev (FCL 0.7; -std=c++17 after pkg-config's -std=c++11
// so that it wins; -O3 -ffp-contract=off as gjk2d builds its adapter, so that no a*b+c is fused):
//   g++ fcl-0.7-indep-hard-extreme-scale-221-random-1e80.cpp $(pkg-config --cflags --libs fcl) -std=c++17 -O3 -ffp-contract=off -o fcl-0.7-indep-hard-extreme-scale-221-random-1e80 && ./fcl-0.7-indep-hard-extreme-scale-221-random-1e80
//
// The case: hard/extreme-scale/221-random-1e80 (family hard/extreme-scale), variant fcl-0.7-indep (request.gjk_solver_type = GST_INDEP,
// request.enable_signed_distance = false). Each
// number is the shortest decimal that reads back as the same double: the compiler reads a decimal
// literal correctly rounded to the nearest double, so FCL gets the very bits gjk-validate gave it.
//
// The call, as gjk2d's adapter makes it (validation/plugins/fcl/fcl.cpp): each 2D shape (points in
// its local frame, a radius, world = R * local + p with R = [[c, -s], [s, c]]) becomes a 3D one:
// - its points are placed in the world frame here, in double, and FCL gets identity transforms;
// - radius 0: the prism P x [-h, h], an fcl::Convex of its 2n vertices and no faces, with
//   h = 2 * (eA + eB), e = radius + max_i (|x_i| + |y_i|) over the shape's local points (1 when
//   that is 0, at most the largest double / 8): far taller than any depth of the case, so a
//   nearest pair never runs along z;
// - radius r > 0: one point is an fcl::Sphere, two points an fcl::Capsule around the segment.
// Then fcl::distance with enable_nearest_points = true and enable_signed_distance = false; a
// negative min_distance is, unsigned, FCL's "in collision" (overlap `zero`), signed, minus the
// penetration depth (overlap `penetration`): gjk-validate reports it as it is.
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <vector>

using Vec3 = fcl::Vector3<double>;

struct Shape
{
    std::vector<double> points; // x0, y0, x1, y1, ...
    double radius, px, py, c, s;
};

const Shape A = {{1.5534358683491851e+80, 7.750486449842708e+79, 8.231199584816636e+79, 1.5285080742720615e+80, -1.2831608848330728e+79, 1.7312996218454172e+80, -8.308281166683527e+79, 1.524331997866298e+80, -1.700627237354121e+80, 3.4889883739421045e+79, 1.1663310142093654e+80, -1.2858986602602453e+80, 1.5710084390490613e+80, -7.38779996753007e+79}, 0.0, 1.0144736378604016e+80, -2.2128757897075237e+80, -0.20815800676434623, 0.9780952122466884};
const Shape B = {{3.6271215347059646e+79, 7.496158737155564e+79, 3.4223954768221536e+79, 7.591812408140016e+79, -7.77406381070186e+78, 8.291202913861944e+79, -9.19471914175944e+78, 8.276652574513629e+79, 7.867923435794972e+79, -2.7284037913457176e+79}, 0.0, 2.3284840068382247e+80, -1.7054000649658897e+80, 0.6013451664368226, 0.7989893558759529};

// The exact answer for these inputs (gjk2d's CGAL/GMP ground truth), correctly rounded to double.
// On overlap the shapes share points: no pair of nearest points is unique, and the exact side's
// witness is one common point.
const double exactDistance = 0;
const bool exactOverlap = true;
const double exactA[2] = {1.611896276779844e+80, -1.281152390215171e+80}, exactB[2] = {1.611896276779844e+80, -1.281152390215171e+80};
// The exact signed distance (minus the penetration depth on overlap) and penetration pair, where
// gjk-validate computed them (a variant whose contract says penetration).
const bool exactSigned = false;
const double exactSignedDistance = 0;
const double exactPA[2] = {0, 0}, exactPB[2] = {0, 0};

// The shape's reach from its own origin: radius + the largest |x| + |y| of its local points.
double reach(const Shape& s)
{
    double m = 0;
    for (std::size_t i = 0; i < s.points.size(); i += 2)
        m = std::max(m, std::abs(s.points[i]) + std::abs(s.points[i + 1]));
    return s.radius + m;
}

std::vector<Vec3> worldPoints(const Shape& s)
{
    std::vector<Vec3> out;
    for (std::size_t i = 0; i < s.points.size(); i += 2)
    {
        const double x = s.points[i], y = s.points[i + 1];
        out.emplace_back(s.c * x - s.s * y + s.px, s.s * x + s.c * y + s.py, 0.0);
    }
    return out;
}

struct Placed
{
    std::shared_ptr<fcl::CollisionGeometry<double>> geometry;
    fcl::Transform3<double> pose = fcl::Transform3<double>::Identity();
};

// FCL's Capsule lies along its own z axis, centred on its origin: the rotation's third column is
// the segment's unit direction u, its second the world z, its first their cross product.
Placed capsule(const Vec3& p0, const Vec3& p1, double r)
{
    const Vec3 d = p1 - p0;
    const double length = d.norm();
    Placed out;
    out.pose.translation() = 0.5 * (p0 + p1);
    if (length == 0)
    {
        out.geometry = std::make_shared<fcl::Sphere<double>>(r);
        return out;
    }
    const Vec3 u = d / length;
    fcl::Matrix3<double> rot;
    rot.col(0) = Vec3(-u.y(), u.x(), 0.0);
    rot.col(1) = Vec3(0.0, 0.0, 1.0);
    rot.col(2) = u;
    out.pose.linear() = rot;
    out.geometry = std::make_shared<fcl::Capsule<double>>(r, length);
    return out;
}

Placed prism(const std::vector<Vec3>& p, double h)
{
    auto vertices = std::make_shared<std::vector<Vec3>>();
    for (const Vec3& v : p)
    {
        vertices->emplace_back(v.x(), v.y(), -h);
        vertices->emplace_back(v.x(), v.y(), h);
    }
    Placed out;
    out.geometry = std::make_shared<fcl::Convex<double>>(
        vertices, 0, std::make_shared<std::vector<int>>(), /*throw_if_invalid=*/false);
    return out;
}

Placed geometryOf(const Shape& s, double h)
{
    const std::vector<Vec3> p = worldPoints(s);
    if (s.radius == 0)
        return prism(p, h);
    if (p.size() == 1)
    {
        Placed out;
        out.geometry = std::make_shared<fcl::Sphere<double>>(s.radius);
        out.pose.translation() = p[0];
        return out;
    }
    return capsule(p[0], p[1], s.radius); // FCL has no rounded polygon: gjk2d refuses those
}

int main()
{
    double h = 2 * (reach(A) + reach(B));
    if (h == 0)
        h = 1;
    h = std::min(h, std::numeric_limits<double>::max() / 8);
    const Placed ga = geometryOf(A, h), gb = geometryOf(B, h);
    fcl::DistanceRequest<double> request;
    request.enable_nearest_points = true;
    request.enable_signed_distance = false;
    request.gjk_solver_type = fcl::GST_INDEP;
    fcl::DistanceResult<double> result;
    const double none = std::numeric_limits<double>::quiet_NaN(); // FCL may leave them unwritten
    result.nearest_points[0] = result.nearest_points[1] = Vec3(none, none, none);
    const double d =
        fcl::distance(ga.geometry.get(), ga.pose, gb.geometry.get(), gb.pose, request, result);
    const Vec3 &pa = result.nearest_points[0], &pb = result.nearest_points[1];
    std::printf("FCL fcl::distance, GST_INDEP, on hard/extreme-scale/221-random-1e80 (half-height h = %.17g):\n", h);
    std::printf("fcl    min_distance %.17g  nearest_points (%.17g, %.17g, %.17g) (%.17g, %.17g, %.17g)\n",
                d, pa.x(), pa.y(), pa.z(), pb.x(), pb.y(), pb.z());
    // As gjk-validate reports it: min_distance as it is (negative: FCL's "in collision", or minus
    // the depth when signed), the points' x and y.
    const double reported = d;
    std::printf("answer distance %.17g %a\n", reported, reported);
    std::printf("answer pointA %.17g %.17g %a %a\n", pa.x(), pa.y(), pa.x(), pa.y());
    std::printf("answer pointB %.17g %.17g %a %a\n", pb.x(), pb.y(), pb.x(), pb.y());
    std::printf("exact distance %.17g%s\n", exactDistance, exactOverlap ? " (the shapes overlap)" : "");
    std::printf("exact pointA %.17g %.17g%s\n", exactA[0], exactA[1], exactOverlap ? " (a common point)" : "");
    std::printf("exact pointB %.17g %.17g\n", exactB[0], exactB[1]);
    if (exactSigned && exactSignedDistance < 0)
        std::printf("exact signed distance %.17g (minus the depth), penetration pair (%.17g, "
                    "%.17g) (%.17g, %.17g)\n",
                    exactSignedDistance, exactPA[0], exactPA[1], exactPB[0], exactPB[1]);
    return 0;
}
