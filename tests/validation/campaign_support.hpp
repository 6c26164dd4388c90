// Shared by the validation tests: the configuration of a campaign run inside a test.
#pragma once

#include "campaign.hpp"
#include "variants.hpp"

#include <string>
#include <vector>

namespace gjkval
{
// The given families and variants, 2 threads, no timed passes.
inline CampaignConfig untimedConfig(std::vector<std::string> families, const std::string& variants = "all")
{
    CampaignConfig c;
    c.families = std::move(families);
    c.variants = parseVariants(variants);
    c.threads = 2;
    c.timing = false;
    c.command = "test";
    return c;
}
} // namespace gjkval
