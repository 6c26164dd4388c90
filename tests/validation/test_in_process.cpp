// In-process variants (implementations/in_process.hpp): answered by a callback in the campaign's
// own process, judged, counted and timed as any plugin's variant. The Python package's
// gjk2d.validate stands on them; python/tests/test_validate.py checks the Python side.
#include "campaign/campaign.hpp"
#include "implementations/in_process.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <stdexcept>
#include <unistd.h>

using namespace gjkval;

namespace
{
// gjk2d's double query with the reference options, as an in-process implementation answers.
void referenceAnswer(const PreparedCase& p, ExternalAnswer& a)
{
    gjk::SimplexCache cache{};
    const gjk::DistanceOutput<double> o = gjk::distance(p.input<double>(), cache);
    a.distance = o.distance;
    a.pointA = {o.pointA.x, o.pointA.y};
    a.pointB = {o.pointB.x, o.pointB.y};
    a.iterations = o.iterations;
}

InProcessVariant variantOf(const std::string& name,
                           std::function<void(const PreparedCase&, ExternalAnswer&)> perCase)
{
    InProcessVariant v;
    v.name = name;
    v.source = "test:" + name;
    v.library = "gjk2d (test)";
    v.calls.perCase = std::move(perCase);
    return v;
}

// A campaign over `families` of "double" and the in-process variant: 2 threads, 1 or 2 timed
// passes.
Campaign runWith(const VariantInfo* v, std::vector<std::string> families)
{
    CampaignConfig c;
    c.families = std::move(families);
    c.variants = {findVariant("double"), v};
    c.threads = 2;
    c.minPasses = 1;
    c.maxPasses = 2;
    c.timingBudgetSeconds = 0.01;
    c.command = "test";
    return runCampaign(c, campaignInputs(c));
}

const Json& statsOf(const Campaign& camp, std::size_t family, const std::string& variant)
{
    return camp.report["families"][family]["variants"][variant];
}
} // namespace

TEST_CASE("an in-process variant answering as gjk2d's double query is judged as double, in this "
          "process",
          "[in-process]")
{
    const pid_t self = ::getpid();
    int calls = 0, elsewhere = 0;
    const VariantInfo* v = registerInProcessVariant(variantOf(
        "test-in-process-reference",
        [&](const PreparedCase& p, ExternalAnswer& a)
        {
            ++calls;
            elsewhere += ::getpid() != self ? 1 : 0; // a child's count would never reach us
            referenceAnswer(p, a);
        }));
    const Campaign camp = runWith(v, {"random:300", "hard/near-parallel"});
    releaseInProcessVariant(v->name);
    CHECK(elsewhere == 0);
    // 348 accuracy queries, then the timing's calibration and passes.
    CHECK(calls > 348);
    CHECK(camp.exitCode == kExitPass);
    for (std::size_t f = 0; f < 2; ++f)
    {
        const Json &d = statsOf(camp, f, "double"), &p = statsOf(camp, f, v->name);
        CHECK(p["cases"] == d["cases"]);
        CHECK(p["failures"] == 0);
        CHECK(p["plugin_errors"] == 0);
        CHECK(p["errors"]["abs"] == d["errors"]["abs"]);
        CHECK(p["errors"]["bound_ratio"] == d["errors"]["bound_ratio"]);
        CHECK(p["iterations"] == d["iterations"]);
        CHECK(p["ns_per_query"].get<double>() > 0);
    }
    const Json& plugins = camp.report["context"]["plugins"];
    REQUIRE(plugins.size() == 1);
    CHECK(plugins[0]["kind"] == "in-process");
    CHECK(plugins[0]["file"] == "test:test-in-process-reference");
    CHECK(plugins[0]["library"] == "gjk2d (test)");
}

