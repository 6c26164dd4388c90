// Cold queries for callgrind: gjk::distance<double> or <float> (reference options), or Box2D v3's
// b2ShapeDistance (float, called as the anchors' harness calls it), over the cases of a text file
// written by ../shared/anchors/json2txt.py, REPS times. Built and run by stage_profile.sh; the
// query is behind a noinline function so that callgrind attributes it. Not part of the build: Box2D
// v3's sources live beside the repository (../shared/anchors), not in it.
//   stage_driver d|f|b[p][w] CASES.txt REPS
//     p: gjk2d's query on prepared shapes (gjk2d/prepared.hpp, prepared once before the queries;
//        the answers are checked against the plain query's, bit for bit);
//     w: warm, each case's query from the cache its previous query left (seeded by one query)
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
template <class T>
[[gnu::noinline]] gjk::DistanceOutput<T> queryWarm(const gjk::DistanceInput<T>& in,
                                                   gjk::SimplexCache& cache)
{
    return gjk::distance(in, cache);
}
template <class T>
[[gnu::noinline]] void seedWarm(const gjk::DistanceInput<T>& in, gjk::SimplexCache& cache)
{
    gjk::distance(in, cache);
}
template <class T>
[[gnu::noinline]] gjk::DistanceOutput<T>
queryPrepared(const gjk::PreparedShape<T>& a, const gjk::PreparedShape<T>& b,
              const gjk::DistanceInput<T>& in, gjk::SimplexCache& cache)
{
    return gjk::distance(a, in.transformA, b, in.transformB, cache);
}
template <class T> [[gnu::noinline]] gjk::PreparedShape<T> prepareShape(const gjk::Polygon<T>& poly)
{
    return gjk::prepare(poly);
}

[[gnu::noinline]] b2DistanceOutput bquery(const b2DistanceInput* in)
{
    b2SimplexCache cache = {};
    return b2ShapeDistance(in, &cache, nullptr, 0);
}
[[gnu::noinline]] b2DistanceOutput bqueryWarm(const b2DistanceInput* in, b2SimplexCache* cache)
{
    return b2ShapeDistance(in, cache, nullptr, 0);
}
[[gnu::noinline]] void bseedWarm(const b2DistanceInput* in, b2SimplexCache* cache)
{
    b2ShapeDistance(in, cache, nullptr, 0);
}

template <class T> bool sameAnswer(const gjk::DistanceOutput<T>& x, const gjk::DistanceOutput<T>& y)
{
    return std::memcmp(&x.distance, &y.distance, sizeof(T)) == 0 && x.pointA == y.pointA &&
           x.pointB == y.pointB && x.normal == y.normal && x.iterations == y.iterations &&
           x.outOfRange == y.outOfRange && x.rescaled == y.rescaled;
}

