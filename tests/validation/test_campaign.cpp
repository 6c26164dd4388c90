// Campaigns end to end (in process): the report follows docs/report-schema.md, rejected cases do
// not stop the others, failures are detected, and nothing depends on the number of threads.
#include "campaign/campaign.hpp"
#include "inputs/geometry.hpp"
#include "report/explain.hpp"
#include "report/report.hpp"

#include "../within.hpp" // within(x, m): an absolute margin and nothing else
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

using namespace gjkval;

namespace
{
CampaignConfig smallConfig(int threads)
{
    CampaignConfig c;
    c.families = {"random:200", "hard/talk-segment", "hard/ulp-gap", "hard/rounded", "hard/points"};
    c.variants = parseVariants("double,float");
    c.threads = threads;
    c.maxPasses = 2;
    c.minPasses = 1;
    c.timingBudgetSeconds = 0.01;
    c.perCase = true;
    c.command = "test";
    return c;
}

// A campaign in process, with the lines it streams to cases.jsonl.
struct Run : Campaign
{
    std::vector<std::string> perCaseLines;
};

Run run(const CampaignConfig& c)
{
    std::ostringstream lines;
    Run r{runCampaign(c, campaignInputs(c), c.perCase ? &lines : nullptr), {}};
    std::istringstream in(lines.str());
    for (std::string l; std::getline(in, l);)
        r.perCaseLines.push_back(l);
    return r;
}

// The report directory as `run` writes it, cases.jsonl included.
std::string write(const Run& r, const std::string& dir)
{
    StagedDir out(reportDirPath(dir));
    std::string lines;
    for (const auto& l : r.perCaseLines)
        lines += l + "\n";
    if (!r.perCaseLines.empty())
        out.write("cases.jsonl", lines);
    return writeReportPages(r, out);
}

std::string tmpDir(const std::string& name)
{
    const std::string d = std::string(VALIDATION_TEST_TMP) + "/" + name;
    std::filesystem::remove_all(d);
    return d;
}
} // namespace

TEST_CASE("a small campaign passes and its report follows the schema", "[campaign]")
{
    const Run camp = run(smallConfig(2));
    const Json& r = camp.report;
    CHECK(camp.exitCode == kExitPass);
    CHECK(r["schema"] == "gjk-report/1");
    CHECK(r["passed"] == true);
    for (const char* k :
         {"date", "host", "compiler", "flags", "build_type", "batch_isa", "git_revision", "command",
          "seed", "threads", "inputs", "cases_total", "cases_rejected", "exact_route", "elapsed_s"})
        CHECK(r["context"].contains(k));
    CHECK(r["context"]["cases_total"] == 200 + 16 + 32 + 40 + 16);
    CHECK(r["context"]["flags"].get<std::string>().find("-ffp-contract=off") != std::string::npos);
    CHECK(r["baseline_variant"] == "double");
    REQUIRE(r["variants"].size() == 2);
    CHECK(r["variants"][0]["bound"].contains("formula"));
    REQUIRE(r["families"].size() == 5);
    for (const auto& f : r["families"])
    {
        INFO(f["name"]);
        CHECK(f["pass"] == true);
        for (const auto& [name, s] : f["variants"].items())
        {
            for (const char* k :
                 {"cases", "failures", "pass", "false_overlap", "false_separation", "undecidable",
                  "nonfinite", "out_of_range", "iteration_limit", "failure_rate_upper95", "errors",
                  "iterations", "stops", "ns_per_query", "ns_spread", "ratio_to_baseline"})
                CHECK(s.contains(k));
            for (const char* h :
                 {"abs", "rel", "ulps", "normalized", "bound_ratio", "witness", "witness_gap"})
            {
                const Json& hist = s["errors"][h];
                for (const char* k : {"count", "zeros", "max", "mean", "sum", "p50", "p99", "p999",
                                      "log10_min", "bins_per_decade", "counts", "max_case"})
                    CHECK(hist.contains(k));
            }
            CHECK(s["errors"].contains("input_rounding") == (name == "float"));
            CHECK(s["ns_per_query"].get<double>() > 0);
        }
    }
    // One worst case per family, with traces in world coordinates.
    REQUIRE(r["worst"].size() == 5);
    for (const auto& w : r["worst"])
    {
        CHECK(w.contains("minkowski"));
        CHECK(w["exact"]["squared"].get<std::string>().find('/') != std::string::npos);
        for (const auto& [name, v] : w["variants"].items())
        {
            REQUIRE(v["trace"].size() >= 1);
            CHECK(v["trace"][0]["simplex"].size() >= 1);
        }
    }
    // Worst cases: replayable case file.
    CHECK(camp.worstCases.size() == 5 * 3);
    CHECK(camp.perCaseLines.size() == 304);
    const Json line = Json::parse(camp.perCaseLines[0]);
    CHECK(line["name"] == "random/0");
    CHECK(line["variants"]["double"].contains("distance"));
    CHECK(line["variants"]["float"].contains("stop"));
    CHECK(line["exact"].contains("overlap"));

    // Written files.
    const std::string dir = tmpDir("small");
    const std::string page = write(camp, dir);
    CHECK(std::filesystem::path(page).is_absolute());
    for (const char* f : {"report.json", "report.md", "worst-cases.json", "cases.jsonl"})
        CHECK(std::filesystem::exists(std::filesystem::path(dir) / f));
    const CaseFile worst = readCaseFile(dir + "/worst-cases.json");
    CHECK(worst.entries.size() == 15);
    CHECK_FALSE(worst.comments.empty());
    for (const auto& e : worst.entries)
        CHECK(e.rejected.empty());
    std::ifstream in(dir + "/report.json");
    CHECK(Json::parse(in) == r);
}

namespace
{
// Whether a and b have the same type at every node (== compares numbers across their types).
bool sameTypes(const nlohmann::json& a, const nlohmann::json& b)
{
    if (a.type() != b.type() || a.size() != b.size())
        return false;
    if (a.is_object())
        for (auto it = a.begin(); it != a.end(); ++it)
            if (!b.contains(it.key()) || !sameTypes(it.value(), b.at(it.key())))
                return false;
    if (a.is_array())
        for (std::size_t i = 0; i < a.size(); ++i)
            if (!sameTypes(a[i], b[i]))
                return false;
    return true;
}
} // namespace

