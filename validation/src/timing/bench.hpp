// `gjk-validate bench`: times GJK variants on given cases (families and case files), without the
// exact side: repeated single-threaded passes over all cases, the median ns per query and the
// spread over the passes. Reuses the campaign's inputs (collectInputs) and timing (timeQueries).
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
};

struct BenchResult
{
    Json json; // docs/report-schema.md, "bench JSON"
    int exitCode = kExitPass;
};

BenchResult runBench(const BenchConfig& config, const std::vector<FamilyData>& inputs);
// The table `bench` prints, from the JSON.
std::string benchTable(const Json& bench);

} // namespace gjkval
