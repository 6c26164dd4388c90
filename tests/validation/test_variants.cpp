// The variant table (judged and comparison variants, binary-search support, warm start), the
// convex-order precondition, a reduced campaign over every variant, and `bench`.
#include "campaign/campaign.hpp"
#include "inputs/geometry.hpp"
#include "timing/bench.hpp"

#ifdef GJK2D_HAVE_HTML
#include <gjk_html/html.hpp>
#endif

#include "../within.hpp" // within(x, m): an absolute margin and nothing else
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

using namespace gjkval;

namespace
{
std::vector<P2> regular(int n, bool ccw = true)
{
    std::vector<P2> p;
    for (int i = 0; i < n; ++i)
    {
        const double t = 2 * M_PI * i / n * (ccw ? 1 : -1);
        p.push_back({std::cos(t), std::sin(t)});
    }
    return p;
}

Case caseOf(std::vector<P2> a, std::vector<P2> b)
{
    Case c;
    c.name = std::string("convex-order");
    c.a.points = std::move(a);
    c.b.points = std::move(b);
    c.b.px = 3;
    return c;
}
} // namespace

TEST_CASE("the variant table: judged and comparison variants", "[variants]")
{
    const std::set<std::string> judged = {"double",
                                          "float",
                                          "double-certified",
                                          "float-certified",
                                          "double-binary-support",
                                          "float-binary-support",
                                          "double-warm",
                                          "float-warm",
                                          "double-every-start",
                                          "float-every-start",
                                          "double-batch",
                                          "float-batch",
                                          "double-correct",
                                          "double-signed",
                                          "float-signed"};
    const std::set<std::string> comparison = {"double-closest-point", "double-world-frame",
                                              "double-duality-gap", "float-closest-point",
                                              "float-world-frame"};
    std::set<std::string> seen;
    for (const auto& v : variantTable())
    {
        INFO(v.name);
        seen.insert(v.name);
        CHECK(v.judged == (judged.count(v.name) == 1));
        CHECK((v.start == Start::Warm) == (v.name.find("-warm") != std::string::npos));
        CHECK((v.start == Start::EveryStart) == (v.name.find("-every-start") != std::string::npos));
        CHECK(needsConvexOrder(v) == (v.name.find("binary-support") != std::string::npos));
        CHECK(v.batch == (v.name.find("-batch") != std::string::npos));
    }
    for (const auto& n : judged)
        CHECK(seen.count(n) == 1);
    for (const auto& n : comparison)
        CHECK(seen.count(n) == 1);
    CHECK(seen.size() == judged.size() + comparison.size());
    // The default campaign runs every variant; --variants still selects.
    CHECK(parseVariants(kDefaultVariants).size() == variantTable().size());
    CHECK(parseVariants("double-warm,float-binary-support").size() == 2);
}

TEST_CASE("convex order: the binary-search support's precondition", "[variants]")
{
    CHECK(inConvexOrder(regular(20)));
    CHECK(inConvexOrder(regular(4096)));
    CHECK(inConvexOrder(regular(20, false))); // clockwise
    auto rotated = regular(20);
    std::rotate(rotated.begin(), rotated.begin() + 7, rotated.end());
    CHECK(inConvexOrder(rotated));
    // Collinear points on the edges, in order.
    CHECK(inConvexOrder({{0, 0}, {0.5, 0}, {1, 0}, {1, 0.25}, {1, 1}, {0, 1}, {0, 0.5}}));
    CHECK(inConvexOrder({{0, 0}}));
    // Not in convex order.
    CHECK_FALSE(inConvexOrder({{0, 0}, {1, 0}}));                 // a segment turns back
    CHECK_FALSE(inConvexOrder({{0, 0}, {1, 0}, {1, 0}, {1, 1}})); // repeated point
    CHECK_FALSE(
        inConvexOrder({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}})); // repeated across the wrap
    CHECK_FALSE(inConvexOrder({{0, 0}, {1, 0}, {0.5, 0}, {1, 1}, {0, 1}})); // collinear going back
    CHECK_FALSE(inConvexOrder({{0, 0}, {2, 0}, {1, 0.1}, {2, 2}, {0, 2}})); // a reflex vertex
    CHECK_FALSE(inConvexOrder({{0, 0}, {1, 0}, {2, 0}}));                   // all collinear
    // A pentagram: every turn to the same side, but two turns around.
    std::vector<P2> star;
    for (int i = 0; i < 5; ++i)
        star.push_back(regular(5)[std::size_t(2 * i % 5)]);
    CHECK_FALSE(inConvexOrder(star));
    auto swapped = regular(20);
    std::swap(swapped[3], swapped[4]);
    CHECK_FALSE(inConvexOrder(swapped));
    // Exactness: a vertex pushed one ulp outside/inside the edge of its neighbours.
    const double y = std::nextafter(0.0, 1.0);
    CHECK(inConvexOrder({{0, 0}, {0.5, -y}, {1, 0}, {1, 1}, {0, 1}}));
    CHECK_FALSE(inConvexOrder({{0, 0}, {0.5, y}, {1, 0}, {1, 1}, {0, 1}}));
}