// What the HTML renderer is given is what it was given before: the report dumped and parsed into
// nlohmann::json (non-finite doubles null, nonnegative integers unsigned, keys sorted).
TEST_CASE("the HTML renderer's input is the report's dump, parsed", "[campaign][html]")
{
    Json r = run(smallConfig(1)).report;
    r["z"] = Json::object({{"nan", NAN},
                           {"inf", -INFINITY},
                           {"neg", -3},
                           {"pos", 7},
                           {"big", std::uint64_t(1) << 63},
                           {"zero", -0.0},
                           {"null", nullptr},
                           {"list", Json::array({1.5, false, "text", Json::array()})}});
    const nlohmann::json expected = nlohmann::json::parse(r.dump());
    const nlohmann::json got = forHtmlRenderer(r);
    CHECK(got == expected);
    CHECK(got.dump() == expected.dump());
    CHECK(sameTypes(got, expected));
    CHECK(got["z"]["nan"].is_null());
    CHECK(got["z"]["pos"].is_number_unsigned());
}

TEST_CASE("the report does not depend on the number of threads", "[campaign]")
{
    const Run one = run(smallConfig(1));
    const Run two = run(smallConfig(2));
    const Run three = run(smallConfig(3));
    CHECK(stripVolatile(one.report) == stripVolatile(two.report));
    CHECK(stripVolatile(one.report) == stripVolatile(three.report));
    CHECK(one.perCaseLines == two.perCaseLines);
    CHECK(caseFileText({}, one.worstCases) == caseFileText({}, two.worstCases));
}

TEST_CASE("the report does not depend on the chunk size nor the thread count", "[campaign]")
{
    // Chunks of 1 case, of a prime number that cuts every family mid-way, of more than a family,
    // with 1 to 3 threads; with a case file holding rejected cases, and 2 worst cases per family so
    // that ties across chunk boundaries matter.
    auto config = [](std::size_t chunk, int threads)
    {
        CampaignConfig c = smallConfig(threads);
        c.families = {"random:150", "hard/touching-edge", "hard/points:40"};
        c.caseFiles = {std::string(VALIDATION_TEST_DATA) + "/bad-cases.json"};
        c.timing = false;
        c.worstPerFamily = 2;
        c.chunkCases = chunk;
        return c;
    };
    const Run reference = run(config(kDefaultChunkCases, 2));
    REQUIRE(reference.report["context"]["cases_rejected"] == 7);
    for (const auto& [chunk, threads] :
         std::vector<std::pair<std::size_t, int>>{{1, 1}, {7, 2}, {7, 3}, {64, 1}, {1000, 3}})
    {
        INFO("chunk " << chunk << ", threads " << threads);
        const Run r = run(config(chunk, threads));
        CHECK(stripVolatile(r.report) == stripVolatile(reference.report));
        CHECK(r.perCaseLines == reference.perCaseLines);
        CHECK(caseFileText({}, r.worstCases) == caseFileText({}, reference.worstCases));
        // The comments after the first (which gives the date) name each worst case's variant.
        CHECK(std::vector(r.worstComments.begin() + 1, r.worstComments.end()) ==
              std::vector(reference.worstComments.begin() + 1, reference.worstComments.end()));
    }
}

TEST_CASE("an error of the fold stops the run, on one thread and beside the evaluation",
          "[campaign]")
{
    // cases.jsonl's stream fails: the fold that writes to it throws, on the caller's thread with
    // one thread, on the fold's own thread (fold.cpp, ChunkFolder) with more, where the next
    // chunk's submission or the end of the run rethrows it. Chunks of 7 cases: many folds.
    for (int threads : {1, 2, 3})
    {
        INFO("threads " << threads);
        CampaignConfig c = smallConfig(threads);
        c.timing = false;
        c.chunkCases = 7;
        std::ostringstream lines;
        lines.setstate(std::ios::badbit);
        try
        {
            runCampaign(c, campaignInputs(c), &lines);
            FAIL("no OutputError");
        }
        catch (const OutputError& e)
        {
            CHECK(std::string(e.what()).find("cases.jsonl: write failed") == 0);
        }
    }
}

TEST_CASE("merging the shards of a campaign gives the one-process report", "[campaign][shard]")
{
    // Families cut mid-chunk, a case file with rejected cases, 2 worst cases per family (ties
    // across shards matter), shards given in any order and through their JSON text, as on disk.
    CampaignConfig c = smallConfig(2);
    c.families = {"random:150", "hard/touching-edge", "hard/points:40"};
    c.caseFiles = {std::string(VALIDATION_TEST_DATA) + "/bad-cases.json"};
    c.timing = false;
    c.worstPerFamily = 2;
    c.perCase = true;
    c.chunkCases = 7;
    const Run whole = run(c);
    REQUIRE(whole.report["context"]["cases_rejected"] == 7);
    std::string wholeLines;
    for (const auto& l : whole.perCaseLines)
        wholeLines += l + "\n";
    for (std::size_t n : {1u, 2u, 3u, 5u, 40u})
    {
        INFO(n << " shards");
        std::vector<Json> shards;
        std::vector<std::string> names;
        std::vector<std::stringstream> lines(n);
        for (std::size_t i = n; i-- > 0;) // the last shard first
        {
            shards.push_back(
                Json::parse(runShard(c, campaignInputs(c), Shard{i, n}, &lines[i]).dump()));
            names.push_back("shard " + std::to_string(i));
        }
        const Campaign merged = mergeShards(shards, names, c);
        CHECK(stripVolatile(merged.report) == stripVolatile(whole.report));
        CHECK(caseFileText({}, merged.worstCases) == caseFileText({}, whole.worstCases));
        CHECK(merged.exitCode == whole.exitCode);
        std::vector<std::istream*> inOrder;
        for (auto& l : lines)
            inOrder.push_back(&l);
        std::ostringstream joined;
        joinPerCase(merged.report, c.chunkCases, inOrder, joined);
        CHECK(joined.str() == wholeLines);
    }
}

