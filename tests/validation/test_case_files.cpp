// The gjk-cases/1 format: bit-exact round trip, refused files, rejected cases.
#include "cases.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

using namespace gjkval;

namespace
{
std::uint64_t bits(double v)
{
    return std::bit_cast<std::uint64_t>(v);
}

void requireSameBits(const ShapeIn& x, const ShapeIn& y)
{
    REQUIRE(x.points.size() == y.points.size());
    for (std::size_t i = 0; i < x.points.size(); ++i)
    {
        CHECK(bits(x.points[i][0]) == bits(y.points[i][0]));
        CHECK(bits(x.points[i][1]) == bits(y.points[i][1]));
    }
    CHECK(bits(x.radius) == bits(y.radius));
    CHECK(bits(x.px) == bits(y.px));
    CHECK(bits(x.py) == bits(y.py));
    CHECK(bits(x.c) == bits(y.c));
    CHECK(bits(x.s) == bits(y.s));
}

std::string messageOf(const std::string& text, const std::string& name)
{
    try
    {
        parseCaseFile(text, name);
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "(no error)";
}
} // namespace

TEST_CASE("case files round-trip every double bit for bit", "[cases]")
{
    const double special[] = {0.0,
                              -0.0,
                              std::numeric_limits<double>::denorm_min(),
                              -std::numeric_limits<double>::denorm_min(),
                              2.2250738585072009e-308, // largest subnormal
                              std::numeric_limits<double>::min(),
                              1e-300,
                              1e300,
                              -1e300,
                              std::numeric_limits<double>::max(),
                              0.1,
                              1.0 / 3.0,
                              std::nextafter(1.0, 2.0),
                              std::nextafter(1.0, 0.0),
                              79.584320,
                              0.021119118,
                              123456789012345678.0,
                              9007199254740993.0};
    std::vector<Case> cases;
    Case c;
    c.name = "special";
    for (double v : special)
        c.a.points.push_back({v, -v});
    c.a.radius = 1e-300;
    c.a.px = -0.0;
    c.a.py = 1e300;
    c.a.c = std::cos(0.3);
    c.a.s = std::sin(0.3);
    c.b.points = {{std::numeric_limits<double>::denorm_min(), 1e-300}};
    c.b.radius = -0.0; // not negative: allowed, and written (its sign bit is kept)
    cases.push_back(c);

    // Random bit patterns (finite ones), including subnormals.
    std::mt19937_64 rng(42);
    Case r;
    r.name = "random-bits";
    while (r.a.points.size() < 500)
    {
        const double x = std::bit_cast<double>(rng()),
                     y = std::bit_cast<double>(rng() >> (rng() % 64));
        if (std::isfinite(x) && std::isfinite(y))
            r.a.points.push_back({x, y});
    }
    r.b.points = {{1, 2}};
    cases.push_back(r);

    const std::string text =
        caseFileText({"a comment", "with \"quotes\" and unicode \u00e9"}, cases);
    const CaseFile back = parseCaseFile(text, "roundtrip.json");
    REQUIRE(back.entries.size() == 2);
    REQUIRE(back.comments ==
            std::vector<std::string>{"a comment", "with \"quotes\" and unicode \u00e9"});
    for (std::size_t i = 0; i < 2; ++i)
    {
        INFO(back.entries[i].rejected);
        REQUIRE(back.entries[i].rejected.empty());
        CHECK(back.entries[i].c.name == cases[i].name);
        requireSameBits(back.entries[i].c.a, cases[i].a);
        requireSameBits(back.entries[i].c.b, cases[i].b);
    }
    // Writing what was read gives the same text.
    std::vector<Case> again;
    for (const auto& e : back.entries)
        again.push_back(e.c);
    CHECK(caseFileText(back.comments, again) == text);
}

TEST_CASE("radius and transform are optional", "[cases]")
{
    const CaseFile f = parseCaseFile(
        R"({"format": "gjk-cases/1", "cases": [{"name": "n", "a": {"points": [[1, 2]]}, "b": {"points": [[3, 4]]}}]})",
        "min.json");
    REQUIRE(f.entries.size() == 1);
    REQUIRE(f.entries[0].rejected.empty());
    const ShapeIn& a = f.entries[0].c.a;
    CHECK(a.radius == 0);
    CHECK(a.c == 1);
    CHECK(a.s == 0);
    CHECK(a.px == 0);
    CHECK(a.py == 0);
    CHECK(f.comments.empty());
}

TEST_CASE("an invalid JSON file is refused with file, line and column", "[cases]")
{
    const std::string text =
        "{\"format\": \"gjk-cases/1\",\n \"cases\": [\n  {\"name\": \"x\", \"a\": }\n ]}\n";
    const std::string m = messageOf(text, "dir/bad.json");
    INFO(m);
    CHECK(m.rfind("dir/bad.json:3:22: invalid JSON", 0) == 0);
    CHECK(lineColumn("ab\ncd\n", 4) == std::pair<std::size_t, std::size_t>{2, 2});
    CHECK(lineColumn("ab", 0) == std::pair<std::size_t, std::size_t>{1, 1});
}

TEST_CASE("a file of another format is refused", "[cases]")
{
    CHECK_THAT(messageOf(R"({"format": "gjk-cases/2", "cases": []})", "f.json"),
               Catch::StartsWith("f.json: not a gjk-cases/1 file: format is \"gjk-cases/2\""));
    CHECK_THAT(messageOf(R"({"cases": []})", "f.json"), Catch::Contains("no \"format\" field"));
    CHECK_THAT(messageOf(R"([1, 2])", "f.json"), Catch::Contains("the top level is an array"));
    CHECK_THAT(messageOf(R"({"format": "gjk-cases/1"})", "f.json"),
               Catch::Contains("\"cases\" is missing"));
    CHECK_THAT(messageOf(R"({"format": "gjk-cases/1", "cases": [], "comments": [1]})", "f.json"),
               Catch::Contains("comments"));
    CHECK_THROWS_AS(readCaseFile("/nonexistent/cases.json"), InputError);
}

TEST_CASE("invalid cases are rejected naming file, case and field; the others are valid", "[cases]")
{
    const CaseFile f = readCaseFile(std::string(VALIDATION_TEST_DATA) + "/bad-cases.json");
    REQUIRE(f.entries.size() == 9);
    auto reason = [&](std::size_t i) { return f.entries[i].rejected; };
    CHECK(reason(0).empty());
    CHECK(reason(1) == "a.points[1][0] is NaN");
    CHECK(reason(2) == "a.points is empty");
    CHECK(reason(3) == "a.radius is negative (-1)");
    CHECK(reason(4) == "missing field 'b'");
    CHECK(reason(5) == "a.points is a string, expected an array");
    CHECK(reason(6) == "a.transform.p[0] is infinite");
    CHECK_THAT(reason(7), Catch::StartsWith("a.transform.q is not a rotation"));
    CHECK(reason(8).empty());
    CHECK(f.entries[1].label == "bad-cases.json#1 (case 'nan')");
    CHECK(f.entries[8].c.b.c == 0);
    CHECK(f.entries[8].c.b.s == 1);
    CHECK(f.entries[8].c.a.radius == 0.25);
}

TEST_CASE("more rejections: names, wrong types, duplicates", "[cases]")
{
    const CaseFile f = parseCaseFile(R"({"format": "gjk-cases/1", "cases": [
        3,
        {"a": {"points": [[0, 0]]}, "b": {"points": [[0, 0]]}},
        {"name": "p", "a": {"points": [[0]]}, "b": {"points": [[0, 0]]}},
        {"name": "p", "a": {"points": [[0, 0]]}, "b": {"points": [[0, 0]]}},
        {"name": "q", "a": {"points": [[0, 0]], "radius": "big"}, "b": {"points": [[0, 0]]}},
        {"name": "r", "a": {"points": [[0, true]]}, "b": {"points": [[0, 0]]}},
        {"name": "s", "a": {"points": [[0, 0]], "transform": []}, "b": {"points": [[0, 0]]}}
    ]})",
                                     "more.json");
    REQUIRE(f.entries.size() == 7);
    CHECK(f.entries[0].rejected == "the case is a number, expected an object");
    CHECK(f.entries[0].label == "more.json#0");
    CHECK(f.entries[1].rejected == "missing field 'name'");
    CHECK(f.entries[2].rejected == "a.points[0] has 1 elements, expected 2");
    CHECK(f.entries[3].rejected == "duplicate case name 'p'");
    CHECK(f.entries[4].rejected == "a.radius is a string, expected a number");
    CHECK(f.entries[5].rejected == "a.points[0][1] is a boolean, expected a number");
    CHECK(f.entries[6].rejected == "a.transform is an array, expected an object");
}

