// The engine families (validation/src/inputs/engine.cpp): queries recorded from Box2D 2.4.1 worlds.
// They are deterministic, the TOI families hold b2TimeOfImpact's own b2Distance calls (interposed:
// useRadii = false, so radius 0), every case keeps the engine's float rotation (not a unit vector
// in double) and is valid case-file input, and every family's make-up checks hold.
#include "campaign/campaign.hpp"
#include "campaign_support.hpp"
#include "implementations/variants.hpp"
#include "inputs/engine.hpp"
#include "inputs/families.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

using namespace gjkval;

namespace
{
const std::vector<std::string> kEngineFamilies = {
    "engine/pyramid-proximity", "engine/pyramid-toi",       "engine/container-proximity",
    "engine/container-toi",     "engine/bullets-proximity", "engine/bullets-toi"};

GeneratedFamily engineFamily(const std::string& name, std::uint64_t seed, int count)
{
    auto fs = generateFamilies(name + ":" + std::to_string(count), seed);
    REQUIRE(fs.size() == 1);
    return fs[0];
}

bool isToi(const std::string& family)
{
    return family.ends_with("-toi");
}

// A float rotation is a unit vector only to float rounding.
bool nonUnit(const ShapeIn& s)
{
    return s.c * s.c + s.s * s.s != 1;
}

bool isFloat(double v)
{
    return double(float(v)) == v;
}
} // namespace

TEST_CASE("engine families: the spec `engine` is the six families, 12,000 cases by default",
          "[engine]")
{
    const auto counts = familyCaseCounts(parseFamilySpec("engine"));
    REQUIRE(counts.size() == kEngineFamilies.size());
    std::size_t total = 0;
    for (std::size_t i = 0; i < counts.size(); ++i)
    {
        CHECK(counts[i].first == kEngineFamilies[i]);
        total += counts[i].second;
    }
    CHECK(total == 12000);
    CHECK(familyCaseCounts(parseFamilySpec("engine:7")).size() == 6);
    CHECK(familyCaseCounts(parseFamilySpec("engine/bullets-toi:7"))[0].second == 7);
    CHECK(engineSubFamilies().size() == 6);
    for (const auto& e : engineSubFamilies())
        CHECK(e.reason.size() > 100);
    CHECK_THROWS_AS(parseFamilySpec("engine/nope"), InputError);
    CHECK_THROWS_WITH(parseFamilySpec("engine/nope"), Catch::Contains("engine/container-toi"));
    const auto defaults = defaultFamilies();
    CHECK(std::find(defaults.begin(), defaults.end(), "engine") != defaults.end());
}

TEST_CASE("engine families: the same seed and count give the same cases, another seed others",
          "[engine]")
{
    for (const auto& name : kEngineFamilies)
    {
        INFO(name);
        const auto a = engineFamily(name, 7, 150);
        const auto b = engineFamily(name, 7, 150);
        const auto c = engineFamily(name, 8, 150);
        REQUIRE(a.cases.size() == 150);
        CHECK(caseFileText({}, a.cases) == caseFileText({}, b.cases));
        CHECK(caseFileText({}, a.cases) != caseFileText({}, c.cases));
        CHECK(a.seed != c.seed);
        // Within the family `engine`, the same cases as alone.
        if (name == "engine/container-toi")
            for (const auto& f : generateFamilies("engine:150", 7))
                if (f.name == name)
                    CHECK(caseFileText({}, f.cases) == caseFileText({}, a.cases));
    }
}

TEST_CASE("engine families: the interposer sees libbox2d's own b2Distance calls", "[engine]")
{
    // b2TestOverlap inside libbox2d.so calls b2Distance through its PLT: without the export
    // (validation/CMakeLists.txt) this throws std::logic_error.
    REQUIRE_NOTHROW(checkB2DistanceInterposed());
    const std::uint64_t before = interposedB2DistanceCalls();
    const auto toi = engineFamily("engine/bullets-toi", 3, 200);
    // A 600-step bullet scene makes thousands of b2TimeOfImpact distance calls; 200 are kept.
    CHECK(toi.cases.size() == 200);
    CHECK(interposedB2DistanceCalls() - before >= 1000);
}

