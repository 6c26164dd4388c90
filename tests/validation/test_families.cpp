// The case families: deterministic from the seed, the hard sub-families all present with their
// reasons, and every family's make-up checks hold on its own cases (measured with the exact side).
#include "families.hpp"

#include <catch2/catch.hpp>

#include <set>

using namespace gjkval;

namespace
{
std::string textOf(const std::vector<GeneratedFamily>& fs)
{
    std::vector<Case> all;
    for (const auto& f : fs)
        all.insert(all.end(), f.cases.begin(), f.cases.end());
    return caseFileText({}, all);
}

std::vector<MakeupResult> makeupOf(const GeneratedFamily& f)
{
    std::vector<exact::Result> truths;
    for (const auto& c : f.cases)
        truths.push_back(exact::distance(toExact(c.a), toExact(c.b)));
    std::vector<const Case*> cs;
    std::vector<const exact::Result*> ts;
    for (std::size_t i = 0; i < f.cases.size(); ++i)
    {
        cs.push_back(&f.cases[i]);
        ts.push_back(&truths[i]);
    }
    return evaluateMakeup(f.makeup, cs, ts);
}
} // namespace

TEST_CASE("families are deterministic functions of the seed", "[families]")
{
    CHECK(textOf(generateFamilies("random:50", 7)) == textOf(generateFamilies("random:50", 7)));
    CHECK(textOf(generateFamilies("random:50", 7)) != textOf(generateFamilies("random:50", 8)));
    CHECK(textOf(generateFamilies("hard", 3)) == textOf(generateFamilies("hard", 3)));
    // Case i depends only on (seed, family, i): a smaller count gives a prefix.
    const auto small = generateFamilies("random:20", 7)[0].cases;
    const auto big = generateFamilies("random:50", 7)[0].cases;
    CHECK(caseFileText({}, small) ==
          caseFileText({}, std::vector<Case>(big.begin(), big.begin() + 20)));
    // A sub-family alone is the same as within `hard`.
    const auto all = generateFamilies("hard", 3);
    const auto one = generateFamilies("hard/sliver", 3);
    REQUIRE(one.size() == 1);
    for (const auto& f : all)
        if (f.name == "hard/sliver")
            CHECK(caseFileText({}, f.cases) == caseFileText({}, one[0].cases));
}

TEST_CASE("the hard sub-families: at least 12, named, with reasons and unique case names",
          "[families]")
{
    const auto& subs = hardSubFamilies();
    CHECK(subs.size() >= 12);
    std::set<std::string> names;
    for (const auto& s : subs)
    {
        CHECK_FALSE(s.reason.empty());
        CHECK(s.count > 0);
        names.insert(s.name);
    }
    for (const char* required :
         {"talk-segment", "near-parallel", "far-from-origin", "sliver", "touching-vertex",
          "touching-edge", "ulp-gap", "degenerate-vertices", "segment-segment", "identical-nested",
          "tiny-scale", "huge-scale", "many-vertices", "rotated", "rounded"})
        CHECK(names.count(required) == 1);

    const auto fams = generateFamilies("hard", 1);
    CHECK(fams.size() == subs.size());
    std::set<std::string> caseNames;
    for (const auto& f : fams)
        for (const auto& c : f.cases)
            CHECK(caseNames.insert(c.name).second);

    // The talk's segment, exactly as in the talk.
    const auto talk = generateFamilies("hard/talk-segment", 1)[0].cases[0];
    REQUIRE(talk.a.points.size() == 2);
    CHECK(talk.a.points[0][0] == 0.021119118);
    CHECK(talk.a.points[0][1] == 79.584320);
    CHECK(talk.a.points[1][0] == 0.020964622);
    CHECK(talk.a.points[1][1] == -31.515678);
    CHECK(talk.b.points == std::vector<std::array<double, 2>>{{0, 0}});

    // Counts: built in, overridable.
    CHECK(generateFamilies("hard/points:3", 1)[0].cases.size() == 3);
    CHECK(generateFamilies("random", 1)[0].cases.size() == std::size_t(kDefaultRandomCount));
}

TEST_CASE("family specs are checked", "[families]")
{
    CHECK_THROWS_AS(generateFamilies("nope", 1), InputError);
    CHECK_THROWS_AS(generateFamilies("hard/nope", 1), InputError);
    CHECK_THROWS_AS(generateFamilies("random:x", 1), InputError);
    CHECK_THROWS_AS(generateFamilies("random:-3", 1), InputError);
    CHECK_THROWS_WITH(generateFamilies("nope", 1), Catch::Contains("hard/near-parallel"));
}

TEST_CASE("every family's make-up checks hold on its own cases", "[families]")
{
    std::vector<GeneratedFamily> fams = generateFamilies("hard", 1);
    for (auto& f : generateFamilies("random:400", 1))
        fams.push_back(std::move(f));
    for (const auto& f : fams)
    {
        INFO(f.name);
        CHECK_FALSE(f.makeup.empty());
        for (const auto& m : makeupOf(f))
        {
            INFO(m.check << " = " << m.value << " in [" << m.min << ", " << m.max << "]");
            CHECK(m.ok);
            CHECK_FALSE(m.skipped);
        }
    }
}

TEST_CASE("a make-up check fails on cases that do not have that make-up", "[families]")
{
    // The random family's checks on 120 identical (overlapping) pairs: the overlapping fraction is
    // 1, outside [0.2, 0.8], and there is no near-touching case.
    GeneratedFamily f = generateFamilies("random:0", 1)[0];
    const auto nested = generateFamilies("hard/identical-nested", 1)[0].cases;
    for (int i = 0; i < 120; ++i)
        f.cases.push_back(nested[0]);
    int failed = 0;
    for (const auto& m : makeupOf(f))
        failed += m.ok ? 0 : 1;
    CHECK(failed >= 2);
    // Statistical checks are not judged below 100 cases.
    f.cases.resize(50);
    for (const auto& m : makeupOf(f))
        if (m.skipped)
            CHECK(m.ok);
}
