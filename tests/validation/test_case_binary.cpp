// The binary case-file form gjk-cases-msgpack/1: the same cases as the JSON form bit for bit,
// recognised by content, invalid cases rejected one by one, broken files refused in one line.
#include "inputs/case_binary.hpp"
#include "inputs/cases.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

using namespace gjkval;

namespace
{
std::uint64_t bits(double v)
{
    return std::bit_cast<std::uint64_t>(v);
}

void requireSameCase(const Case& x, const Case& y)
{
    CHECK(x.name == y.name);
    CHECK(x.source == y.source);
    CHECK(x.comment == y.comment);
    for (auto shape : {&Case::a, &Case::b})
    {
        const ShapeIn &s = x.*shape, &t = y.*shape;
        REQUIRE(s.points.size() == t.points.size());
        for (std::size_t i = 0; i < s.points.size(); ++i)
        {
            CHECK(bits(s.points[i][0]) == bits(t.points[i][0]));
            CHECK(bits(s.points[i][1]) == bits(t.points[i][1]));
        }
        CHECK(bits(s.radius) == bits(t.radius));
        CHECK(bits(s.px) == bits(t.px));
        CHECK(bits(s.py) == bits(t.py));
        CHECK(bits(s.c) == bits(t.c));
        CHECK(bits(s.s) == bits(t.s));
    }
}

// Cases whose numbers are awkward for any text or binary form: floats (the values a float engine
// records, as doubles), doubles of every exponent, subnormals, -0, non-unit rotations; names and
// provenance with non-ASCII text; shapes of 1 to 9 points.
std::vector<Case> awkwardCases(std::size_t n, bool asFloat)
{
    std::mt19937_64 rng(n * 2 + asFloat);
    std::uniform_int_distribution<std::uint64_t> anyBits;
    // Any finite value of the type, from its bits: a float as the double it converts to exactly.
    const auto number = [&]
    {
        double v;
        do
            v = asFloat ? double(std::bit_cast<float>(std::uint32_t(anyBits(rng))))
                        : std::bit_cast<double>(anyBits(rng));
        while (!std::isfinite(v));
        return v;
    };
    std::vector<Case> cases;
    for (std::size_t i = 0; i < n; ++i)
    {
        Case c;
        c.name = "awkward/" + std::to_string(i) + (i % 3 == 0 ? "-\u00e9\u4e2d" : "");
        for (auto shape : {&Case::a, &Case::b})
        {
            ShapeIn& s = c.*shape;
            s.points.resize(1 + (i + (shape == &Case::b)) % 9);
            for (auto& p : s.points)
                p = {number(), number()};
            s.radius = i % 4 == 0 ? 0.0 : i % 4 == 1 ? -0.0 : std::fabs(number());
            if (i % 5 != 0)
                s.px = number(), s.py = number(), s.c = number(), s.s = number();
            if (s.c == 0 && s.s == 0) // not a rotation: the reader rejects it (tested below)
                s.c = 1;
        }
        c.a.points[0] = {std::numeric_limits<double>::denorm_min(), -0.0};
        if (i % 2 == 0)
            c.source = "https://example.org/trace?" + std::to_string(i);
        if (i % 3 == 1)
            c.comment = "recorded at step " + std::to_string(i) + " \u2014 \"quoted\"";
        cases.push_back(c);
    }
    return cases;
}

std::string messageOf(const std::string& bytes)
{
    try
    {
        parseBinaryCaseFile(bytes, "dir/broken.bin");
    }
    catch (const InputError& e)
    {
        return e.what();
    }
    return "(no error)";
}

std::string tempPath(const std::string& name)
{
    return (std::filesystem::temp_directory_path() /
            ("gjk2d-binary-" + std::to_string(::getpid()) + "-" + name))
        .string();
}

void writeBytes(const std::string& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary) << bytes;
}
} // namespace