TEST_CASE("an in-process variant 1% off fails every separated random case, judged", "[in-process]")
{
    const VariantInfo* v =
        registerInProcessVariant(variantOf("test-in-process-one-percent",
                                           [](const PreparedCase& p, ExternalAnswer& a)
                                           {
                                               referenceAnswer(p, a);
                                               a.distance *= 1.01;
                                           }));
    judgePluginVariant(v->name);
    CampaignConfig c;
    c.families = {"random:400"};
    c.variants = {findVariant("double"), v};
    c.threads = 2;
    c.timing = false;
    c.perCase = true;
    c.command = "test";
    std::ostringstream lines;
    const Campaign camp = runCampaign(c, campaignInputs(c), &lines);
    releaseInProcessVariant(v->name);
    // gjk-validate's own count of separated cases: the per-case lines' exact side. A random case
    // apart is O(1) apart at size O(1): 1% is far beyond the bound (~1e-14 relative).
    int separated = 0;
    std::istringstream in(lines.str());
    for (std::string l; std::getline(in, l);)
        separated += Json::parse(l)["exact"]["overlap"] == false ? 1 : 0;
    CHECK(separated > 100); // the family's make-up: 30% to 70% of its cases overlap
    CHECK(statsOf(camp, 0, v->name)["failures"] == separated);
    CHECK(statsOf(camp, 0, "double")["failures"] == 0);
    CHECK(camp.exitCode == kExitFail);
}

TEST_CASE("an in-process callback that throws: each case an error with its message, the campaign "
          "completes",
          "[in-process]")
{
    const VariantInfo* v = registerInProcessVariant(
        variantOf("test-in-process-throws", [](const PreparedCase&, ExternalAnswer&)
                  { throw std::runtime_error("ValueError: no answer here"); }));
    const Campaign camp = runWith(v, {"random:50", "hard/points"});
    releaseInProcessVariant(v->name);
    CHECK(camp.exitCode == kExitPass); // a comparison variant
    for (std::size_t f = 0; f < 2; ++f)
    {
        const Json& s = statsOf(camp, f, v->name);
        CHECK(s["cases"] == statsOf(camp, f, "double")["cases"]);
        CHECK(s["plugin_errors"] == s["cases"]);
        CHECK(s["failures"] == s["cases"]);
        CHECK(s["ns_per_query"].is_null()); // no case answered: none is timed
    }
    const Json& worst = camp.report["worst"][0]["variants"][v->name];
    CHECK(worst["plugin_status"] == "error");
    CHECK(worst["plugin_detail"] == "ValueError: no answer here");
}

TEST_CASE("a batch callback gives the per-case callback's report", "[in-process]")
{
    int batches = 0;
    InProcessVariant b = variantOf("test-in-process-batch", nullptr);
    b.calls.perBatch =
        [&](const std::vector<const PreparedCase*>& cases, std::vector<ExternalAnswer>& out)
    {
        ++batches;
        for (std::size_t i = 0; i < cases.size(); ++i)
            referenceAnswer(*cases[i], out[i]);
    };
    const VariantInfo* vb = registerInProcessVariant(std::move(b));
    const Campaign batch = runWith(vb, {"random:200", "hard/sliver"});
    releaseInProcessVariant(vb->name);
    CHECK(batches >= 2); // one per chunk of each family, then the timing's
    const VariantInfo* vc =
        registerInProcessVariant(variantOf("test-in-process-batch", referenceAnswer));
    CHECK(vc == vb); // the same name again: registered in place
    const Campaign each = runWith(vc, {"random:200", "hard/sliver"});
    releaseInProcessVariant(vc->name);
    CHECK(stripVolatile(batch.report)["families"] == stripVolatile(each.report)["families"]);
}

TEST_CASE("in-process registration: names, callbacks, a released variant", "[in-process]")
{
    CHECK_THROWS_AS(registerInProcessVariant(variantOf("double", referenceAnswer)), InputError);
    CHECK_THROWS_AS(registerInProcessVariant(variantOf("no spaces", referenceAnswer)), InputError);
    CHECK_THROWS_AS(registerInProcessVariant(variantOf("test-no-callback", nullptr)), InputError);
    const VariantInfo* v =
        registerInProcessVariant(variantOf("test-in-process-released", referenceAnswer));
    judgePluginVariant(v->name);
    CHECK(v->judged);
    CHECK(registerInProcessVariant(variantOf(v->name, referenceAnswer)) == v);
    CHECK_FALSE(v->judged); // registered again: judged again only on request
    releaseInProcessVariant(v->name);
    CampaignConfig c;
    c.families = {"random:2"};
    c.variants = {v};
    c.timing = false;
    c.command = "test";
    CHECK_THROWS_AS(runCampaign(c, campaignInputs(c)), std::logic_error);
}