TEST_CASE("an interrupted run resumes from its checkpoint to the uninterrupted report",
          "[campaign][checkpoint]")
{
    CampaignConfig c = smallConfig(2);
    c.families = {"random:150", "hard/touching-edge", "hard/points:40"};
    c.caseFiles = {std::string(VALIDATION_TEST_DATA) + "/bad-cases.json"};
    c.timing = false;
    c.perCase = false;
    c.worstPerFamily = 2;
    c.chunkCases = 9;
    const Run whole = run(c);
    c.checkpointDir = tmpDir("checkpoint");
    c.checkpointSeconds = 0;
    for (const char* stopAfter : {"1", "5", "19"}) // the first chunk, mid-family, the last input
    {
        INFO("stopped after " << stopAfter << " chunks");
        ::setenv("GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS", stopAfter, 1);
        CHECK_THROWS_WITH(run(c), Catch::Contains("test: stopped after"));
        ::unsetenv("GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS");
        CampaignConfig resumed = c;
        resumed.resume = true;
        const Run r = run(resumed);
        CHECK(stripVolatile(r.report) == stripVolatile(whole.report));
        CHECK(caseFileText({}, r.worstCases) == caseFileText({}, whole.worstCases));
    }
    // Another campaign's checkpoint is refused, naming what differs.
    ::setenv("GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS", "2", 1);
    CHECK_THROWS(run(c));
    ::unsetenv("GJK2D_VALIDATE_TEST_STOP_AFTER_CHUNKS");
    CampaignConfig other = c;
    other.resume = true;
    other.seed = 9;
    CHECK_THROWS_WITH(run(other),
                      Catch::Contains("the checkpoint is of another campaign: its seed is 1"));
    // An earlier version of the state: refused, naming the last revision that wrote (and reads) it.
    std::ofstream(c.checkpointDir + "/checkpoint.json") << R"({"schema": "gjk-checkpoint/1"})";
    CampaignConfig resumed = c;
    resumed.resume = true;
    CHECK_THROWS_WITH(run(resumed),
                      Catch::EndsWith("checkpoint.json: a gjk-checkpoint/1 file, written by gjk2d "
                                      "up to ff6aac0 (which reads it); this release writes "
                                      "gjk-checkpoint/3: run again without --resume"));
    std::ofstream(c.checkpointDir + "/checkpoint.json") << R"({"schema": "gjk-checkpoint/2"})";
    CHECK_THROWS_WITH(run(resumed),
                      Catch::EndsWith("checkpoint.json: a gjk-checkpoint/2 file, written by gjk2d "
                                      "up to ff7916d (which reads it); this release writes "
                                      "gjk-checkpoint/3: run again without --resume"));
}

TEST_CASE("merge refuses shards of different campaigns, a missing or a repeated shard",
          "[campaign][shard]")
{
    CampaignConfig c = smallConfig(2);
    c.families = {"random:30"};
    c.timing = false;
    c.perCase = false;
    const Json s0 = runShard(c, campaignInputs(c), Shard{0, 2});
    const Json s1 = runShard(c, campaignInputs(c), Shard{1, 2});
    CampaignConfig other = c;
    other.seed = 2;
    const Json s1Seed2 = runShard(other, campaignInputs(other), Shard{1, 2});
    auto refusal = [&](std::vector<Json> shards)
    {
        try
        {
            mergeShards(shards, {"a/shard.json", "b/shard.json"}, c);
        }
        catch (const InputError& e)
        {
            return std::string(e.what());
        }
        return std::string("merged");
    };
    CHECK(refusal({s0, s1}) == "merged");
    CHECK(refusal({s0, s1Seed2}) ==
          "b/shard.json: a shard of another campaign: its seed is 2, a/shard.json's is 1");
    CHECK(refusal({s0}) == "merge: shard 1/2 is missing");
    CHECK(refusal({s0, s0}) == "b/shard.json: shard 0/2 is given twice");
    CHECK(refusal({s0, Json{{"schema", "gjk-report/1"}}}) ==
          "b/shard.json: not a gjk-shard/3 file");
    // An earlier version of the state: refused, naming the last revision that wrote (and reads) it.
    CHECK(refusal({s0, Json{{"schema", "gjk-shard/1"}}}) ==
          "b/shard.json: a gjk-shard/1 file, written by gjk2d up to ff6aac0 (which reads it); this "
          "release writes gjk-shard/3: run the shards again with it");
    // Version 2 (before the contract verdict) likewise, naming its last writer.
    CHECK(refusal({s0, Json{{"schema", "gjk-shard/2"}}}) ==
          "b/shard.json: a gjk-shard/2 file, written by gjk2d up to ff7916d (which reads it); this "
          "release writes gjk-shard/3: run the shards again with it");
}

TEST_CASE("rejected cases are reported and the other cases still run", "[campaign]")
{
    CampaignConfig c = smallConfig(2);
    c.families = {};
    c.caseFiles = {std::string(VALIDATION_TEST_DATA) + "/bad-cases.json"};
    const Run camp = run(c);
    CHECK(camp.exitCode == kExitInput);
    const Json& r = camp.report;
    CHECK(r["passed"] == false);
    CHECK(r["context"]["cases_rejected"] == 7);
    REQUIRE(r["rejected"].size() == 7);
    CHECK(r["rejected"][0]["name"] == "bad-cases.json#1 (case 'nan')");
    CHECK(r["rejected"][0]["reason"] == "a.points[1][0] is NaN");
    const Json& f = r["families"][0];
    CHECK(f["name"] == "file:bad-cases.json");
    CHECK(f["cases"] == 9);
    CHECK(f["rejected"] == 7);
    CHECK(f["variants"]["double"]["cases"] == 2);
    CHECK(f["variants"]["double"]["failures"] == 0);
    const Json rejectedLine = Json::parse(camp.perCaseLines[1]);
    CHECK(rejectedLine["rejected"] == "a.points[1][0] is NaN");
}

// The message of the whole-file reader (readCaseFile) on `path`, or "" when it reads it.
std::string wholeReadMessage(const std::string& path)
{
    try
    {
        readCaseFile(path);
        return "";
    }
    catch (const InputError& e)
    {
        return e.what();
    }
}

