// The FCL 0.7 adapter (a shipped peer, gjk2d/plugin.h, ABI version 2): fcl::distance between two
// prisms, with both of FCL's GJK solvers as two double variants, "fcl-0.7-libccd" (GST_LIBCCD,
// FCL's default) and "fcl-0.7-indep" (GST_INDEP), and a third, "fcl-0.7-libccd-signed":
// GST_LIBCCD with DistanceRequest::enable_signed_distance = true. Built against Debian's
// libfcl-dev (FCL 0.7.0, whose headers are upstream's tag 0.7.0 unchanged); docs/peers/fcl.md.
//
// The 2D case as a 3D one (docs/peers/prisms.md): a shape of points P becomes the
// prism P x [-h, h], the same h for both shapes, chosen per case (prismHalfHeight, below); the
// distance of two prisms is the 2D distance of their polygons, and their nearest points can be
// taken at z = 0. The adapter returns FCL's nearest points' x and y.
// - Transforms: the adapter applies the case's transform to the points itself, world = R * local +
//   p in double with R = [[c, -s], [s, c]] from the case's (c, s) as given, and hands FCL identity
//   transforms. FCL's Transform3 is an Eigen Isometry and libccd turns its linear part into a
//   quaternion, which drops the scale of a (c, s) that is not of unit length: handing FCL the
//   case's transform would silently answer another case.
// - Polygons: an fcl::Convex<double> of the prism's 2n vertices and no faces (throw_if_invalid =
//   false). Both solvers' support functions read only the vertices (a linear scan; FCL walks
//   faces only on a valid mesh of 32 or more vertices, and a face-less mesh is not valid), so the
//   shape is the hull of the points, in any order, as the case means it; one or two points (a
//   segment along z, a degenerate rectangle) need no special path.
// - Radius: Convex has none. A one-point shape of radius r > 0 is an fcl::Sphere of radius r at
//   the point, a two-point one an fcl::Capsule (FCL's capsule lies along its z axis: the adapter
//   rotates z onto the segment's direction in the xy-plane; the unit direction is rounded, a
//   relative error of about 1e-16 of the segment's length). No prism there: a ball and a
//   capsule are the 2D point and segment swept by r in 3D, whose distance to a prism is again the
//   2D one. Any other shape with radius > 0 is refused (GJK2D_STATUS_REFUSED): FCL has no
//   rounded polytope, and approximating one would judge our approximation, not FCL.
// - Overlap: the first two variants ask for unsigned distance (enable_signed_distance = false,
//   FCL's default). FCL's answer is reported as it is: in collision its min_distance is
//   "implementation defined" and negative (mostly -1), and it sets no nearest points (both stay
//   the origin). fcl-0.7-libccd-signed asks for signed distance: on overlap FCL's libccd path
//   (primitive shapes: "SD_1, NP", distance_request.h:64-76) runs libccd's GJK then its EPA
//   (gjk_libccd-inl.h:2186-2210, ccdGJKSignedDist) and answers minus the penetration depth and the
//   EPA's pair, each point on its own shape's surface; its x, y are reported, as for a distance.
//   Signed distance with GST_INDEP is not offered: it hits an assert compiled into Debian's libfcl
//   (distance-inl.h:177) on overlapping convexes. Asserts inside libccd's EPA
//   (ComputeVisiblePatch, gjk_libccd-inl.h:1315-1340) abort the process: the runner calls a plugin
//   in a child process, so an abort costs that one case, counted as a crash.
// - Exceptions: FCL reports some failures by throwing (FCL_THROW_FAILED_AT_THIS_CONFIGURATION, a
//   std::logic_error: libccd's EPA on a degenerate face, gjk_libccd-inl.h:994, "Cannot compute
//   face normal for a degenerate (zero-area) triangle"). A user catches it; the adapter does, and
//   answers GJK2D_STATUS_ERROR ("tried and failed", counted as an error), the message in the
//   plugin's log. An exception must not cross the plugin's C functions.
// - Shapes prepared once (gjk2d_plugin_prepared, scope `case`): a prepared shape is the
//   fcl::CollisionObject of its geometry, built from the case's world points with the case's half
//   height; a query is fcl::distance on two objects with the request below. distance_d is
//   prepare, query, release, so that the two forms answer alike, bit for bit.
// - No answer: on some cases of huge coordinates FCL returns without touching its DistanceResult
//   (min_distance stays at its initial numeric max, the nearest points at whatever the memory
//   held). The adapter sets the points to NaN before the call, so such an answer is reported the
//   same in every run: FCL's distance, NaN points (non-finite in the report).
//
// The contract (gjk2d_contract, kContracts below; each clause's source is FCL 0.7.0's file:line,
// identical in Debian's /usr/include/fcl and upstream's include/fcl at tag 0.7.0):
// - overlap `zero`, both solvers: a distance of 0 or below, no points promised
//   (DistanceResult::min_distance and DistanceRequest::enable_signed_distance, quoted there);
// - tolerance: DistanceRequest::distance_tolerance (default 1e-6) reaches both solvers
//   (distance-inl.h:234, :240) but means different things. GST_INDEP: its GJK reports contact
//   when the simplex is within it of the origin (gjk-inl.h:115) and stops when the duality gap is
//   within it relative to the distance (gjk-inl.h:147): abs 1e-6, rel 1e-6. GST_LIBCCD: libccd
//   stops when the distance improves by less than it (gjk_libccd-inl.h:2081, :2105), which FCL
//   says "does NOT necessarily mean that the computed distance is within" it
//   (gjk_libccd-inl.h:2693-2696): none stated;
// - margin 0: FCL keeps no skin around its shapes.
//
// Findings (docs/peers/fcl.md; validation/plugins/fcl/tests/test_fcl.cpp): GST_LIBCCD answers
// a vertex-to-vertex distance when the nearest feature is an edge (FCL issue #508: 3.6048 for two
// squares 3.57 apart); GST_INDEP answers the edge distance but calls shapes closer than its
// distance_tolerance (1e-6) colliding; GST_LIBCCD aborts on an assertion (doSimplex2, "A is not in
// region 1") on some cases of coordinates beyond 1e160.
#include <gjk2d/plugin.h>

