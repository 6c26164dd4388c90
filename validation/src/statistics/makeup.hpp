// A family's make-up checks (families.hpp, MakeupSpec), folded case by case: the campaign streams
// its cases, so each check keeps a count, a minimum or a maximum, never the cases.
#pragma once

#include "inputs/families.hpp"

#include <exact/exact.hpp>

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
    // A valid case and its exact truth, in case order.
    void add(const Case& c, const exact::Result& truth);
    std::vector<MakeupResult> results() const;

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
