// The plain structs of the GJK query (gjk2d/distance.hpp): shapes, the variants as data (Options),
// the simplex and its cache, input, output and trace, with the names of every enum's values and
// the input contract. No algorithm here.
#pragma once

#include "gjk2d/math.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "gjk2d/detail/fp_begin.hpp" // no contraction into FMA, whatever the user's flags

namespace gjk
{

// A convex shape: the hull of `count` points in its local frame, plus a radius (a rounded shape,
// capsule or disc). A view: the points are owned by the caller.
template <class T> struct Polygon
{
    const Vec2<T>* points = nullptr;
    int count = 0;
    T radius = T(0);
};

// --- Variants are data ---------------------------------------------------------------------------

enum class SearchDirection : std::uint8_t
{
    // Talk, "An accurate search direction": on an edge, d = cross(edge, z) with its sign fixed
    // towards the origin. dot(d, edge) == 0 exactly in floating point. No division.
    EdgePerpendicular,
    // The naive rule, d = Q - P from the barycentric closest point: dot(d, edge) carries roundoff
    // (the talk's single-precision example gives 3.2e-6), which can pick a wrong support point.
    ClosestPoint,
};

constexpr const char* searchDirectionName(SearchDirection d)
{
    switch (d)
    {
    case SearchDirection::EdgePerpendicular:
        return "edge-perpendicular";
    case SearchDirection::ClosestPoint:
        return "closest-point";
    }
    return "?";
}

enum class StoppingRule : std::uint8_t
{
    // Talk, "Termination conditions", case 1: stop when the support point is already a vertex of
    // the simplex (compared by index pair). Exact: no tolerance at all.
    RepeatedSupport,
    // Also stop when the new support point w cannot lower the distance by more than roundoff:
    // dot(v, v) - dot(v, w) <= Tolerances<T>::dualityGap * dot(v, v) (v: current closest point).
    // The duality gap bounds the distance error: d(v) - d* <= (v.v - v.w) / |v|.
    DualityGap,
};

constexpr const char* stoppingRuleName(StoppingRule r)
{
    switch (r)
    {
    case StoppingRule::RepeatedSupport:
        return "repeated-support";
    case StoppingRule::DualityGap:
        return "duality-gap";
    }
    return "?";
}

enum class Frame : std::uint8_t
{
    LocalA, // compute in A's local frame (see the conventions above)
    World,  // transform both shapes to world coordinates first (loses small gaps far from 0)
};

constexpr const char* frameName(Frame f)
{
    switch (f)
    {
    case Frame::LocalA:
        return "local-a";
    case Frame::World:
        return "world";
    }
    return "?";
}

enum class SupportStrategy : std::uint8_t
{
    Linear,       // the talk's loop over all vertices: any point order
    BinarySearch, // O(log n): needs the points in convex order (either winding, collinear
                  // points allowed, no repeated consecutive point), e.g. a hull routine's output.
                  // Gallops from the previous support point, so converging queries cost less.
                  // Small shapes still use the linear scan (usesBinarySearch, below).
};

// Shapes of at most this many points use the linear scan under SupportStrategy::BinarySearch too:
// the scan is faster there (docs/speed.md, "Tried and rejected").
inline constexpr int linearScanMaxCount = 16;

constexpr bool usesBinarySearch(SupportStrategy s, int count)
{
    return s == SupportStrategy::BinarySearch && count > linearScanMaxCount;
}

constexpr const char* supportStrategyName(SupportStrategy s)
{
    switch (s)
    {
    case SupportStrategy::Linear:
        return "linear";
    case SupportStrategy::BinarySearch:
        return "binary-search";
    }
    return "?";
}

struct Options
{
    SearchDirection direction = SearchDirection::EdgePerpendicular;
    StoppingRule stopping = StoppingRule::RepeatedSupport;
    Frame frame = Frame::LocalA;
    SupportStrategy support = SupportStrategy::Linear;
    // Iteration limit; 0 means automatic: defaultMaxIterations. With exact arithmetic the
    // distance decreases strictly at every iteration, so a long run means a cycle made by rounding;
    // reaching the limit is reported as StopReason::IterationLimit, never silently.
    int maxIterations = 0;
    // Apply the radii at the end (rounded shapes). false: distance between the core hulls.
    bool useRadii = true;
    // Also return a certified interval [lower, upper] that provably contains the exact distance
    // (gjk2d/certify.hpp). Costs one more scan of each shape.
    bool certify = false;
    // Return the correctly rounded distance of the exact problem (gjk2d/correct.hpp): the double
    // nearest to it, 0 exactly when it is 0. DistanceOutput::path says how it was decided;
    // CorrectPath::NeedsExact asks the caller for the exact completion
    // (exact/include/gjk2d/correct_fallback.hpp). double queries only.
    bool correctlyRounded = false;
    // Return the signed distance (gjk2d/expand.hpp, docs/gjk.md "Signed distance"): on
    // overlapping shapes, minus the penetration depth of the rounded shapes, found by expanding
    // GJK's final simplex into a polygon inside the Minkowski difference (EPA), with a penetration
    // pair and a certified interval for the depth. Rounded shapes whose cores are apart but whose
    // radii overlap get the core distance minus both radii, unclamped. Answers on separated shapes
    // are bit for bit those of the same options without it.
    bool signedDistance = false;

