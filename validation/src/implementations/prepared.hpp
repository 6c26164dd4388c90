// A case as an implementation under test takes it: its inputs converted once to both scalar
// types (PreparedCase, which the accuracy run, the timing loop and the plugin children share), and
// a gjk2d variant's query on them, as the accuracy run and the timing loop both make it.
#pragma once

#include "implementations/variants.hpp"
#include "inputs/cases.hpp"

#include "gjk2d/batch.hpp"
#include "gjk2d/distance.hpp"

#include <boost/container/small_vector.hpp>

#include <span>
#include <type_traits>

namespace gjkval
{

// A shape's points, inline up to 8 (Box2D's polygon limit; the random family's 3 to 8): preparing
// a case allocates nothing on the common path (docs/speed.md).
template <class T> using CasePoints = boost::container::small_vector<gjk::Vec2<T>, 8>;

// A case's inputs converted once to both scalar types (the timing loop reuses them).
struct PreparedCase
{
    CasePoints<double> ad, bd;
    CasePoints<float> af, bf;
    gjk::Transform<double> xad, xbd;
    gjk::Transform<float> xaf, xbf;
    double rad = 0, rbd = 0;
    float raf = 0, rbf = 0;
    bool floatOk = true; // every input finite after rounding to float
    // Both shapes' points in convex order (or at most kLinearSupportMaxPoints of them), as double
    // [0] and as float-rounded [1]: the precondition of SupportStrategy::BinarySearch.
    bool binaryOk[2] = {true, true};
    // The case's world case (inputs/geometry.hpp, worldCase) fits double [0] and float [1]: what
    // an implementation given world points (InputForm::World) needs to run on it.
    bool worldOk[2] = {true, true};

    template <class T> gjk::DistanceInput<T> input() const
    {
        if constexpr (std::is_same_v<T, float>)
            return {{af.data(), int(af.size()), raf}, {bf.data(), int(bf.size()), rbf}, xaf, xbf};
        else
            return {{ad.data(), int(ad.size()), rad}, {bd.data(), int(bd.size()), rbd}, xad, xbd};
    }
};
PreparedCase prepare(const Case& c);

// exact::completeCorrectlyRounded (gjk2d/correct_fallback.hpp), out of line: the timing loop of
// every variant inlines query() below, and only correctly rounded variants ever call it.
[[gnu::noinline]] void completeExactly(const gjk::DistanceInput<double>& in,
                                       const gjk::Options& options,
                                       gjk::DistanceOutput<double>& out);

// The variant's GJK query as both the accuracy run and the timing loop make it: cold (fresh
// cache), or for warm variants (Start::Warm) a cold query whose cache starts the one
// returned (and traced).
template <class T>
gjk::DistanceOutput<T> query(const PreparedCase& p, const VariantInfo& v,
                             gjk::Trace<T>* trace = nullptr)
{
    gjk::SimplexCache cache;
    const gjk::DistanceInput<T> in = p.input<T>();
    if (v.start == Start::Warm)
        gjk::distance(in, cache, v.options);
    gjk::DistanceOutput<T> out;
    if (v.batch && !trace) // a batch of one (a trace needs the scalar query: the same bits)
        gjk::distanceBatchLanes(std::span<const gjk::DistanceInput<T>>(&in, 1),
                                std::span<gjk::SimplexCache>(&cache, 1),
                                std::span<gjk::DistanceOutput<T>>(&out, 1), v.options);
    else
        out = gjk::distance(in, cache, v.options, trace);
    // A correctly rounded variant: its undecided queries completed exactly, as a user would.
    if constexpr (std::is_same_v<T, double>)
        if (out.path == gjk::CorrectPath::NeedsExact) [[unlikely]]
            completeExactly(in, v.options, out);
    return out;
}

} // namespace gjkval