TEST_CASE("a case file is read once: refused up front when cut short, else where its fault is met",
          "[campaign][files]")
{
    const std::string dir = tmpDir("read-once");
    std::filesystem::create_directories(dir);
    const std::vector<Case> cases = collectInputs({"random:30"}, {}, 7)[0].cases;
    const std::string text = caseFileText({"thirty random cases"}, cases);
    const auto file = [&](const std::string& name, const std::string& body)
    {
        std::ofstream(dir + "/" + name, std::ios::binary) << body;
        return dir + "/" + name;
    };
    CampaignConfig c = smallConfig(2);
    c.families = {};
    c.perCase = false;
    c.timing = false;

    // A good file: only its start is read up front; its count and comment are known at its end.
    c.caseFiles = {file("good.json", text)};
    std::vector<CampaignInput> in = campaignInputs(c);
    REQUIRE(in.size() == 1);
    CHECK_FALSE(in[0].counted);
    const Run good = run(c);
    CHECK(good.exitCode == kExitPass);
    CHECK(good.report["families"][0]["cases"] == 30);
    CHECK(good.report["context"]["inputs"][0]["count"] == 30);
    CHECK(good.report["context"]["cases_total"] == 30);
    // merge reads the whole file up front (it streams nothing).
    in = campaignInputs(c, FileCheck::Whole);
    CHECK(in[0].counted);
    CHECK(in[0].count == 30);
    CHECK(in[0].reason == "thirty random cases");

    // JSON broken after the 20th case: met as the file streams, with the whole reader's message.
    std::string broken = text;
    std::size_t at = 0;
    for (int line = 0; line < 22; ++line) // the header's two lines, then 20 cases
        at = broken.find('\n', at) + 1;
    broken.insert(at, "@");
    c.caseFiles = {file("broken.json", broken)};
    const std::string brokenMessage = wholeReadMessage(c.caseFiles[0]);
    REQUIRE_THAT(brokenMessage, Catch::Contains("broken.json:23:"));
    in = campaignInputs(c); // its start is a case file's
    CHECK_FALSE(in[0].counted);
    CHECK_THROWS_WITH(run(c), brokenMessage);

    // Cut short: refused up front, before any work, with the same message.
    c.caseFiles = {file("short.json", text.substr(0, text.size() / 2))};
    const std::string shortMessage = wholeReadMessage(c.caseFiles[0]);
    REQUIRE_FALSE(shortMessage.empty());
    CHECK_THROWS_WITH(campaignInputs(c), shortMessage);

    // Not a case file at its start: refused up front.
    c.caseFiles = {file("other.json", "{\"format\": \"gjk-cases/0\", \"cases\": [" +
                                          text.substr(text.find("{\"name\"")))};
    const std::string otherMessage = wholeReadMessage(c.caseFiles[0]);
    REQUIRE_THAT(otherMessage, Catch::Contains("not a gjk-cases/1 file"));
    in = campaignInputs(c); // "format" is checked at the end of the file
    CHECK_THROWS_WITH(run(c), otherMessage);
}

TEST_CASE("failures beyond the bound give exit code 1", "[campaign]")
{
    // The regression file: the naive closest-point direction misses by ~1e-9 on near-parallel
    // edges, far beyond the bound. As a judged variant (made here: the table's is a comparison
    // variant) it fails the campaign.
    static const VariantInfo judgedClosestPoint{
        "judged-closest-point", Scalar::Double,
        gjk::Options{.direction = gjk::SearchDirection::ClosestPoint}, "test", true};
    CampaignConfig c = smallConfig(2);
    c.families = {};
    c.caseFiles = {std::string(GJK2D_SOURCE_DIR) + "/validation/cases/regressions.json"};
    c.variants = {findVariant("double"), &judgedClosestPoint};
    const Run camp = run(c);
    CHECK(camp.exitCode == kExitFail);
    CHECK(camp.report["passed"] == false);
    CHECK(camp.report["families"][0]["pass"] == false);
    const Json& s = camp.report["families"][0]["variants"];
    CHECK(s["double"]["failures"] == 0);
    CHECK(s["judged-closest-point"]["failures"].get<int>() >= 1);
    CHECK(s["judged-closest-point"]["beyond_bound"].get<int>() >= 1);
    CHECK(s["judged-closest-point"]["failure_rate_upper95"].is_null());
}

TEST_CASE("comparison variants' failures are counted and shown, not judged", "[campaign]")
{
    CampaignConfig c = smallConfig(2);
    c.families = {};
    c.caseFiles = {std::string(GJK2D_SOURCE_DIR) + "/validation/cases/regressions.json"};
    c.variants = parseVariants("double,double-closest-point");
    const Run camp = run(c);
    CHECK(camp.exitCode == kExitPass);
    const Json& r = camp.report;
    CHECK(r["passed"] == true);
    CHECK(r["families"][0]["pass"] == true);
    CHECK(r["variants"][0]["judged"] == true);
    CHECK(r["variants"][1]["judged"] == false);
    const Json& s = r["families"][0]["variants"];
    CHECK(s["double-closest-point"]["failures"].get<int>() >= 1);
    CHECK(s["double-closest-point"]["pass"] == false);
    // gjk2d's own contract: its violations are exactly its failures, each with a reason, and the
    // worst names a case of the family (issue 49).
    for (const char* name : {"double", "double-closest-point"})
    {
        INFO(name);
        const Json& cv = s[name]["contract_violations"];
        CHECK(cv["count"] == s[name]["failures"]);
        std::uint64_t reasons = 0;
        for (const auto& [reason, n] : cv["reasons"].items())
            reasons += n.get<std::uint64_t>();
        CHECK(reasons == cv["count"].get<std::uint64_t>());
        CHECK(s[name]["beyond_bound_keeping_contract"] == 0);
        CHECK(r["variants"][name == std::string("double") ? 0 : 1]["contract"]["own"] == true);
    }
    const Json& worst = r["variants"][1]["worst_contract_violation"];
    REQUIRE(worst.is_object());
    CHECK(worst["family"] == r["families"][0]["name"]);
    CHECK(worst["case"] == s["double-closest-point"]["contract_violations"]["worst"]["case"]);
    CHECK(r["variants"][0]["worst_contract_violation"].is_null());
    const std::string md = renderMarkdown(r);
    CHECK_THAT(md, Catch::Contains("(not judged)") && Catch::Contains("| comparison |"));
    // The terminal: the comparison variant's verdict on its line; its families only with --verbose.
    CHECK_THAT(terminalSummary(r),
               Catch::Contains("fails\n") && !Catch::Contains("fails (not judged)"));
    CHECK_THAT(terminalSummary(r, true), Catch::Contains("fails (not judged)"));
}

