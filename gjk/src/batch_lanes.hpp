// The GJK loop of gjk/include/gjk/distance.hpp, one query per SIMD lane (gjk/batch.hpp).
// No include guard: gjk/src/batch.cpp includes this file once per instruction set, each time in
// its own namespace (GJK_LANES_NAMESPACE) under its own `#pragma GCC target`, so that no function
// compiled for AVX2 or AVX-512 can be picked by the linker for code that runs on the baseline.
// Nothing here calls the scalar library: the lanes' state is plain arrays (LaneState, batch.cpp),
// which the scalar code fills when a query starts and reads when it ends.
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
// - solve3 with inconsistent signs (its closest-edge fallback);
// - a support scan whose running sum is not finite (the scalar query's overflow flag: the padding
//   points of a lane, below, could raise it where the scalar scan does not).

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
    // Slots 0 and 1 of the solved simplex (slot 2 only ever stays): x[0] <- x[1] or x[2], x[1] <- x[2].
    template <class X>
    [[gnu::always_inline]] static void move(X* x, M solving, M from1to0, M from2to0, M from2to1)
    {
        const X x0 = x[0], x1 = x[1], x2 = x[2];
        x[0] = sel(solving, sel(from1to0, x1, sel(from2to0, x2, x0)), x0);
        x[1] = sel(solving, sel(from2to1, x2, x1), x1);
    }
    [[gnu::always_inline]] static bool any(M m)
    {
        I r = 0;
        for (int l = 0; l < W; ++l)
            r |= m[l];
        return r != 0;
    }
};