TEST_CASE("engine families: the engine's floats verbatim, radius as the query used it", "[engine]")
{
    const std::regex name(
        R"(engine/[a-z]+-[a-z]+/\d+-step\d+-(circle|edge|polygon|rounded)-(circle|edge|polygon|rounded))");
    for (const auto& fam : kEngineFamilies)
    {
        INFO(fam);
        const auto f = engineFamily(fam, 1, 300);
        int nonUnitCases = 0, zeroRadius = 0, rounded = 0, circles = 0;
        std::set<std::string> tags;
        for (const auto& c : f.cases)
        {
            INFO(c.name);
            CHECK(std::regex_match(c.name, name));
            CHECK(c.name.starts_with(fam + "/"));
            nonUnitCases += nonUnit(c.a) || nonUnit(c.b) ? 1 : 0;
            for (const ShapeIn* s : {&c.a, &c.b})
            {
                REQUIRE(!s->points.empty());
                CHECK(s->points.size() <= 8); // b2_maxPolygonVertices
                // Every number is a float of the engine's, converted exactly.
                for (const auto& p : s->points)
                    CHECK((isFloat(p[0]) && isFloat(p[1])));
                CHECK((isFloat(s->px) && isFloat(s->py) && isFloat(s->c) && isFloat(s->s)));
                CHECK(isFloat(s->radius));
                zeroRadius += s->radius == 0 ? 1 : 0;
                rounded += s->points.size() >= 3 && s->radius > 0.02 ? 1 : 0;
                circles += s->points.size() == 1 ? 1 : 0;
                // Only the float rounding of cos and sin: |c^2 + s^2 - 1| < 2^-22.
                CHECK(std::abs(s->c * s->c + s->s * s->s - 1) < 0x1p-22);
            }
        }
        // Float rotations: most cases carry one that is not a unit vector in double.
        CHECK(nonUnitCases >= 250);
        if (isToi(fam))
        {
            // b2TimeOfImpact asks b2Distance with useRadii = false: the interposed records have
            // radius 0 everywhere, even for circles (their centres) and rounded polygons.
            CHECK(zeroRadius == 2 * int(f.cases.size()));
        }
        else
        {
            CHECK(zeroRadius == 0); // every Box2D proxy has a radius (0.01 skin at least)
        }
        if (fam == "engine/container-proximity")
            CHECK(rounded >= 10); // rounded polygons: m_radius 0.05 .. 0.25
        if (fam.starts_with("engine/container") || fam.starts_with("engine/bullets"))
            CHECK(circles >= 1);
    }
}

TEST_CASE("engine families: every case is valid case-file input and round-trips", "[engine]")
{
    // Needs the reader to accept float rotations (|c^2 + s^2 - 1| up to ~1e-7).
    for (const auto& fam : kEngineFamilies)
    {
        INFO(fam);
        const auto f = engineFamily(fam, 2, 300);
        const std::string text = caseFileText({}, f.cases);
        const CaseFile back = parseCaseFile(text, "engine.json");
        REQUIRE(back.entries.size() == f.cases.size());
        std::vector<Case> cs;
        for (const auto& e : back.entries)
        {
            INFO(e.label);
            CHECK(e.rejected == "");
            cs.push_back(e.c);
        }
        CHECK(caseFileText({}, cs) == text);
    }
}

TEST_CASE("engine families: make-up checks hold on a few hundred cases, and fail on others",
          "[engine]")
{
    const auto random = generateFamilies("random:300", 1)[0].cases;
    for (std::uint64_t seed : {1u, 2u, 3u})
        for (const auto& fam : kEngineFamilies)
        {
            INFO(fam << " seed " << seed);
            GeneratedFamily f = engineFamily(fam, seed, 300);
            CHECK(f.makeup.size() >= 5);
            for (const auto& m : makeupOn(f.makeup, f.cases))
            {
                INFO(m.check << " = " << m.value << " in [" << m.min << ", " << m.max << "]");
                CHECK(m.ok);
                CHECK_FALSE(m.skipped);
            }
            if (seed != 1)
                continue;
            // The random family (double rotations, no radii) fails each engine family's checks.
            int failed = 0;
            for (const auto& m : makeupOn(f.makeup, random))
                failed += m.ok ? 0 : 1;
            CHECK(failed >= 2);
        }
}

TEST_CASE("engine families: the judged variants pass on engine data", "[engine][campaign]")
{
    const CampaignConfig c = untimedConfig({"engine:300"});
    const Campaign camp = runCampaign(c, campaignInputs(c));
    REQUIRE(camp.report["families"].size() == 6);
    for (const Json& fam : camp.report["families"])
    {
        INFO(fam["name"].get<std::string>());
        CHECK(fam["makeup_ok"] == true);
        CHECK(fam["rejected"] == 0);
        for (const auto* v : c.variants)
            if (v->judged)
            {
                INFO(v->name);
                CHECK(fam["variants"][v->name]["failures"] == 0);
            }
    }
    CHECK(camp.exitCode == kExitPass);
}