namespace
{
std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);)
        lines.push_back(l);
    return lines;
}

// The lines of `lines` whose first word is `word`.
std::size_t startingWith(const std::vector<std::string>& lines, const std::string& word)
{
    return std::count_if(lines.begin(), lines.end(),
                         [&](const std::string& l) { return l.rfind(word + " ", 0) == 0; });
}
} // namespace

TEST_CASE("the terminal summary reads like the report page's first screen", "[campaign][report]")
{
    // Issue 50: the verdict first, then a line per variant; per family only what failed the run (a
    // judged variant's failures), every family x variant that failed with --verbose.
    static const VariantInfo judgedClosestPoint{
        "judged-closest-point", Scalar::Double,
        gjk::Options{.direction = gjk::SearchDirection::ClosestPoint}, "test", true};
    CampaignConfig c = smallConfig(2);
    c.families = {"hard/near-parallel"};
    c.caseFiles = {std::string(GJK2D_SOURCE_DIR) + "/validation/cases/regressions.json"};
    c.variants = {findVariant("double"), findVariant("double-closest-point"), &judgedClosestPoint};
    const Run camp = run(c);
    REQUIRE(camp.exitCode == kExitFail);
    const Json& r = camp.report;
    const auto lines = linesOf(terminalSummary(r));
    REQUIRE(lines.size() > 2);
    CHECK(lines[0] == "result: " + resultText(r));
    CHECK_THAT(lines[0], Catch::StartsWith("result: FAIL (exit code 1): "));
    CHECK_THAT(lines[1], Catch::StartsWith("ran ") && Catch::Contains("2 families") &&
                             Catch::Contains("3 variants: 2 judged, 1 comparison"));
    for (const char* name : {"double", "double-closest-point", "judged-closest-point"})
    {
        INFO(name);
        CHECK(startingWith(lines, name) == 1); // its line of the variant table
    }
    for (const auto& l : lines)
        if (startingWith({l}, "double") || startingWith({l}, "double-closest-point") ||
            startingWith({l}, "judged-closest-point"))
            CHECK(l.size() <= 100);
    // Per family: the judged variant's failures, never the comparison variant's.
    std::size_t judgedRows = 0, failingFamilies = 0;
    for (const auto& l : lines)
    {
        CHECK_FALSE((l.rfind("  ", 0) == 0 && l.find("double-closest-point") != std::string::npos));
        judgedRows += l.rfind("  ", 0) == 0 && l.find("judged-closest-point") != std::string::npos;
    }
    for (const auto& f : r["families"])
        failingFamilies += f["variants"]["judged-closest-point"]["failures"].get<int>() > 0;
    CHECK(failingFamilies >= 1);
    CHECK(judgedRows == failingFamilies);
    // --verbose: every family x variant, and the comparison variant's failing families too.
    const auto verbose = linesOf(terminalSummary(r, true));
    CHECK(verbose[0] == lines[0]);
    std::size_t comparisonRows = 0;
    for (const auto& l : verbose)
        comparisonRows += l.rfind("  ", 0) == 0 &&
                          l.find("double-closest-point") != std::string::npos &&
                          l.find("fails (not judged)") != std::string::npos;
    CHECK(comparisonRows >= 1);
    CHECK(verbose.size() > lines.size() + 3 * r["families"].size());
}

