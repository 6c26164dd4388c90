// The gjk-cases/1 format: bit-exact round trip, refused files, rejected cases.
#include "inputs/case_fields.hpp"
#include "inputs/cases.hpp"
#include "inputs/geometry.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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

TEST_CASE("a case's optional source and comment are read, written and type-checked", "[cases]")
{
    const CaseFile f = parseCaseFile(R"({"format": "gjk-cases/1", "cases": [
        {"name": "both", "source": "https://example.org/issues/1", "comment": "expected 3",
         "a": {"points": [[0, 0]]}, "b": {"points": [[3, 0]]}},
        {"name": "none", "a": {"points": [[0, 0]]}, "b": {"points": [[3, 0]]}},
        {"name": "bad-source", "source": 508, "a": {"points": [[0, 0]]}, "b": {"points": [[3, 0]]}},
        {"name": "bad-comment", "comment": ["x"], "a": {"points": [[0, 0]]}, "b": {"points": [[3, 0]]}}
    ]})",
                                     "prov.json");
    REQUIRE(f.entries.size() == 4);
    REQUIRE(f.entries[0].rejected.empty());
    CHECK(f.entries[0].c.source == "https://example.org/issues/1");
    CHECK(f.entries[0].c.comment == "expected 3");
    // A file without them (every file before they existed) is read as before.
    REQUIRE(f.entries[1].rejected.empty());
    CHECK(f.entries[1].c.source.empty());
    CHECK(f.entries[1].c.comment.empty());
    // A wrong type rejects the case, naming file, case and field.
    CHECK(f.entries[2].label == "prov.json#2 (case 'bad-source')");
    CHECK(f.entries[2].rejected == "source is a number, expected a string");
    CHECK(f.entries[3].label == "prov.json#3 (case 'bad-comment')");
    CHECK(f.entries[3].rejected == "comment is an array, expected a string");
    // Longer than a file comment may be: rejected.
    const std::string longText = std::string(kMaxCommentBytes + 1, 'x');
    const CaseFile g = parseCaseFile(
        R"({"format": "gjk-cases/1", "cases": [{"name": "long", "comment": ")" + longText +
            R"(", "a": {"points": [[0, 0]]}, "b": {"points": [[3, 0]]}}]})",
        "long.json");
    REQUIRE(g.entries.size() == 1);
    CHECK(g.entries[0].rejected == "comment is 65537 bytes long, more than 65536");
    // Written only when present, and read back unchanged.
    std::vector<Case> cases{f.entries[0].c, f.entries[1].c};
    const std::string text = caseFileText({}, cases);
    CHECK(text.find(R"("source":"https://example.org/issues/1")") != std::string::npos);
    CHECK(caseToJson(f.entries[1].c).count("source") == 0);
    CHECK(caseToJson(f.entries[1].c).count("comment") == 0);
    const CaseFile back = parseCaseFile(text, "back.json");
    REQUIRE(back.entries.size() == 2);
    CHECK(back.entries[0].c.source == cases[0].source);
    CHECK(back.entries[0].c.comment == cases[0].comment);
    CHECK(back.entries[1].c.comment.empty());
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

TEST_CASE("invalid cases are rejected naming file, case and field, and the others are valid",
          "[cases]")
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
    CHECK(reason(7) == "a.transform.q is (0, 0): not a rotation");
    CHECK(reason(8).empty());
    CHECK(f.entries[1].label == "bad-cases.json#1 (case 'nan')");
    CHECK(f.entries[8].c.b.c == 0);
    CHECK(f.entries[8].c.b.s == 1);
    CHECK(f.entries[8].c.a.radius == 0.25);
}

TEST_CASE("any finite rotation (c, s) other than (0, 0) is a transform", "[cases]")
{
    // A float engine's (cos, sin) (here of 0.3 rad, rounded to float: |c^2 + s^2 - 1| = 4.8e-8
    // in double), a scaled rotation (3, 4) of size 5, and tiny and huge ones: all valid input
    //, kept exactly as written.
    const CaseFile f = parseCaseFile(R"({"format": "gjk-cases/1", "cases": [
        {"name": "float", "a": {"points": [[0, 0]], "transform": {"q": [0.95533651113510132, 0.29552021622657776]}}, "b": {"points": [[2, 2]]}},
        {"name": "scaled", "a": {"points": [[0, 0]], "transform": {"q": [3, 4]}}, "b": {"points": [[2, 2]]}},
        {"name": "tiny", "a": {"points": [[0, 0]], "transform": {"q": [1e-300, 0]}}, "b": {"points": [[2, 2]]}},
        {"name": "huge", "a": {"points": [[0, 0]], "transform": {"q": [0, -1e300]}}, "b": {"points": [[2, 2]]}}
    ]})",
                                     "rot.json");
    REQUIRE(f.entries.size() == 4);
    for (const auto& e : f.entries)
        CHECK(e.rejected.empty());
    CHECK(f.entries[0].c.a.c == double(0.95533651113510132f));
    CHECK(std::abs(f.entries[0].c.a.c * f.entries[0].c.a.c +
                   f.entries[0].c.a.s * f.entries[0].c.a.s - 1) > 1e-9);
    CHECK(f.entries[1].c.a.s == 4);
    CHECK(f.entries[3].c.a.s == -1e300);
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
    // A rotation (1e-200, -1e-200) is a transform in double, (0, 0) in float: none.
    Case r = c;
    r.b.c = 1e-200;
    r.b.s = -1e-200;
    CHECK_FALSE(representableInFloat(r));
    r.b.s = 1e-30; // (0, 1e-30) in float: a transform
    CHECK(representableInFloat(r));
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