    bool operator==(const Options&) const = default;
};

// The reference variant, with a stable name. The default Options{} is this variant.
inline constexpr Options referenceOptions{};

// The automatic iteration limit (Options::maxIterations = 0) for shapes of countA and countB
// points.
constexpr int defaultMaxIterations(int countA, int countB)
{
    return 32 + 2 * (countA + countB);
}

// The iteration limit a query with these options runs under.
constexpr int iterationLimit(const Options& options, int countA, int countB)
{
    return options.maxIterations > 0 ? options.maxIterations : defaultMaxIterations(countA, countB);
}

// Why the loop stopped; every stopping rule of the talk has its own name.
enum class StopReason : std::uint8_t
{
    RepeatedSupport, // case 1 (and cases 3b and 4 end here when d points away from new vertices)
    Containment,     // case 2: all three triangle barycentric coordinates positive
    ZeroDirection,   // case 3a: the closest point is the origin itself (vertex overlap)
    DualityGap,      // StoppingRule::DualityGap met
    IterationLimit,  // Options::maxIterations reached: the answer is the best simplex so far
};

constexpr const char* stopReasonName(StopReason r)
{
    switch (r)
    {
    case StopReason::RepeatedSupport:
        return "repeated-support";
    case StopReason::Containment:
        return "containment";
    case StopReason::ZeroDirection:
        return "zero-direction";
    case StopReason::DualityGap:
        return "duality-gap";
    case StopReason::IterationLimit:
        return "iteration-limit";
    }
    return "?";
}

// How Options::correctlyRounded decided the distance (gjk2d/correct.hpp).
enum class CorrectPath : std::uint8_t
{
    Plain,        // the option is off: the plain answer
    Double,       // containment certified in double (a static filter, then a running error bound)
    Extended,     // the features' distance in 80-bit extended precision with a static error bound
    DoubleDouble, // the features' distance and its support bound in double-double
    NeedsExact,   // not decided: the output holds the plain answer, the caller completes it
    Exact,        // completed with exact arithmetic (set by the completion, outside gjk/)
};

constexpr const char* correctPathName(CorrectPath p)
{
    switch (p)
    {
    case CorrectPath::Plain:
        return "plain";
    case CorrectPath::Double:
        return "double";
    case CorrectPath::Extended:
        return "extended";
    case CorrectPath::DoubleDouble:
        return "double-double";
    case CorrectPath::NeedsExact:
        return "needs-exact";
    case CorrectPath::Exact:
        return "exact";
    }
    return "?";
}

// Why the expanding polygon (Options::signedDistance, gjk2d/expand.hpp) stopped; None when it did
// not run (the shapes are apart).
enum class ExpandStop : std::uint8_t
{
    None,            // no expansion: the rounded shapes are apart, or their cores are
    Touching,        // the origin is on the Minkowski difference's boundary: core depth 0
    GapClosed,       // the support value along the closest edge's normal is within the named
                     // tolerance of that edge's distance (the certified interval is that narrow)
    RepeatedSupport, // the support point along the closest edge's normal is already a vertex
    IterationLimit,  // the polygon grew past its limit: the answer is the best edge so far
};

constexpr const char* expandStopName(ExpandStop r)
{
    switch (r)
    {
    case ExpandStop::None:
        return "none";
    case ExpandStop::Touching:
        return "touching";
    case ExpandStop::GapClosed:
        return "gap-closed";
    case ExpandStop::RepeatedSupport:
        return "repeated-support";
    case ExpandStop::IterationLimit:
        return "iteration-limit";
    }
    return "?";
}

// How many StopReason values there are (IterationLimit is the last: checked below).
inline constexpr std::size_t stopReasonCount = std::size_t(StopReason::IterationLimit) + 1;
static_assert(stopReasonName(StopReason(stopReasonCount - 1))[0] != '?' &&
                  stopReasonName(StopReason(stopReasonCount))[0] == '?',
              "stopReasonCount: a StopReason was added after IterationLimit");

// --- Simplex -------------------------------------------------------------------------------------

template <class T> struct SimplexVertex
{
    Vec2<T> wA; // support point of A (compute frame)
    Vec2<T> wB; // support point of B (compute frame)
    Vec2<T> w;  // wA - wB, a point of the Minkowski difference Z
    T a;        // barycentric weight of this vertex in the closest point
    int indexA; // index of wA in A's points
    int indexB; // index of wB in B's points
};

template <class T> struct Simplex
{
    SimplexVertex<T> v[3];
    int count = 0;
};

// Warm start: the indices of the final simplex. A value-initialised cache is a cold start; pass the
// output cache back in for the next query between the same shapes.
// A final edge is stored in canonical order, the origin on the left of Z's edge from slot 0 to
// slot 1: a warm start's first search direction then always takes the same side of its sign test,
// which the branch predictor learns (why: docs/speed.md, "Canonical cache order"). `edgeBase` is
// the slot the distance was measured from (the query's own first vertex), so that a repeated query
// returns the very same bits as the cold one.
struct SimplexCache
{
    int count = 0;
    int indexA[3] = {0, 0, 0};
    int indexB[3] = {0, 0, 0};
    int edgeBase = 0;
    // Where the last support searches of A and B started (SupportStrategy::BinarySearch gallops
    // from there, and near ties the result depends on the start): a warm start makes its first
    // search from the same place, so that it finds what the last search found. -1: from indexA[0]
    // and indexB[0].
    int searchA = -1;
    int searchB = -1;
};

// --- Input, output, trace ------------------------------------------------------------------------

template <class T> struct DistanceInput
{
    Polygon<T> proxyA;
    Polygon<T> proxyB;
    Transform<T> transformA;
    Transform<T> transformB;
};

// The input contract of distance() (asserted there; the SIMD batch runs an input that breaks it
// on the scalar query, which asserts): at least one point per shape, radii >= 0 (false for NaN),
// and any finite rotation (c, s) but (0, 0), which maps a shape to one point (docs/gjk.md).
template <class T> constexpr bool meetsInputContract(const DistanceInput<T>& in)
{
    return in.proxyA.count > 0 && in.proxyB.count > 0 && in.proxyA.radius >= T(0) &&
           in.proxyB.radius >= T(0) && !(in.transformA.q.c == T(0) && in.transformA.q.s == T(0)) &&
           !(in.transformB.q.c == T(0) && in.transformB.q.s == T(0));
}

template <class T> struct DistanceOutput
{
    Vec2<T> pointA{}; // closest point on A (world), on the rounded surface when radii are used
    Vec2<T> pointB{}; // closest point on B (world)
    // Unit, from pointA towards pointB when distance > 0; zero otherwise. With
    // Options::signedDistance and distance < 0: the unit direction in which B leaves A,
    // (pointA - pointB) / |pointA - pointB| (moving B by pointA - pointB brings it to contact).
    Vec2<T> normal{};
    // >= 0; with Options::signedDistance, < 0 on overlap: minus the rounded shapes' penetration
    // depth, pointA on A's boundary and pointB on B's (a penetration pair).
    T distance = T(0);
    int iterations = 0; // support points computed
    int simplexCount = 0;
    StopReason stop = StopReason::RepeatedSupport;
    // The query left its safe range and rescaling could not bring it back: a support point had a
    // coordinate outside [Tolerances<T>::minCoordinate, maxCoordinate] (all of them below the
    // minimum, or any above the maximum), or a support scan's dot products overflowed, and the
    // rescaled retry too (the problem's points span more than the exponent range, so scaling lost
    // bits of some); or the rescaled answer does not fit in T (a distance or world witness point
    // beyond T's largest value). The output is not trustworthy.
    bool outOfRange = false;
    // The first pass left the safe range and the query ran again on the problem scaled by a power
    // of two (exact): the answer is then as accurate as in range. outOfRange stays set only when
    // that could not help.
    bool rescaled = false;
    // Options::certify: the exact distance lies in [lower, upper] (double, rounded outwards).
    // certified is false when the bounds could not be computed (an overflow): [0, inf] then.
    bool certified = false;
    // Options::correctlyRounded: how the distance was decided. Beside the flags, in their padding:
    // the output keeps its size.
    CorrectPath path = CorrectPath::Plain;
    // Options::signedDistance: how the expansion stopped (None on separated shapes). On overlap
    // the expansion also sets certified and [lower, upper], which then enclose the signed
    // distance (minus the depth), rounded outwards.
    ExpandStop expand = ExpandStop::None;
    double lower = 0;
    double upper = std::numeric_limits<double>::infinity();
};

// One GJK iteration as the talk's demo draws it: the simplex after culling, its closest point to
// the origin, the search direction and the support point it found. Compute-frame coordinates;
// Trace::frame maps them to world.
template <class T> struct TraceStep
{
    Simplex<T> simplex;
    Vec2<T> closest;
    Vec2<T> direction;
    bool hasSupport = false;
    SimplexVertex<T> support;
};

template <class T> struct Trace
{
    Transform<T> frame; // world from compute frame
    // Compute-frame coordinates are the frame's times 2^scaleExponent (a rescaled query; 0 else).
    int scaleExponent = 0;
    std::vector<TraceStep<T>> steps;
};

} // namespace gjk

#include "gjk2d/detail/fp_end.hpp"