TEST_CASE("what a variant's ns/query includes, in report.md and on the terminal",
          "[campaign][report]")
{
    // variants[].timing and prepare_ns_per_shape. gjk2d's own variants with a prepared form give
    // two figures, the plain query's and the same queries' on prepared shapes, and the preparation
    // per shape; one without it says why, in a row per reason; a variant that prepares its shapes
    // has its preparation figure, the families' weighted by their cases; an adapter's own timing
    // and a figure with shape set-up are marked.
    CampaignConfig c = smallConfig(2);
    c.families = {"random:200", "hard/talk-segment"};
    c.variants = parseVariants("double,float,double-closest-point");
    Json r = run(c).report;
    for (const auto& f : r["families"])
        for (const char* name : {"double", "float"})
        {
            INFO(f["name"] << " " << name);
            const Json& st = f["variants"][name];
            CHECK(st["ns_per_query"].get<double>() > 0);
            CHECK(st["prepared_ns_per_query"].get<double>() > 0);
            CHECK(st["prepare_ns_per_shape"].get<double>() > 0);
        }
    for (const auto& f : r["families"])
    {
        const Json& st = f["variants"]["double-closest-point"];
        CHECK(st["ns_per_query"].get<double>() > 0);
        CHECK(st["prepared_ns_per_query"].is_null());
        CHECK(st["prepare_ns_per_shape"].is_null());
    }
    CHECK(r["variants"][0]["timing"]["prepared"]["timed"] == true);
    CHECK(r["variants"][2]["timing"]["prepared"]["timed"] == false);
    {
        const std::string md = renderMarkdown(r);
        CHECK_THAT(md, !Catch::Contains("no preparation: the plain query takes the points"));
        std::size_t rows = 0; // in the timing table (the families' tables have rows per variant)
        const std::size_t at = md.find("\n### Timing\n");
        REQUIRE(at != std::string::npos);
        for (const auto& l : linesOf(md.substr(at, md.find("\n#", at + 1) - at)))
            if (l.rfind("| double | ", 0) == 0 || l.rfind("| float | ", 0) == 0)
            {
                ++rows;
                CHECK_THAT(l,
                           Catch::Matches("\\| [a-z]+ \\| plain: [0-9.]+ ns/query, the points as "
                                          "given; prepared: [0-9.]+ ns/query, the same queries "
                                          "on shapes prepared once by gjk::prepare [^|]* \\| "
                                          "[0-9.]+ \\|"));
            }
        CHECK(rows == 2);
        CHECK_THAT(md, Catch::Contains("| gjk2d's own (1 variant: double-closest-point) | the "
                                       "plain query, the points as given; no prepared form: with "
                                       "these options the query on prepared shapes runs the plain "
                                       "query | - |"));
    }
    // Made a prepared peer timed by its adapter (the names of a real one are tested with the
    // plugins): 100 ns/shape on 200 cases and 400 on 16 weigh to (100 * 200 + 400 * 16) / 216.
    Json& v = r["variants"][2];
    v["plugin"] = {{"path", "/x.so"}};
    v["timing"] = {
        {"preparation", "shape"}, {"includes", "the query alone"}, {"timed_by", "adapter"}};
    REQUIRE(r["families"].size() == 2);
    r["families"][0]["variants"]["double-closest-point"]["prepare_ns_per_shape"] = 100.0;
    r["families"][1]["variants"]["double-closest-point"]["prepare_ns_per_shape"] = 400.0;
    const double cases0 =
                     r["families"][0]["variants"]["double-closest-point"]["cases"].get<double>(),
                 cases1 =
                     r["families"][1]["variants"]["double-closest-point"]["cases"].get<double>();
    // double's figures made up as well, weighted alike: plain 60 and 90 ns/query, prepared 50 and
    // 80, 20 and 30 ns/shape. A report written before timing.prepared (float's removed): its old
    // words, in a row of their own.
    const double d0 = r["families"][0]["variants"]["double"]["cases"].get<double>(),
                 d1 = r["families"][1]["variants"]["double"]["cases"].get<double>();
    for (auto [key, x0, x1] :
         {std::tuple{"ns_per_query", 60.0, 90.0}, std::tuple{"prepared_ns_per_query", 50.0, 80.0},
          std::tuple{"prepare_ns_per_shape", 20.0, 30.0}})
    {
        r["families"][0]["variants"]["double"][key] = x0;
        r["families"][1]["variants"]["double"][key] = x1;
    }
    const auto weighed = [&](double x0, double x1) { return (x0 * d0 + x1 * d1) / (d0 + d1); };
    r["variants"][1]["timing"].erase("prepared");
    const std::string md = renderMarkdown(r);
    CHECK_THAT(md, Catch::Contains(fmt::format("| double | plain: {:.1f} ns/query, the points as "
                                               "given; prepared: {:.1f} ns/query, the same",
                                               weighed(60, 90), weighed(50, 80))));
    CHECK_THAT(md, Catch::Contains(fmt::format("per shape | {:.1f} |", weighed(20, 30))));
    CHECK_THAT(md, Catch::Contains("| gjk2d's own (1 variant: float) | no preparation: the plain "
                                   "query takes the points as given | - |"));
    CHECK_THAT(md, !Catch::Contains("double-closest-point) |"));
    CHECK_THAT(md, Catch::Contains(fmt::format(
                       "| double-closest-point | the query alone; timed by the adapter | {:.1f} |",
                       (100 * cases0 + 400 * cases1) / (cases0 + cases1))));
    v["timing"]["preparation"] = "in-call";
    for (const auto& l : linesOf(terminalSummary(r)))
        if (startingWith({l}, "double-closest-point"))
            CHECK_THAT(l, Catch::Matches(".* [0-9.]+a\\+  [a-z].*"));
        else if (startingWith({l}, "double"))
            CHECK_THAT(l, Catch::Matches(".* [0-9.]+ {4}pass"));
}

TEST_CASE("the talk's cases: float with the closest-point direction fails, the reference passes",
          "[campaign]")
{
    CampaignConfig c = smallConfig(1);
    c.families = {};
    c.caseFiles = {std::string(GJK2D_SOURCE_DIR) + "/validation/cases/talk.json"};
    c.variants = parseVariants("double,float,float-closest-point");
    const Run camp = run(c);
    const Json& s = camp.report["families"][0]["variants"];
    CHECK(s["double"]["failures"] == 0);
    CHECK(s["float"]["failures"] == 0);
    CHECK(s["float-closest-point"]["failures"].get<int>() >= 1);
}

TEST_CASE(
    "the reported cases: each names its report, the truth is the report's answer, gjk2d passes",
    "[campaign]")
{
    const std::string file = std::string(GJK2D_SOURCE_DIR) + "/validation/cases/reported.json";
    // The expected distance of each case as its report (or its maintainers) gave it, restated in
    // the case's comment; 0 for every "overlapping" or "colliding" one. The circle's by hand:
    // |(2.34812546, 40.4136238) - (2, 40)| - 0.5.
    const std::map<std::string, double> expected{
        {"fcl-508-box-box", 3},
        {"libccd-25-stacked-cubes", 0},
        {"opengjk-52-overlapping-prisms-far-from-origin", 0},
        {"opengjk-3-flat-quad-triangle", 0},
        {"cute-c2-160-large-integer-rectangles", 0},
        {"gjk-c-pr5-near-identical-triangles", 0},
        {"collision-rs-51-rectangle-with-itself", 0},
        {"shapely-628-triangle-square", 1},
        {"shapely-628-rectangle-inside", 0},
        {"box2d-883-concentric-squares", 0},
        {"jitter2-302-box-and-point", 0.5},
        {"cute-c2-404-aabb-poly-shared-edge-line", 0},
        {"cute-c2-252-circle-near-square-corner",
         std::hypot(2.34812546 - 2, 40.4136238 - 40) - 0.5},
        {"jsk-roseus-616-bullet-cubes-50", 99950},
        {"jsk-roseus-616-bullet-cubes-10", 99990},
    };
    const CaseFile f = readCaseFile(file);
    REQUIRE(f.entries.size() == expected.size());
    EvalContext ctx;
    ctx.variants = parseVariants("double");
    for (const auto& e : f.entries)
    {
        INFO(e.label);
        REQUIRE(e.rejected.empty());
        CHECK(e.c.source.rfind("https://github.com/", 0) == 0);
        CHECK(e.c.comment.find("Expected") != std::string::npos);
        REQUIRE(expected.count(e.c.name) == 1);
        const CaseOutcome o = evaluateCase(e.c, ctx);
        CHECK(o.exact.distance == within(expected.at(e.c.name), 1e-12));
    }
    CampaignConfig c = smallConfig(1);
    c.families = {};
    c.caseFiles = {file};
    c.variants = parseVariants("double,float");
    const Run camp = run(c);
    const Json& s = camp.report["families"][0]["variants"];
    CHECK(s["double"]["failures"] == 0);
    CHECK(s["float"]["failures"] == 0);
}