TEST_CASE("the world case of a case: world points in double, rounded to float for float", "[cases]")
{
    // B's point (0.1, 0.3) under the rotation (0.6, 0.8) and the translation (2, 1): in double,
    // x' = (0.6 * 0.1 - 0.8 * 0.3) + 2 and y' = (0.8 * 0.1 + 0.6 * 0.3) + 1, each operation
    // rounded, are the doubles nearest 1.82 and 1.26 (Python's IEEE doubles give the same:
    // (0.6*0.1 - 0.8*0.3) + 2.0 == 1.82); in float, 1.8200000524520874 and 1.2599999904632568
    // (struct.pack('f', 1.82)). The exact image, with the doubles 0.6, 0.8, 0.1, 0.3 taken
    // exactly, is neither (0.6 and 0.8 are no unit rotation in binary).
    Case c;
    c.name = "w";
    c.a.points = {{0.0, 0.0}};
    c.b.points = {{0.1, 0.3}};
    c.b.radius = 0.1;
    c.b.px = 2.0;
    c.b.py = 1.0;
    c.b.c = 0.6;
    c.b.s = 0.8;
    const std::optional<Case> d = worldCase(c, false), f = worldCase(c, true);
    REQUIRE(d);
    REQUIRE(f);
    CHECK(d->name == "w");
    CHECK(d->b.points[0][0] == 1.82);
    CHECK(d->b.points[0][1] == 1.26);
    CHECK(d->b.radius == 0.1);
    CHECK(f->b.points[0][0] == 1.8200000524520874);
    CHECK(f->b.points[0][1] == 1.2599999904632568);
    CHECK(f->b.radius == 0.10000000149011612);
    for (const Case* w : {&*d, &*f})
        for (const ShapeIn* s : {&w->a, &w->b})
            CHECK((s->px == 0 && s->py == 0 && s->c == 1 && s->s == 0));
    CHECK(f->a.points[0] == P2{0.0, 0.0});
    CHECK(worldCaseFits(c, false));
    CHECK(worldCaseFits(c, true));
    // 3e38 + 1e38 = 4e38: a double, beyond float's 3.4e38, though 3e38 and 1e38 are floats.
    c.b.points = {{3e38, 0.0}};
    c.b.c = 1.0;
    c.b.s = 0.0;
    c.b.px = 1e38;
    CHECK(worldCase(c, false));
    CHECK_FALSE(worldCase(c, true));
    CHECK_FALSE(worldCaseFits(c, true));
    // 1e308 + 1e308 overflows double too; a radius beyond float does not fit float.
    c.b.points = {{1e308, 0.0}};
    c.b.px = 1e308;
    CHECK_FALSE(worldCase(c, false));
    CHECK_FALSE(worldCaseFits(c, false));
    c.b.points = {{1.0, 0.0}};
    c.b.px = 0;
    c.b.radius = 1e39;
    CHECK(worldCaseFits(c, false));
    CHECK_FALSE(worldCase(c, true));
    CHECK_FALSE(worldCaseFits(c, true));
}

