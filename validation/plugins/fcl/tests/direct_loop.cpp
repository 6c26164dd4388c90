// FCL called directly, beside the FCL adapter (validation/plugins/fcl/fcl.cpp): each case's two
// shapes built once as FCL's users build them, fcl::CollisionObjects of the adapter's geometry (a
// prism of a Convex, a Sphere, a Capsule: docs/peers/prisms.md), then passes of
// fcl::distance(o1, o2, request, result), FCL's "Main distance interface"
// (fcl/narrowphase/distance.h:49), with one DistanceRequest and a fresh DistanceResult per query
// (a result keeps the smallest distance it was given, so a user does not reuse one). Prints the
// median ns/query; with --plugin, the adapter's prepared queries of the same cases
// (gjk2d_plugin_prepared), timed the same way in alternate passes, and their ratio. Not a test:
// a speed figure belongs to a quiet machine, not to CTest. Its CTest (--check 50) checks that it
// runs and that its distances are the adapter's.
//
//     cd build/release
//     validation/gjk-validate generate --family random:20000 --seed 1 --out /tmp/r.json
//     tests/plugins/fcl_direct_loop /tmp/r.json --plugin validation/plugins/gjk2d-fcl.so
//
// (GST_LIBCCD; add --variant fcl-0.7-indep for GST_INDEP, --variant fcl-0.7-libccd-signed for
// GST_LIBCCD with enable_signed_distance.)
//
// Cases FCL cannot take (a radius on more than two points: the adapter refuses them) are left out.
#include "direct_loop.hpp"

#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <limits>
#include <memory>

namespace
{

using Vec3 = fcl::Vector3<double>;

const char* const kUsage =
    "usage: fcl_direct_loop CASES.json [--variant fcl-0.7-libccd|fcl-0.7-indep|"
    "fcl-0.7-libccd-signed] [--passes N]\n"
    "                       [--plugin gjk2d-fcl.so] [--check N]\n";

// The adapter's prism reduction (fcl.cpp: extent, prismHalfHeight, worldPoints, capsule, prism),
// the same rule, so that both sides query the same shapes.
double extent(const directloop::Shape& s)
{
    double m = 0;
    for (int32_t i = 0; i < s.count(); ++i)
        m = std::max(m, std::abs(s.points[2 * i]) + std::abs(s.points[2 * i + 1]));
    return s.radius + m;
}

double prismHalfHeight(const directloop::Shape& a, const directloop::Shape& b)
{
    const double h = 2 * (extent(a) + extent(b));
    return h == 0 ? 1.0 : std::min(h, std::numeric_limits<double>::max() / 8);
}

std::vector<Vec3> worldPoints(const directloop::Shape& s)
{
    std::vector<Vec3> out;
    for (int32_t i = 0; i < s.count(); ++i)
    {
        const double x = s.points[2 * i], y = s.points[2 * i + 1];
        out.emplace_back(s.c * x - s.s * y + s.px, s.s * x + s.c * y + s.py, 0.0);
    }
    return out;
}

// The shape's collision object, or none when FCL cannot take it.
std::unique_ptr<fcl::CollisionObject<double>> objectOf(const directloop::Shape& s, double h)
{
    const std::vector<Vec3> p = worldPoints(s);
    fcl::Transform3<double> pose = fcl::Transform3<double>::Identity();
    std::shared_ptr<fcl::CollisionGeometry<double>> geometry;
    if (s.radius == 0)
    {
        auto vertices = std::make_shared<std::vector<Vec3>>();
        for (const Vec3& v : p)
        {
            vertices->emplace_back(v.x(), v.y(), -h);
            vertices->emplace_back(v.x(), v.y(), h);
        }
        geometry = std::make_shared<fcl::Convex<double>>(
            vertices, 0, std::make_shared<std::vector<int>>(), /*throw_if_invalid=*/false);
    }
    else if (s.count() == 1)
    {
        geometry = std::make_shared<fcl::Sphere<double>>(s.radius);
        pose.translation() = p[0];
    }
    else if (s.count() == 2)
    {
        const Vec3 d = p[1] - p[0];
        const double length = d.norm();
        pose.translation() = 0.5 * (p[0] + p[1]);
        if (length == 0)
            geometry = std::make_shared<fcl::Sphere<double>>(s.radius);
        else
        {
            const Vec3 u = d / length;
            fcl::Matrix3<double> rot;
            rot.col(0) = Vec3(-u.y(), u.x(), 0.0);
            rot.col(1) = Vec3(0.0, 0.0, 1.0);
            rot.col(2) = u;
            pose.linear() = rot;
            geometry = std::make_shared<fcl::Capsule<double>>(s.radius, length);
        }
    }
    else
        return nullptr;
    return std::make_unique<fcl::CollisionObject<double>>(geometry, pose);
}

} // namespace

int main(int argc, char** argv)
{
    const directloop::Options o = directloop::parseOptions(argc, argv, kUsage, "fcl-0.7-libccd");
    fcl::DistanceRequest<double> request;
    request.enable_nearest_points = true;
    request.enable_signed_distance = o.variant == "fcl-0.7-libccd-signed";
    if (o.variant == "fcl-0.7-libccd" || o.variant == "fcl-0.7-libccd-signed")
        request.gjk_solver_type = fcl::GST_LIBCCD;
    else if (o.variant == "fcl-0.7-indep")
        request.gjk_solver_type = fcl::GST_INDEP;
    else
    {
        std::fprintf(stderr, "unknown variant %s\n%s", o.variant.c_str(), kUsage);
        return 2;
    }
    const std::vector<directloop::Case> all = directloop::readCases(o.cases);
    std::vector<const directloop::Case*> cases;
    std::vector<std::unique_ptr<fcl::CollisionObject<double>>> objects; // A, B of each case
    for (const directloop::Case& c : all)
    {
        const double h = prismHalfHeight(c.a, c.b);
        auto a = objectOf(c.a, h), b = objectOf(c.b, h);
        if (!a || !b)
            continue;
        cases.push_back(&c);
        objects.push_back(std::move(a));
        objects.push_back(std::move(b));
    }
    return directloop::run(o, cases,
                           [&](std::size_t k)
                           {
                               fcl::DistanceResult<double> result;
                               double d = 0;
                               try // FCL throws on some configurations, as the adapter catches
                               {
                                   d = fcl::distance(objects[2 * k].get(), objects[2 * k + 1].get(),
                                                     request, result);
                               }
                               catch (const std::exception&)
                               {
                                   return directloop::Answer{GJK2D_STATUS_ERROR};
                               }
                               return directloop::Answer{GJK2D_STATUS_OK,
                                                         d,
                                                         result.nearest_points[0].x(),
                                                         result.nearest_points[0].y(),
                                                         result.nearest_points[1].x(),
                                                         result.nearest_points[1].y()};
                           });
}