TEST_CASE("case detail: trace and Minkowski difference in world coordinates", "[campaign]")
{
    Case c;
    c.name = "detail";
    c.a.points = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    c.a.c = std::cos(0.7);
    c.a.s = std::sin(0.7);
    c.a.px = 10;
    c.a.py = -3;
    c.b.points = {{0, 0}, {1, 0}, {0, 1}};
    c.b.px = 12.5; // 1.56 apart, an edge of A closest: the double trace is a vertex, then an edge
    c.b.py = -2;
    EvalContext ctx;
    ctx.variants = parseVariants("double,float");
    const CaseOutcome o = evaluateCase(c, ctx);
    REQUIRE(o.rejected.empty());
    const Json d = caseDetail(c, "test", ctx, o, "normalized");
    const auto wa = worldPoints(c.a), wb = worldPoints(c.b);
    int vertices = 0;
    for (const auto& step : d["variants"]["double"]["trace"])
        for (const auto& v : step["simplex"])
        {
            ++vertices;
            const auto& pa = wa[v["iA"].get<std::size_t>()];
            const auto& pb = wb[v["iB"].get<std::size_t>()];
            CHECK(v["wA"][0].get<double>() == within(pa[0], 1e-12));
            CHECK(v["wA"][1].get<double>() == within(pa[1], 1e-12));
            CHECK(v["wB"][0].get<double>() == within(pb[0], 1e-12));
            CHECK(v["w"][0].get<double>() == within(pa[0] - pb[0], 1e-12));
            CHECK(v["w"][1].get<double>() == within(pa[1] - pb[1], 1e-12));
        }
    CHECK(vertices == 3); // steps of 1 and 2 vertices
    // Minkowski difference A - B: counter-clockwise, positive area, 4 + 3 edges at most.
    const Json& mk = d["minkowski"];
    REQUIRE(mk.size() >= 3);
    CHECK(mk.size() <= 7);
    double area = 0;
    for (std::size_t i = 0; i < mk.size(); ++i)
    {
        const Json& p = mk[i];
        const Json& q = mk[(i + 1) % mk.size()];
        area += p[0].get<double>() * q[1].get<double>() - p[1].get<double>() * q[0].get<double>();
    }
    CHECK(area > 0);
    CHECK(d["exact"]["distance"].get<double>() > 0);
    CHECK(d["variants"]["double"]["errors"]["abs"].get<double>() <=
          d["variants"]["double"]["bound"].get<double>());
    CHECK(d.contains("exact_float_input"));
    // The text of `explain` mentions every variant and the exact result.
    const std::string text = explainText(d);
    CHECK_THAT(text, Catch::Contains("variant double") && Catch::Contains("variant float") &&
                         Catch::Contains("exact: distance"));
    // No provenance given: none shown.
    CHECK_FALSE(d.contains("source"));
    CHECK_FALSE(d.contains("comment"));
    CHECK_THAT(text, !Catch::Contains("source:"));
    // A case file's source and comment go into the detail and the text (a control character
    // quoted as excerpt() does).
    c.source = "https://example.org/issues/7";
    c.comment = "reported 3.16,\nexpected 3";
    const Json dp = caseDetail(c, "file:reported.json", ctx, o, "explain");
    CHECK(dp["source"] == "https://example.org/issues/7");
    CHECK(dp["comment"] == "reported 3.16,\nexpected 3");
    CHECK_THAT(explainText(dp), Catch::Contains("  source: https://example.org/issues/7\n") &&
                                    Catch::Contains("  comment: reported 3.16,\\x0Aexpected 3\n"));
}

TEST_CASE("metrics: ulps, the bound, misclassification", "[campaign]")
{
    CHECK(ulpOf(Scalar::Double, 1.0) == std::ldexp(1.0, -52));
    CHECK(ulpOf(Scalar::Double, 1.5) == std::ldexp(1.0, -52));
    CHECK(ulpOf(Scalar::Double, 0.75) == std::ldexp(1.0, -53));
    CHECK(ulpOf(Scalar::Float, 1.0) == std::ldexp(1.0, -23));
    CHECK(ulpOf(Scalar::Double, 4.9e-324) == 4.9e-324);
    CHECK(ulpOf(Scalar::Float, 1e-45) == std::ldexp(1.0, -149));
    // The bound (bounds.cpp, docs/error-bound.md) is positive and proportional to u.
    CaseMetrics m;
    m.R = 3;
    m.maxA = m.maxB = m.maxBMapped = m.translation = 1;
    m.maxW = 2;
    m.exactDistance = 0.5;
    m.unitRoundoff = unitRoundoff(Scalar::Float);
    const double bf = errorBound(*findVariant("float"), m);
    m.unitRoundoff = unitRoundoff(Scalar::Double);
    const double bd = errorBound(*findVariant("double"), m);
    CHECK(bf > 0);
    CHECK(bf / bd == std::ldexp(1.0, 29)); // u_float / u_double; every other factor the same

    // Exact touching: double GJK may answer a tiny positive distance; within the bound it is
    // "undecidable", never a failure.
    Case c;
    c.name = "touch";
    c.a.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    c.b.points = {{1, 0.5}, {2, 0}, {2, 1}};
    EvalContext ctx;
    ctx.variants = parseVariants("double");
    const CaseOutcome o = evaluateCase(c, ctx);
    CHECK(o.exact.distance == 0);
    CHECK_FALSE(o.variants[0].failed);
    CHECK((o.variants[0].mis == Misclass::None || o.variants[0].mis == Misclass::Undecidable));
}