// ---- Hostile files (the reader's part of the hostile-input hardening) ----

namespace
{
// A gjk-cases/1 file around the given case entries.
std::string caseFile(const std::string& cases)
{
    return R"({"format": "gjk-cases/1", "cases": [)" + cases + "]}";
}

std::string oneCase(const std::string& name, const std::string& pointA)
{
    return R"({"name": ")" + name + R"(", "a": {"points": [)" + pointA +
           R"(]}, "b": {"points": [[1, 1]]}})";
}

// Everything the reader passes on goes into report.json: none of it may make a dump throw.
void requireDumpable(const CaseFile& f)
{
    for (const auto& s : f.comments)
        REQUIRE_NOTHROW(Json(s).dump());
    for (const auto& e : f.entries)
    {
        REQUIRE_NOTHROW(Json(e.label).dump());
        REQUIRE_NOTHROW(Json(e.c.name).dump());
        REQUIRE_NOTHROW(Json(e.c.source).dump());
        REQUIRE_NOTHROW(Json(e.c.comment).dump());
        REQUIRE_NOTHROW(Json(e.rejected).dump());
    }
}
} // namespace

TEST_CASE("excerpt: a short, printable, valid UTF-8 quote of any string", "[cases][excerpt]")
{
    CHECK(excerpt("gjk-cases/2") == "gjk-cases/2");
    CHECK(excerpt("caf\xc3\xa9") == "caf\xc3\xa9"); // valid UTF-8 kept
    CHECK(excerpt("a\xff"
                  "b") == "a\\xFFb");                        // invalid byte escaped
    CHECK(excerpt("\x1b[2J\n\x7f") == "\\x1B[2J\\x0A\\x7F"); // C0 and DEL escaped
    CHECK(excerpt("\xc2\x9b") == "\\xC2\\x9B");              // C1 (CSI) escaped
    CHECK(excerpt("\xed\xa0\x80") == "\\xED\\xA0\\x80");     // a surrogate is not UTF-8
    CHECK(excerpt("a\\b") == "a\\\\b");                      // \xHH stays unambiguous
    const std::string big(200'000'000, 'x');
    CHECK(excerpt(big) == std::string(60, 'x') + "... (200000000 bytes)");
    // Cut between characters, never inside one.
    std::string e;
    for (int i = 0; i < 40; ++i)
        e += "\xc3\xa9";
    CHECK(excerpt(e) == e.substr(0, 60) + "... (80 bytes)");
    CHECK(isValidUtf8(excerpt(std::string("\xe2\x82") + std::string(100, '\xff'))));
    CHECK(isValidUtf8("\xf0\x9f\x98\x80"));
    CHECK_FALSE(isValidUtf8("\xf4\x90\x80\x80")); // above U+10FFFF
    CHECK_FALSE(isValidUtf8("\xc0\xaf"));         // overlong
}

