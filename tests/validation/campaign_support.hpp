// Shared by the validation tests: the configuration of a campaign run inside a test.
#pragma once

#include "campaign/campaign.hpp"
#include "implementations/variants.hpp"
#include "inputs/families.hpp"
#include "statistics/makeup.hpp"

#include <gjk2d/exact.hpp>

#include <string>
#include <vector>

namespace gjkval
{
// The given families and variants, 2 threads, no timed passes.
inline CampaignConfig untimedConfig(std::vector<std::string> families,
                                    const std::string& variants = "all")
{
    CampaignConfig c;
    c.families = std::move(families);
    c.variants = parseVariants(variants);
    c.threads = 2;
    c.timing = false;
    c.command = "test";
    return c;
}

// The make-up checks `specs` evaluated on `cases`, with their exact truths.
inline std::vector<MakeupResult> makeupOn(const std::vector<MakeupSpec>& specs,
                                          const std::vector<Case>& cases)
{
    std::vector<exact::Result> truths;
    for (const auto& c : cases)
        truths.push_back(exact::distance(toExact(c.a), toExact(c.b)));
    std::vector<const Case*> cs;
    std::vector<const exact::Result*> ts;
    for (std::size_t i = 0; i < cases.size(); ++i)
    {
        cs.push_back(&cases[i]);
        ts.push_back(&truths[i]);
    }
    return evaluateMakeup(specs, cs, ts);
}
} // namespace gjkval
