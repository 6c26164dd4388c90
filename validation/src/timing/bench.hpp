// `gjk-validate bench`: times GJK variants on given cases (families and case files), without the
// exact side: repeated single-threaded passes over all cases, the median ns per query and the
// spread over the passes. Reuses the campaign's inputs (collectInputs) and timing (timeAlternated).
#pragma once

#include "common/context.hpp"
#include "inputs/sources.hpp"
#include "timing/timing.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace gjkval
{

struct BenchConfig
{
    std::vector<std::string> families, caseFiles;
    std::uint64_t seed = 1;
    std::vector<const VariantInfo*> variants;
    bool warm = false; // time warm-started queries for every variant
    int passes = 15;
    // As run's passes (TimingConfig's default, one home): 10x longer passes read a plugin up to
    // 1.6x slower than run on a loaded machine (a longer pass is more often preempted, and the
    // median pass includes it).
    double minPassSeconds = TimingConfig{}.minPassSeconds;
    std::string command;
    double pluginTimeoutSeconds = kDefaultPluginTimeoutSeconds; // bench --plugin-timeout
    // bench --against NAME: a plugin variant timed by its plugin's own loop, cold and warm
    // (ownTimingLoop), its passes alternated with gjk2d's; every variant's ratio to it.
    const VariantInfo* against = nullptr;
    std::string againstName; // as given: "box2d-v3"
};

// The variants `bench --against` times when --variants is not given: the columns of the
// comparison table against Box2D v3 (docs/speed.md).
inline constexpr const char* kAgainstVariants =
    "double,float,double-warm,float-warm,double-correct,float-batch,double-batch";

struct BenchResult
{
    Json json; // docs/report-schema.md, "bench JSON"
    int exitCode = kExitPass;
};

BenchResult runBench(const BenchConfig& config, const std::vector<FamilyData>& inputs);
// The table `bench` prints, from the JSON.
std::string benchTable(const Json& bench);

} // namespace gjkval
