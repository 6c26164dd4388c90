// A family's make-up checks (families.hpp, MakeupSpec), folded case by case: the campaign streams
// its cases, so each check keeps a count, a minimum or a maximum, never the cases.
//
// A check's range was measured at F = MakeupSpec::measuredAt cases (the built-in count of a hard
// sub-family, kMinCasesForStatistics for random, kMinEngineCasesForMakeup for engine). At n cases:
// - case by case (MakeupScope::EveryCase, or a fraction of exactly 0 or 1), F = 0, or n = F: the
//   range as written.
// - n < F: only the side every case obeys. A hard family's n cases are n of its F built-in ones
//   (families.cpp, spreadPositions), an engine family's are drawn from the same run: a minimum
//   keeps its lower bound, a maximum and a distinct count their upper bound; the other side (some
//   case reaching the extreme) and fractions need all F cases, so a fraction, or an extreme whose
//   kept bound is infinite, is reported, not judged.
// - n > F, a sweep (hard: case i is sweep position i mod F): floor(n/F) complete sweeps, each
//   within the range, and r = n mod F further cases that may all count or none, so a fraction's
//   range becomes [kF min / n, (kF max + r) / n] (k = floor(n/F)) and a distinct count's upper
//   bound grows to max ceil(n/F); extremes as written.
// - n > F, independent draws (random, engine): the range as written.
#pragma once

#include "inputs/families.hpp"

#include <gjk2d/exact.hpp>

#include <cstdint>
#include <set>
#include <vector>

namespace gjkval
{

// DistinctDistances counts distinct exact distances up to this many; beyond, it reports this
// number (every check range asks for far fewer).
inline constexpr std::size_t kMaxDistinctCounted = 1024;

class MakeupFold
{
  public:
    explicit MakeupFold(std::vector<MakeupSpec> specs);
    // A valid case and its exact truth, in any order: counts, minima, maxima and sets commute.
    void add(const Case& c, const exact::Result& truth);
    // Another fold of the same specs (a shard's): the fold of both sets of cases.
    void merge(const MakeupFold& other);
    std::vector<MakeupResult> results() const;
    // The running values, exactly (shards, checkpoints); the specs come from the input.
    Json state() const;
    static MakeupFold fromState(std::vector<MakeupSpec> specs, const Json& j);

  private:
    struct Check
    {
        MakeupSpec spec;
        double value;            // the running minimum or maximum, or the count of a fraction
        std::set<double> values; // DistinctDistances
    };
    std::vector<Check> checks_;
    std::uint64_t cases_ = 0;
};

// All at once (tests): the fold over `cases` with their `truths`.
std::vector<MakeupResult> evaluateMakeup(const std::vector<MakeupSpec>& specs,
                                         const std::vector<const Case*>& cases,
                                         const std::vector<const exact::Result*>& truths);

} // namespace gjkval
