// gjk2d_html on hand-made fixtures (tests/report/fixtures): the pages are self-contained, the
// inlined data block is valid JSON equal to the input, nothing in the data can end its <script>
// block, and every placeholder of the template is filled. What the page draws is checked in a real
// browser by browser_check.py (tests "report: browser*").
#include "gjk_html/html.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

using nlohmann::json;

namespace
{
// The report format the pages are made for: kReportSchema (validation/src/report/report.hpp), which
// this test, linking gjk_html alone, cannot include.
constexpr const char* kSchema = "gjk-report/1";

json loadFixture(const std::string& name)
{
    std::ifstream in(std::string(GJK_REPORT_FIXTURES) + "/" + name);
    REQUIRE(in.good());
    return json::parse(in);
}

std::size_t count(const std::string& hay, const std::string& needle)
{
    std::size_t n = 0;
    for (std::size_t at = hay.find(needle); at != std::string::npos; at = hay.find(needle, at + 1))
        ++n;
    return n;
}

// The text of the <script type="application/json" id="report-data"> block.
std::string dataBlock(const std::string& page)
{
    const std::string open = "<script type=\"application/json\" id=\"report-data\">";
    const std::size_t a = page.find(open);
    REQUIRE(a != std::string::npos);
    const std::size_t b = page.find("</script>", a);
    REQUIRE(b != std::string::npos);
    return page.substr(a + open.size(), b - a - open.size());
}

// The page outside the data block (the template, CSS and JS).
std::string withoutData(const std::string& page)
{
    const std::string data = dataBlock(page);
    const std::size_t at = page.find(data);
    return page.substr(0, at) + page.substr(at + data.size());
}

void checkSelfContained(const std::string& page)
{
    const std::string code = withoutData(page);
    // No external resource of any kind: no src/href to another document, no CSS import or url(),
    // no <link>, <iframe>, <img>, <object>, <embed>, and no script loaded by src.
    const std::regex external(R"((src|href|action)\s*=\s*["']?\s*(https?:|//|file:|data:))",
                              std::regex::icase);
    CHECK_FALSE(std::regex_search(code, external));
    const std::regex tags(R"(<\s*(link|iframe|img|object|embed|base)\b)", std::regex::icase);
    CHECK_FALSE(std::regex_search(code, tags));
    CHECK_FALSE(std::regex_search(code, std::regex(R"(<script[^>]*\bsrc\s*=)", std::regex::icase)));
    CHECK_FALSE(std::regex_search(code, std::regex(R"(@import|url\s*\()", std::regex::icase)));
    CHECK_FALSE(std::regex_search(
        code, std::regex(R"(\b(fetch|XMLHttpRequest|WebSocket|EventSource|importScripts)\b)")));
    // The only "http" is the SVG namespace name (an identifier, never fetched).
    std::string rest = code;
    for (std::size_t at; (at = rest.find("http://www.w3.org/2000/svg")) != std::string::npos;)
        rest.erase(at, 26);
    CHECK(rest.find("http") == std::string::npos);
}

void checkTemplateFilled(const std::string& page)
{
    CHECK(page.rfind("<!DOCTYPE html>", 0) == 0);
    for (const char* placeholder : {"@MODE@", "@SCHEMA@", "/*@CSS@*/", "@DATA@", "/*@JS@*/"})
        CHECK(page.find(placeholder) == std::string::npos);
    // Three script elements (error hook, data, page script), and nothing else closes one.
    CHECK(count(page, "<script") == 3);
    CHECK(count(page, "</script") == 3);
    CHECK(page.find("</html>") != std::string::npos);
}

} // namespace

TEST_CASE("renderReport on the realistic fixture is a complete, self-contained page", "[html]")
{
    const json report = loadFixture("report.json");
    const std::string page = gjk_html::renderReport(report, kSchema);
    checkTemplateFilled(page);
    checkSelfContained(page);
    CHECK(page.find("<html lang=\"en\" data-mode=\"report\" data-schema=\"gjk-report/1\">") !=
          std::string::npos);
    // The page's own code is inlined: CSS and the viewer's JS are there.
    CHECK(page.find("Viewer.prototype.drawMinkowski") != std::string::npos);
    CHECK(page.find("--pass:") != std::string::npos);
}

