// FCL's fcl::distance on one case: a standalone reproduction, with nothing of gjk2d in it.
// Written by gjk2d's `gjk-validate repro` (docs/peers.md, "Repro programs"):
//   gjk-validate repro --family hard/range:72 --seed 1 hard/range/48-offset-x1e+19 --variants fcl-0.7-libccd-signed --no-default-plugins --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-box2d.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-float.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-bullet-double.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-fcl.so --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-geos --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-jolt --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-planck --plugin /work/wt-issue55-runner/build/release/validation/plugins/gjk2d-rapier --out /work/wt-issue55-runner/docs/peers/repro
// Build and run it against Debian's libfcl-dev (FCL 0.7; -std=c++17 after pkg-config's -std=c++11
// so that it wins; -O3 -ffp-contract=off as gjk2d builds its adapter, so that no a*b+c is fused):
//   g++ fcl-0.7-libccd-signed-hard-range-48-offset-x1e-19.cpp $(pkg-config --cflags --libs fcl) -std=c++17 -O3 -ffp-contract=off -o fcl-0.7-libccd-signed-hard-range-48-offset-x1e-19 && ./fcl-0.7-libccd-signed-hard-range-48-offset-x1e-19
//
// The case: hard/range/48-offset-x1e+19 (family hard/range), variant fcl-0.7-libccd-signed (request.gjk_solver_type = GST_LIBCCD,
// request.enable_signed_distance = true). Each
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
// Then fcl::distance with enable_nearest_points = true and enable_signed_distance = true; a
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

const Shape A = {{-0.9420361503355652, 0.027923572749687597, 0.5932483412594818, -0.7323033797867058, 0.7889248817643468, -0.5155670328747467, 0.9358726536374528, -0.11114949674987742}, 0.0, -7.493979782493007e+18, -6.621198306921948e+18, 0.11673639293301871, 0.9931629345505136};
const Shape B = {{-0.475552247406243, 1.4213411108029987, -1.0743233487445618, 1.045078865738898, -0.7014170210939988, -1.3245280879586705, -0.580968877799903, -1.3816061871241574, -0.39669267229471217, -1.4453357454306286, -0.39234273155261445, -1.4465226145033696}, 0.0, -7.493979782493007e+18, -6.621198306921948e+18, 0.48820073755293797, 0.8727313675196781};

// The exact answer for these inputs (gjk2d's CGAL/GMP ground truth), correctly rounded to double.
// On overlap the shapes share points: no pair of nearest points is unique, and the exact side's
// witness is one common point.
const double exactDistance = 0;
const bool exactOverlap = true;
const double exactA[2] = {-7.493979782493007e+18, -6.621198306921948e+18}, exactB[2] = {-7.493979782493007e+18, -6.621198306921948e+18};
// The exact signed distance (minus the penetration depth on overlap) and penetration pair, where
// gjk-validate computed them (a variant whose contract says penetration).
const bool exactSigned = true;
const double exactSignedDistance = -0.4561198835536618;
const double exactPA[2] = {-7.493979782493007e+18, -6.621198306921948e+18}, exactPB[2] = {-7.493979782493007e+18, -6.621198306921948e+18};

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
    request.enable_signed_distance = true;
    request.gjk_solver_type = fcl::GST_LIBCCD;
    fcl::DistanceResult<double> result;
    const double none = std::numeric_limits<double>::quiet_NaN(); // FCL may leave them unwritten
    result.nearest_points[0] = result.nearest_points[1] = Vec3(none, none, none);
    const double d =
        fcl::distance(ga.geometry.get(), ga.pose, gb.geometry.get(), gb.pose, request, result);
    const Vec3 &pa = result.nearest_points[0], &pb = result.nearest_points[1];
    std::printf("FCL fcl::distance, GST_LIBCCD, on hard/range/48-offset-x1e+19 (half-height h = %.17g):\n", h);
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