TEST_CASE("binary-search support is skipped as not applicable where its precondition fails",
          "[variants]")
{
    auto shuffled = regular(20);
    std::swap(shuffled[3], shuffled[11]);
    const auto small = []
    {
        auto p = regular(16);
        std::swap(p[0], p[5]);
        return p;
    }();
    CHECK(prepare(caseOf(regular(20), regular(30, false))).binaryOk[0]);
    CHECK(prepare(caseOf(regular(20), regular(30, false))).binaryOk[1]);
    CHECK_FALSE(prepare(caseOf(regular(20), shuffled)).binaryOk[0]);
    CHECK(prepare(caseOf(small, regular(3))).binaryOk[0]); // <= 16 points: the linear scan

    EvalContext ctx;
    ctx.variants = parseVariants("double,double-binary-support,float-binary-support");
    const CaseOutcome o = evaluateCase(caseOf(regular(20), shuffled), ctx);
    REQUIRE(o.rejected.empty());
    CHECK_FALSE(o.variants[0].skipped);
    CHECK(o.variants[1].skipped);
    CHECK(o.variants[1].notApplicable);
    CHECK(o.variants[2].notApplicable);
    const CaseOutcome ok = evaluateCase(caseOf(regular(20), regular(40)), ctx);
    CHECK_FALSE(ok.variants[1].skipped);
    CHECK(ok.variants[1].distance == within(ok.variants[0].distance, 1e-12));
}

TEST_CASE("a reduced campaign over every variant: judged variants pass, comparison variants run",
          "[variants][campaign]")
{
    CampaignConfig c;
    c.families = {"random:10000", "hard"};
    c.variants = parseVariants("all");
    c.threads = 2;
    c.minPasses = c.maxPasses = 1;
    c.timingBudgetSeconds = 0;
    c.command = "test";
    const Campaign camp = runCampaign(c, campaignInputs(c));
    const Json& r = camp.report;
    CHECK(camp.exitCode == kExitPass);
    CHECK(r["passed"] == true);
    REQUIRE(r["variants"].size() == variantTable().size());
    std::set<std::string> judged, comparison;
    for (const auto& v : r["variants"])
        (v["judged"].get<bool>() ? judged : comparison).insert(v["name"].get<std::string>());
    CHECK(comparison.size() == 5);
    std::uint64_t comparisonCases = 0, notApplicable = 0;
    for (const auto& f : r["families"])
    {
        const std::string fam = f["name"].get<std::string>();
        CHECK(f["pass"] == true);
        for (const auto& [name, s] : f["variants"].items())
        {
            INFO(fam << " / " << name);
            const std::uint64_t cases = s["cases"].get<std::uint64_t>();
            CHECK(s["ratio_to_baseline"].is_number());
            if (comparison.count(name))
            {
                comparisonCases += cases; // run and counted; failures allowed
                continue;
            }
            CHECK(s["failures"] == 0);
            const Json& br = s["errors"]["bound_ratio"]["max"];
            REQUIRE(br.is_number());
            CHECK(br.get<double>() <= 1.0);
            if (name.find("certified") != std::string::npos)
            {
                // Never a wrong certificate. The interval is computed in double on the unscaled
                // input, so it fails closed (not certified) where squares of the coordinates leave
                // the double range: coordinates near 1e160 in hard/range and 1e+-300 in
                // hard/extreme-scale (docs/gjk.md, "Certified interval").
                CHECK(s["interval"]["contains"] == s["interval"]["certified"]);
                if (fam != "hard/range" && fam != "hard/extreme-scale")
                    CHECK(s["interval"]["certified"] == cases);
                else
                    CHECK(s["interval"]["certified"].get<std::uint64_t>() * 2 >= cases);
            }
            // The signed variants (issue 51): gjk2d's own contract with overlap = penetration; on
            // every overlapping case the depth within gjk2d's depth bound, no contract violation;
            // no other variant has the block.
            const bool isSigned = name.find("-signed") != std::string::npos;
            CHECK(s.contains("penetration") == isSigned);
            if (isSigned)
            {
                const Json& p = s["penetration"];
                CHECK(p["contract_violations"] == 0);
                CHECK(p["beyond_bound"] == 0);
                if (p["cases"].get<std::uint64_t>() > 0)
                    CHECK(p["bound_ratio"]["max"].get<double>() <= 1.0);
                if (fam == "random") // 30 % to 70 % of random cases overlap (its make-up)
                    CHECK(p["cases"].get<std::uint64_t>() > 1000);
            }
            notApplicable += s["not_applicable"].get<std::uint64_t>();
            if (fam == "hard/many-vertices")
                CHECK(s["skipped"] == 0); // the binary search really runs on the big polygons
        }
        if (fam == "random")
        {
            // Warm start: the second query of the same pose needs (almost) no iteration.
            const Json& v = f["variants"];
            CHECK(v["double-warm"]["iterations"]["mean"].get<double>() <
                  v["double"]["iterations"]["mean"].get<double>());
            CHECK(v["double"]["ratio_to_baseline"].get<double>() == 1.0);
        }
    }
    CHECK(comparisonCases > 5 * 10000);
    CHECK(notApplicable > 0); // hard/degenerate-vertices: shuffled shapes of more than 16 points
}