TEST_CASE("deep JSON is refused with line and column, never dumped", "[cases][hostile]")
{
    // Regression (hostile-input hardening): a "format" nested 100,000 deep crashed run and explain
    // (SIGSEGV) in the recursive dump of the error message. The reader refuses depth 65 while
    // parsing; a case file needs 6 levels. The column is that of the 65th opening bracket.
    const std::string deep = R"({"format": )" + std::string(100'000, '[') +
                             std::string(100'000, ']') + R"(, "cases": []})";
    CHECK(messageOf(deep, "deep.json") == "deep.json:1:75: JSON nested deeper than 64 levels");
    const std::string deepCase = caseFile(std::string(100'000, '[') + std::string(100'000, ']'));
    CHECK_THAT(messageOf(deepCase, "d.json"), Catch::EndsWith("JSON nested deeper than 64 levels"));
    // 64 levels (the top-level object and 63 arrays in an ignored field) are fine.
    const std::string ok = R"({"format": "gjk-cases/1", "cases": [], "x": )" +
                           std::string(63, '[') + std::string(63, ']') + "}";
    CHECK(parseCaseFile(ok, "ok.json").entries.empty());
    CHECK_THAT(messageOf(R"({"format": "gjk-cases/1", "cases": [], "x": )" + std::string(64, '[') +
                             std::string(64, ']') + "}",
                         "d.json"),
               Catch::StartsWith("d.json:1:108: JSON nested deeper than 64 levels"));
}

TEST_CASE("a long value is quoted as a short excerpt", "[cases][hostile]")
{
    // Regression (hostile-input hardening): a 200 MB "format" string was echoed whole to stderr.
    const std::string m =
        messageOf(R"({"format": ")" + std::string(1'000'000, 'x') + R"(", "cases": []})", "f.json");
    CHECK(m == "f.json: not a gjk-cases/1 file: format is \"" + std::string(60, 'x') +
                   "... (1000000 bytes)\"");
    // A format of the wrong type is named by its type, not dumped.
    CHECK(messageOf(R"({"format": {"a": [1, 2]}, "cases": []})", "f.json") ==
          "f.json: not a gjk-cases/1 file: format is an object");
    // nlohmann's own syntax errors quote the last token whole (control characters as <U+0001>):
    // only an excerpt of it remains.
    const std::string s =
        messageOf(caseFile("\"" + std::string(1'000'000, 'y') + "\x01\""), "s.json");
    INFO(s);
    CHECK(s.size() < 300);
    CHECK_THAT(s, Catch::StartsWith("s.json:1:1000038: invalid JSON: "));
    CHECK_THAT(s, Catch::EndsWith("... (1000009 bytes)'"));
}

TEST_CASE("duplicate keys are refused, naming the key and where it is", "[cases][hostile]")
{
    // Regression (hostile-input hardening): duplicate keys silently took the last value.
    const std::string text = "{\"format\": \"gjk-cases/1\", \"cases\": [\n" +
                             std::string(R"({"name": "d", "a": {"points": [[0, 0]]},)") +
                             R"( "a": {"points": [[5, 5]]}, "b": {"points": [[1, 1]]}}]})";
    CHECK(messageOf(text, "dup.json") == "dup.json:2:42: invalid JSON: duplicate key \"a\"");
    CHECK(messageOf(R"({"format": "gjk-cases/1", "format": "gjk-cases/1", "cases": []})",
                    "dup.json") == "dup.json:1:27: invalid JSON: duplicate key \"format\"");
    // Escaped quotes in the key: the position is still its opening quote; the key is excerpted.
    CHECK(messageOf(R"({"format": "gjk-cases/1", "cases": [], "k\"\u0001": 1, "k\"\u0001": 2})",
                    "dup.json") == "dup.json:1:56: invalid JSON: duplicate key \"k\"\\x01\"");
    // In an ignored field too.
    CHECK_THAT(messageOf(R"({"format": "gjk-cases/1", "cases": [], "x": {"y": 1, "y": 1}})", "d"),
               Catch::Contains("duplicate key \"y\""));
}

TEST_CASE("a number that overflows or silently becomes 0 is refused", "[cases][hostile]")
{
    // Regression (hostile-input hardening): 1e-999 silently became 0.
    CHECK(messageOf(caseFile(oneCase("u", "[0, 1e-999]")), "u.json") ==
          "u.json:1:72: number 1e-999 is not 0 but rounds to 0 in a double");
    CHECK_THAT(messageOf(caseFile(oneCase("u", "[-2e-324, 0]")), "u.json"),
               Catch::EndsWith("number -2e-324 is not 0 but rounds to 0 in a double"));
    CHECK(messageOf(caseFile(oneCase("o", "[0, 1e999]")), "o.json") ==
          "o.json:1:72: number 1e999 overflows a double");
    // The literal is quoted as an excerpt.
    CHECK_THAT(messageOf(caseFile(oneCase("o", "[0, 1" + std::string(500, '0') + "]")), "o.json"),
               Catch::EndsWith("... (501 bytes) overflows a double"));
    // Zeros, the smallest subnormal (and a literal rounding up to it) and the largest double are
    // numbers like any other; "-0" keeps its sign as "-0.0" does.
    const CaseFile f = parseCaseFile(
        caseFile(
            oneCase("z", "[0.0e-999, -0e5], [4.9e-324, 3e-324], [1.7976931348623157e308, -0]")),
        "z.json");
    REQUIRE(f.entries.size() == 1);
    REQUIRE(f.entries[0].rejected.empty());
    const auto& p = f.entries[0].c.a.points;
    CHECK(bits(p[0][0]) == bits(0.0));
    CHECK(bits(p[0][1]) == bits(-0.0));
    CHECK(p[1][0] == std::numeric_limits<double>::denorm_min());
    CHECK(p[1][1] == std::numeric_limits<double>::denorm_min());
    CHECK(p[2][0] == std::numeric_limits<double>::max());
    CHECK(bits(p[2][1]) == bits(-0.0)); // regression: the integer literal -0 was read as +0
}

TEST_CASE("names must be short, printable UTF-8, and labels are excerpts", "[cases][hostile]")
{
    // Regression (hostile-input hardening): a name or path with bytes that are not UTF-8 went into
    // labels and report.json, where nlohmann's dump threw type_error (abort). A JSON string is
    // valid UTF-8 (nlohmann's parser checks it); a control character or a long name is a
    // per-case rejection; the path is excerpted into the label.
    CHECK_THAT(messageOf(caseFile(oneCase("a\xff", "[0, 0]")), "f.json"),
               Catch::Contains("ill-formed UTF-8 byte; last read: '\"a\\xFF'"));
    const CaseFile f = parseCaseFile(caseFile(oneCase(R"(esc\u001b[2J)", "[0, 0]") + "," +
                                              oneCase(std::string(300, 'n'), "[0, 0]") + "," +
                                              oneCase("good", "[0, 0]")),
                                     "dir/x\xff.json");
    REQUIRE(f.entries.size() == 3);
    CHECK(f.entries[0].rejected == "name contains a control character or is not valid UTF-8");
    CHECK(f.entries[0].label == "x\\xFF.json#0 (case 'esc\\x1B[2J')");
    CHECK(f.entries[1].rejected == "name is 300 bytes long, more than 256");
    CHECK(f.entries[1].label ==
          "x\\xFF.json#1 (case '" + std::string(60, 'n') + "... (300 bytes)')");
    CHECK(f.entries[2].rejected.empty());
    CHECK(f.entries[2].c.name == "good");
    requireDumpable(f);
    // A duplicate name is quoted as an excerpt.
    const CaseFile d = parseCaseFile(
        caseFile(oneCase("\xc3\xa9", "[0, 0]") + "," + oneCase("\xc3\xa9", "[0, 0]")), "d.json");
    CHECK(d.entries[1].rejected == "duplicate case name '\xc3\xa9'");
}

TEST_CASE("comments and shapes have documented limits", "[cases][hostile]")
{
    const std::string longComment(64 * 1024 + 1, 'c');
    CHECK_THAT(messageOf(R"({"format": "gjk-cases/1", "cases": [], "comments": ["ok", ")" +
                             longComment + "\"]}",
                         "c.json"),
               Catch::EndsWith("comments[1] is 65537 bytes long, more than 65536"));
    CHECK(parseCaseFile(R"({"format": "gjk-cases/1", "cases": [], "comments": [")" +
                            std::string(64 * 1024, 'c') + "\"]}",
                        "c.json")
              .comments.size() == 1);
    // A shape of more than 1,000,000 points is rejected; the other cases run.
    std::string many = "[0, 0]";
    for (int i = 0; i < 1'000'000; ++i)
        many += ",[1,2]";
    const CaseFile f =
        parseCaseFile(caseFile(oneCase("many", many) + "," + oneCase("few", "[0, 0]")), "m.json");
    REQUIRE(f.entries.size() == 2);
    CHECK(f.entries[0].rejected == "a.points has 1000001 points, more than 1000000");
    CHECK(f.entries[1].rejected.empty());
}

