// The filtered truth (exact::Options::filter, `--truth filtered`, the default) equals the GMP route
// (`--truth exact`) bit for bit, squared rational included, on every built-in family and every
// case file of validation/cases/, for the input as given and rounded to float (the two truths a
// campaign computes). docs/exact.md, "The filter".
#include "inputs/cases.hpp"
#include "inputs/sources.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace gjkval;

namespace
{

std::uint64_t bits(double v)
{
    return std::bit_cast<std::uint64_t>(v);
}

// Whether the two truths of one case are the same; counts the filtered ones that took GMP.
bool sameTruth(const exact::Shape& a, const exact::Shape& b, std::size_t& gmp)
{
    exact::Options exactOnly;
    exactOnly.filter = false;
    const exact::Result f = exact::distance(a, b), e = exact::distance(a, b, exactOnly);
    gmp += f.fallbacks.gmp ? 1 : 0;
    return f.overlap == e.overlap && f.squaredNum == e.squaredNum && f.squaredDen == e.squaredDen &&
           bits(f.squared) == bits(e.squared) && bits(f.distance) == bits(e.distance) &&
           bits(f.lower) == bits(e.lower) && bits(f.upper) == bits(e.upper) &&
           bits(f.witnessA.x) == bits(e.witnessA.x) && bits(f.witnessA.y) == bits(e.witnessA.y) &&
           bits(f.witnessB.x) == bits(e.witnessB.x) && bits(f.witnessB.y) == bits(e.witnessB.y);
}

} // namespace

TEST_CASE("the filtered truth equals the GMP route on every built-in family and case file",
          "[truth][filter]")
{
    std::vector<std::string> files;
    for (const auto& e :
         std::filesystem::directory_iterator(std::string(GJK2D_SOURCE_DIR) + "/validation/cases"))
        if (e.path().extension() == ".json")
            files.push_back(e.path().string());
    REQUIRE(files.size() >= 5);
    // random at 20,000 cases, or GJK2D_TRUTH_RANDOM_COUNT (docs/exact.md records a run of 1e6),
    // every hard and engine family at its default count.
    const char* count = std::getenv("GJK2D_TRUTH_RANDOM_COUNT");
    const std::string random = "random:" + std::string(count ? count : "20000");
    const auto inputs = collectInputs({random, "hard", "engine"}, files, 1);
    std::size_t checked = 0, gmp = 0, engineTruths = 0, engineGmp = 0;
    for (const FamilyData& f : inputs)
    {
        INFO("input " << f.name);
        std::size_t mismatches = 0;
        const bool engine = f.name.rfind("engine/", 0) == 0;
        const std::size_t gmpBefore = gmp, checkedBefore = checked;
        for (std::size_t i = 0; i < f.cases.size(); ++i)
        {
            if (!f.rejected[i].empty())
                continue;
            const Case& c = f.cases[i];
            exact::Shape a, b;
            try
            {
                a = toExact(c.a);
                b = toExact(c.b);
                exact::validateShape(a);
                exact::validateShape(b);
            }
            catch (const std::invalid_argument&)
            {
                continue; // refused by the exact side as by a campaign
            }
            mismatches += sameTruth(a, b, gmp) ? 0 : 1;
            if (representableInFloat(c))
            {
                mismatches += sameTruth(toExact(c.a, true), toExact(c.b, true), gmp) ? 0 : 1;
                engineTruths += engine ? 1 : 0;
            }
            ++checked;
        }
        CHECK(mismatches == 0);
        if (engine)
        {
            engineTruths += checked - checkedBefore;
            engineGmp += gmp - gmpBefore;
        }
    }
    // Float engines' data keep the filter exact where it can be (a transformed point of float
    // input is exactly a sum of two doubles, so exactly representable distances round without
    // GMP): 1,116 of the engine families' 24,000 truths take GMP (4.65 %, at issue 34's sixth
    // step). A transform that lost that exactness sent 2,752 (11.5 %) there; the ceiling is 5 %.
    CHECK(engineTruths == 24000);
    CHECK(engineGmp * 20 <= engineTruths);
    CHECK(checked > 30000); // 34,137 with random:20000
    WARN("truths compared: " << checked << " cases; filtered ones on the GMP route: " << gmp);
}