TEST_CASE("binary case files: the same cases as the JSON form, bit for bit", "[cases][binary]")
{
    for (const bool asFloat : {false, true})
    {
        CAPTURE(asFloat);
        const std::vector<std::string> comments = {"a comment", "unicode \u00e9 and \"quotes\""};
        const std::vector<Case> cases = awkwardCases(60, asFloat);
        // JSON -> cases -> binary -> cases: nothing changes, not a bit.
        const std::string json = caseFileText(comments, cases);
        const CaseFile fromJson = parseCaseFile(json, "r.json");
        std::vector<Case> read;
        for (const auto& e : fromJson.entries)
        {
            REQUIRE(e.rejected.empty());
            read.push_back(e.c);
        }
        const std::string bytes = binaryCaseFileBytes(fromJson.comments, read);
        CHECK(bytes.size() < json.size());
        const CaseFile back = parseBinaryCaseFile(bytes, "r.bin");
        CHECK(back.comments == comments);
        REQUIRE(back.entries.size() == cases.size());
        for (std::size_t i = 0; i < cases.size(); ++i)
        {
            REQUIRE(back.entries[i].rejected.empty());
            requireSameCase(back.entries[i].c, cases[i]);
            CHECK(back.entries[i].label ==
                  "r.bin#" + std::to_string(i) + " (case '" + excerpt(cases[i].name) + "')");
        }
        // ... and back to the same JSON text.
        std::vector<Case> again;
        for (const auto& e : back.entries)
            again.push_back(e.c);
        CHECK(caseFileText(back.comments, again) == json);
    }
}

TEST_CASE("binary case files: recognised by content, streamed in blocks", "[cases][binary]")
{
    // More cases than a block holds, so that the reader crosses blocks; two cases of many points
    // close a block early.
    std::vector<Case> cases = awkwardCases(kWriterBlockCases + 300, false);
    cases[17].a.points.assign(kWriterBlockPoints / 2 + 1, {1.0, 2.0});
    cases[18].b.points.assign(kWriterBlockPoints / 2 + 1, {3.0, 2.0});
    const std::string bytes = binaryCaseFileBytes({"c"}, cases);
    const std::string path = tempPath("named.json"); // the extension does not matter
    writeBytes(path, bytes);
    CHECK(isBinaryCaseFile(path));
    const CaseFile whole = readCaseFile(path);
    std::vector<CaseEntry> streamed;
    const CaseFileSummary summary =
        streamCaseFile(path, [&](CaseEntry&& e) { streamed.push_back(std::move(e)); });
    CHECK(summary.comments == std::vector<std::string>{"c"});
    CHECK(summary.entries == cases.size());
    REQUIRE(whole.entries.size() == cases.size());
    REQUIRE(streamed.size() == cases.size());
    for (std::size_t i = 0; i < cases.size(); i += 97)
    {
        requireSameCase(whole.entries[i].c, cases[i]);
        requireSameCase(streamed[i].c, cases[i]);
        CHECK(streamed[i].label == "gjk2d-binary-" + std::to_string(::getpid()) + "-named.json#" +
                                       std::to_string(i) + " (case '" + cases[i].name + "')");
    }
    requireSameCase(streamed[17].c, cases[17]);
    requireSameCase(streamed[18].c, cases[18]);
    // A JSON file named .bin is read as JSON.
    writeBytes(path, caseFileText({"c"}, {cases[0]}));
    CHECK_FALSE(isBinaryCaseFile(path));
    CHECK(readCaseFile(path).entries.size() == 1);
    std::filesystem::remove(path);
}