TEST_CASE("a broken invariant of the truth fails the run, and only invalid input rejects a case",
          "[campaign][errors]")
{
    // Regression (hostile-input hardening: a broken invariant of the truth rejected cases):
    // computeTruth caught every std::exception of the exact side as a rejected case (exit 2, "bad
    // input"), and swallowed any exception of the float-input truth, skipping the float variants
    // without a word. A validation tool that reports a bug in its truth as bad input cannot be
    // trusted: only std::invalid_argument is a rejection.
    Case c;
    c.name = "two points";
    c.a.points = {{0, 0}};
    c.b.points = {{1, 0}};
    EvalContext ctx;
    ctx.variants = parseVariants("double,float");

    SECTION("invalid input: the case is rejected")
    {
        ctx.truth = [](const exact::PreparedShape&, const exact::PreparedShape&,
                       const exact::Options&) -> exact::Result
        { throw std::invalid_argument("exact: shape A has no points"); };
        CaseOutcome o;
        computeTruth(c, ctx, o);
        CHECK(o.rejected == "exact: exact: shape A has no points");
    }
    SECTION("a broken invariant of the truth propagates")
    {
        ctx.truth = [](const exact::PreparedShape&, const exact::PreparedShape&,
                       const exact::Options&) -> exact::Result
        { throw std::logic_error("exact: rounding did not converge"); };
        CaseOutcome o;
        CHECK_THROWS_AS(computeTruth(c, ctx, o), std::logic_error);
        CHECK(o.rejected.empty());
    }
    SECTION("a broken invariant of the float-input truth propagates too")
    {
        static int calls;
        calls = 0;
        ctx.truth = [](const exact::PreparedShape& a, const exact::PreparedShape& b,
                       const exact::Options& opt)
        {
            if (++calls == 2) // the second call is the float-rounded input's truth
                throw std::logic_error("exact: rounding did not converge");
            return exact::distance(a, b, opt);
        };
        CaseOutcome o;
        CHECK_THROWS_AS(computeTruth(c, ctx, o), std::logic_error);
        CHECK(calls == 2);
    }
}

TEST_CASE("penetration: report.json's block, the terminal's line, report.md and explain",
          "[campaign][penetration]")
{
    // A small campaign with double and double-signed (gjk2d's own contract, overlap answered by
    // penetration): only double-signed has the penetration block; random:200 overlaps in 20 % to
    // 80 % of its cases (its make-up), so its block judges some; the terminal gives the variant a
    // penetration line, verdict first; report.md a Penetration list.
    CampaignConfig c = smallConfig(2);
    c.families = {"random:200"};
    c.variants = parseVariants("double,double-signed");
    c.timing = false;
    const Campaign camp = runCampaign(c, campaignInputs(c));
    const Json& r = camp.report;
    const Json& f = r["families"][0]["variants"];
    CHECK_FALSE(f["double"].contains("penetration"));
    REQUIRE(f["double-signed"].contains("penetration"));
    const Json& p = f["double-signed"]["penetration"];
    CHECK(p["cases"].get<std::uint64_t>() >= 40);
    CHECK(p["contract_violations"] == 0);
    CHECK(p["bound_ratio"]["count"] == p["cases"]);
    CHECK(r["variants"][1]["contract"]["overlap"] == "penetration");
    CHECK(r["variants"][1].contains("depth_bound"));
    CHECK_FALSE(r["variants"][0].contains("depth_bound"));
    CHECK(camp.exitCode == kExitPass);
    const std::string summary = terminalSummary(r);
    CHECK_THAT(summary,
               Catch::Contains(fmt::format("\n    penetration: pass: {} overlapping, 0 broke, 0 "
                                           "outside, worst {:.3g}\n",
                                           p["cases"].get<std::uint64_t>(),
                                           p["bound_ratio"]["max"].get<double>())));
    CHECK_THAT(renderMarkdown(r), Catch::Contains("### Penetration") &&
                                      Catch::Contains("- **double-signed**: penetration: pass"));
}

TEST_CASE("explain: an overlapping case's exact depth, each penetration answer's depth and error",
          "[campaign][penetration]")
{
    // A hand-made CaseDetail: unit squares A = [0, 1]^2 and B = [0.75, 1.75] x [0, 1] overlap by
    // 0.25 (exact signed distance -0.25, pair (1, 0.5) and (0.75, 0.5)); the variant answered
    // -0.1875 with (1, 0.5) and (0.8125, 0.5): 0.0625 off (relative 0.25), over a depth bound of
    // 1e-15 (ratio 6.25e13). Every number is exact in binary, so the text shows it whole.
    const Json shape = {{"points", Json::array()},
                        {"radius", 0},
                        {"transform", {{"p", {0, 0}}, {"q", {1, 0}}}},
                        {"world", Json::array()}};
    Json d = {{"name", "hand/overlap"}, {"family", "hand"}, {"a", shape}, {"b", shape}};
    d["exact"] = {{"distance", 0},
                  {"squared", "0/1"},
                  {"overlap", true},
                  {"witnessA", {0.875, 0.5}},
                  {"witnessB", {0.875, 0.5}},
                  {"lower", 0},
                  {"upper", 0},
                  {"signed_distance", -0.25},
                  {"signed_lower", -0.25},
                  {"signed_upper", -0.25},
                  {"penetrationA", {1, 0.5}},
                  {"penetrationB", {0.75, 0.5}}};
    Json v = {{"type", "double"},
              {"distance", -0.1875},
              {"pointA", {1, 0.5}},
              {"pointB", {0.8125, 0.5}},
              {"normal", {1, 0}},
              {"iterations", 3},
              {"stop", "repeated-support"},
              {"bound", 1e-15},
              {"witness_bound", 1e-15},
              {"errors",
               {{"abs", 0},
                {"rel", nullptr},
                {"ulps", nullptr},
                {"normalized", 0},
                {"bound_ratio", 0},
                {"witness", 0},
                {"witness_gap", 0},
                {"witness_ratio", 0}}},
              {"misclassified", nullptr},
              {"invalid", nullptr},
              {"failed", true}};
    v["penetration"] = {{"exact", -0.25},     {"distance", -0.1875}, {"abs", 0.0625},
                        {"rel", 0.25},        {"bound", 1e-15},      {"bound_ratio", 6.25e13},
                        {"tolerance", 1e-15}, {"beyond_bound", true}};
    d["variants"] = {{"double-signed", v}};
    const std::string text = explainText(d);
    CHECK_THAT(text, Catch::Contains("signed distance -0.25 in [-0.25, -0.25]: the shapes overlap, "
                                     "exact depth 0.25") &&
                         Catch::Contains("penetration pair A (1, 0.5) B (0.75, 0.5)") &&
                         Catch::Contains("penetration: exact depth 0.25, its depth 0.1875: error "
                                         "0.0625 (relative 0.25), gjk2d's depth bound 1e-15 "
                                         "(ratio 6.25e+13)") &&
                         Catch::Contains("** beyond gjk2d's depth bound **"));
    // Without a signed answer (0 on overlap): "none".
    d["variants"]["double-signed"]["penetration"]["distance"] = 0;
    CHECK_THAT(explainText(d), Catch::Contains("its depth none (distance 0)"));
}
