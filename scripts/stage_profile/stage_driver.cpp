// Cold queries for callgrind: gjk::distance<double> or <float> (reference options), or Box2D v3's
// b2ShapeDistance (float, called as the anchors' harness calls it), over the cases of a text file
// written by ../shared/anchors/json2txt.py, REPS times. Built and run by stage_profile.sh; the
// query is behind a noinline function so that callgrind attributes it. Not part of the build: Box2D
// v3's sources live beside the repository (../shared/anchors), not in it.
//   stage_driver d|f|b CASES.txt REPS
//   stage_driver time CASES.txt ROUNDS   (wall time: per round and query kind, 41 passes over all
//                                         cases, each pass timed alone; prints the fastest and the
//                                         median pass in ns per cold query)
#include "gjk2d/distance.hpp"

#include "box2d/collision.h"
#include "box2d/math_functions.h"
#include "cases.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace
{
template <class T> struct QuerySet
{
    std::vector<std::vector<gjk::Vec2<T>>> points;
    std::vector<gjk::DistanceInput<T>> inputs;
};

template <class T>
void addShape(QuerySet<T>& set, const hshape& h, gjk::Polygon<T>& poly, gjk::Transform<T>& xf)
{
    std::vector<gjk::Vec2<T>> v(std::size_t(h.n));
    for (int k = 0; k < h.n; ++k)
        v[std::size_t(k)] = {T(h.pts[2 * k]), T(h.pts[2 * k + 1])};
    set.points.push_back(std::move(v));
    poly = {set.points.back().data(), h.n, T(h.radius)};
    xf = {{T(h.px), T(h.py)}, {T(h.c), T(h.s)}};
}

template <class T> QuerySet<T> gjkInputs(const hcases& cs)
{
    QuerySet<T> set;
    set.points.reserve(2 * std::size_t(cs.n)); // the polygons point into these vectors
    for (int i = 0; i < cs.n; ++i)
    {
        gjk::DistanceInput<T> in{};
        addShape(set, cs.v[i].a, in.proxyA, in.transformA);
        addShape(set, cs.v[i].b, in.proxyB, in.transformB);
        set.inputs.push_back(in);
    }
    return set;
}

template <class T> [[gnu::noinline]] gjk::DistanceOutput<T> query(const gjk::DistanceInput<T>& in)
{
    gjk::SimplexCache cache;
    return gjk::distance(in, cache);
}

[[gnu::noinline]] b2DistanceOutput bquery(const b2DistanceInput* in)
{
    b2SimplexCache cache = {};
    return b2ShapeDistance(in, &cache, nullptr, 0);
}

template <class T> double runGjk(const hcases& cs, int reps, long& steps)
{
    const QuerySet<T> set = gjkInputs<T>(cs);
    double sum = 0;
    for (int r = 0; r < reps; ++r)
        for (const auto& in : set.inputs)
        {
            const gjk::DistanceOutput<T> o = query(in);
            sum += double(o.distance);
            steps += o.iterations;
        }
    return sum;
}

b2Transform b2Xf(const hshape& s)
{
    b2Transform xf;
    xf.p = {float(s.px), float(s.py)};
    xf.q = {float(s.c), float(s.s)};
    return xf;
}

b2ShapeProxy b2Proxy(const hshape& s)
{
    b2Vec2 pts[B2_MAX_POLYGON_VERTICES];
    for (int k = 0; k < s.n; ++k)
        pts[k] = {float(s.pts[2 * k]), float(s.pts[2 * k + 1])};
    return b2MakeProxy(pts, s.n, float(s.radius));
}

double runBox2d(const hcases& cs, int reps, long& steps)
{
    std::vector<b2DistanceInput> inputs;
    for (int i = 0; i < cs.n; ++i)
    {
        const hcase& c = cs.v[i];
        if (c.a.n > B2_MAX_POLYGON_VERTICES || c.b.n > B2_MAX_POLYGON_VERTICES)
            continue; // refused, as by the harness
        b2DistanceInput in;
        std::memset(&in, 0, sizeof in);
        in.proxyA = b2Proxy(c.a);
        in.proxyB = b2Proxy(c.b);
        in.transform = b2InvMulTransforms(b2Xf(c.a), b2Xf(c.b));
        in.useRadii = true;
        inputs.push_back(in);
    }
    double sum = 0;
    for (int r = 0; r < reps; ++r)
        for (const auto& in : inputs)
        {
            const b2DistanceOutput o = bquery(&in);
            sum += double(o.distance);
            steps += o.iterations;
        }
    return sum;
}
// One timed pass: every case once, cold. Returns ns per query.
template <class Fn> double timePass(std::size_t count, Fn query)
{
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < count; ++i)
        query(i);
    const auto t1 = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(t1 - t0).count() / double(count);
}