template <class T> double runGjk(const hcases& cs, int reps, long& steps, bool prepared, bool warm)
{
    const QuerySet<T> set = gjkInputs<T>(cs);
    std::vector<gjk::PreparedShape<T>> shapes;
    if (prepared)
        for (const auto& in : set.inputs)
        {
            shapes.push_back(prepareShape(in.proxyA));
            shapes.push_back(prepareShape(in.proxyB));
        }
    std::vector<gjk::SimplexCache> caches(set.inputs.size());
    if (warm) // seed every case's cache (out of the query functions callgrind counts)
        for (std::size_t i = 0; i < set.inputs.size(); ++i)
            seedWarm(set.inputs[i], caches[i]);
    double sum = 0;
    long mismatches = 0;
    for (int r = 0; r < reps; ++r)
        for (std::size_t i = 0; i < set.inputs.size(); ++i)
        {
            const auto& in = set.inputs[i];
            gjk::SimplexCache cold;
            gjk::SimplexCache& cache = warm ? caches[i] : cold;
            gjk::DistanceOutput<T> o;
            if (prepared)
            {
                gjk::SimplexCache plainCache = cache;
                o = queryPrepared(shapes[2 * i], shapes[2 * i + 1], in, cache);
                if (r == 0 && !sameAnswer(o, gjk::distance(in, plainCache)))
                    ++mismatches;
            }
            else
                o = warm ? queryWarm(in, cache) : query(in);
            sum += double(o.distance);
            steps += o.iterations;
        }
    if (mismatches > 0)
        std::printf("prepared: %ld answers differ from the plain query's\n", mismatches);
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

double runBox2d(const hcases& cs, int reps, long& steps, bool warm)
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
    std::vector<b2SimplexCache> caches(inputs.size(), b2SimplexCache{});
    if (warm) // seed every case's cache, as the harness does
        for (std::size_t i = 0; i < inputs.size(); ++i)
            bseedWarm(&inputs[i], &caches[i]);
    double sum = 0;
    for (int r = 0; r < reps; ++r)
        for (std::size_t i = 0; i < inputs.size(); ++i)
        {
            const b2DistanceOutput o =
                warm ? bqueryWarm(&inputs[i], &caches[i]) : bquery(&inputs[i]);
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

template <class T> std::vector<gjk::PreparedShape<T>> preparedShapes(const QuerySet<T>& set)
{
    std::vector<gjk::PreparedShape<T>> shapes;
    for (const auto& in : set.inputs)
    {
        shapes.push_back(gjk::prepare(in.proxyA));
        shapes.push_back(gjk::prepare(in.proxyB));
    }
    return shapes;
}

// The kinds alternate pass by pass, so that a loaded machine slows them alike; the fastest pass is
// the least disturbed one. Warm kinds start each case from the cache its previous query left.
int timeAll(const hcases& cs, int rounds)
{
    const QuerySet<double> sd = gjkInputs<double>(cs);
    const QuerySet<float> sf = gjkInputs<float>(cs);
    const auto pd = preparedShapes(sd);
    const auto pf = preparedShapes(sf);
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
    const std::size_t n = std::size_t(cs.n);
    std::vector<gjk::SimplexCache> cw(n), cpw(n);
    std::vector<b2SimplexCache> cb(n, b2SimplexCache{});
    for (std::size_t i = 0; i < n; ++i)
    {
        queryWarm(sd.inputs[i], cw[i]);
        queryPrepared(pd[2 * i], pd[2 * i + 1], sd.inputs[i], cpw[i]);
        bqueryWarm(&sb[i], &cb[i]);
    }
    volatile double sink = 0;
    constexpr int kinds = 8;
    const char* names[kinds] = {"double",     "float",       "box2d-v3",      "double-prep",
                                "float-prep", "double-warm", "dbl-prep-warm", "box2d-v3-warm"};
    for (int r = 0; r < rounds; ++r)
    {
        std::vector<double> t[kinds];
        for (int p = 0; p < 41; ++p)
        {
            t[0].push_back(
                timePass(n, [&](std::size_t i) { sink = sink + query(sd.inputs[i]).distance; }));
            t[1].push_back(
                timePass(n, [&](std::size_t i) { sink = sink + query(sf.inputs[i]).distance; }));
            t[2].push_back(
                timePass(n, [&](std::size_t i) { sink = sink + bquery(&sb[i]).distance; }));
            t[3].push_back(timePass(
                n,
                [&](std::size_t i)
                {
                    gjk::SimplexCache c;
                    sink = sink + queryPrepared(pd[2 * i], pd[2 * i + 1], sd.inputs[i], c).distance;
                }));
            t[4].push_back(timePass(
                n,
                [&](std::size_t i)
                {
                    gjk::SimplexCache c;
                    sink = sink + queryPrepared(pf[2 * i], pf[2 * i + 1], sf.inputs[i], c).distance;
                }));
            t[5].push_back(timePass(n, [&](std::size_t i)
                                    { sink = sink + queryWarm(sd.inputs[i], cw[i]).distance; }));
            t[6].push_back(timePass(
                n,
                [&](std::size_t i) {
                    sink = sink +
                           queryPrepared(pd[2 * i], pd[2 * i + 1], sd.inputs[i], cpw[i]).distance;
                }));
            t[7].push_back(timePass(n, [&](std::size_t i)
                                    { sink = sink + bqueryWarm(&sb[i], &cb[i]).distance; }));
        }
        for (int k = 0; k < kinds; ++k)
        {
            std::sort(t[k].begin(), t[k].end());
            std::printf("round %d %-13s fastest %7.1f median %7.1f ns/query\n", r + 1, names[k],
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
        std::fprintf(stderr, "usage: %s d|f|b[p][w]|time CASES.txt REPS|ROUNDS\n", argv[0]);
        return 2;
    }
    const hcases cs = hload(argv[2]);
    if (argv[1][0] == 't')
        return timeAll(cs, std::atoi(argv[3]));
    const int reps = std::atoi(argv[3]);
    long steps = 0;
    const bool prepared = std::strchr(argv[1] + 1, 'p') != nullptr;
    const bool warm = std::strchr(argv[1] + 1, 'w') != nullptr;
    const double sum = argv[1][0] == 'd'   ? runGjk<double>(cs, reps, steps, prepared, warm)
                       : argv[1][0] == 'f' ? runGjk<float>(cs, reps, steps, prepared, warm)
                                           : runBox2d(cs, reps, steps, warm);
    // iterations: gjk2d's count the loop's support steps (the cold start's is one more), Box2D's
    // every support step.
    std::printf("%d cases, checksum %.17g, iterations per query %.3f\n", cs.n, sum,
                double(steps) / (double(reps) * cs.n));
    return 0;
}