#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <vector>

#ifndef GJK2D_FCL_VERSION
#define GJK2D_FCL_VERSION "unknown"
#endif

namespace
{

using Vec3 = fcl::Vector3<double>;

// A shape's extent about its local origin: e = radius + max_i (|x_i| + |y_i|) over its local
// points, in double from the case's numbers: at least each point's distance to the origin
// (|x| + |y| >= sqrt(x^2 + y^2)), and finite wherever the numbers are (x * x overflows from 1e154).
double extent(const gjk2d_shape_d& s)
{
    double m = 0;
    for (int32_t i = 0; i < s.count; ++i)
    {
        const double x = s.points[2 * i], y = s.points[2 * i + 1];
        m = std::max(m, std::abs(x) + std::abs(y));
    }
    return s.radius + m;
}

// The prisms' half height h, one per case: h = 2 (eA + eB), 1 when that is 0 (two bare points at
// their local origins), at most kMaxHalfHeight (the largest double / 8, so that 2h and the prisms'
// vertices stay finite). The distance and the nearest points' x, y do not depend on h
// (docs/peers/prisms.md), but a minimal translation does: two prisms of the same
// [-h, h] are also separated by 2h along z, so a penetration depth is the 2D one only while that is
// below 2h. Every point of a shape lies within e of its position (for a unit (c, s)), so the
// shape's width is at most 2e, and the 2D depth, at most the smaller shape's width, is at most
// 2 min(eA, eB) <= eA + eB < 2h: the minimal translation never runs along z. The same rule in
// bullet.cpp and in the programs of `gjk-validate repro`, so that they answer as this adapter.
constexpr double kMaxHalfHeight = std::numeric_limits<double>::max() / 8;
double prismHalfHeight(const gjk2d_shape_d& a, const gjk2d_shape_d& b)
{
    const double h = 2 * (extent(a) + extent(b));
    return h == 0 ? 1.0 : std::min(h, kMaxHalfHeight);
}

// The shape's points in the world frame: world = R * local + p, the case's (c, s) as given.
std::vector<Vec3> worldPoints(const gjk2d_shape_d& s)
{
    const double c = s.rotation[0], sn = s.rotation[1];
    std::vector<Vec3> out;
    out.reserve(std::size_t(s.count));
    for (int32_t i = 0; i < s.count; ++i)
    {
        const double x = s.points[2 * i], y = s.points[2 * i + 1];
        out.emplace_back(c * x - sn * y + s.position[0], sn * x + c * y + s.position[1], 0.0);
    }
    return out;
}

// A capsule of radius r around the segment p0 p1 (z = 0): FCL's Capsule lies along its own z axis,
// centred on its origin; the rotation's third column is the segment's unit direction u, its second
// the world z, its first their cross product (a right-handed frame).
struct Placed
{
    std::shared_ptr<fcl::CollisionGeometry<double>> geometry;
    fcl::Transform3<double> pose = fcl::Transform3<double>::Identity();
};

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

// The prism P x [-h, h] as a face-less Convex (see the header comment).
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

// The FCL geometry of one case shape, a prism of half height h when it has no radius; an empty
// geometry when FCL cannot take it (radius > 0 on more than two points).
Placed geometryOf(const gjk2d_shape_d& s, double h)
{
    const std::vector<Vec3> p = worldPoints(s);
    if (s.radius == 0)
        return prism(p, h);
    if (s.count == 1)
    {
        Placed out;
        out.geometry = std::make_shared<fcl::Sphere<double>>(s.radius);
        out.pose.translation() = p[0];
        return out;
    }
    if (s.count == 2)
        return capsule(p[0], p[1], s.radius);
    return {};
}

// A prepared shape (gjk2d_prepared, scope GJK2D_PREPARED_CASE): the fcl::CollisionObject a user
// keeps (fcl/narrowphase/distance.h:49, "Main distance interface: given two collision objects"),
// its geometry built once from the case's world points (geometryOf) with the case's half height,
// which depends on both shapes: hence the `other` shape. The scope is the case's because the world
// points are baked in (see the header comment: libccd drops the scale of a (c, s) that is not of
// unit length, so FCL cannot be handed the case's transform). No object: a shape FCL cannot take
// (no point, a radius on more than two points), which the query refuses as distance_d does.
struct Prepared
{
    std::unique_ptr<fcl::CollisionObject<double>> object;
};

// The variants, in kImplementations' order: FCL's solver and whether signed distance is asked.
struct Variant
{
    const char* name;
    fcl::GJKSolverType solver;
    bool signedDistance;
};
constexpr Variant kVariants[] = {{"fcl-0.7-libccd", fcl::GST_LIBCCD, false},
                                 {"fcl-0.7-indep", fcl::GST_INDEP, false},
                                 {"fcl-0.7-libccd-signed", fcl::GST_LIBCCD, true}};
constexpr int32_t kVariantCount = int32_t(sizeof(kVariants) / sizeof(kVariants[0]));

void* prepare(int32_t implementation, const void* shape, const void* other)
{
    if (implementation < 0 || implementation >= kVariantCount || other == nullptr)
        return nullptr;
    const auto& s = *static_cast<const gjk2d_shape_d*>(shape);
    const auto& o = *static_cast<const gjk2d_shape_d*>(other);
    auto p = std::make_unique<Prepared>();
    if (s.count >= 1 && o.count >= 1)
    {
        const Placed g = geometryOf(s, prismHalfHeight(s, o));
        if (g.geometry)
            p->object = std::make_unique<fcl::CollisionObject<double>>(g.geometry, g.pose);
    }
    return p.release();
}

void release(int32_t /*implementation*/, void* prepared)
{
    delete static_cast<Prepared*>(prepared);
}

// The query, what an FCL user pays for one on two kept objects: the request (nearest points, the
// implementation's solver and signed distance or not), fcl::distance, the result copied out. The
// case's shapes are not read (their transforms are in the objects' points).
int32_t distance(int32_t implementation, const void* preparedA, const void* /*a*/,
                 const void* preparedB, const void* /*b*/, void* /*cache*/, void* result)
{
    const auto& pa = *static_cast<const Prepared*>(preparedA);
    const auto& pb = *static_cast<const Prepared*>(preparedB);
    if (!pa.object || !pb.object)
        return GJK2D_STATUS_REFUSED;
    fcl::DistanceRequest<double> request;
    request.enable_nearest_points = true;
    request.enable_signed_distance = kVariants[implementation].signedDistance;
    request.gjk_solver_type = kVariants[implementation].solver;
    fcl::DistanceResult<double> r; // its nearest points start unwritten (Eigen)
    const double none = std::numeric_limits<double>::quiet_NaN();
    r.nearest_points[0] = r.nearest_points[1] = Vec3(none, none, none);
    double d = 0;
    try
    {
        d = fcl::distance(pa.object.get(), pb.object.get(), request, r);
    }
    catch (const std::exception& e) // FCL's own report of a failure (the header comment)
    {
        std::fprintf(stderr, "gjk2d-fcl: %s: FCL threw: %s\n", kVariants[implementation].name,
                     e.what());
        return GJK2D_STATUS_ERROR;
    }
    auto* out = static_cast<gjk2d_result_d*>(result);
    out->distance = d; // negative: "in collision" (overlap `zero`), or minus the depth (signed)
    out->point_a[0] = r.nearest_points[0].x();
    out->point_a[1] = r.nearest_points[0].y();
    out->point_b[0] = r.nearest_points[1].x();
    out->point_b[1] = r.nearest_points[1].y();
    out->iterations = -1;
    return GJK2D_STATUS_OK;
}

int32_t scope(int32_t /*implementation*/)
{
    return GJK2D_PREPARED_CASE;
}

// distance_d is the prepared form on one case: prepare both shapes, query, release.
int32_t fclDistance(int32_t implementation, const gjk2d_shape_d* a, const gjk2d_shape_d* b,
                    gjk2d_result_d* out)
{
    void* pa = prepare(implementation, a, b);
    void* pb = prepare(implementation, b, a);
    const int32_t status =
        pa && pb ? distance(implementation, pa, a, pb, b, nullptr, out) : GJK2D_STATUS_ERROR;
    release(implementation, pa);
    release(implementation, pb);
    return status;
}

int32_t libccdDistance(const gjk2d_shape_d* a, const gjk2d_shape_d* b, void*, gjk2d_result_d* out)
{
    return fclDistance(0, a, b, out);
}

int32_t indepDistance(const gjk2d_shape_d* a, const gjk2d_shape_d* b, void*, gjk2d_result_d* out)
{
    return fclDistance(1, a, b, out);
}

int32_t signedDistance(const gjk2d_shape_d* a, const gjk2d_shape_d* b, void*, gjk2d_result_d* out)
{
    return fclDistance(2, a, b, out);
}

const gjk2d_prepared kPrepared = {&scope, &prepare, &distance, &release};

const gjk2d_implementation kImplementations[] = {
    {kVariants[0].name,
     "FCL " GJK2D_FCL_VERSION " fcl::distance, GST_LIBCCD, prisms of Convex (Sphere, Capsule for "
     "rounded points, segments)",
     GJK2D_SCALAR_DOUBLE, GJK2D_ACCEPTS_RADIUS, 0, 0, nullptr, &libccdDistance},
    {kVariants[1].name,
     "FCL " GJK2D_FCL_VERSION " fcl::distance, GST_INDEP, prisms of Convex (Sphere, Capsule for "
     "rounded points, segments)",
     GJK2D_SCALAR_DOUBLE, GJK2D_ACCEPTS_RADIUS, 0, 0, nullptr, &indepDistance},
    {kVariants[2].name,
     "FCL " GJK2D_FCL_VERSION " fcl::distance, GST_LIBCCD, enable_signed_distance (EPA on "
     "overlap), prisms of Convex (Sphere, Capsule for rounded points, segments)",
     GJK2D_SCALAR_DOUBLE, GJK2D_ACCEPTS_RADIUS, 0, 0, nullptr, &signedDistance},
};
static_assert(sizeof(kImplementations) / sizeof(kImplementations[0]) == kVariantCount);

// The sources: FCL 0.7.0's headers (Debian's /usr/include/fcl = upstream's include/fcl at tag
// 0.7.0), as read for this contract; a new FCL needs them read again.
#define GJK2D_FCL_OVERLAP_SOURCE                                                                   \
    "fcl/narrowphase/distance_result.h:55-64 (min_distance in collision: \"a implementation "      \
    "defined negative value\"), fcl/narrowphase/distance_request.h:57-62, 86-89 "                  \
    "(enable_signed_distance false, the default: \"implementation defined (mostly -1)\"), "        \
    "FCL 0.7.0"

#define GJK2D_FCL_LIBCCD_TOLERANCE_SOURCE                                                          \
    "none: DistanceRequest::distance_tolerance (fcl/narrowphase/distance_request.h:98-99, 109: "   \
    "1e-6) is GST_LIBCCD's stopping rule (fcl/narrowphase/distance-inl.h:234; "                    \
    "fcl/narrowphase/detail/convexity_based_algorithm/gjk_libccd-inl.h:2081, 2105), which \"does " \
    "NOT necessarily mean that the computed distance is within\" it "                              \
    "(gjk_libccd-inl.h:2693-2696), "                                                               \
    "FCL 0.7.0"

const gjk2d_contract kContracts[] = {
    {-1, -1, GJK2D_FCL_LIBCCD_TOLERANCE_SOURCE, GJK2D_OVERLAP_ZERO, GJK2D_FCL_OVERLAP_SOURCE, 0,
     ""},
    {1e-6, 1e-6,
     "DistanceRequest::distance_tolerance (fcl/narrowphase/distance_request.h:98-99, 109: 1e-6), "
     "GST_INDEP's gjk_tolerance (fcl/narrowphase/distance-inl.h:240): contact when the simplex is "
     "within it of the origin (fcl/narrowphase/detail/convexity_based_algorithm/gjk-inl.h:115), "
     "stop when the duality gap is within it times the distance (gjk-inl.h:147), FCL 0.7.0",
     GJK2D_OVERLAP_ZERO, GJK2D_FCL_OVERLAP_SOURCE, 0, ""},
    {-1, -1, GJK2D_FCL_LIBCCD_TOLERANCE_SOURCE, GJK2D_OVERLAP_PENETRATION,
     "fcl/narrowphase/distance_request.h:57-92 (enable_signed_distance: \"the exact negative "
     "distance, which is the negated penetration depth\"; GST_LIBCCD on primitive shapes: \"SD_1, "
     "NP\", \"The pair of nearest points are guaranteed to be on the surface of objects\"), "
     "fcl/narrowphase/distance_result.h:55-64, FCL 0.7.0",
     0, ""},
};
static_assert(sizeof(kContracts) / sizeof(kContracts[0]) ==
              sizeof(kImplementations) / sizeof(kImplementations[0]));

// The depth clauses (gjk2d_plugin_depth): only the signed variant answers a depth. FCL states its
// accuracy in the doc of GJKSignedDistance, the function its libccd signed distance calls
// (gjk_solver_libccd-inl.h:563-570, with DistanceRequest::distance_tolerance, 1e-6 by default):
// "the EPA algorithm terminates when the difference between the upper bound and the lower bound of
// the penetration depth is smaller than @p tolerance. Hence the computed penetration depth is
// within @p tolerance to the true depth" (gjk_libccd-inl.h:2697-2700): abs 1e-6, rel none.
const gjk2d_depth_contract kDepth[] = {
    {-1, -1, nullptr},
    {-1, -1, nullptr},
    {1e-6, -1,
     "fcl/narrowphase/detail/convexity_based_algorithm/gjk_libccd-inl.h:2697-2700 (EPA stops when "
     "the depth's upper and lower bounds are within the tolerance: \"the computed penetration "
     "depth "
     "is within @p tolerance to the true depth\"), the tolerance DistanceRequest::"
     "distance_tolerance (fcl/narrowphase/distance_request.h:98-99, 109: 1e-6; "
     "fcl/narrowphase/detail/gjk_solver_libccd-inl.h:569), FCL 0.7.0"},
};
static_assert(sizeof(kDepth) / sizeof(kDepth[0]) == kVariantCount);

const gjk2d_plugin kPlugin = {GJK2D_PLUGIN_ABI_VERSION, kVariantCount, kImplementations,
                              kContracts};

} // namespace

extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
{
    return &kPlugin;
}

extern "C" GJK2D_PLUGIN_EXPORT const char* gjk2d_plugin_library(void)
{
    return "FCL " GJK2D_FCL_VERSION " (Debian libfcl-dev)";
}

// The depth clauses (the optional export of gjk2d/plugin.h): FCL's stated EPA tolerance for the
// signed variant.
extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_depth_contract* gjk2d_plugin_depth(void)
{
    return kDepth;
}

// Shapes prepared once (the optional export of gjk2d/plugin.h): each case's fcl::CollisionObjects.
extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_prepared* gjk2d_plugin_prepared(void)
{
    return &kPrepared;
}
