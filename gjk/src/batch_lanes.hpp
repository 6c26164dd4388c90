// The GJK loop of gjk/include/gjk2d/distance.hpp, one query per SIMD lane (gjk2d/batch.hpp).
// No include guard: gjk/src/batch.cpp includes this file once per instruction set, each time in
// its own namespace (GJK_LANES_NAMESPACE) under its own `#pragma GCC target`, so that no function
// compiled for AVX2 or AVX-512 can be picked by the linker for code that runs on the baseline.
// Nothing here calls the scalar library: the lanes' state is plain arrays (LaneState), which the
// scalar code (batch.cpp) fills when a query starts and reads when it ends. The lanes run the cold
// start's support point (a lane of count 0), the loop, and the end of the query (finishQuery's
// common path: witness points, distance, normal, world frame, radii); the scalar side only copies
// the results out, or runs finishQuery itself for a lane whose end is not the common one.
//
// Vectors are GCC vector extensions: `a * b + c * d` on vectors is the same IEEE operations as
// on scalars, lane by lane, in the same order (no contraction into FMA: -ffp-contract=off and
// fp_begin.hpp, and no FMA target enabled). Every branch of the scalar loop becomes a mask and a
// select between the values both sides computed: a lane's values are exactly the ones the scalar
// query computes on its path. Comments name the scalar function each block mirrors.
//
// A lane leaves the lanes (LaneState::stop = kHandBack, the scalar query then runs it from its
// start) on the scalar loop's rare paths, which are not mirrored here:
// - an edge shorter than minEdgeComponent (edgeOfSafeSize would scale it), a zero edge included;
// - solve3 with inconsistent signs (its closest-edge fallback), or an interior whose Cramer weights
//   put the origin outside (keepTriangle's closest-edge fallback);
// - a support scan whose running sum is not finite (the scalar query's overflow flag: the padding
//   points of a lane, below, could raise it where the scalar scan does not).
// A lane whose end is not finishQuery's common path sets LaneState::scalarEnd, and the scalar side
// runs finishQuery on the lane's simplex: a rescaled retry (out of range, or every support point
// 0), a rotation of A whose squared size is out of range, a culled repeat (the cache keeps the
// simplex before the last solve), the certified interval.

