// A family's worst cases, kept while its cases stream by: the k with the largest
// CaseOutcome::worstKey(), ties to the earlier case. The ranking is a total order on (key, index),
// so the cases kept do not depend on how the stream was cut into chunks.
#pragma once

#include "evaluate/evaluate.hpp"

#include <cstddef>
#include <vector>

namespace gjkval
{

struct WorstCase
{
    double key = 0;
    std::size_t index = 0; // in the family
    Case c;
    CaseOutcome outcome;
};

class WorstKeeper
{
  public:
    explicit WorstKeeper(std::size_t k) : k_(k) {}
    // A valid case; copied only when it ranks among the k worst so far.
    void offer(std::size_t index, const Case& c, const CaseOutcome& o)
    {
        const double key = o.worstKey();
        if (k_ == 0 || (kept_.size() == k_ && !before(key, index, kept_.back())))
            return;
        auto at = kept_.begin();
        while (at != kept_.end() && !before(key, index, *at))
            ++at;
        kept_.insert(at, WorstCase{key, index, c, o});
        if (kept_.size() > k_)
            kept_.pop_back();
    }
    // Worst first.
    const std::vector<WorstCase>& cases() const { return kept_; }

  private:
    static bool before(double key, std::size_t index, const WorstCase& w)
    {
        return key > w.key || (key == w.key && index < w.index);
    }
    std::size_t k_;
    std::vector<WorstCase> kept_;
};

} // namespace gjkval