TEST_CASE("bench: timings per variant without the exact side", "[variants][bench]")
{
    BenchConfig b;
    b.variants = parseVariants("double,float,float-warm");
    b.passes = 3;
    b.minPassSeconds = 0.001;
    b.command = "test";
    const BenchResult res = runBench(b, collectInputs({"random:300", "hard/points"}, {}, 1));
    CHECK(res.exitCode == kExitPass);
    const Json& j = res.json;
    for (const char* k : {"date", "host", "compiler", "flags", "build_type", "git_revision",
                          "command", "seed", "threads", "inputs", "cases_total", "cases_rejected"})
        CHECK(j["context"].contains(k));
    CHECK(j["context"]["cases_total"] == 316);
    CHECK(j["baseline_variant"] == "double");
    REQUIRE(j["variants"].size() == 3);
    for (const auto& [name, v] : j["variants"].items())
    {
        INFO(name);
        CHECK(v["ns_per_query"].get<double>() > 0);
        CHECK(v["ns_min"].get<double>() <= v["ns_per_query"].get<double>());
        CHECK(v["ns_per_query"].get<double>() <= v["ns_max"].get<double>());
        CHECK(v["passes"] == 3);
        CHECK(v["cases"] == 316);
        CHECK(v["ratio_to_double"].is_number());
        CHECK(v["warm"] == (name == "float-warm"));
    }
    CHECK(j["variants"]["double"]["ratio_to_double"] == 1.0);
    CHECK_THAT(benchTable(j), Catch::Contains("float-warm") && Catch::Contains("x double"));
}

TEST_CASE("bench: the variants' passes alternate", "[variants][bench]")
{
    // Two fake loops that record the order of their passes and report fixed times: one
    // calibration pass each, then pass k of both before pass k + 1 of either; the medians per
    // query are the fixed times over reps x cases.
    std::vector<char> order;
    auto loop = [&](char name, double nsPerQuery, std::size_t cases)
    {
        TimedLoop l;
        l.cases = cases;
        l.pass = [&order, name, nsPerQuery, cases](int reps)
        {
            order.push_back(name);
            return nsPerQuery * double(reps) * double(cases);
        };
        return l;
    };
    TimingConfig tc;
    tc.minPasses = tc.maxPasses = 3;
    tc.budgetSeconds = 1e9;
    tc.minPassSeconds = 1e-9; // one rep per pass
    TimedLoop b = loop('b', 25, 2);
    b.prepareNsPerShape = [] { return 7.5; };
    const std::vector<TimingResult> r = medianOfAlternatedPasses({loop('a', 10, 4), b}, tc);
    // Calibration, then 3 rounds, round p starting at loop p mod 2: no loop always runs first.
    CHECK(std::string(order.begin(), order.end()) == "ab"
                                                     "ab"
                                                     "ba"
                                                     "ab");
    REQUIRE(r.size() == 2);
    CHECK(r[0].nsPerQuery == 10.0);
    CHECK(r[1].nsPerQuery == 25.0);
    CHECK(r[0].passes == 3);
    CHECK(r[1].cases == 2);
    CHECK(r[0].prepareNsPerShape == -1.0); // a loop without a preparation step
    CHECK(r[1].prepareNsPerShape == 7.5);
    CHECK(r[0].preparedNsPerQuery == -1.0); // only timeAlternated pairs a prepared loop
}

