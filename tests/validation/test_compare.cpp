// gjk-validate compare (docs/cli.md, "`compare`: gate a change on two reports"): the
// comparison of two reports (compareReports) on a real report and copies of it with planted
// changes, and the program's exit codes and messages. The real report comes from one small
// campaign per test process: `gjk-validate run --family random:300 --family hard/near-parallel
// --no-timing` (about a second in release).
#include "cli_support.hpp"
#include "common/common.hpp"
#include "report/compare.hpp"

#include "gjk_html/html.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace gjkval;
namespace fs = std::filesystem;

namespace
{
using Run = CliRun;

// This test process's scratch directory (CTest runs test cases in parallel processes).
fs::path scratch()
{
    const fs::path d = fs::path(VALIDATION_TEST_TMP) / ("compare-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

Run runCli(const std::vector<std::string>& args)
{
    return runGjkValidate(args);
}

// The real report's directory, made once per process.
const fs::path& smallReportDir()
{
    static const fs::path dir = []
    {
        const fs::path d = scratch() / "small";
        const Run r = runCli({"run", "--family", "random:300", "--family", "hard/near-parallel",
                              "--no-timing", "--no-progress", "--out", d.string()});
        INFO("stderr: " << r.err);
        REQUIRE(r.code == kExitPass);
        return d;
    }();
    return dir;
}

const Json& smallReport()
{
    static const Json report = readReport(smallReportDir().string());
    return report;
}

Json& stats(Json& report, const std::string& family, const std::string& variant)
{
    for (auto& f : report["families"])
        if (f["name"] == family)
            return f["variants"][variant];
    FAIL("no family " << family);
    throw;
}

Json& familyOf(Json& report, const std::string& family)
{
    for (auto& f : report["families"])
        if (f["name"] == family)
            return f;
    FAIL("no family " << family);
    throw;
}

std::vector<const CompareRow*> failing(const Comparison& c)
{
    std::vector<const CompareRow*> v;
    for (const auto& r : c.rows)
        if (r.fails())
            v.push_back(&r);
    return v;
}

const CompareRow* findRow(const Comparison& c, const std::string& family,
                          const std::string& variant, const std::string& statistic)
{
    for (const auto& r : c.rows)
        if (r.family == family && r.variant == variant && r.statistic == statistic)
            return &r;
    return nullptr;
}

bool contains(const std::string& s, const std::string& part)
{
    return s.find(part) != std::string::npos;
}

fs::path writeReport(const Json& report, const std::string& name)
{
    const fs::path p = scratch() / name;
    std::ofstream(p) << report.dump();
    return p;
}
} // namespace

TEST_CASE("compare: a report against itself: every statistic the same, exit 0", "[compare]")
{
    const Comparison c = compareReports(smallReport(), smallReport());
    CHECK(c.exitCode == kExitPass);
    CHECK(c.failing() == 0);
    CHECK(c.count(Change::Same) == c.rows.size());
    // Every family x variant is compared: 2 families x 15 variants x (9 counts + 7 or 8 error
    // histograms x 4 + 2 iterations) and more.
    CHECK(c.rows.size() > 2 * 15 * 40);
    for (const char* statistic : {"errors.abs.max", "errors.abs.p99", "errors.abs.p999",
                                  "errors.abs.mean", "errors.bound_ratio.max", "failures",
                                  "false_overlap", "iterations.max", "iterations.mean"})
        CHECK(findRow(c, "random", "double", statistic) != nullptr);
    CHECK(findRow(c, "random", "double-certified", "interval.misses") != nullptr);
    CHECK(findRow(c, "hard/near-parallel", "", "makeup_ok") != nullptr);
    CHECK(findRow(c, "", "", "exit_code") != nullptr);
    CHECK(findRow(c, "random", "double", "ns_per_query") == nullptr); // timing only on request
    CHECK(contains(compareText(c), "result: NO REGRESSION (exit code 0)"));
}

TEST_CASE("compare: a planted error regression of a judged variant fails, naming it", "[compare]")
{
    Json worse = smallReport();
    Json& abs = stats(worse, "random", "double")["errors"]["abs"];
    const double max = abs["max"].get<double>();
    REQUIRE(max > 0);
    CompareOptions o;
    SECTION("beyond --rel-tol: regressed")
    {
        abs["max"] = max * 1.5;
        const Comparison c = compareReports(smallReport(), worse, o);
        CHECK(c.exitCode == kExitFail);
        const auto f = failing(c);
        REQUIRE(f.size() == 1);
        CHECK(f[0]->family == "random");
        CHECK(f[0]->variant == "double");
        CHECK(f[0]->statistic == "errors.abs.max");
        CHECK(f[0]->limit == Approx(max * 1.1).epsilon(1e-12));
        const std::string text = compareText(c);
        CHECK(contains(text, "errors.abs.max"));
        CHECK(contains(text, "REGRESSED"));
        CHECK(contains(text, "result: REGRESSION (exit code 1)"));
        CHECK(contains(compareMarkdown(c), "| random | double | errors.abs.max |"));
        const Json j = compareJson(c);
        CHECK(j["exit_code"] == 1);
        CHECK(j["rows"][0]["statistic"] == "errors.abs.max");
        CHECK(j["rows"][0]["fails"] == true);
        // A larger --rel-tol lets the same change pass, listed as worse.
        o.relTol = 0.6;
        const Comparison loose = compareReports(smallReport(), worse, o);
        CHECK(loose.exitCode == kExitPass);
        CHECK(findRow(loose, "random", "double", "errors.abs.max")->change == Change::Worse);
    }
    SECTION("within --rel-tol: worse, passes")
    {
        abs["max"] = max * 1.05;
        const Comparison c = compareReports(smallReport(), worse, o);
        CHECK(c.exitCode == kExitPass);
        CHECK(findRow(c, "random", "double", "errors.abs.max")->change == Change::Worse);
        CHECK(c.count(Change::Worse) == 1);
    }
}

// The percentiles are upper bin edges, 10 bins per decade: one bin up (x 10^0.1) passes the
// default --percentile-tol 0.3, two bins up (x 10^0.2 = 1.58) fail.
TEST_CASE("compare: a percentile one bin up passes, two bins up regresses", "[compare]")
{
    Json worse = smallReport();
    Json& ulps = stats(worse, "hard/near-parallel", "float")["errors"]["ulps"];
    const double p99 = ulps["p99"].get<double>();
    REQUIRE(p99 > 0);
    ulps["p99"] = p99 * std::pow(10.0, 0.1);
    const Comparison one = compareReports(smallReport(), worse);
    CHECK(one.exitCode == kExitPass);
    CHECK(findRow(one, "hard/near-parallel", "float", "errors.ulps.p99")->change == Change::Worse);
    ulps["p99"] = p99 * std::pow(10.0, 0.2);
    const Comparison two = compareReports(smallReport(), worse);
    CHECK(two.exitCode == kExitFail);
    REQUIRE(failing(two).size() == 1);
    CHECK(failing(two)[0]->statistic == "errors.ulps.p99");
}

TEST_CASE("compare: one planted failure fails, any count increase does", "[compare]")
{
    Json worse = smallReport();
    Json& s = stats(worse, "hard/near-parallel", "float");
    s["failures"] = s["failures"].get<int>() + 1;
    const Comparison c = compareReports(smallReport(), worse);
    CHECK(c.exitCode == kExitFail);
    const auto f = failing(c);
    REQUIRE(f.size() == 1);
    CHECK(f[0]->family == "hard/near-parallel");
    CHECK(f[0]->variant == "float");
    CHECK(f[0]->statistic == "failures");
    CHECK(contains(compareText(c), "hard/near-parallel"));

    // A family's make-up check and the exit code, flipped.
    Json flipped = smallReport();
    familyOf(flipped, "random")["makeup_ok"] = false;
    familyOf(flipped, "random")["makeup"][0]["ok"] = false;
    flipped["exit_code"] = 1;
    const Comparison m = compareReports(smallReport(), flipped);
    CHECK(m.exitCode == kExitFail);
    CHECK(findRow(m, "random", "", "makeup_ok")->fails());
    const std::string check = smallReport()["families"][0]["makeup"][0]["check"];
    CHECK(findRow(m, "random", "", "makeup: " + check)->fails());
    CHECK(findRow(m, "", "", "exit_code")->fails());
}

TEST_CASE("compare: improvements are listed as better and never fail", "[compare]")
{
    Json worse = smallReport();
    Json& s = stats(worse, "random", "double");
    s["errors"]["abs"]["max"] = s["errors"]["abs"]["max"].get<double>() * 4;
    s["nonfinite"] = 3;
    // OLD the worse one: NEW improved.
    const Comparison c = compareReports(worse, smallReport());
    CHECK(c.exitCode == kExitPass);
    CHECK(c.failing() == 0);
    CHECK(c.count(Change::Better) == 2);
    CHECK(findRow(c, "random", "double", "errors.abs.max")->change == Change::Better);
    CHECK(findRow(c, "random", "double", "nonfinite")->change == Change::Better);
    CHECK(contains(compareText(c), "better"));
}

TEST_CASE("compare: comparison variants are reported, gate only with --all-variants", "[compare]")
{
    Json worse = smallReport();
    Json& s = stats(worse, "random", "double-closest-point");
    s["false_separation"] = s["false_separation"].get<int>() + 5;
    CompareOptions o;
    const Comparison c = compareReports(smallReport(), worse, o);
    const CompareRow* row = findRow(c, "random", "double-closest-point", "false_separation");
    REQUIRE(row != nullptr);
    CHECK_FALSE(row->judged);
    CHECK(row->change == Change::Regressed);
    CHECK_FALSE(row->fails());
    CHECK(c.exitCode == kExitPass);
    CHECK(contains(compareText(c), "not gated"));
    o.allVariants = true;
    CHECK(compareReports(smallReport(), worse, o).exitCode == kExitFail);
}

TEST_CASE("compare: timing only with --timing, as a ratio with its own tolerance", "[compare]")
{
    Json a = smallReport(), b = smallReport();
    stats(a, "random", "double")["ns_per_query"] = 100.0;
    stats(b, "random", "double")["ns_per_query"] = 120.0;
    CompareOptions o;
    CHECK(compareReports(a, b, o).exitCode == kExitPass);
    o.timing = true;
    const Comparison within = compareReports(a, b, o);
    CHECK(within.exitCode == kExitPass);
    CHECK(findRow(within, "random", "double", "ns_per_query")->change == Change::Same);
    stats(b, "random", "double")["ns_per_query"] = 130.0;
    const Comparison slower = compareReports(a, b, o);
    CHECK(slower.exitCode == kExitFail);
    CHECK(findRow(slower, "random", "double", "ns_per_query")->fails());
    // --no-timing reports (null) are not compared, not failed.
    CHECK(compareReports(smallReport(), smallReport(), o).exitCode == kExitPass);
}

TEST_CASE("compare: different inputs are refused unless allowed", "[compare]")
{
    Json other = smallReport();
    familyOf(other, "random")["cases"] = 200;
    CompareOptions o;
    o.oldName = "OLD 'a'";
    o.newName = "NEW 'b'";
    try
    {
        compareReports(smallReport(), other, o);
        FAIL("different inputs were compared");
    }
    catch (const InputError& e)
    {
        const std::string what = e.what();
        CHECK(contains(what, "OLD 'a' and NEW 'b' ran different inputs"));
        CHECK(contains(what, "family 'random': cases 300 in OLD, 200 in NEW"));
        CHECK(contains(what, "--allow-different-inputs"));
        CHECK_FALSE(contains(what, "\n"));
    }
    o.allowDifferentInputs = true;
    const Comparison c = compareReports(smallReport(), other, o);
    CHECK(c.inputsDiffer);
    CHECK(c.exitCode == kExitPass);
    CHECK(findRow(c, "random", "", "inputs")->change == Change::NotCompared);
    CHECK(findRow(c, "random", "double", "failures") == nullptr);
    CHECK(findRow(c, "hard/near-parallel", "double", "failures") != nullptr);

    Json schema = smallReport();
    schema["schema"] = "gjk-report/2";
    CHECK_THROWS_WITH(compareReports(smallReport(), schema, o),
                      Catch::Contains("NEW 'b': not a gjk-report/1 report"));
}

TEST_CASE("compare: a variant in one report only is listed, fails only with --strict", "[compare]")
{
    Json fewer = smallReport();
    auto& vs = fewer["variants"];
    vs.erase(std::remove_if(vs.begin(), vs.end(),
                            [](const Json& v) { return v["name"] == "float-warm"; }),
             vs.end());
    for (auto& f : fewer["families"])
        f["variants"].erase("float-warm");
    CompareOptions o;
    const Comparison c = compareReports(smallReport(), fewer, o);
    CHECK(c.exitCode == kExitPass);
    const CompareRow* row = findRow(c, "", "float-warm", "variant");
    REQUIRE(row != nullptr);
    CHECK(row->change == Change::OnlyOld);
    CHECK(findRow(c, "random", "float-warm", "failures") == nullptr);
    o.strict = true;
    CHECK(compareReports(smallReport(), fewer, o).exitCode == kExitFail);
}

TEST_CASE("compare: bad report files are refused with one line naming the file", "[compare]")
{
    const fs::path dir = scratch();
    auto refusal = [](const std::string& path)
    {
        try
        {
            readReport(path);
        }
        catch (const InputError& e)
        {
            return std::string(e.what());
        }
        return std::string("(read without error)");
    };
    const std::string notJson = refusal(std::string(VALIDATION_TEST_DATA) + "/invalid-json.json");
    CHECK(contains(notJson, "invalid-json.json:4:"));
    CHECK(contains(notJson, "not JSON"));
    const std::string cases = refusal(std::string(VALIDATION_TEST_DATA) + "/wrong-format.json");
    CHECK(contains(cases, "wrong-format.json"));
    CHECK(contains(cases, "not a gjk-report/1 report"));
    CHECK(contains(refusal((dir / "no-such").string()), "no-such: no such file"));
    std::ofstream(dir / "families.json") << R"({"schema": "gjk-report/1", "families": {}})";
    CHECK(contains(refusal((dir / "families.json").string()),
                   "\"families\" is object, expected an array"));
    std::string deep(200, '[');
    std::ofstream(dir / "deep.json") << deep;
    CHECK(contains(refusal((dir / "deep.json").string()), "nested more than 64 deep"));
    for (const auto& m : {notJson, cases})
        CHECK(std::count(m.begin(), m.end(), '\n') == 0);
    // A directory stands for its report.json.
    CHECK(readReport(smallReportDir().string())["schema"] == "gjk-report/1");
}

// The program: exit codes 0, 1, 2, the table on stdout, --json and --md written.
TEST_CASE("compare: the HTML page escapes its text with the report page's escape", "[compare]")
{
    CHECK(gjk_html::escapeHtml("<a title=\"x\">&</a>") ==
          "&lt;a title=&quot;x&quot;&gt;&amp;&lt;/a&gt;");
    CompareOptions o;
    o.oldName = "OLD '<a&b>\"'";
    const std::string html = compareHtml(compareReports(smallReport(), smallReport(), o));
    CHECK(contains(html, "<li>OLD '&lt;a&amp;b&gt;&quot;'</li>"));
}

TEST_CASE("compare: the program's exit codes and outputs", "[compare][cli]")
{
    const std::string old = smallReportDir().string();
    Json worse = smallReport();
    Json& abs = stats(worse, "random", "double")["errors"]["abs"];
    abs["max"] = abs["max"].get<double>() * 2;
    const std::string bad = writeReport(worse, "worse.json").string();
    const fs::path md = scratch() / "compare.md", json = scratch() / "compare.json",
                   html = scratch() / "compare.html";
    fs::remove(md);
    fs::remove(html);
    fs::remove(json);

    const Run same = runCli({"compare", old, old});
    CHECK(same.code == kExitPass);
    CHECK(contains(same.out, "every statistic is the same"));

    const Run r = runCli({"compare", old, bad, "--md", md.string(), "--json", json.string(),
                          "--html", html.string()});
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.code == kExitFail);
    CHECK(contains(r.out, "random"));
    CHECK(contains(r.out, "errors.abs.max"));
    CHECK(contains(r.out, "REGRESSED"));
    CHECK(contains(r.out, "result: REGRESSION (exit code 1)"));
    CHECK(contains(slurp(md), "| random | double | errors.abs.max |"));
    CHECK(contains(slurp(html), "<tr class=\"regressed\"><td>random</td><td>double</td>"
                                "<td>errors.abs.max</td>"));
    CHECK(contains(slurp(html), "REGRESSION (exit code 1)"));
    const Json j = Json::parse(slurp(json));
    CHECK(j["schema"] == "gjk-compare/1");
    CHECK(j["exit_code"] == 1);
    CHECK(j["rows"][0]["family"] == "random");

    // Exit 2, one line naming the file: not JSON, and reports of different inputs.
    const std::string notJson = std::string(VALIDATION_TEST_DATA) + "/invalid-json.json";
    const Run e = runCli({"compare", old, notJson});
    CHECK(e.code == kExitInput);
    CHECK(contains(e.err, "invalid-json.json:4:"));
    CHECK(std::count(e.err.begin(), e.err.end(), '\n') == 1);
    Json other = smallReport();
    familyOf(other, "hard/near-parallel")["seed"] = 12345;
    const Run d = runCli({"compare", old, writeReport(other, "other.json").string()});
    CHECK(d.code == kExitInput);
    CHECK(contains(d.err, "ran different inputs: family 'hard/near-parallel': seed"));
    CHECK(std::count(d.err.begin(), d.err.end(), '\n') == 1);
}
