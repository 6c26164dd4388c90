// A case prepared once for every implementation under test (implementations/prepared.hpp), and
// the exact completion of a correctly rounded query.
#include "implementations/prepared.hpp"

#include "inputs/geometry.hpp"

#include <gjk2d/correct_fallback.hpp>

#include <vector>

namespace gjkval
{

PreparedCase prepare(const Case& c)
{
    PreparedCase p;
    p.ad.reserve(c.a.points.size());
    p.af.reserve(c.a.points.size());
    p.bd.reserve(c.b.points.size());
    p.bf.reserve(c.b.points.size());
    for (const auto& q : c.a.points)
    {
        p.ad.push_back({q[0], q[1]});
        p.af.push_back({float(q[0]), float(q[1])});
    }
    for (const auto& q : c.b.points)
    {
        p.bd.push_back({q[0], q[1]});
        p.bf.push_back({float(q[0]), float(q[1])});
    }
    p.xad = {{c.a.px, c.a.py}, {c.a.c, c.a.s}};
    p.xbd = {{c.b.px, c.b.py}, {c.b.c, c.b.s}};
    p.xaf = {{float(c.a.px), float(c.a.py)}, {float(c.a.c), float(c.a.s)}};
    p.xbf = {{float(c.b.px), float(c.b.py)}, {float(c.b.c), float(c.b.s)}};
    p.rad = c.a.radius;
    p.rbd = c.b.radius;
    p.raf = float(c.a.radius);
    p.rbf = float(c.b.radius);
    p.floatOk = representableInFloat(c);
    p.worldOk[0] = worldCaseFits(c, false);
    p.worldOk[1] = worldCaseFits(c, true);
    auto convex = [](const auto& pts)
    {
        if (int(pts.size()) <= kLinearSupportMaxPoints)
            return true;
        std::vector<P2> q;
        q.reserve(pts.size());
        for (const auto& v : pts)
            q.push_back({double(v.x), double(v.y)});
        return inConvexOrder(q);
    };
    p.binaryOk[0] = convex(p.ad) && convex(p.bd);
    p.binaryOk[1] = p.floatOk && convex(p.af) && convex(p.bf);
    return p;
}

void completeExactly(const gjk::DistanceInput<double>& in, const gjk::Options& options,
                     gjk::DistanceOutput<double>& out)
{
    exact::completeCorrectlyRounded(in, options, out);
}

} // namespace gjkval