TEST_CASE("gjk2d's own variants are timed plain and on prepared shapes", "[variants][timing]")
{
    // The variants of the reference options, not batched, have a prepared form (the query on
    // gjk::PreparedShape decides its range checks before the loop with those options alone): the
    // table's names, listed here by hand.
    std::set<std::string> withForm;
    for (const auto& v : variantTable())
        if (hasPreparedForm(v))
            withForm.insert(v.name);
    CHECK(withForm == std::set<std::string>{"double", "float", "double-warm", "float-warm",
                                            "double-every-start", "float-every-start"});

    // Timed: both figures and the preparation per shape for those, the plain figure alone for the
    // others; a warm variant's prepared loop is warm as its plain one.
    std::vector<PreparedCase> prepared;
    for (int i = 0; i < 40; ++i)
    {
        Case c = caseOf(regular(6 + i % 5), regular(4 + i % 3, false));
        c.b.px = 2.5 + 0.01 * i;
        prepared.push_back(prepare(c));
    }
    std::vector<const PreparedCase*> cases;
    for (const auto& p : prepared)
        cases.push_back(&p);
    const std::vector<const VariantInfo*> variants =
        parseVariants("double,float-warm,double-closest-point,double-batch");
    TimingConfig tc;
    tc.minPasses = tc.maxPasses = 3;
    tc.minPassSeconds = 1e-4;
    const std::vector<TimingResult> r = timeAlternated(
        std::vector<std::vector<const PreparedCase*>>(variants.size(), cases), variants, tc, 10);
    REQUIRE(r.size() == variants.size());
    for (std::size_t k = 0; k < r.size(); ++k)
    {
        INFO(variants[k]->name);
        CHECK(r[k].nsPerQuery > 0); // the plain figure stays
        CHECK(r[k].cases == cases.size());
        CHECK(r[k].passes == 3);
        if (k < 2)
        {
            CHECK(r[k].preparedNsPerQuery > 0);
            CHECK(r[k].prepareNsPerShape > 0);
        }
        else
        {
            CHECK(r[k].preparedNsPerQuery == -1.0);
            CHECK(r[k].prepareNsPerShape == -1.0);
        }
    }
    CHECK(preparedLoop(cases, *variants[1], tc).warm);
    CHECK_FALSE(preparedLoop(cases, *variants[0], tc).warm);
    CHECK_FALSE(preparedLoop(cases, *variants[2], tc).pass); // no prepared form: an empty loop
}