namespace GJK_LANES_NAMESPACE
{

template <class T> struct LaneInt;
template <> struct LaneInt<double>
{
    using type = std::int64_t;
};
template <> struct LaneInt<float>
{
    using type = std::int32_t;
};

template <class T, int W> struct Lanes
{
    using I = typename LaneInt<T>::type;
    typedef T V __attribute__((vector_size(W * sizeof(T))));
    typedef I M __attribute__((vector_size(W * sizeof(T)))); // masks (-1 / 0) and indices

    static V load(const T* p)
    {
        V v;
        __builtin_memcpy(&v, p, sizeof(V));
        return v;
    }
    static M load(const I* p)
    {
        M v;
        __builtin_memcpy(&v, p, sizeof(M));
        return v;
    }
    static void store(T* p, V v) { __builtin_memcpy(p, &v, sizeof(V)); }
    static void store(I* p, M v) { __builtin_memcpy(p, &v, sizeof(M)); }
    static V splat(T x) { return V{} + x; }
    static M splat(I x) { return M{} + x; }
    // m ? x : y, lane by lane.
    [[gnu::always_inline]] static V sel(M m, V x, V y) { return m ? x : y; }
    [[gnu::always_inline]] static M sel(M m, M x, M y) { return m ? x : y; }
    // An edge that edgeOfSafeSize scales in the scalar query: max(|x|, |y|) < minEdge (std::max).
    [[gnu::always_inline]] static M tiny(V ex, V ey, T minEdge)
    {
        const V ax = ex < V{} ? -ex : ex, ay = ey < V{} ? -ey : ey;
        const V m = ax < ay ? ay : ax;
        return m < V{} + minEdge;
    }
    // Slots 0 and 1 of the solved simplex (slot 2 only ever stays): x[0] <- x[1] or x[2], x[1] <-
    // x[2].
    template <class X>
    [[gnu::always_inline]] static void move(X* x, M solving, M from1to0, M from2to0, M from2to1)
    {
        const X x0 = x[0], x1 = x[1], x2 = x[2];
        x[0] = sel(solving, sel(from1to0, x1, sel(from2to0, x2, x0)), x0);
        x[1] = sel(solving, sel(from2to1, x2, x1), x1);
    }
    // std::abs: the sign bit cleared (of -0 and NaN too).
    [[gnu::always_inline]] static V absBits(V x)
    {
        return (V)((M)x & ~(M)(-V{})); // -0.0: the sign bit alone
    }
    // The correctly rounded square root (IEEE: the scalar std::sqrt's bits), one instruction.
    [[gnu::always_inline]] static V sqrt(V x)
    {
        if constexpr (sizeof(V) == 64 && sizeof(T) == 8)
            return (V)_mm512_sqrt_pd((__m512d)x);
        else if constexpr (sizeof(V) == 64)
            return (V)_mm512_sqrt_ps((__m512)x);
        else if constexpr (sizeof(V) == 32 && sizeof(T) == 8)
            return (V)_mm256_sqrt_pd((__m256d)x);
        else if constexpr (sizeof(V) == 32)
            return (V)_mm256_sqrt_ps((__m256)x);
        else if constexpr (sizeof(T) == 8)
            return (V)_mm_sqrt_pd((__m128d)x);
        else
            return (V)_mm_sqrt_ps((__m128)x);
    }
    // base[index[l] * W + l] for each lane l: lane l's point index[l] in a [point][lane] buffer.
    [[gnu::always_inline]] static V gather(const T* base, M index)
    {
        M offset = index * I(W);
        for (int l = 0; l < W; ++l)
            offset[l] += I(l);
        if constexpr (sizeof(V) == 64 && sizeof(T) == 8)
            return (V)_mm512_i64gather_pd((__m512i)offset, base, 8);
        else if constexpr (sizeof(V) == 64)
            return (V)_mm512_i32gather_ps((__m512i)offset, base, 4);
        else if constexpr (sizeof(V) == 32 && sizeof(T) == 8)
            return (V)_mm256_i64gather_pd(base, (__m256i)offset, 8);
        else if constexpr (sizeof(V) == 32)
            return (V)_mm256_i32gather_ps(base, (__m256i)offset, 4);
        else
        {
            V r;
            for (int l = 0; l < W; ++l)
                r[l] = base[offset[l]];
            return r;
        }
    }
    // One bit per lane (a mask's lanes are all ones or all zeros).
    [[gnu::always_inline]] static unsigned bits(M m)
    {
        if constexpr (sizeof(V) == 64 && sizeof(T) == 8)
            return _mm512_test_epi64_mask((__m512i)m, (__m512i)m);
        else if constexpr (sizeof(V) == 64)
            return _mm512_test_epi32_mask((__m512i)m, (__m512i)m);
        else if constexpr (sizeof(V) == 32 && sizeof(T) == 8)
            return unsigned(_mm256_movemask_pd((__m256d)m));
        else if constexpr (sizeof(V) == 32)
            return unsigned(_mm256_movemask_ps((__m256)m));
        else if constexpr (sizeof(T) == 8)
            return unsigned(_mm_movemask_pd((__m128d)m));
        else
            return unsigned(_mm_movemask_ps((__m128)m));
    }
    [[gnu::always_inline]] static bool any(M m) { return bits(m) != 0; }
    // The sum of the lanes.
    [[gnu::always_inline]] static std::uint64_t sum(M m)
    {
        std::uint64_t r = 0;
        for (int l = 0; l < W; ++l)
            r += std::uint64_t(m[l]);
        return r;
    }
};

// State of the W lanes between two calls of runLanes; the scalar side (batch.cpp) writes a lane
// when its query starts and reads it when it ends. Arrays indexed [slot][lane] or [lane].
// A lane of count 0 has no simplex yet: its first step finds the cold start's support point in
// the direction bp (B's origin in A's frame) and makes it the simplex, as startSimplex does.
template <class T, int W> struct LaneState
{
    using I = typename LaneInt<T>::type;
    // Simplex vertices: w = wA - wB (A's frame), weight, index pair. wA and wB are gathered from
    // the lane's points by index at the end (gatherVertex), as makeVertex makes them.
    alignas(64) T wx[3][W];
    alignas(64) T wy[3][W];
    alignas(64) T a[3][W];
    alignas(64) I ia[3][W];
    alignas(64) I ib[3][W];
    alignas(64) I count[W];
    alignas(64) I edgeBase[W];
    alignas(64) I iteration[W];
    alignas(64) I maxIterations[W];
    alignas(64) T maxAbs[W];
    alignas(64) T bpx[W], bpy[W], bqc[W], bqs[W]; // B's transform into A's frame
    alignas(64) I savedA[3][W];                   // the simplex before the last solve
    alignas(64) I savedB[3][W];
    alignas(64) I savedCount[W];
    alignas(64) I lastA[W], lastB[W]; // the last support point's index pair
    alignas(64) I stop[W];            // kRunning, a StopReason, or kHandBack
    alignas(64) I countA[W], countB[W];
    // The end of the query (finishQuery's common path).
    bool laneEnd = true;                          // false: every lane ends in the scalar code
    bool useRadii = true;                         // Options::useRadii
    alignas(64) T xpx[W], xpy[W], xqc[W], xqs[W]; // A's transform: the world from A's frame
    alignas(64) T radiusA[W], radiusB[W];
    alignas(64) T outAx[W], outAy[W], outBx[W], outBy[W], outNx[W], outNy[W], outDistance[W];
    alignas(64) I flipEdge[W];  // the final edge goes into the cache reversed
    alignas(64) I scalarEnd[W]; // the scalar code runs finishQuery for this lane
    unsigned stopped = 0;       // lanes that stopped in the last runLanes (one bit each)
    int minStopped = 1;         // runLanes returns once this many lanes have stopped
    // Points of each lane's shapes, [point][lane]; a lane's points past its own count repeat its
    // point 0, which can never win a support scan (ties keep the lowest index) but could make its
    // running sum overflow (then kHandBack).
    T* ax = nullptr;
    T* ay = nullptr;
    T* bx = nullptr;
    T* by = nullptr;
    int boundA = 0, boundB = 0; // points each scan visits: the largest count among the lanes
    // Utilisation counters (BatchStats).
    std::uint64_t steps = 0, busyLaneSteps = 0, scannedPoints = 0, usefulPoints = 0;
};

using gjk::lanes::kHandBack; // lane_stop.hpp
using gjk::lanes::kRunning;

// Runs the lanes whose stop is kRunning in lockstep until at least one of them stops; returns
// whether any lane stopped (no lane running: returns false at once). LaneState::stopped then says
// which, their stop values why (a StopReason or kHandBack), and for the lanes that stopped with
// a StopReason, scalarEnd and the out* arrays give their end. Mirrors distanceImpl (runLoop, then
// finishQuery) with Options' default direction and stopping rule, A's local frame and the linear
// support scan.
// One long kernel on purpose: it reads beside distance.hpp's loop step by step, in one scope.
template <class T, int W>
bool runLanes(LaneState<T, W>& s, T minEdge, T minCoordinate, T maxCoordinate)
{
    using L = Lanes<T, W>;
    using V = typename L::V;
    using M = typename L::M;
    using I = typename L::I;
    const V zero{};
    const V one = L::splat(T(1));
    const M mzero{};
    const M mone = L::splat(I(1));
    auto tiny = [minEdge](V ex, V ey) { return L::tiny(ex, ey, minEdge); };
    auto sel = [](M m, V x, V y) { return L::sel(m, x, y); };
    auto seli = [](M m, M x, M y) { return L::sel(m, x, y); };
    auto splati = [](int x) { return L::splat(I(x)); };
    // gjk::accurateCross (simplex.hpp), lane by lane: the same steps, the same bits.
    auto accurateCross = [](V ax, V ay, V bx, V by)
    {
        const V split = L::splat(T((1 << ((std::numeric_limits<T>::digits + 1) / 2)) + 1));
        auto twoProduct = [&split](V x, V y, V& lo)
        {
            const V p = x * y;
            const V cx = split * x, xh = cx - (cx - x), xl = x - xh;
            const V cy = split * y, yh = cy - (cy - y), yl = y - yh;
            lo = ((xh * yh - p) + xh * yl + xl * yh) + xl * yl;
            return p;
        };
        V l1, l2;
        const V h1 = twoProduct(ax, by, l1), h2 = twoProduct(ay, bx, l2);
        return (h1 - h2) + (l1 - l2);
    };

    M stop = L::load(s.stop);
    M running = stop == splati(kRunning);
    s.stopped = 0;
    if (!L::any(running))
        return false;

    V wx[3], wy[3], a[3];
    M ia[3], ib[3], savedA[3], savedB[3];
    for (int k = 0; k < 3; ++k)
    {
        wx[k] = L::load(s.wx[k]);
        wy[k] = L::load(s.wy[k]);
        a[k] = L::load(s.a[k]);
        ia[k] = L::load(s.ia[k]);
        ib[k] = L::load(s.ib[k]);
        savedA[k] = L::load(s.savedA[k]);
        savedB[k] = L::load(s.savedB[k]);
    }
    M count = L::load(s.count), edgeBase = L::load(s.edgeBase), iteration = L::load(s.iteration);
    const M maxIterations = L::load(s.maxIterations);
    V maxAbs = L::load(s.maxAbs);
    const V bpx = L::load(s.bpx), bpy = L::load(s.bpy), bqc = L::load(s.bqc), bqs = L::load(s.bqs);
    M savedCount = L::load(s.savedCount);
    M lastA = L::load(s.lastA), lastB = L::load(s.lastB);
    const M countA = L::load(s.countA), countB = L::load(s.countB);

    M useful = mzero; // points of the lanes' own shapes scanned
    // Lockstep until s.minStopped lanes have stopped (or none runs): stopped lanes wait, idle,
    // for the others, and the end and the refills are made for all of them at once.
    M stopped = mzero;
    while (__builtin_popcount(L::bits(stopped)) < s.minStopped && L::any(running))
    {
        ++s.steps;
        s.busyLaneSteps += unsigned(__builtin_popcount(L::bits(running)));

        // Remember the simplex (case 1's repeated-support check): unused slots hold -1.
        for (int k = 0; k < 3; ++k)
        {
            const M used = count > splati(k);
            savedA[k] = seli(running, seli(used, ia[k], splati(-1)), savedA[k]);
            savedB[k] = seli(running, seli(used, ib[k], splati(-1)), savedB[k]);
        }
        savedCount = seli(running, count, savedCount);

        M handBack = mzero;
        const M is2 = count == splati(2), is3 = count == splati(3);

        // --- solve2 on (w1, w2) -------------------------------------------------------------
        const V e12x = wx[1] - wx[0], e12y = wy[1] - wy[0];
        const V u12 = wx[1] * e12x + wy[1] * e12y;    // dot(w2, e12)
        const V v12 = -(wx[0] * e12x + wy[0] * e12y); // -dot(w1, e12)
        handBack |= (is2 | is3) & tiny(e12x, e12y);

        // --- solve3 on (w1, w2, w3) ---------------------------------------------------------
        const V e13x = wx[2] - wx[0], e13y = wy[2] - wy[0];
        const V u13 = wx[2] * e13x + wy[2] * e13y;
        const V v13 = -(wx[0] * e13x + wy[0] * e13y);
        const V e23x = wx[2] - wx[1], e23y = wy[2] - wy[1];
        const V u23 = wx[2] * e23x + wy[2] * e23y;
        const V v23 = -(wx[1] * e23x + wy[1] * e23y);
        handBack |= is3 & (tiny(e13x, e13y) | tiny(e23x, e23y));
        const V n123 = e12x * e13y - e12y * e13x;
        const V sign = n123 > zero ? one : (n123 < zero ? -one : zero);
        const V u123 = sign * (wx[1] * wy[2] - wy[1] * wx[2]); // sign * cross(w2, w3)
        const V v123 = sign * (wx[2] * wy[0] - wy[2] * wx[0]); // sign * cross(w3, w1)
        const V w123 = sign * (wx[0] * wy[1] - wy[0] * wx[1]); // sign * cross(w1, w2)
        // The regions in the talk's order, each excluding the ones before it.
        M taken = mzero;
        auto region = [&taken](M m)
        {
            const M r = m & ~taken;
            taken |= r;
            return r;
        };
        [[maybe_unused]] const M r1 =
            region((v12 <= zero) & (v13 <= zero)); // region w1: nothing moves
        const M r2 = region((u12 <= zero) & (v23 <= zero));
        const M r3 = region((u13 <= zero) & (u23 <= zero));
        const M r12 = region((u12 > zero) & (v12 > zero) & (w123 <= zero));
        const M r13 = region((u13 > zero) & (v13 > zero) & (v123 <= zero));
        const M r23 = region((u23 > zero) & (v23 > zero) & (u123 <= zero));
        const M r123 = region((u123 > zero) & (v123 > zero) & (w123 > zero));
        handBack |= is3 & ~taken; // inconsistent signs: solve3's closest-edge fallback

        // The solved simplex. solve2 (count 2): region w1 (v12 <= 0), region w2 (u12 <= 0), else
        // the edge. Edge weights as keepEdge and solve2 make them: ui * inv, vj * inv with
        // inv = 1 / (ui + vj); the interior's: each coordinate divided by their sum.
        const M s2v1 = v12 <= zero;
        const M s2v2 = ~s2v1 & (u12 <= zero);
        const M s2e = ~s2v1 & ~s2v2;
        const V ue = sel(is3, sel(r12, u12, sel(r13, u13, u23)), u12);
        const V ve = sel(is3, sel(r12, v12, sel(r13, v13, v23)), v12);
        const V inv = one / (ue + ve);
        const V ae0 = ue * inv, ae1 = ve * inv;
        // The interior's weights as solve3 makes them (simplex.hpp): Cramer's rule from w1 with
        // accurateCross's steps, else (n zero or not finite) the areas'. Only when some lane is in
        // the interior (containment ends that lane's query): the other lanes never read them, and
        // the exact products' cost stays out of the common iteration.
        const V sum = (u123 + v123) + w123;
        V i1 = u123 / sum, i2 = v123 / sum, i3 = w123 / sum;
        if (L::any(is3 & r123)) [[unlikely]]
        {
            const V nr = accurateCross(e12x, e12y, e13x, e13y);
            const M cramer = ((nr > zero) | (nr < zero)) &
                             (nr <= L::splat(std::numeric_limits<T>::max())) &
                             (nr >= L::splat(-std::numeric_limits<T>::max()));
            V bq = accurateCross(e13x, e13y, wx[0], wy[0]) / nr,
              cq = accurateCross(wx[0], wy[0], e12x, e12y) / nr;
            // keepTriangle's "origin outside after all": the scalar query keeps the closest edge
            // and goes on, a path not mirrored here.
            const V u4 = L::splat(gjk::kOutsideWeightBC<T>);
            const V u16 = L::splat(gjk::kOutsideWeightA1<T>);
            handBack |=
                is3 & r123 & cramer & ((bq < -u4) | (cq < -u4) | (((one - bq) - cq) < -u16));
            bq = sel(bq > zero, bq, zero);
            cq = sel(cq > zero, cq, zero);
            V arq = (one - bq) - cq;
            arq = sel(arq > zero, arq, zero);
            const V tq = (arq + bq) + cq;
            i1 = sel(cramer, arq / tq, i1);
            i2 = sel(cramer, bq / tq, i2);
            i3 = sel(cramer, cq / tq, i3);
        }
        const M edge = (is2 & s2e) | (is3 & (r12 | r13 | r23));
        const M interior = is3 & r123;
        const M from1to0 = (is2 & s2v2) | (is3 & (r2 | r23));
        const M from2to0 = is3 & r3;
        const M from2to1 = is3 & (r13 | r23);
        const M solving = running & (is2 | is3);
        L::move(wx, solving, from1to0, from2to0, from2to1);
        L::move(wy, solving, from1to0, from2to0, from2to1);
        L::move(ia, solving, from1to0, from2to0, from2to1);
        L::move(ib, solving, from1to0, from2to0, from2to1);
        a[0] = sel(solving, sel(interior, i1, sel(edge, ae0, one)), a[0]);
        a[1] = sel(solving & (edge | interior), sel(interior, i2, ae1), a[1]);
        a[2] = sel(solving & interior, i3, a[2]);
        count = seli(solving, seli(interior, splati(3), seli(edge, splati(2), mone)), count);

        // Case 2: containment.
        const M containment = running & (count == splati(3));

        // --- searchDirection; a lane of count 0 searches from B's origin in A's frame ------------
        const M edgeNow = count == splati(2), start = count == mzero;
        const V fx = wx[1] - wx[0], fy = wy[1] - wy[0];
        handBack |= edgeNow & tiny(fx, fy);
        const M base1 = edgeBase != mzero;
        const V bx = sel(base1, wx[1], wx[0]), by = sel(base1, wy[1], wy[0]);
        const V side = fx * -by - fy * -bx; // originSide: cross(e12, -w1)
        const M left = side > zero;
        // leftPerp(e) = (-e.y, e.x), rightPerp(e) = (e.y, -e.x); a single vertex: -w. The start:
        // d0 = B.xf.p - A.xf.p = bp - 0 = bp (x - 0 is x, -0 too); d0 = 0 scans to vertex 0 of
        // each shape, which is startSimplex's makeVertex(0, 0).
        const V dx = sel(start, bpx, sel(edgeNow, sel(left, -fy, fy), -wx[0]));
        const V dy = sel(start, bpy, sel(edgeNow, sel(left, fx, -fx), -wy[0]));
        const M zeroDirection = running & ~start & ~containment & (dx == zero) & (dy == zero);
        const M limit =
            running & ~start & ~containment & ~zeroDirection & (iteration == maxIterations);
        handBack &= running;
        stop = seli(containment, splati(int(gjk::StopReason::Containment)), stop);
        stop = seli(zeroDirection, splati(int(gjk::StopReason::ZeroDirection)), stop);
        stop = seli(limit, splati(int(gjk::StopReason::IterationLimit)), stop);

        // --- findMinkowskiSupport: A in its own frame, B through invRotate(qB, -d) ------------
        const M searching = running & ~containment & ~zeroDirection & ~limit & ~handBack;
        V pax = L::load(s.ax), pay = L::load(s.ay);
        V bestA = dx * pax + dy * pay;
        V sumA = bestA;
        M indexA = mzero;
        for (int i = 1; i < s.boundA; ++i)
        {
            const V px = L::load(s.ax + i * W), py = L::load(s.ay + i * W);
            const V value = dx * px + dy * py;
            sumA += value;
            const M better = value > bestA;
            indexA = seli(better, splati(i), indexA);
            bestA = sel(better, value, bestA);
            pax = sel(better, px, pax);
            pay = sel(better, py, pay);
        }
        const V ndx = -dx, ndy = -dy;
        const V lx = bqc * ndx + bqs * ndy, ly = -bqs * ndx + bqc * ndy; // invRotate(qB, -d)
        V pbx = L::load(s.bx), pby = L::load(s.by);
        V bestB = lx * pbx + ly * pby;
        V sumB = bestB;
        M indexB = mzero;
        for (int i = 1; i < s.boundB; ++i)
        {
            const V px = L::load(s.bx + i * W), py = L::load(s.by + i * W);
            const V value = lx * px + ly * py;
            sumB += value;
            const M better = value > bestB;
            indexB = seli(better, splati(i), indexB);
            bestB = sel(better, value, bestB);
            pbx = sel(better, px, pbx);
            pby = sel(better, py, pby);
        }
        s.scannedPoints += std::uint64_t(W) * std::uint64_t(s.boundA + s.boundB);
        useful += seli(searching, countA + countB, mzero);
        // The scalar scan's finiteness test, abs(sum) <= max.
        const V big = L::splat(std::numeric_limits<T>::max());
        const M overflow = searching & ~((L::absBits(sumA) <= big) & (L::absBits(sumB) <= big));
        handBack |= overflow;
        const M found = searching & ~overflow;

        // makeVertex: wA = A's point (A's frame), wB = transformPoint(B's transform, B's point).
        const V nwAx = pax, nwAy = pay;
        const V nwBx = (bqc * pbx - bqs * pby) + bpx, nwBy = (bqs * pbx + bqc * pby) + bpy;
        const V nwx = nwAx - nwBx, nwy = nwAy - nwBy;
        iteration = seli(found & ~start, iteration + mone, iteration); // the start is no iteration
        // maxAbs = std::max({maxAbs, |w.x|, |w.y|}): the first largest, by <.
        const V awx = L::absBits(nwx), awy = L::absBits(nwy);
        V m = maxAbs;
        m = m < awx ? awx : m;
        m = m < awy ? awy : m;
        maxAbs = sel(found, m, maxAbs);
        lastA = seli(found & ~start, indexA, lastA);
        lastB = seli(found & ~start, indexB, lastB);

        // Case 1: the support point is already in the simplex (compared by index pair).
        M repeated = mzero;
        for (int k = 0; k < 3; ++k)
            repeated |= (indexA == savedA[k]) & (indexB == savedB[k]);
        repeated &= found & ~start;
        stop = seli(repeated, splati(int(gjk::StopReason::RepeatedSupport)), stop);

        // Otherwise the support point joins the simplex.
        const M grow = found & ~repeated;
        for (int k = 0; k < 3; ++k)
        {
            const M slot = grow & (count == splati(k));
            wx[k] = sel(slot, nwx, wx[k]);
            wy[k] = sel(slot, nwy, wy[k]);
            a[k] = sel(slot, one, a[k]);
            ia[k] = seli(slot, indexA, ia[k]);
            ib[k] = seli(slot, indexB, ib[k]);
        }
        count = seli(grow, count + mone, count);
        edgeBase = seli(grow, mzero, edgeBase);

        stop = seli(handBack, splati(kHandBack), stop);
        stopped |= running & ~grow;
        running &= grow;
    }
    s.stopped = L::bits(stopped);
    s.usefulPoints += L::sum(useful);

    // --- The end of the query: finishQuery's common path, for the lanes that stopped ------------
    if (s.laneEnd)
    {
        const M ended = stopped & (stop >= mzero);
        const M c1 = count == mone, c2 = count == splati(2);
        // makeVertex's wA and wB of the simplex, from the lanes' points by index (a slot past the
        // count reads point 0), then computeWitnessPoints.
        V wAx[3], wAy[3], wBx[3], wBy[3];
        for (int k = 0; k < 3; ++k)
        {
            const M used = count > splati(k);
            const M iA = seli(used, ia[k], mzero), iB = seli(used, ib[k], mzero);
            wAx[k] = L::gather(s.ax, iA);
            wAy[k] = L::gather(s.ay, iA);
            const V px = L::gather(s.bx, iB), py = L::gather(s.by, iB);
            wBx[k] = (bqc * px - bqs * py) + bpx;
            wBy[k] = (bqs * px + bqc * py) + bpy;
        }
        const V pA2x = a[0] * wAx[0] + a[1] * wAx[1], pA2y = a[0] * wAy[0] + a[1] * wAy[1];
        const V pB2x = a[0] * wBx[0] + a[1] * wBx[1], pB2y = a[0] * wBy[0] + a[1] * wBy[1];
        const V pA3x = pA2x + a[2] * wAx[2], pA3y = pA2y + a[2] * wAy[2];
        const V pAx = sel(c1, wAx[0], sel(c2, pA2x, pA3x)),
                pAy = sel(c1, wAy[0], sel(c2, pA2y, pA3y));
        const V pBx = sel(c1, wBx[0], sel(c2, pB2x, pA3x)),
                pBy = sel(c1, wBy[0], sel(c2, pB2y, pA3y));
        // Distance and unit normal from A to B: a vertex, or an edge measured from edgeBase.
        const V len1 = L::sqrt(wx[0] * wx[0] + wy[0] * wy[0]); // length(w1)
        const V inv1 = one / len1;
        const M pos1 = len1 > zero;
        const V n1x = sel(pos1, inv1 * -wx[0], zero), n1y = sel(pos1, inv1 * -wy[0], zero);
        const V ex = wx[1] - wx[0], ey = wy[1] - wy[0];
        const M tinyEnd = c2 & tiny(ex, ey);
        const M base1 = edgeBase != mzero;
        const V bx = sel(base1, wx[1], wx[0]), by = sel(base1, wy[1], wy[0]);
        const V side = ex * -by - ey * -bx;
        const M flip = c2 & (side < zero);
        const V len2 = L::sqrt(ex * ex + ey * ey); // length(e)
        const V dist2 = L::absBits(bx * ey - by * ex) / len2;
        const V inv2 = one / len2;
        const M left = side > zero;
        const M pos2 = dist2 > zero;
        const V n2x = sel(pos2, inv2 * sel(left, -ey, ey), zero);
        const V n2y = sel(pos2, inv2 * sel(left, ex, -ex), zero);
        V dist = sel(c1, len1, sel(c2, dist2, zero));
        V nx = sel(c1, n1x, sel(c2, n2x, zero)), ny = sel(c1, n1y, sel(c2, n2y, zero));
        // Back to world coordinates through A's transform.
        const V xc = L::load(s.xqc), xs = L::load(s.xqs), xpx = L::load(s.xpx),
                xpy = L::load(s.xpy);
        const V frameSize2 = xc * xc + xs * xs;
        const M nonUnit =
            ~(L::absBits(frameSize2 - one) <= L::splat(gjk::Tolerances<T>::unitRotation));
        V worldAx = (xc * pAx - xs * pAy) + xpx, worldAy = (xs * pAx + xc * pAy) + xpy;
        V worldBx = (xc * pBx - xs * pBy) + xpx, worldBy = (xs * pBx + xc * pBy) + xpy;
        const V rnx = xc * nx - xs * ny, rny = xs * nx + xc * ny;
        nx = rnx;
        ny = rny;
        // A rotation of A that is not a unit one measures lengths in units of |qA| (finishQuery):
        // the distance times |qA|, the normal divided by it; |qA|^2 itself out of range: scalarEnd.
        const V frameSize = L::sqrt(frameSize2);
        dist = sel(nonUnit, dist * frameSize, dist);
        nx = sel(nonUnit, nx / frameSize, nx);
        ny = sel(nonUnit, ny / frameSize, ny);
        const M frameOutOfRange =
            nonUnit & ~((frameSize2 >= L::splat(minCoordinate * minCoordinate)) &
                        (frameSize2 <= L::splat(maxCoordinate * maxCoordinate)));
        // The radii are world lengths.
        if (s.useRadii)
        {
            const V rA = L::load(s.radiusA), rB = L::load(s.radiusB);
            const M rounded = (rA > zero) | (rB > zero);
            const V rSum = rA + rB;
            const M apart = rounded & (dist > rSum);
            const M overlap = rounded & ~apart;
            // One point in both (distance.hpp): rA / (rA + rB) of the way from A's point to B's.
            const V t = rA / rSum;
            const V midx = worldAx + t * (worldBx - worldAx),
                    midy = worldAy + t * (worldBy - worldAy);
            dist = sel(apart, dist - rSum, sel(overlap, zero, dist));
            const V ax2 = sel(apart, worldAx + rA * nx, sel(overlap, midx, worldAx));
            const V ay2 = sel(apart, worldAy + rA * ny, sel(overlap, midy, worldAy));
            worldBx = sel(apart, worldBx - rB * nx, sel(overlap, midx, worldBx));
            worldBy = sel(apart, worldBy - rB * ny, sel(overlap, midy, worldBy));
            worldAx = ax2;
            worldAy = ay2;
            nx = sel(overlap, zero, nx);
            ny = sel(overlap, zero, ny);
        }
        // "+ 0": a negative zero becomes +0.
        worldAx = worldAx + zero;
        worldAy = worldAy + zero;
        worldBx = worldBx + zero;
        worldBy = worldBy + zero;
        nx = nx + zero;
        ny = ny + zero;
        // The range check, and the ends the scalar code makes (scalarEnd).
        const V bigT = L::splat(std::numeric_limits<T>::max());
        const M finite = (L::absBits(dist) <= bigT) & (L::absBits(worldAx) <= bigT) &
                         (L::absBits(worldAy) <= bigT) & (L::absBits(worldBx) <= bigT) &
                         (L::absBits(worldBy) <= bigT) & (L::absBits(nx) <= bigT) &
                         (L::absBits(ny) <= bigT);
        const M inRange = (maxAbs <= L::splat(maxCoordinate)) &
                          ~((maxAbs > zero) & (maxAbs < L::splat(minCoordinate)));
        const M culled = (stop == splati(int(gjk::StopReason::RepeatedSupport))) &
                         ((lastA != ia[0]) | (lastB != ib[0])) &
                         (c1 | (lastA != ia[1]) | (lastB != ib[1]));
        const M scalarEnd =
            ended & (~finite | ~inRange | (maxAbs == zero) | frameOutOfRange | culled | tinyEnd);
        L::store(s.outAx, worldAx);
        L::store(s.outAy, worldAy);
        L::store(s.outBx, worldBx);
        L::store(s.outBy, worldBy);
        L::store(s.outNx, nx);
        L::store(s.outNy, ny);
        L::store(s.outDistance, dist);
        L::store(s.flipEdge, flip);
        L::store(s.scalarEnd, scalarEnd);
    }

    for (int k = 0; k < 3; ++k)
    {
        L::store(s.wx[k], wx[k]);
        L::store(s.wy[k], wy[k]);
        L::store(s.a[k], a[k]);
        L::store(s.ia[k], ia[k]);
        L::store(s.ib[k], ib[k]);
        L::store(s.savedA[k], savedA[k]);
        L::store(s.savedB[k], savedB[k]);
    }
    L::store(s.count, count);
    L::store(s.edgeBase, edgeBase);
    L::store(s.iteration, iteration);
    L::store(s.maxAbs, maxAbs);
    L::store(s.savedCount, savedCount);
    L::store(s.lastA, lastA);
    L::store(s.lastB, lastB);
    L::store(s.stop, stop);
    return true;
}

} // namespace GJK_LANES_NAMESPACE