TEST_CASE("float rounding of a case for the float variants' truth", "[cases]")
{
    Case c;
    c.a.points = {{0.1, 1e300}};
    c.b.points = {{0.2, 0.3}};
    CHECK_FALSE(representableInFloat(c));
    c.a.points = {{0.1, 1e30}};
    CHECK(representableInFloat(c));
    const exact::Shape e = toExact(c.a, true);
    CHECK(e.points[0].x == double(0.1f));
    CHECK(e.points[0].y == double(1e30f));
}

TEST_CASE("float rounding survives the optimiser: a point's x and y together", "[cases]")
{
    // Regression: GCC 12.2 at -O2/-O3 folded `p = {double(float(p[0])), double(float(p[1]))}`
    // into the identity (its SLP vectorizer pairs the two round trips and drops them), so the
    // float variants' truth was computed on unrounded doubles. roundedToFloat must round both.
    ShapeIn s;
    s.points = {{0.1, 0.2}, {1e30, -0.3}};
    const ShapeIn r = roundedToFloat(s);
    CHECK(r.points[0][0] == double(0.1f));
    CHECK(r.points[0][1] == double(0.2f));
    CHECK(r.points[1][0] == double(1e30f));
    CHECK(r.points[1][1] == double(-0.3f));
    CHECK(r.points[0][0] != 0.1);
}
