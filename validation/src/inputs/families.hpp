// Case families: seeded generators of cases, each with the checks of its own make-up.
// `random` is the realistic mix; `hard/<sub>` are the known ways to break GJK, with a reason per
// sub-family; `engine/<scene>-<kind>` are queries recorded from Box2D worlds (engine.hpp). Each
// family's row (name, count, reason, make-up) sits beside its generator in its group's file under
// inputs/families/ (rows.hpp lists the groups); families.cpp gathers them.
#pragma once

#include "inputs/cases.hpp"

#include <gjk2d/exact.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace gjkval
{

// What a make-up check measures over a family's cases (from the inputs and the exact results).
enum class MakeupMetric
{
    OverlapFraction,      // fraction with exact distance 0 (touching or overlapping)
    SeparatedFraction,    // 1 - OverlapFraction
    NearTouchingFraction, // fraction with 0 < exact distance <= 1e-2
    MinPositiveDistance,  // smallest exact distance among separated cases
    MaxDistance,          // largest exact distance
    MaxCoordinate,        // largest |world coordinate| of any point
    MinVertices,          // fewest points of a shape
    MinHullVertices,      // fewest distinct hull vertices of a shape (1: a point, 2: a segment)
    MaxVertices,          // most points of a shape
    MaxAspect,            // largest diameter / min width of a shape (hulls of <= 64 vertices)
    RadiusFraction,       // fraction of cases with a rounded shape (radius > 0)
    MinScale,             // smallest, over the cases, of a case's largest |world coordinate|
    MinEdgeRatio,         // shortest hull edge / hull diameter, smallest over the shapes (local
                          // points; shapes of >= 3 hull vertices)
    MinSizeRatio,         // per case, larger / smaller hull diameter of the two shapes: smallest
    MaxSizeRatio,         //   ... and largest over the cases
    OutsideFloatRangeFraction, // fraction of cases whose largest |world coordinate| lies outside
                               // float's safe range [Tolerances<float>::minCoordinate,
                               // maxCoordinate]
    DistinctDistances,         // number of distinct exact distances (bit patterns) among the cases
    SharedOriginFraction,      // fraction of cases where both shapes have the same translation
    MaxPolygonRadius,          // largest radius of a shape of >= 3 points (rounded polygons)
    NonUnitRotationFraction,   // fraction of cases where a shape's c^2 + s^2 is not 1 in double
};

// How a check's range is judged at a count other than the one it was measured at (the rules are
// in statistics/makeup.hpp). A fraction of exactly 0 or 1 is case by case whatever its scope.
enum class MakeupScope
{
    Family,    // a fraction or an extreme of the family's cases as a whole
    EveryCase, // each case alone lies in the range: judged as written at any count
};

struct MakeupSpec
{
    std::string check;
    MakeupMetric metric;
    double min, max;
    MakeupScope scope = MakeupScope::Family;
    // Set by planFamilies from the family, not written in the tables: the count the range was
    // measured at (0: judged as written at any count), and whether the cases repeat a sweep of
    // that many positions (hard sub-families) instead of being independent draws (random, engine).
    std::size_t measuredAt = 0;
    bool sweep = false;
};

// The count the random family's ranges hold from (statistics of independent draws).
inline constexpr std::size_t kMinCasesForStatistics = 100;
// ... and the engine families' (their ranges were measured at 300 and 2000 cases).
inline constexpr std::size_t kMinEngineCasesForMakeup = 300;

struct MakeupResult
{
    std::string check;
    double value, min, max; // min, max: the range judged at this count
    bool ok;
    bool skipped;     // reported, not judged
    std::string note; // why skipped, or why the range is not the table's; empty: as written
};

struct GeneratedFamily
{
    std::string name;   // "random", "hard/near-parallel"
    std::string reason; // why the family exists
    std::uint64_t seed; // the family's own seed (derived from the campaign seed and the name)
    std::vector<Case> cases;
    std::vector<MakeupSpec> makeup;
};

// A family before its cases are made: what the report says of it, and its cases on demand, any
// range [begin, end) of 0..count, each case the same whatever the range (the campaign streams them
// in chunks).
struct FamilyPlan
{
    std::string name, reason;
    std::uint64_t seed = 0;
    std::size_t count = 0;
    std::vector<MakeupSpec> makeup;
    std::function<std::vector<Case>(std::size_t begin, std::size_t end)> cases;
};

struct HardSubFamilyInfo
{
    std::string name; // without "hard/"
    int count;
    std::string reason;
};
const std::vector<HardSubFamilyInfo>& hardSubFamilies();
// The engine families `engine/<scene>-<kind>` (engine.hpp), names without "engine/"; the spec
// `engine` is all of them.
const std::vector<HardSubFamilyInfo>& engineSubFamilies();

inline constexpr int kDefaultRandomCount = 200000;
inline constexpr int kDefaultEngineCount = 2000; // per engine family: 12,000 cases in all

// The largest N of a family spec (the memory a run needs is checked apart, in main).
inline constexpr int kMaxFamilyCount = 100000000;

// A family spec parsed: "random[:N]", "hard[:N]" (N per sub-family), "hard/<sub>[:N]",
// "engine[:N]" (N per engine family), "engine/<scene>-<kind>[:N]", N a whole number in
// 1..kMaxFamilyCount. Throws InputError (unknown family, bad count).
struct FamilySpec
{
    std::string name; // "random", "hard", "hard/sliver", "engine", "engine/pyramid-toi"
    int count = -1;   // -1: the default count
};
FamilySpec parseFamilySpec(const std::string& spec);

// The families a spec stands for and their case counts, without generating them.
std::vector<std::pair<std::string, std::size_t>> familyCaseCounts(const FamilySpec& spec);

// The families of a spec (parseFamilySpec), to generate chunk by chunk. Throws InputError.
std::vector<FamilyPlan> planFamilies(const std::string& spec, std::uint64_t seed);
// ... and generated whole.
std::vector<GeneratedFamily> generateFamilies(const std::string& spec, std::uint64_t seed);

// The checks are evaluated by statistics/makeup.hpp.

} // namespace gjkval