TEST_CASE("what is read is bounded: devices and directories are refused, not large files",
          "[cases][files]")
{
    // Regression (hostile-input hardening): `--cases /dev/zero` read until bad_alloc.
    auto readMessage = [](const std::string& path)
    {
        try
        {
            readCaseFile(path);
        }
        catch (const InputError& e)
        {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    CHECK(readMessage("/dev/zero") ==
          "/dev/zero: is a character device, expected a case file (a regular file or a pipe)");
    const std::filesystem::path dir = std::string(VALIDATION_TEST_TMP) + "/case-files";
    std::filesystem::create_directories(dir);
    CHECK(readMessage(dir.string()) == dir.string() +
                                           ": is a directory, expected a case file (a regular "
                                           "file or a pipe)");
    CHECK_THAT(readMessage(dir.string() + "/missing.json"),
               Catch::EndsWith("missing.json: cannot open the file: No such file or directory"));
    // No size limit: a regular file above the former 256 MiB cap is read, not refused by its
    // size (a sparse file: "{" then zeros, refused at its second byte as not JSON).
    const std::string big = (dir / "big.json").string();
    {
        std::ofstream(big) << "{";
    }
    std::filesystem::resize_file(big, (std::uintmax_t(256) << 20) + 1);
    CHECK_THAT(readMessage(big), Catch::StartsWith(big + ":1:2: invalid JSON: "));
    std::filesystem::remove(big);
}

namespace
{
// A case file of n small cases named c0, c1, ..., one per line, as text; `extra` goes into every
// case before its name.
std::string smallCases(int n, const std::string& extra = "")
{
    std::string text = "{\"format\": \"gjk-cases/1\", \"cases\": [\n";
    for (int i = 0; i < n; ++i)
        text += (i > 0 ? ",\n{" : "{") + extra + "\"name\": \"c" + std::to_string(i) +
                "\", \"a\": {\"points\": [[0, " + std::to_string(i) +
                "]], \"radius\": 0.5}, \"b\": {\"points\": [[1.25, -2], [3, 4]], "
                "\"transform\": {\"p\": [1, 2], \"q\": [0.6, 0.8]}}}";
    return text + "\n]}\n";
}
} // namespace

TEST_CASE("a pipe is read as it arrives, not whole first", "[cases][files][pipe]")
{
    // The writer sends the first case, then waits until the reader has passed it on before it
    // sends the rest: a reader that read the pipe whole first would see the first case only
    // after the writer gave up waiting.
    const std::string fifo = std::string(VALIDATION_TEST_TMP) + "/case-files/stream.fifo";
    std::filesystem::create_directories(std::filesystem::path(fifo).parent_path());
    std::filesystem::remove(fifo);
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string text = smallCases(3);
    const std::size_t cut = text.find("},\n{\"name\": \"c1\"") + 3; // after the first case
    std::atomic<bool> firstSeen{false}, waited{false};
    std::thread writer(
        [&]
        {
            const int fd = open(fifo.c_str(), O_WRONLY);
            if (fd < 0)
                return;
            (void)!write(fd, text.data(), cut);
            for (int i = 0; i < 1000 && !firstSeen; ++i) // up to 10 s
                std::this_thread::sleep_for(std::chrono::milliseconds(10));
            waited = firstSeen.load();
            (void)!write(fd, text.data() + cut, text.size() - cut);
            close(fd);
        });
    std::vector<std::string> names;
    streamCaseFile(fifo,
                   [&](CaseEntry&& e)
                   {
                       names.push_back(e.c.name);
                       firstSeen = true;
                   });
    writer.join();
    std::filesystem::remove(fifo);
    CHECK(waited);
    CHECK(names == std::vector<std::string>{"c0", "c1", "c2"});
}

TEST_CASE("a pipe's copy is read twice and named as the pipe", "[cases][files][pipe]")
{
    const std::string fifo = std::string(VALIDATION_TEST_TMP) + "/case-files/copied.fifo";
    std::filesystem::create_directories(std::filesystem::path(fifo).parent_path());
    std::filesystem::remove(fifo);
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string text = smallCases(2, "\"x\": 1, "); // "x": read and dropped
    std::thread writer(
        [&]
        {
            const int fd = open(fifo.c_str(), O_WRONLY);
            if (fd >= 0)
                (void)!write(fd, text.data(), text.size());
            close(fd);
        });
    const PipeCopy copy(fifo);
    writer.join();
    std::filesystem::remove(fifo);
    for (int pass = 0; pass < 2; ++pass)
    {
        std::vector<std::string> labels;
        const CaseFileSummary s =
            streamCaseFile(copy.path(), fifo, [&](CaseEntry&& e) { labels.push_back(e.label); });
        CHECK(s.entries == 2);
        CHECK(labels ==
              std::vector<std::string>{"copied.fifo#0 (case 'c0')", "copied.fifo#1 (case 'c1')"});
    }
}

TEST_CASE("the fast reader and the SAX reader give the same entries and messages", "[cases]")
{
    // An unknown field ("x": dropped by readCase) sends every case through the SAX path; without
    // it the same cases take the fast path.
    const CaseFile fast = parseCaseFile(smallCases(50), "f.json");
    const CaseFile slow = parseCaseFile(smallCases(50, "\"x\": [true], "), "f.json");
    REQUIRE(fast.entries.size() == 50);
    REQUIRE(slow.entries.size() == 50);
    for (std::size_t i = 0; i < 50; ++i)
    {
        CHECK(fast.entries[i].label == slow.entries[i].label);
        CHECK(fast.entries[i].rejected.empty());
        CHECK(slow.entries[i].rejected.empty());
        CHECK(caseFileText({}, {fast.entries[i].c}) == caseFileText({}, {slow.entries[i].c}));
    }
    // A name seen before is rejected either way.
    std::string twice = smallCases(2);
    twice.replace(twice.find("\"c1\""), 4, "\"c0\"");
    const CaseFile d = parseCaseFile(twice, "d.json");
    REQUIRE(d.entries.size() == 2);
    CHECK(d.entries[1].rejected == "duplicate case name 'c0'");
    CHECK(d.entries[1].label == "d.json#1 (case 'c0')");
    // An error after cases the fast path read: line, column and nlohmann's "last read" as main's
    // SAX-only reader gave them (the characters from the last case's last number on).
    const std::string late =
        "{\"format\": \"gjk-cases/1\", \"cases\": [\n"
        "{\"name\": \"a\", \"a\": {\"points\": [[0, 0]]}, \"b\": {\"points\": [[1, 1]]}},\n"
        "{\"name\": \"b\", \"a\": {\"points\": [[0, 0]]}, \"b\": {\"points\": [[1, 1]]}} x\n]}\n";
    CHECK(messageOf(late, "late.json") ==
          "late.json:3:69: invalid JSON: syntax error while parsing array - invalid literal; "
          "last read: '1]]}} x'; expected ']'");
}

TEST_CASE("duplicate names are found among many, in a few bytes a name", "[cases]")
{
    NameSet names;
    for (int i = 0; i < 200'000; ++i)
        REQUIRE(names.insert("random/" + std::to_string(i)));
    for (int i = 0; i < 200'000; i += 997)
        CHECK_FALSE(names.insert("random/" + std::to_string(i)));
    CHECK(names.insert("random/200000"));
    CHECK(names.insert(""));
    CHECK_FALSE(names.insert(""));
}

TEST_CASE("the name set answers as a set of strings, whichever way it keeps a name", "[cases]")
{
    // Names of every kind NameSet keeps apart: counted (a stem and a counter, in order, shuffled
    // past kMaxRanges ranges, or for more stems than kCountedStems), and hashed (no counter, a
    // leading 0, 19 digits). Each is inserted twice, in a shuffled order; std::set decides.
    std::vector<std::string> names;
    for (int i = 0; i < 5000; ++i)
        names.push_back("random/" + std::to_string(i)); // in order: one range
    for (int i = 0; i < 3000; ++i)
        names.push_back("s/" + std::to_string(i * 7 % 3001 * 2)); // even only: past kMaxRanges
    for (std::size_t stem = 0; stem < NameSet::kCountedStems + 10; ++stem)
        names.push_back("stem" + std::to_string(stem) + "-" + std::to_string(stem % 3));
    for (const char* n : {"0", "1", "00", "01", "c01", "c1", "c10", "x", "", "1234567890123456789",
                          "123456789012345678", "c999999999999999999", "c99999999999999999"})
        names.emplace_back(n);
    std::vector<std::string> order = names;
    order.insert(order.end(), names.begin(), names.end());
    std::mt19937_64 rng(7);
    std::shuffle(order.begin(), order.end(), rng);
    NameSet set;
    std::set<std::string> reference;
    for (const std::string& n : order)
    {
        INFO(n);
        REQUIRE(set.insert(n) == reference.insert(n).second);
    }
    CHECK(reference.size() == names.size()); // the names listed are all different
}

TEST_CASE("the streaming reader reads from disk what the whole-file reader reads", "[cases][files]")
{
    // streamCaseFile (what run uses, one case at a time from disk) and parseCaseFile (the file in
    // memory) share the handler but not the input: same entries, comments and errors.
    const std::string data = VALIDATION_TEST_DATA;
    for (const std::string& path :
         {data + "/bad-cases.json", std::string(GJK2D_SOURCE_DIR) + "/validation/cases/talk.json",
          std::string(GJK2D_SOURCE_DIR) + "/validation/cases/transforms.json"})
    {
        INFO(path);
        const CaseFile whole = readCaseFile(path);
        std::vector<CaseEntry> streamed;
        const CaseFileSummary summary =
            streamCaseFile(path, [&](CaseEntry&& e) { streamed.push_back(std::move(e)); });
        CHECK(summary.comments == whole.comments);
        REQUIRE(summary.entries == whole.entries.size());
        REQUIRE(streamed.size() == whole.entries.size());
        for (std::size_t i = 0; i < streamed.size(); ++i)
        {
            CHECK(streamed[i].label == whole.entries[i].label);
            CHECK(streamed[i].rejected == whole.entries[i].rejected);
            CHECK(caseFileText({}, {streamed[i].c}) == caseFileText({}, {whole.entries[i].c}));
        }
    }
    // An error on the third line of a file on disk: the same line, column and message.
    const std::filesystem::path dir = std::string(VALIDATION_TEST_TMP) + "/case-files";
    std::filesystem::create_directories(dir);
    const std::string bad = (dir / "bad-at-3.json").string();
    std::ofstream(bad)
        << "{\"format\": \"gjk-cases/1\",\n \"cases\": [\n  {\"name\": \"x\", \"a\": }\n ]}\n";
    std::string streamedMessage;
    try
    {
        streamCaseFile(bad, [](CaseEntry&&) {});
    }
    catch (const InputError& e)
    {
        streamedMessage = e.what();
    }
    CHECK(streamedMessage.rfind(bad + ":3:22: invalid JSON", 0) == 0);
}