TEST_CASE("every-start variants judge the worst answer over many starts", "[variants]")
{
    const VariantInfo* v = findVariant("double-every-start");
    REQUIRE(v != nullptr);
    REQUIRE(v->start == Start::EveryStart);
    // The talk's walk-through pentagon against the origin (distance exactly 1): every start the
    // variant tries agrees with the truth.
    Case walk;
    walk.name = "walk";
    walk.a.points = {{-4, 3}, {-4, 6}, {3, 5}, {3, 1}, {-1, 1}};
    walk.b.points = {{0, 0}};
    CHECK(worstStart<double>(prepare(walk), *v, 1.0).distance == 1.0);

    // Starts that disagree: a pentagon and a triangle 2.016 apart (found by a random search over
    // small polygons; digits round-trip), where the starts' answers differ in the last bits. With
    // at most 12 points a side the variant starts from every vertex pair (and four edge and
    // triangle caches besides), so the answers of the cold start and of every vertex pair, computed
    // here, are among those it judges: whatever the truth, the judged answer must be at least as
    // far from it as each of them, never the best of them.
    Case c;
    c.name = "starts-disagree";
    c.a.points = {{0.1135283153087232, 0.89031030845795578},
                  {-0.8116532416105342, 0.3830928596390818},
                  {-0.61515760570306366, -0.6535459003536106},
                  {0.43146493284803461, -0.78700643926576508},
                  {0.8818175991568401, 0.16714917152233785}};
    c.b.points = {{4.3673514235223836, -1.1939405016232185},
                  {3.0666654538527451, 1.472448605923772},
                  {2.7991215561036595, -0.78729330572428835}};
    const PreparedCase p = prepare(c);
    const gjk::DistanceInput<double> in = p.input<double>();
    gjk::SimplexCache cold;
    double lo = gjk::distance(in, cold, v->options).distance, hi = lo;
    for (int i = 0; i < in.proxyA.count; ++i)
        for (int j = 0; j < in.proxyB.count; ++j)
        {
            gjk::SimplexCache start{1, {i, 0, 0}, {j, 0, 0}};
            const double d = gjk::distance(in, start, v->options).distance;
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    INFO("the starts' answers range over [" << lo << ", " << hi << "]");
    REQUIRE(lo < hi); // the starts disagree
    // A truth below every answer: the farthest is the largest; above every answer: the smallest.
    // Both errors are exact (d - 0, and 3 - d by Sterbenz for d in [1.5, 6]), so answers a few ulps
    // apart keep distinct errors (a truth of 100 would round them all to one).
    CHECK(worstStart<double>(p, *v, 0.0).distance >= hi);
    CHECK(worstStart<double>(p, *v, 3.0).distance <= lo);
    // The campaign judges that answer against the exact truth.
    EvalContext ctx;
    ctx.variants = parseVariants("double-every-start");
    const CaseOutcome o = evaluateCase(c, ctx);
    REQUIRE(o.rejected.empty());
    const VariantOutcome& judged = o.variants[0];
    INFO("truth " << judged.truth << ", judged answer " << judged.distance);
    CHECK(judged.distance == worstStart<double>(p, *v, judged.truth).distance);
    CHECK(std::abs(judged.distance - judged.truth) >=
          std::max(std::abs(lo - judged.truth), std::abs(hi - judged.truth)));
}

#ifdef GJK2D_HAVE_HTML
TEST_CASE("every variant of the table has its own colour on the report page", "[variants][html]")
{
    // The page (validation/html/assets/report.js) gives each built-in variant a fixed colour, the
    // same on index.html and on explain --html pages; a variant added to the table without one
    // would get a hashed colour that may clash with another's. The browser test checks the
    // colours are distinct and equal across pages.
    const std::string page = gjk_html::renderCase(Json::object());
    for (const auto& v : variantTable())
    {
        INFO(v.name);
        CHECK(page.find("'" + v.name + "': '#") != std::string::npos);
    }
}
#endif

TEST_CASE("docs list every variant of the table once, with its type and judged flag",
          "[variants][docs]")
{
    // docs/campaign.md, "Variants", lists the table by hand: `| names | type | judged | options
    // |`, a row naming one variant or a double/float pair (type "both"). A variant added to the
    // table, renamed or made a comparison one without the docs following fails here.
    std::ifstream in(std::filesystem::path(GJK2D_SOURCE_DIR) / "docs" / "campaign.md");
    REQUIRE(in);
    std::string line;
    bool inSection = false;
    std::map<std::string, int> listed;
    while (std::getline(in, line))
    {
        if (line.rfind("## ", 0) == 0)
            inSection = line == "## Variants";
        if (!inSection || line.rfind("| `", 0) != 0)
            continue;
        std::vector<std::string> cells;
        std::size_t at = 1;
        for (int k = 0; k < 3; ++k)
        {
            const std::size_t bar = line.find(" | ", at);
            REQUIRE(bar != std::string::npos);
            cells.push_back(line.substr(at, bar - at));
            at = bar + 2;
        }
        const std::string type = cells[1].substr(cells[1].find_first_not_of(' ')),
                          judged = cells[2].substr(cells[2].find_first_not_of(' '));
        for (std::size_t q = cells[0].find('`'); q != std::string::npos;
             q = cells[0].find('`', cells[0].find('`', q + 1) + 1))
        {
            const std::string name = cells[0].substr(q + 1, cells[0].find('`', q + 1) - q - 1);
            INFO(line);
            INFO("docs name " << name);
            ++listed[name];
            const auto it = std::find_if(variantTable().begin(), variantTable().end(),
                                         [&](const VariantInfo& v) { return v.name == name; });
            REQUIRE(it != variantTable().end());
            CHECK(judged == (it->judged ? "judged" : "comparison"));
            CHECK((type == "both" || type == scalarName(it->scalar)));
        }
    }
    for (const auto& v : variantTable())
    {
        INFO(v.name);
        CHECK(listed[v.name] == 1);
    }
    CHECK(listed.size() == variantTable().size());
}
