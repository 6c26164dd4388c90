// gjk::distanceBatchLanes in SIMD lanes (gjk2d/batch.hpp): the run-time choice of instruction set,
// and the scalar side of the lanes: starting a query in a lane (startSimplex, as distance() starts
// it), ending it (finishQuery, as distance() ends it), refilling the lane with the next pair.
//
// Why GCC vector extensions and `#pragma GCC target` rather than Highway (libhwy-dev): the lanes
// need element-wise +, -, *, /, comparisons and selects only (no gather: a lane's points are
// copied into a [point][lane] buffer when its query starts, and the support scan keeps the best
// point beside its index). Vector extensions write them as the scalar code writes them
// (`a.x * b.x + a.y * b.y`), so the lane code reads like distance.hpp line by line and does the
// same IEEE operations by construction; one source compiled under three target pragmas gives the
// SSE2, AVX2 and AVX-512 versions, each in its own namespace (no function compiled for AVX2 can be
// picked by the linker for baseline code), and __builtin_cpu_supports chooses at run time. No new
// dependency. Highway would give the same with more vocabulary (its own names for every operation,
// HWY_EXPORT tables), and its MulAdd is one careless edit away from an FMA.
#include "gjk2d/batch.hpp"

#include "lane_stop.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define GJK_BATCH_LANES 1
#include <immintrin.h> // square roots and movemasks (batch_lanes.hpp), used under the target pragmas

// SSE2: x86-64's baseline, no target pragma needed.
#include "gjk2d/detail/fp_begin.hpp"
#define GJK_LANES_NAMESPACE gjk_lanes_sse2
#include "batch_lanes.hpp"
#undef GJK_LANES_NAMESPACE
#include "gjk2d/detail/fp_end.hpp"

#pragma GCC push_options
#pragma GCC target("avx2")
#include "gjk2d/detail/fp_begin.hpp"
#define GJK_LANES_NAMESPACE gjk_lanes_avx2
#include "batch_lanes.hpp"
#undef GJK_LANES_NAMESPACE
#include "gjk2d/detail/fp_end.hpp"
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f")
#include "gjk2d/detail/fp_begin.hpp"
#define GJK_LANES_NAMESPACE gjk_lanes_avx512
#include "batch_lanes.hpp"
#undef GJK_LANES_NAMESPACE
#include "gjk2d/detail/fp_end.hpp"
#pragma GCC pop_options
#else
#define GJK_BATCH_LANES 0
#endif

#include "gjk2d/detail/fp_begin.hpp"