// State of the W lanes between two calls of runLanes; the scalar side (batch.cpp) writes a lane
// when its query starts and reads it when it ends. Arrays indexed [slot][lane] or [lane].
// Simplex vertices keep only w = wA - wB, the weight and the index pair: the loop needs no more,
// and the scalar end (finishQuery) rebuilds wA, wB and w from the indices with the same operations.
template <class T, int W> struct LaneState
{
    using I = typename LaneInt<T>::type;
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

inline constexpr int kRunning = -1;
inline constexpr int kHandBack = -2;

// Runs the lanes whose stop is kRunning in lockstep until at least one of them stops; returns
// whether any lane stopped (no lane running: returns false at once). The lanes' stop values then
// say which. Mirrors distanceImpl's loop with Options' default direction and stopping rule,
// A's local frame and the linear support scan.
template <class T, int W> bool runLanes(LaneState<T, W>& s, T minEdge)
{
    using L = Lanes<T, W>;
    using V = typename L::V;
    using M = typename L::M;
    using I = typename L::I;
    const V zero{};
    const V one = L::splat(T(1));
    const M mzero{};
    const M mone = L::splat(I(1));

    M stop = L::load(s.stop);
    M running = stop == L::splat(I(kRunning));
    if (!L::any(running))
        return false;

    V wx[3], wy[3], a[3];
    M ia[3], ib[3];
    for (int k = 0; k < 3; ++k)
    {
        wx[k] = L::load(s.wx[k]);
        wy[k] = L::load(s.wy[k]);
        a[k] = L::load(s.a[k]);
        ia[k] = L::load(s.ia[k]);
        ib[k] = L::load(s.ib[k]);
    }
    M count = L::load(s.count), edgeBase = L::load(s.edgeBase), iteration = L::load(s.iteration);
    const M maxIterations = L::load(s.maxIterations);
    V maxAbs = L::load(s.maxAbs);
    const V bpx = L::load(s.bpx), bpy = L::load(s.bpy), bqc = L::load(s.bqc), bqs = L::load(s.bqs);
    M savedA[3], savedB[3], savedCount = L::load(s.savedCount);
    for (int k = 0; k < 3; ++k)
    {
        savedA[k] = L::load(s.savedA[k]);
        savedB[k] = L::load(s.savedB[k]);
    }
    M lastA = L::load(s.lastA), lastB = L::load(s.lastB);
    const M countA = L::load(s.countA), countB = L::load(s.countB);

    auto tiny = [minEdge](V ex, V ey) { return L::tiny(ex, ey, minEdge); };
    auto sel = [](M m, V x, V y) { return L::sel(m, x, y); };
    auto seli = [](M m, M x, M y) { return L::sel(m, x, y); };

    bool anyStopped = false;
    while (!anyStopped)
    {
        ++s.steps;
        for (int l = 0; l < W; ++l)
            s.busyLaneSteps += running[l] != 0;

        // Remember the simplex (case 1's repeated-support check): unused slots hold -1.
        for (int k = 0; k < 3; ++k)
        {
            const M used = count > L::splat(I(k));
            savedA[k] = seli(running, seli(used, ia[k], L::splat(I(-1))), savedA[k]);
            savedB[k] = seli(running, seli(used, ib[k], L::splat(I(-1))), savedB[k]);
        }
        savedCount = seli(running, count, savedCount);

        M handBack = mzero;
        const M is2 = count == L::splat(I(2)), is3 = count == L::splat(I(3));

        // --- solve2 on (v0, v1) -------------------------------------------------------------
        const V e12x = wx[1] - wx[0], e12y = wy[1] - wy[0];
        const V u12 = wx[1] * e12x + wy[1] * e12y;     // dot(w2, e12)
        const V v12 = -(wx[0] * e12x + wy[0] * e12y);  // -dot(w1, e12)
        handBack |= (is2 | is3) & tiny(e12x, e12y);

        // --- solve3 on (v0, v1, v2) ---------------------------------------------------------
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
        [[maybe_unused]] const M r1 = region( // region w1: nothing moves
            (v12 <= zero) & (v13 <= zero));
        const M r2 = region((u12 <= zero) & (v23 <= zero));
        const M r3 = region((u13 <= zero) & (u23 <= zero));
        const M r12 = region((u12 > zero) & (v12 > zero) & (w123 <= zero));
        const M r13 = region((u13 > zero) & (v13 > zero) & (v123 <= zero));
        const M r23 = region((u23 > zero) & (v23 > zero) & (u123 <= zero));
        const M r123 = region((u123 > zero) & (v123 > zero) & (w123 > zero));
        handBack |= is3 & ~taken; // inconsistent signs: solve3's closest-edge fallback

        // The solved simplex: slot k takes vertex src[k]; weights; count.
        // solve2 (count 2): region w1 (v12 <= 0), region w2 (u12 <= 0), else the edge.
        const M s2v1 = v12 <= zero;
        const M s2v2 = ~s2v1 & (u12 <= zero);
        const M s2e = ~s2v1 & ~s2v2;
        // Edge weights: keepEdge's / solve2's ui * inv, vj * inv with inv = 1 / (ui + vj).
        const V ue = sel(is3, sel(r12, u12, sel(r13, u13, u23)), u12);
        const V ve = sel(is3, sel(r12, v12, sel(r13, v13, v23)), v12);
        const V inv = one / (ue + ve);
        const V ae0 = ue * inv, ae1 = ve * inv;
        const V sum = (u123 + v123) + w123;
        const M edge = (is2 & s2e) | (is3 & (r12 | r13 | r23));
        const M interior = is3 & r123;
        // Which vertex moves to slot 0 and slot 1 (slot 2 only stays, in the interior).
        const M from1to0 = (is2 & s2v2) | (is3 & (r2 | r23));
        const M from2to0 = is3 & r3;
        const M from2to1 = is3 & (r13 | r23);
        const M solving = running & (is2 | is3);
        L::move(wx, solving, from1to0, from2to0, from2to1);
        L::move(wy, solving, from1to0, from2to0, from2to1);
        L::move(ia, solving, from1to0, from2to0, from2to1);
        L::move(ib, solving, from1to0, from2to0, from2to1);
        const V a0 = sel(interior, u123 / sum, sel(edge, ae0, one));
        const V a1 = sel(interior, v123 / sum, ae1);
        const V a2 = w123 / sum;
        a[0] = sel(solving, a0, a[0]);
        a[1] = sel(solving & (edge | interior), a1, a[1]);
        a[2] = sel(solving & interior, a2, a[2]);
        count = seli(solving, seli(interior, L::splat(I(3)), seli(edge, L::splat(I(2)), mone)), count);

        // Case 2: containment.
        const M containment = running & (count == L::splat(I(3)));

        // --- searchDirection ----------------------------------------------------------------
        const M edgeNow = count == L::splat(I(2));
        const V fx = wx[1] - wx[0], fy = wy[1] - wy[0];
        handBack |= running & edgeNow & ~containment & tiny(fx, fy);
        const M base1 = edgeBase != mzero;
        const V bx = sel(base1, wx[1], wx[0]), by = sel(base1, wy[1], wy[0]);
        const V side = fx * -by - fy * -bx; // originSide: cross(e12, -w1)
        const M left = side > zero;
        // leftPerp(e) = (-e.y, e.x), rightPerp(e) = (e.y, -e.x); a single vertex: -w.
        const V dx = sel(edgeNow, sel(left, -fy, fy), -wx[0]);
        const V dy = sel(edgeNow, sel(left, fx, -fx), -wy[0]);
        const M zeroDirection = running & ~containment & (dx == zero) & (dy == zero);
        const M limit = running & ~containment & ~zeroDirection & (iteration == maxIterations);
        handBack &= running;
        M stopped = containment | zeroDirection | limit;
        stop = seli(running & containment, L::splat(I(int(gjk::StopReason::Containment))), stop);
        stop = seli(running & zeroDirection, L::splat(I(int(gjk::StopReason::ZeroDirection))), stop);
        stop = seli(running & limit, L::splat(I(int(gjk::StopReason::IterationLimit))), stop);

        // --- findMinkowskiSupport: A in its own frame, B through invRotate(qB, -d) ------------
        const M searching = running & ~stopped & ~handBack;
        V bestA = dx * L::load(s.ax) + dy * L::load(s.ay);
        V sumA = bestA;
        V pax = L::load(s.ax), pay = L::load(s.ay);
        M indexA = mzero;
        for (int i = 1; i < s.boundA; ++i)
        {
            const V px = L::load(s.ax + i * W), py = L::load(s.ay + i * W);
            const V value = dx * px + dy * py;
            sumA += value;
            const M better = value > bestA;
            indexA = seli(better, L::splat(I(i)), indexA);
            bestA = sel(better, value, bestA);
            pax = sel(better, px, pax);
            pay = sel(better, py, pay);
        }
        const V ndx = -dx, ndy = -dy;
        const V lx = bqc * ndx + bqs * ndy, ly = -bqs * ndx + bqc * ndy; // invRotate(qB, -d)
        V bestB = lx * L::load(s.bx) + ly * L::load(s.by);
        V sumB = bestB;
        V pbx = L::load(s.bx), pby = L::load(s.by);
        M indexB = mzero;
        for (int i = 1; i < s.boundB; ++i)
        {
            const V px = L::load(s.bx + i * W), py = L::load(s.by + i * W);
            const V value = lx * px + ly * py;
            sumB += value;
            const M better = value > bestB;
            indexB = seli(better, L::splat(I(i)), indexB);
            bestB = sel(better, value, bestB);
            pbx = sel(better, px, pbx);
            pby = sel(better, py, pby);
        }
        s.scannedPoints += std::uint64_t(W) * std::uint64_t(s.boundA + s.boundB);
        for (int l = 0; l < W; ++l)
            if (searching[l])
                s.usefulPoints += std::uint64_t(countA[l] + countB[l]);
        // The scalar scan's finiteness test, abs(sum) <= max.
        const V big = L::splat(std::numeric_limits<T>::max());
        const V asA = sumA < zero ? -sumA : sumA, asB = sumB < zero ? -sumB : sumB;
        const M overflow = searching & ~((asA <= big) & (asB <= big));
        handBack |= overflow;
        const M found = searching & ~overflow;

        // makeVertex: wA = A's point (A's frame), wB = transformPoint(B's transform, B's point).
        const V wBx = (bqc * pbx - bqs * pby) + bpx, wBy = (bqs * pbx + bqc * pby) + bpy;
        const V nwx = pax - wBx, nwy = pay - wBy;
        iteration = seli(found, iteration + mone, iteration);
        // maxAbs = std::max({maxAbs, |w.x|, |w.y|}): the first largest, by <.
        const V awx = nwx < zero ? -nwx : nwx, awy = nwy < zero ? -nwy : nwy;
        V m = maxAbs;
        m = m < awx ? awx : m;
        m = m < awy ? awy : m;
        maxAbs = sel(found, m, maxAbs);
        lastA = seli(found, indexA, lastA);
        lastB = seli(found, indexB, lastB);

        // Case 1: the support point is already in the simplex (compared by index pair).
        M repeated = mzero;
        for (int k = 0; k < 3; ++k)
            repeated |= (indexA == savedA[k]) & (indexB == savedB[k]);
        repeated &= found;
        stop = seli(repeated, L::splat(I(int(gjk::StopReason::RepeatedSupport))), stop);

        // Otherwise the support point joins the simplex.
        const M grow = found & ~repeated;
        for (int k = 0; k < 3; ++k)
        {
            const M slot = grow & (count == L::splat(I(k)));
            wx[k] = sel(slot, nwx, wx[k]);
            wy[k] = sel(slot, nwy, wy[k]);
            ia[k] = seli(slot, indexA, ia[k]);
            ib[k] = seli(slot, indexB, ib[k]);
        }
        count = seli(grow, count + mone, count);
        edgeBase = seli(grow, mzero, edgeBase);

        stop = seli(handBack, L::splat(I(kHandBack)), stop);
        stopped = running & ~grow;
        running &= grow;
        anyStopped = L::any(stopped);
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
