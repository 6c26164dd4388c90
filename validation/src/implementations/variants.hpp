// The GJK variants the runner knows: one table (variants.cpp) from a stable name to a scalar type
// and a gjk::Options. Adding a variant is one line in that table.
#pragma once

#include "common/common.hpp"

#include "gjk2d/batch.hpp"
#include "gjk2d/distance.hpp"

#include <string>
#include <vector>

namespace gjkval
{

enum class Scalar
{
    Float,
    Double
};

// How a variant's query starts.
enum class Start
{
    Cold, // a fresh SimplexCache
    // The query is run twice, the second time with the SimplexCache the first one returned; the
    // second is judged and timed (the timing prepares the caches beforehand).
    Warm,
    // The accuracy run repeats the query from many caches (every initial vertex pair, strided to
    // at most 12 x 12, and a few two- and three-vertex caches) and keeps the answer farthest from
    // the truth: a start-dependent failure cannot hide behind the one cold start. Timed like a
    // cold query.
    EveryStart,
};

struct PluginImpl; // implementations/plugins.hpp

struct VariantInfo
{
    std::string name; // stable: used on the command line and in every report
    Scalar scalar;
    gjk::Options options;
    std::string description;
    // Judged variants decide the exit code and "passed": the reference options and the variants
    // that must match them (certified, binary-search support, warm start). Comparison variants
    // (judged = false) are the alternatives the talk discusses: their failures are counted and
    // shown per family, never judged.
    bool judged = true;
    Start start = Start::Cold;
    // Set for a plugin's implementation (implementations/plugins.hpp, `--plugin`): the answer comes
    // from it, evaluated in a child process; `options` then only names the bound it is compared
    // with.
    const PluginImpl* plugin = nullptr;
    // Run through gjk::distanceBatchLanes (gjk2d/batch.hpp: SIMD lanes, the instruction set chosen
    // at run time): the accuracy run on one-case batches, each checked to be bit for bit the scalar
    // query (evaluate.cpp); the timing on batches of all the timed cases.
    bool batch = false;
};

const std::vector<VariantInfo>& variantTable();
// The default of `run --variants`.
inline constexpr const char* kDefaultVariants = "all";
// The variant speed ratios are given against (report.json baseline_variant; bench).
inline constexpr const char* kBaselineVariant = "double";
// "all", or names separated by commas. Throws InputError naming the unknown one. "all" is the
// table; a loaded plugin's variants can be named (findVariant finds them too).
std::vector<const VariantInfo*> parseVariants(const std::string& list);
const VariantInfo* findVariant(const std::string& name);

// Options::support == BinarySearch: the shapes' points must be in convex order (either winding,
// collinear points allowed, no repeated consecutive point); cases where they are not are skipped
// as not applicable (PreparedCase::binaryOk).
bool needsConvexOrder(const VariantInfo& v);
// Whether the variant's query has a prepared form of its own, timed beside the plain one
// (timing/timing.hpp, preparedLoop): gjk::distance on two gjk::PreparedShape (gjk2d/prepared.hpp)
// decides its range checks before the loop with the reference options only; with any other
// options that overload runs the plain query, and gjk::distanceBatchLanes takes plain inputs. So:
// gjk2d's own variants of the reference options, cold, warm or every start, not batched.
bool hasPreparedForm(const VariantInfo& v);
// The library uses the linear scan for shapes of at most this many points whatever the strategy
// (gjk2d/types.hpp, usesBinarySearch): they always fit.
inline constexpr int kLinearSupportMaxPoints = gjk::linearScanMaxCount;

const char* scalarName(Scalar s);
double unitRoundoff(Scalar s);      // u = eps / 2 of the variant's type
double smallestSubnormal(Scalar s); // denorm_min of the variant's type
int scalarDigits(Scalar s);         // significand bits (24, 53)
int scalarMinExponent(Scalar s);

// {"direction": ..., "stopping": ..., "frame": ..., "support": ..., "certified": ...}
Json optionsJson(const gjk::Options& o);

} // namespace gjkval