namespace gjk
{

BatchIsa bestBatchIsa()
{
#if GJK_BATCH_LANES
    static const BatchIsa best = []
    {
        __builtin_cpu_init();
        if (__builtin_cpu_supports("avx512f"))
            return BatchIsa::Avx512;
        if (__builtin_cpu_supports("avx2"))
            return BatchIsa::Avx2;
        return BatchIsa::Sse2;
    }();
    return best;
#else
    return BatchIsa::Scalar;
#endif
}

bool batchIsaSupported(BatchIsa isa)
{
    return isa == BatchIsa::Best || std::uint8_t(isa) <= std::uint8_t(bestBatchIsa());
}

namespace
{

using lanes::kHandBack; // lane_stop.hpp
using lanes::kRunning;

// Shapes of more points than this run the scalar query (the lanes copy each shape's points into
// their buffer when a query starts; a lane scans as many points as the largest shape among the
// lanes, so one large shape would slow the others down).
constexpr int kMaxLanePoints = 64;

// Whether the lanes run this pair with these options (docs/gjk.md, "Batches in SIMD lanes"):
// the default search direction and stopping rule, A's local frame, no signed distance, the linear
// scan (a binary search on small shapes is the linear scan too: usesBinarySearch). Inputs that
// break the input contract (meetsInputContract, asserted by distance()) run the scalar query, which
// asserts.
template <class T> bool runsInLanes(const DistanceInput<T>& in, const Options& options)
{
    if (options.direction != SearchDirection::EdgePerpendicular ||
        options.stopping != StoppingRule::RepeatedSupport || options.frame != Frame::LocalA)
        return false;
    // Options::signedDistance needs the shapes after the loop (the expanding polygon, gjk2d/
    // expand.hpp): every pair runs the scalar query, with its results.
    if (options.signedDistance)
        return false;
    if (!meetsInputContract(in))
        return false;
    const int nA = in.proxyA.count, nB = in.proxyB.count;
    if (nA > kMaxLanePoints || nB > kMaxLanePoints)
        return false;
    return !usesBinarySearch(options.support, nA) && !usesBinarySearch(options.support, nB);
}

constexpr int kIdle = -3; // a lane with no query (LaneState::stop)
#ifndef GJK_BATCH_SORT
#define GJK_BATCH_SORT 0
#endif
constexpr bool kSortBySize = GJK_BATCH_SORT;
constexpr std::size_t kSortBlock = 1024;
// The lanes return to the scalar side (ends, refills) once this share of them has stopped: the
// lanes then idle for a while, but the ends and refills of several lanes share one return, which
// costs less than a return at every stop (docs/speed.md, "Batches in SIMD lanes").
#ifndef GJK_BATCH_STOPPED_PERCENT
#define GJK_BATCH_STOPPED_PERCENT 75
#endif
constexpr int kStoppedPercent = GJK_BATCH_STOPPED_PERCENT;

template <class T, int W, class State> class LaneBatch
{
  public:
    using Run = bool (*)(State&, T, T, T);

    LaneBatch(std::span<const DistanceInput<T>> inputs, std::span<SimplexCache> caches,
              std::span<DistanceOutput<T>> outputs, const Options& options, Run run,
              BatchStats& stats)
        : inputs_(inputs), caches_(caches), outputs_(outputs), options_(options), run_(run),
          stats_(stats)
    {
    }

    void operator()()
    {
        int cap = 1;
        for (std::size_t i = 0; i < inputs_.size(); ++i)
        {
            if (runsInLanes(inputs_[i], options_))
            {
                order_.push_back(i);
                cap = std::max({cap, inputs_[i].proxyA.count, inputs_[i].proxyB.count});
            }
            else
            {
                outputs_[i] = distance(inputs_[i], caches_[i], options_);
                ++stats_.scalarQueries;
            }
        }
        if (order_.empty())
            return;
        if (kSortBySize)
            sortBySize(cap);
        s_ = std::make_unique<State>();
        points_.assign(std::size_t(4) * std::size_t(cap) * W, T(0));
        s_->ax = points_.data();
        s_->ay = s_->ax + cap * W;
        s_->bx = s_->ay + cap * W;
        s_->by = s_->bx + cap * W;
        for (int l = 0; l < W; ++l)
            paddedA_[l] = paddedB_[l] = cap;                           // zeros
        s_->laneEnd = !options_.certify && !options_.correctlyRounded; // both end in finishQuery
        s_->minStopped = std::max(1, W * kStoppedPercent / 100);
        s_->useRadii = options_.useRadii;
        for (int l = 0; l < W; ++l)
            start(l);
        setBounds();
        const T minEdge = minEdgeComponent<T>();
        while (run_(*s_, minEdge, Tolerances<T>::minCoordinate, Tolerances<T>::maxCoordinate))
        {
            for (unsigned bits = s_->stopped; bits != 0; bits &= bits - 1)
            {
                const int l = __builtin_ctz(bits);
                finish(l);
                start(l);
            }
            setBounds();
        }
        stats_.steps = s_->steps;
        stats_.busyLaneSteps = s_->busyLaneSteps;
        stats_.scannedPoints = s_->scannedPoints;
        stats_.usefulPoints = s_->usefulPoints;
    }

  private:
    static constexpr std::size_t kNone = std::size_t(-1);

    // Within each block of kSortBlock pairs, the pairs in order of their larger shape (a stable
    // counting sort): lanes running at once then hold shapes of about one size, and the scans
    // visit fewer padding points, while the pairs' memory is still visited block by block.
    // Left off (GJK_BATCH_SORT 0): slower, docs/speed.md, "Tried and rejected".
    void sortBySize(int cap)
    {
        std::vector<std::size_t> sorted(order_.size());
        std::vector<std::size_t> start(std::size_t(cap) + 2);
        auto key = [&](std::size_t i)
        { return std::size_t(std::max(inputs_[i].proxyA.count, inputs_[i].proxyB.count)); };
        for (std::size_t b = 0; b < order_.size(); b += kSortBlock)
        {
            const std::size_t e = std::min(order_.size(), b + kSortBlock);
            std::fill(start.begin(), start.end(), 0);
            for (std::size_t j = b; j < e; ++j)
                ++start[key(order_[j]) + 1];
            start[0] = b;
            for (std::size_t k = 0; k + 1 < start.size(); ++k)
                start[k + 1] += start[k];
            for (std::size_t j = b; j < e; ++j)
                sorted[start[key(order_[j])]++] = order_[j];
        }
        order_.swap(sorted);
    }

    // A lane's points: the shape's own; padded (setBounds) with its point 0 up to the scan bound.
    static void copyPoints(T* xs, T* ys, int l, const Polygon<T>& poly)
    {
        for (int p = 0; p < poly.count; ++p)
        {
            xs[p * W + l] = poly.points[p].x;
            ys[p * W + l] = poly.points[p].y;
        }
    }

    // Each scan visits as many points as the largest shape among the lanes; a lane whose own
    // points (and padding) end before that repeats its point 0 up to it. An idle lane's points
    // are whatever its last pair left (finite: the scan's sum stays finite... or it is ignored).
    static void pad(T* xs, T* ys, int* padded, int bound)
    {
        for (int l = 0; l < W; ++l)
            for (; padded[l] < bound; ++padded[l])
            {
                xs[padded[l] * W + l] = xs[l];
                ys[padded[l] * W + l] = ys[l];
            }
    }
    void setBounds()
    {
        int boundA = 1, boundB = 1;
        for (int l = 0; l < W; ++l)
            if (pair_[l] != kNone)
            {
                boundA = std::max(boundA, int(s_->countA[l]));
                boundB = std::max(boundB, int(s_->countB[l]));
            }
        pad(s_->ax, s_->ay, paddedA_, boundA);
        pad(s_->bx, s_->by, paddedB_, boundB);
        s_->boundA = boundA;
        s_->boundB = boundB;
    }

    // The next pair into lane l, started as distance() starts it (A's frame, startSimplex).
    void start(int l)
    {
        if (next_ == order_.size())
        {
            pair_[l] = kNone;
            s_->stop[l] = kIdle;
            return;
        }
        const std::size_t i = order_[next_++];
        pair_[l] = i;
        const DistanceInput<T>& in = inputs_[i];
        TransformedShape<T> A{.poly = in.proxyA, .identity = true};
        TransformedShape<T> B{.poly = in.proxyB,
                              .xf = invMulTransforms(in.transformA, in.transformB)};
        // Warm: the cache's simplex, made here (no search). Cold: a simplex of count 0, whose
        // first step in the lanes is startSimplex's support point between the shapes.
        Simplex<T> simplex;
        int edgeBase = 0;
        if (cacheFits(caches_[i], in.proxyA.count, in.proxyB.count))
            edgeBase = startSimplex<T>(caches_[i], A, B, simplex);
        else
            simplex.count = 0;
        searchA_[l] = A.last;
        searchB_[l] = B.last;
        loadSimplex(l, simplex, edgeBase);
        loadPair(l, in, B.xf);
    }

    // Lane l's start simplex, and the largest coordinate among its points (the range check).
    void loadSimplex(int l, const Simplex<T>& simplex, int edgeBase)
    {
        State& s = *s_;
        T maxAbs = T(0);
        for (int k = 0; k < simplex.count; ++k)
            maxAbs = std::max({maxAbs, std::abs(simplex.v[k].w.x), std::abs(simplex.v[k].w.y)});
        for (int k = 0; k < simplex.count; ++k) // a cold start (count 0) fills its slots itself
        {
            const SimplexVertex<T>& v = simplex.v[k];
            s.wx[k][l] = v.w.x;
            s.wy[k][l] = v.w.y;
            s.a[k][l] = v.a;
            s.ia[k][l] = v.indexA;
            s.ib[k][l] = v.indexB;
        }
        s.count[l] = simplex.count;
        s.edgeBase[l] = edgeBase;
        s.maxAbs[l] = maxAbs;
    }

    // Lane l's pair: its shapes' points, sizes and radii, B in A's frame (xfB), A's transform to
    // world, and the loop's counters at their start.
    void loadPair(int l, const DistanceInput<T>& in, const Transform<T>& xfB)
    {
        State& s = *s_;
        s.iteration[l] = 0;
        s.maxIterations[l] = iterationLimit(options_, in.proxyA.count, in.proxyB.count);
        s.bpx[l] = xfB.p.x;
        s.bpy[l] = xfB.p.y;
        s.bqc[l] = xfB.q.c;
        s.bqs[l] = xfB.q.s;
        s.xpx[l] = in.transformA.p.x;
        s.xpy[l] = in.transformA.p.y;
        s.xqc[l] = in.transformA.q.c;
        s.xqs[l] = in.transformA.q.s;
        s.radiusA[l] = in.proxyA.radius;
        s.radiusB[l] = in.proxyB.radius;
        s.savedCount[l] = 0;
        s.lastA[l] = s.lastB[l] = -1;
        s.countA[l] = in.proxyA.count;
        s.countB[l] = in.proxyB.count;
        s.stop[l] = kRunning;
        copyPoints(s.ax, s.ay, l, in.proxyA);
        copyPoints(s.bx, s.by, l, in.proxyB);
        paddedA_[l] = in.proxyA.count;
        paddedB_[l] = in.proxyB.count;
    }

    // Lane l's query has stopped: its output and cache, as distance() ends it (finishQuery).
    void finish(int l)
    {
        const std::size_t i = pair_[l];
        if (s_->stop[l] == kHandBack)
        {
            outputs_[i] = distance(inputs_[i], caches_[i], options_);
            ++stats_.handedBack;
            return;
        }
        ++stats_.laneQueries;
        if (s_->laneEnd && !s_->scalarEnd[l])
            copyLaneEnd(l, i);
        else
            finishOnScalarSide(l, i);
    }

    // The lanes made the end: copy it out, and the cache as finishQuery writes it.
    void copyLaneEnd(int l, std::size_t i)
    {
        const State& s = *s_;
        const int count = int(s.count[l]);
        DistanceOutput<T> out;
        out.pointA = {s.outAx[l], s.outAy[l]};
        out.pointB = {s.outBx[l], s.outBy[l]};
        out.normal = {s.outNx[l], s.outNy[l]};
        out.distance = s.outDistance[l];
        out.iterations = int(s.iteration[l]);
        out.simplexCount = count;
        out.stop = StopReason(s.stop[l]);
        outputs_[i] = out;
        SimplexCache& cache = caches_[i];
        cache.count = count;
        for (int k = 0; k < count; ++k)
        {
            cache.indexA[k] = int(s.ia[k][l]);
            cache.indexB[k] = int(s.ib[k][l]);
        }
        storeEdgeInCanonicalOrder(cache, int(s.edgeBase[l]), s.flipEdge[l] != 0);
        cache.searchA = searchA_[l];
        cache.searchB = searchB_[l];
    }

    // finishQuery on the lane's simplex, remade from its indices and weights.
    void finishOnScalarSide(int l, std::size_t i)
    {
        const State& s = *s_;
        const DistanceInput<T>& in = inputs_[i];
        const StopReason stop = StopReason(s.stop[l]);
        Simplex<T> simplex;
        simplex.count = int(s.count[l]);
        TransformedShape<T> A{.poly = in.proxyA, .identity = true};
        TransformedShape<T> B{.poly = in.proxyB,
                              .xf = {{s.bpx[l], s.bpy[l]}, {s.bqc[l], s.bqs[l]}}};
        for (int k = 0; k < simplex.count; ++k)
        {
            simplex.v[k] = makeVertex<T>(A, B, int(s.ia[k][l]), int(s.ib[k][l]));
            simplex.v[k].a = s.a[k][l];
        }
        QueryEnd<T> end;
        end.edgeBase = int(s.edgeBase[l]);
        end.iteration = int(s.iteration[l]);
        end.maxAbs = s.maxAbs[l];
        end.savedCount = int(s.savedCount[l]);
        for (int k = 0; k < 3; ++k)
            end.saved[k] =
                s.savedA[k][l] < 0 ? -1 : packIndices(int(s.savedA[k][l]), int(s.savedB[k][l]));
        const std::int64_t key = packIndices(int(s.lastA[l]), int(s.lastB[l]));
        end.culledRepeat =
            stop == StopReason::RepeatedSupport &&
            key != packIndices(simplex.v[0].indexA, simplex.v[0].indexB) &&
            (simplex.count == 1 || key != packIndices(simplex.v[1].indexA, simplex.v[1].indexB));
        end.searchA = searchA_[l];
        end.searchB = searchB_[l];
        end.supportOutOfRange = false; // an overflowing scan hands the lane back
        outputs_[i] = finishQuery<T, false>(in, caches_[i], options_, nullptr, 0, in.transformA,
                                            stop, simplex, end);
    }

    std::span<const DistanceInput<T>> inputs_;
    std::span<SimplexCache> caches_;
    std::span<DistanceOutput<T>> outputs_;
    const Options& options_;
    Run run_;
    BatchStats& stats_;
    std::vector<std::size_t> order_;
    std::size_t next_ = 0;
    std::unique_ptr<State> s_;
    std::vector<T> points_;
    std::size_t pair_[W];
    int searchA_[W], searchB_[W];
    int paddedA_[W], paddedB_[W]; // points written in each lane's column of the buffers
};

template <class T, int W, class State>
void runLaneBatch(std::span<const DistanceInput<T>> inputs, std::span<SimplexCache> caches,
                  std::span<DistanceOutput<T>> outputs, const Options& options,
                  bool (*run)(State&, T, T, T), BatchStats& stats)
{
    stats.lanes = W;
    LaneBatch<T, W, State>(inputs, caches, outputs, options, run, stats)();
}

// Whether the lanes pay for this batch, chosen once from its shapes' point counts (BatchIsa::Best
// only: an instruction set asked for by name runs as asked). Float lanes beat the scalar loop on
// every set timed; double lanes only where the shapes are small, as the engine's boxes against
// edges and circles, and they lose from a mean of 4 points per shape (a mean of 3.5 ties). So
// double runs in lanes when the mean is at most 3.75 points per shape (the figures:
// docs/speed.md, "Batches in SIMD lanes").
constexpr double kDoubleLanesMaxMeanPoints = 3.75;

template <class T> bool lanesPay(std::span<const DistanceInput<T>> inputs)
{
    if constexpr (std::is_same_v<T, float>)
        return true;
    double points = 0;
    for (const DistanceInput<T>& in : inputs)
        points += double(std::max(0, in.proxyA.count)) + double(std::max(0, in.proxyB.count));
    return points <= kDoubleLanesMaxMeanPoints * 2 * double(inputs.size());
}

} // namespace

BatchIsa bestBatchIsaFor(std::span<const DistanceInput<double>> inputs)
{
    return lanesPay(inputs) ? bestBatchIsa() : BatchIsa::Scalar;
}

BatchIsa bestBatchIsaFor(std::span<const DistanceInput<float>> inputs)
{
    return lanesPay(inputs) ? bestBatchIsa() : BatchIsa::Scalar;
}

namespace
{
template <class T>
void distanceBatchLanesImpl(std::span<const DistanceInput<T>> inputs,
                            std::span<SimplexCache> caches, std::span<DistanceOutput<T>> outputs,
                            const Options& options, BatchIsa isa, BatchStats* stats)
{
    GJK_ASSERT(inputs.size() == caches.size() && inputs.size() == outputs.size());
    const BatchIsa best = bestBatchIsa();
    if (isa == BatchIsa::Best)
        isa = bestBatchIsaFor(inputs);
    else if (std::uint8_t(isa) > std::uint8_t(best))
        isa = best;
    BatchStats st;
    st.isa = isa;
    st.queries = inputs.size();
    switch (isa)
    {
#if GJK_BATCH_LANES
    case BatchIsa::Sse2:
        runLaneBatch<T, 16 / sizeof(T)>(inputs, caches, outputs, options,
                                        &gjk_lanes_sse2::runLanes<T, 16 / sizeof(T)>, st);
        break;
    case BatchIsa::Avx2:
        runLaneBatch<T, 32 / sizeof(T)>(inputs, caches, outputs, options,
                                        &gjk_lanes_avx2::runLanes<T, 32 / sizeof(T)>, st);
        break;
    case BatchIsa::Avx512:
        runLaneBatch<T, 64 / sizeof(T)>(inputs, caches, outputs, options,
                                        &gjk_lanes_avx512::runLanes<T, 64 / sizeof(T)>, st);
        break;
#endif
    default:
        st.isa = BatchIsa::Scalar;
        for (std::size_t i = 0; i < inputs.size(); ++i)
            outputs[i] = distance(inputs[i], caches[i], options);
        st.scalarQueries = inputs.size();
        break;
    }
    if (stats)
        *stats = st;
}

} // namespace

void distanceBatchLanes(std::span<const DistanceInput<double>> inputs,
                        std::span<SimplexCache> caches, std::span<DistanceOutput<double>> outputs,
                        const Options& options, BatchIsa isa, BatchStats* stats)
{
    distanceBatchLanesImpl<double>(inputs, caches, outputs, options, isa, stats);
}

void distanceBatchLanes(std::span<const DistanceInput<float>> inputs,
                        std::span<SimplexCache> caches, std::span<DistanceOutput<float>> outputs,
                        const Options& options, BatchIsa isa, BatchStats* stats)
{
    distanceBatchLanesImpl<float>(inputs, caches, outputs, options, isa, stats);
}

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