TEST_CASE("the data block parses back to the report, with every family", "[html]")
{
    const json report = loadFixture("report.json");
    const std::string page = gjk_html::renderReport(report, kSchema);
    const json back = json::parse(dataBlock(page));
    CHECK(back == report);
    REQUIRE(back["families"].size() == report["families"].size());
    for (const auto& f : report["families"])
    {
        bool found = false;
        for (const auto& g : back["families"])
            found = found || g["name"] == f["name"];
        CHECK(found);
    }
    CHECK(back["worst"].size() == 3);
    CHECK(back["worst"][0]["variants"]["double"]["trace"].size() == 4);
}

TEST_CASE("markup inside strings cannot close or disturb the data block", "[html]")
{
    // The fixture's rejected input is named "...</script><b>x</b>"; add a few more.
    json report = loadFixture("report.json");
    report["context"]["host"] = "</SCRIPT><!--<script>alert(1)</script>-->&amp;";
    report["families"][0]["name"] = "</script >";
    const std::string page = gjk_html::renderReport(report, kSchema);
    const std::string data = dataBlock(page);
    CHECK(data.find('<') == std::string::npos);
    CHECK(data.find('>') == std::string::npos);
    CHECK(data.find('&') == std::string::npos);
    CHECK(data.find("\\u003c/script\\u003e\\u003cb\\u003ex") != std::string::npos);
    CHECK(json::parse(data) == report);
    checkTemplateFilled(page);
}

TEST_CASE("embedJson is valid JSON for awkward strings", "[html]")
{
    const json j = {{"s", "a</script>b<!--c-->d&e\u2028f\"g\\h"},
                    {"n", {1.5, -0.0, 1e-300, 12345678901234567.0}}};
    const std::string text = gjk_html::embedJson(j);
    CHECK(text.find("</") == std::string::npos);
    CHECK(json::parse(text) == j);
    // Invalid UTF-8 is replaced rather than thrown on.
    const json bad = {{"s", std::string("ok\xff\xfe")}};
    std::string t2;
    REQUIRE_NOTHROW(t2 = gjk_html::embedJson(bad));
    CHECK(json::parse(t2)["s"].get<std::string>().rfind("ok", 0) == 0);
}

TEST_CASE("renderCase makes a viewer page with the case as its data", "[html]")
{
    const json report = loadFixture("report.json");
    for (const auto& c : report["worst"])
    {
        const std::string page = gjk_html::renderCase(c);
        checkTemplateFilled(page);
        checkSelfContained(page);
        CHECK(page.find("data-mode=\"case\"") != std::string::npos);
        CHECK(json::parse(dataBlock(page)) == c);
    }
}

TEST_CASE("pages render from sparse or odd data without throwing", "[html]")
{
    const json minimal = loadFixture("minimal.json");
    for (const json& j : {minimal, json::object(), json::array(), json(nullptr), json("text"),
                          json::parse(R"({"families": [{"name": "f"}], "worst": [{}]})")})
    {
        std::string page;
        REQUIRE_NOTHROW(page = gjk_html::renderReport(j, kSchema));
        checkTemplateFilled(page);
        checkSelfContained(page);
        CHECK(json::parse(dataBlock(page)) == j);
        REQUIRE_NOTHROW(page = gjk_html::renderCase(j));
        checkTemplateFilled(page);
    }
    // Non-finite doubles (which JSON cannot hold) become null rather than invalid JSON.
    const json nan = {{"x", std::numeric_limits<double>::quiet_NaN()},
                      {"y", std::numeric_limits<double>::infinity()}};
    CHECK(json::parse(dataBlock(gjk_html::renderReport(nan, kSchema)))["x"].is_null());
}

TEST_CASE("the minimal fixture's tricky family name stays inside the data", "[html]")
{
    const json minimal = loadFixture("minimal.json");
    const std::string page = gjk_html::renderReport(minimal, kSchema);
    CHECK(page.find("tricky family") != std::string::npos);
    CHECK(page.find("<!-- tricky") == std::string::npos);
    CHECK(page.find("<script>alert") == std::string::npos);
}