TEST_CASE("binary case files: an invalid case is rejected, the others kept", "[cases][binary]")
{
    std::vector<Case> cases = awkwardCases(12, true);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    cases[1].a.points[0][1] = nan;
    cases[2].b.radius = -1;
    cases[3].b.c = 0, cases[3].b.s = 0;
    cases[4].a.points.clear();
    cases[5].name = cases[0].name;
    cases[6].name = "";
    cases[7].name = "esc\x1b[2J";
    cases[8].b.py = -inf;
    cases[9].comment = std::string(kMaxCommentBytes + 1, 'x');
    cases[10].source = "\xff not UTF-8";
    const CaseFile f = parseBinaryCaseFile(binaryCaseFileBytes({}, cases), "dir/bad.bin");
    REQUIRE(f.entries.size() == cases.size());
    const auto rejected = [&](std::size_t i) { return f.entries[i].rejected; };
    CHECK(rejected(0).empty());
    CHECK(rejected(1) == "a.points[0][1] is NaN");
    CHECK(rejected(2) == "b.radius is negative (-1)");
    CHECK(rejected(3) == "b.transform.q is (0, 0): not a rotation");
    CHECK(rejected(4) == "a.points is empty");
    CHECK(rejected(5) == "duplicate case name '" + cases[0].name + "'");
    CHECK(rejected(6) == "name is not a non-empty string");
    CHECK(f.entries[6].label == "bad.bin#6");
    CHECK(rejected(7) == "name contains a control character or is not valid UTF-8");
    CHECK(f.entries[7].label == "bad.bin#7 (case 'esc\\x1B[2J')");
    CHECK(rejected(8) == "b.transform.p[1] is infinite");
    CHECK(rejected(9) == fmt::format("comment is {} bytes long, more than {}", kMaxCommentBytes + 1,
                                     kMaxCommentBytes));
    CHECK(rejected(10) == "source is not valid UTF-8");
    CHECK(rejected(11).empty());
    requireSameCase(f.entries[11].c, cases[11]);
    // The same fields give the same messages in the JSON form (where it can say them: JSON has no
    // NaN, so those travel as the strings the JSON reader also takes).
    const CaseFile j = parseCaseFile(caseFileText({}, {cases[2], cases[3], cases[4]}), "bad.json");
    CHECK(j.entries[0].rejected == rejected(2));
    CHECK(j.entries[1].rejected == rejected(3));
    CHECK(j.entries[2].rejected == rejected(4));
}

TEST_CASE("binary case files: a broken file is refused in one line", "[cases][binary]")
{
    const std::string good = binaryCaseFileBytes({"comment"}, awkwardCases(3, false));
    REQUIRE(messageOf(good) == "(no error)");
    // Cut anywhere: an error naming the file, never a crash nor a silent loss. Cut right after
    // the header, it is a valid file of no cases.
    const std::size_t header = binaryCaseFileBytes({"comment"}, {}).size();
    CHECK(parseBinaryCaseFile(good.substr(0, header), "h.bin").entries.empty());
    for (std::size_t n = 1; n < good.size(); ++n)
    {
        CAPTURE(n);
        if (n == header)
            continue;
        const std::string m = messageOf(good.substr(0, n));
        CHECK(m.rfind("dir/broken.bin: ", 0) == 0);
        CHECK(m.find('\n') == std::string::npos);
    }
    CHECK(messageOf(good.substr(0, good.size() - 1)) ==
          "dir/broken.bin: in block 0 (after case 0): the file ends inside it (truncated)");
    // Any byte changed: accepted or refused with InputError, nothing else escapes.
    std::mt19937 rng(7);
    for (int k = 0; k < 2000; ++k)
    {
        std::string bad = good;
        bad[rng() % bad.size()] = char(rng());
        try
        {
            parseBinaryCaseFile(bad, "flip.bin");
        }
        catch (const InputError&)
        {
        }
    }
    // A header of another format, a block whose columns disagree.
    std::string other = good;
    other[other.find("msgpack/1") + 8] = '2';
    CHECK(messageOf(other) ==
          "dir/broken.bin: not a gjk-cases-msgpack/1 file: format is \"gjk-cases-msgpack/2\"");
    std::vector<Case> two = awkwardCases(2, false);
    std::string cut = binaryCaseFileBytes({}, two);
    // The block's a.counts says 1 point for case 0 (awkwardCases), make it 2: a.points is short.
    const std::size_t counts = cut.find("counts") + 6 + 2; // "counts", bin8 header (2 bytes)
    REQUIRE(cut[counts] == 1);
    cut[counts] = 2;
    CHECK(messageOf(cut) == "dir/broken.bin: block 0 (cases 0..): a.points is 48 bytes, expected "
                            "64 (4 values of 16 bytes)");
    CHECK(messageOf(good + "\xc1") ==
          "dir/broken.bin: in block 1 (after case 3): invalid MessagePack: parse error");
}