// The three kinds alternate pass by pass, so that a loaded machine slows them alike; the fastest
// pass is the least disturbed one.
int timeAll(const hcases& cs, int rounds)
{
    const QuerySet<double> sd = gjkInputs<double>(cs);
    const QuerySet<float> sf = gjkInputs<float>(cs);
    std::vector<b2DistanceInput> sb;
    for (int i = 0; i < cs.n; ++i)
    {
        const hcase& c = cs.v[i];
        if (c.a.n > B2_MAX_POLYGON_VERTICES || c.b.n > B2_MAX_POLYGON_VERTICES)
        {
            std::fprintf(stderr, "time: case %s has more than %d points\n", c.name,
                         B2_MAX_POLYGON_VERTICES);
            return 2;
        }
        b2DistanceInput in;
        std::memset(&in, 0, sizeof in);
        in.proxyA = b2Proxy(c.a);
        in.proxyB = b2Proxy(c.b);
        in.transform = b2InvMulTransforms(b2Xf(c.a), b2Xf(c.b));
        in.useRadii = true;
        sb.push_back(in);
    }
    volatile double sink = 0;
    const std::size_t n = std::size_t(cs.n);
    for (int r = 0; r < rounds; ++r)
    {
        std::vector<double> t[3];
        for (int p = 0; p < 41; ++p)
        {
            t[0].push_back(
                timePass(n, [&](std::size_t i) { sink = sink + query(sd.inputs[i]).distance; }));
            t[1].push_back(
                timePass(n, [&](std::size_t i) { sink = sink + query(sf.inputs[i]).distance; }));
            t[2].push_back(
                timePass(n, [&](std::size_t i) { sink = sink + bquery(&sb[i]).distance; }));
        }
        const char* names[3] = {"double", "float", "box2d-v3"};
        for (int k = 0; k < 3; ++k)
        {
            std::sort(t[k].begin(), t[k].end());
            std::printf("round %d %-9s fastest %7.1f median %7.1f ns/query\n", r + 1, names[k],
                        t[k].front(), t[k][t[k].size() / 2]);
        }
    }
    return 0;
}
} // namespace

int main(int argc, char** argv)
{
    if (argc != 4 || std::strchr("dfbt", argv[1][0]) == nullptr)
    {
        std::fprintf(stderr, "usage: %s d|f|b|time CASES.txt REPS|ROUNDS\n", argv[0]);
        return 2;
    }
    const hcases cs = hload(argv[2]);
    if (argv[1][0] == 't')
        return timeAll(cs, std::atoi(argv[3]));
    const int reps = std::atoi(argv[3]);
    long steps = 0;
    const double sum = argv[1][0] == 'd'   ? runGjk<double>(cs, reps, steps)
                       : argv[1][0] == 'f' ? runGjk<float>(cs, reps, steps)
                                           : runBox2d(cs, reps, steps);
    // iterations: gjk2d's count the loop's support steps (the cold start's is one more), Box2D's
    // every support step.
    std::printf("%d cases, checksum %.17g, iterations per query %.3f\n", cs.n, sum,
                double(steps) / (double(reps) * cs.n));
    return 0;
}
