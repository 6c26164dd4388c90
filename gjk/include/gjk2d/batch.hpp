// Many queries at once in SIMD lanes: one query per lane, AVX-512, AVX2 or SSE2 chosen at run time.
// The compiled part of the library (CMake target gjk::batch, gjk/src/batch.cpp): everything else in
// gjk/ is header-only, but a run-time choice between instruction sets needs code compiled for each
// of them, which a header cannot give a user who builds for Debian's x86-64 baseline.
//
// The promise: outputs[i] and caches[i] are bit for bit what distance(inputs[i], caches[i],
// options) gives (distance, witness points, normal, iterations, stop reason, flags, the cache),
// whatever instruction set runs (tests/gjk/test_batch.cpp). Each lane makes the scalar query's
// IEEE operations in the same order (Mul then Add, never fused: -ffp-contract=off, and no FMA
// target is enabled), and a lane that meets a rare path leaves the lanes for the scalar query.
// docs/gjk.md, "Batches in SIMD lanes", says which options and inputs run in lanes; the others
// run the scalar query, with the same results.
#pragma once

#include "gjk2d/distance.hpp"

#include <cstdint>
#include <span>

namespace gjk
{

// The instruction set of the lanes. Scalar: no lanes, the single-query loop.
enum class BatchIsa : std::uint8_t
{
    Scalar,
    Sse2,   // 16-byte vectors (2 double or 4 float lanes): x86-64's baseline
    Avx2,   // 32-byte vectors (4 double or 8 float lanes)
    Avx512, // 64-byte vectors (8 double or 16 float lanes), AVX-512F
    Best,   // the default: the widest one this CPU has, or the scalar loop where lanes lose (below)
};

constexpr const char* batchIsaName(BatchIsa isa)
{
    switch (isa)
    {
    case BatchIsa::Scalar:
        return "scalar";
    case BatchIsa::Sse2:
        return "sse2";
    case BatchIsa::Avx2:
        return "avx2";
    case BatchIsa::Avx512:
        return "avx512";
    case BatchIsa::Best:
        return "best";
    }
    return "?";
}

// The widest instruction set this CPU runs (Best resolved), and whether `isa` runs here.
BatchIsa bestBatchIsa();
bool batchIsaSupported(BatchIsa isa);

// What BatchIsa::Best runs for these inputs: bestBatchIsa(), or Scalar where the lanes lose on
// shapes of these sizes (gjk/src/batch.cpp, lanesPay). A caller with a loop of its own can keep
// it where the batch would run the same loop.
BatchIsa bestBatchIsaFor(std::span<const DistanceInput<double>> inputs);
BatchIsa bestBatchIsaFor(std::span<const DistanceInput<float>> inputs);

// What a batch did, for measuring lane utilisation (docs/speed.md, "Batches in SIMD lanes").
struct BatchStats
{
    BatchIsa isa = BatchIsa::Scalar; // the instruction set that ran
    int lanes = 1;                   // lanes per vector
    std::uint64_t queries = 0;       // queries in the batch
    std::uint64_t laneQueries = 0;   // queries finished in lanes
    std::uint64_t scalarQueries = 0; // run by the scalar query from the start (options, sizes)
    std::uint64_t handedBack = 0;    // started in lanes, handed to the scalar query (rare paths)
    std::uint64_t steps = 0;         // lockstep iterations of the lanes
    std::uint64_t busyLaneSteps = 0; // lane-iterations that worked on a query (<= steps * lanes)
    std::uint64_t scannedPoints = 0; // points the lanes' support scans visited, padding included
    std::uint64_t usefulPoints = 0;  // of them, the points of the lane's own shapes
};

// Its own name, not an overload of distance.hpp's distanceBatch: with one name, a user's call would
// switch between the portable loop and these lanes depending on whether some header included this
// one; with two, each call says which it runs. "Lanes" is what it adds (BatchIsa, BatchStats;
// docs/gjk.md, "Batches in SIMD lanes"), under the batch's prefix.
//
// The batch: outputs[i] = distance(inputs[i], caches[i], options), caches[i] updated (warm batches:
// pass each pair's cache from the previous step). The spans must have equal sizes. `isa`: Best, or
// one this CPU runs (else the next narrower one that it runs). Best chooses once per batch, from
// its shapes' point counts, between the widest lanes and the scalar loop, whichever was faster on
// such shapes: float always lanes, double lanes only when the mean is at most 3.75 points per
// shape (gjk/src/batch.cpp, kDoubleLanesMaxMeanPoints; stats->isa says which ran). The bits are
// the same either way. `stats`: filled when given.
void distanceBatchLanes(std::span<const DistanceInput<double>> inputs,
                        std::span<SimplexCache> caches, std::span<DistanceOutput<double>> outputs,
                        const Options& options = referenceOptions, BatchIsa isa = BatchIsa::Best,
                        BatchStats* stats = nullptr);
void distanceBatchLanes(std::span<const DistanceInput<float>> inputs,
                        std::span<SimplexCache> caches, std::span<DistanceOutput<float>> outputs,
                        const Options& options = referenceOptions, BatchIsa isa = BatchIsa::Best,
                        BatchStats* stats = nullptr);

} // namespace gjk
