// One case of a gjk-cases/1 file read field by field: shapes, transforms, radii and provenance,
// each field checked, every error one line naming the case and the field (the case is rejected).
#include "inputs/case_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

namespace gjkval
{

const char* typeName(const RJson& j)
{
    switch (j.type())
    {
    case RJson::value_t::null:
        return "null";
    case RJson::value_t::object:
        return "an object";
    case RJson::value_t::array:
        return "an array";
    case RJson::value_t::string:
        return "a string";
    case RJson::value_t::boolean:
        return "a boolean";
    case RJson::value_t::number_integer:
    case RJson::value_t::number_unsigned:
    case RJson::value_t::number_float:
        return "a number";
    default:
        return "not a value";
    }
}

namespace
{
std::uint64_t load(const char* p, std::size_t n)
{
    std::uint64_t v = 0;
    std::memcpy(&v, p, n);
    return v;
}

// 64x64 -> 128-bit multiply folded to 64 bits: every input bit reaches every output bit.
std::uint64_t mix(std::uint64_t a, std::uint64_t b)
{
    const unsigned __int128 r = static_cast<unsigned __int128>(a) * b;
    return std::uint64_t(r) ^ std::uint64_t(r >> 64);
}

std::uint64_t nameHash(std::string_view s)
{
    constexpr std::uint64_t k0 = 0xa0761d6478bd642fULL, k1 = 0xe7037ed1a0b428dbULL,
                            k2 = 0x8ebc6af09c88c6e3ULL;
    std::uint64_t h = mix(s.size() ^ k0, k1);
    std::size_t i = 0;
    for (; i + 8 <= s.size(); i += 8)
        h = mix(h ^ load(s.data() + i, 8), k1 ^ (h << 1 | 1));
    if (i < s.size())
        h = mix(h ^ load(s.data() + i, s.size() - i) ^ k2, k1);
    return mix(h, k0) ^ h;
}

constexpr std::size_t kRecord = 6; // bytes a name takes in its bucket: the hash's low 48 bits

std::uint64_t record(const unsigned char* p)
{
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < kRecord; ++i)
        v = v << 8 | p[i];
    return v;
}

// A name's trailing counter: where its digits start and their value, or nullopt when it has
// none that NameSet counts (none, a leading 0, or more than 18 digits: the value fits 63 bits).
std::optional<std::pair<std::size_t, std::uint64_t>> trailingCounter(std::string_view name)
{
    std::size_t start = name.size();
    while (start > 0 && name[start - 1] >= '0' && name[start - 1] <= '9')
        --start;
    const std::size_t digits = name.size() - start;
    if (digits == 0 || digits > 18 || (digits > 1 && name[start] == '0'))
        return std::nullopt;
    std::uint64_t value = 0;
    for (std::size_t i = start; i < name.size(); ++i)
        value = value * 10 + std::uint64_t(name[i] - '0');
    return std::pair{start, value};
}
} // namespace

NameSet::NameSet() : buckets_(std::size_t(1) << 16) {}

bool NameSet::insert(std::string_view name)
{
    const auto counter = trailingCounter(name);
    if (!counter)
        return insertHashed(name);
    const std::string_view stem = name.substr(0, counter->first);
    auto it = stems_.find(stem);
    if (it == stems_.end())
    {
        if (stems_.size() >= kCountedStems) // a stem first seen now: hashed for good
            return insertHashed(name);
        it = stems_.emplace(std::string(stem), Stem{}).first;
    }
    return it->second.hashed ? insertHashed(name) : insertCounted(it, counter->second);
}

// Adds `counter` to its stem's ranges, merging with the ranges it touches; past kMaxRanges, the
// stem's counters go to the hashes, and so do its names from then on.
bool NameSet::insertCounted(std::map<std::string, Stem, std::less<>>::iterator stem,
                            std::uint64_t counter)
{
    auto& ranges = stem->second.ranges;
    auto next = ranges.upper_bound(counter); // the first range starting past counter
    if (next != ranges.begin() && counter < std::prev(next)->second)
        return false; // inside the range before
    const bool joinsBefore = next != ranges.begin() && std::prev(next)->second == counter;
    const bool joinsAfter = next != ranges.end() && next->first == counter + 1;
    if (joinsBefore && joinsAfter)
    {
        std::prev(next)->second = next->second;
        ranges.erase(next);
    }
    else if (joinsBefore)
        std::prev(next)->second = counter + 1;
    else if (joinsAfter)
    {
        const std::uint64_t end = next->second;
        ranges.erase(next);
        ranges.emplace(counter, end);
    }
    else
        ranges.emplace(counter, counter + 1);
    if (ranges.size() > kMaxRanges)
    {
        for (const auto& [first, end] : ranges)
            for (std::uint64_t k = first; k < end; ++k)
                insertHashed(stem->first + std::to_string(k));
        ranges.clear();
        stem->second.hashed = true;
    }
    return true;
}

bool NameSet::insertHashed(std::string_view name)
{
    const std::uint64_t h = nameHash(name);
    std::vector<unsigned char>& b = buckets_[h >> 48];
    const std::uint64_t key = h & ((std::uint64_t(1) << 48) - 1);
    std::size_t lo = 0, hi = b.size() / kRecord;
    while (lo < hi)
    {
        const std::size_t mid = (lo + hi) / 2;
        const std::uint64_t k = record(b.data() + mid * kRecord);
        if (k == key)
            return false;
        (k < key ? lo = mid + 1 : hi = mid);
    }
    if (b.size() + kRecord > b.capacity()) // grow by an eighth: little unused room
        b.reserve(b.size() + b.size() / 8 + 8 * kRecord);
    unsigned char bytes[kRecord];
    for (std::size_t i = 0; i < kRecord; ++i)
        bytes[i] = static_cast<unsigned char>(key >> (8 * (kRecord - 1 - i)));
    b.insert(b.begin() + std::ptrdiff_t(lo * kRecord), bytes, bytes + kRecord);
    return true;
}

namespace
{
// A field error: thrown while reading one case, caught per case (the case is rejected).
struct FieldError
{
    std::string message;
};

[[noreturn]] void fieldError(std::string message)
{
    throw FieldError{std::move(message)};
}

// A number field. JSON has no NaN or infinity: the strings "nan", "inf", "-inf" (the report's own
// convention) are read as such so that they can be rejected with a precise message.
double readNumber(const RJson& j, const std::string& field)
{
    double v = 0;
    if (j.is_number())
        v = j.get<double>();
    else if (j.is_string())
    {
        std::string s = j.get<std::string>();
        for (auto& ch : s)
            ch = char(std::tolower(static_cast<unsigned char>(ch)));
        if (s == "nan" || s == "-nan" || s == "+nan")
            v = std::numeric_limits<double>::quiet_NaN();
        else if (s == "inf" || s == "+inf" || s == "infinity" || s == "+infinity")
            v = std::numeric_limits<double>::infinity();
        else if (s == "-inf" || s == "-infinity")
            v = -std::numeric_limits<double>::infinity();
        else
            fieldError(fmt::format("{} is a string, expected a number", field));
    }
    else
        fieldError(fmt::format("{} is {}, expected a number", field, typeName(j)));
    if (std::isnan(v))
        fieldError(fmt::format("{} is NaN", field));
    if (std::isinf(v))
        fieldError(fmt::format("{} is infinite", field));
    return v;
}

std::array<double, 2> readPair(const RJson& j, const std::string& field)
{
    if (!j.is_array())
        fieldError(fmt::format("{} is {}, expected an array [x, y]", field, typeName(j)));
    if (j.size() != 2)
        fieldError(fmt::format("{} has {} elements, expected 2", field, j.size()));
    return {readNumber(j[0], field + "[0]"), readNumber(j[1], field + "[1]")};
}

ShapeIn readShape(const RJson& c, const char* key)
{
    const std::string k = key;
    if (!c.contains(key))
        fieldError(fmt::format("missing field '{}'", k));
    const RJson& j = c[key];
    if (!j.is_object())
        fieldError(fmt::format("{} is {}, expected an object", k, typeName(j)));
    ShapeIn s;
    if (!j.contains("points"))
        fieldError(fmt::format("missing field '{}.points'", k));
    const RJson& pts = j["points"];
    if (!pts.is_array())
        fieldError(fmt::format("{}.points is {}, expected an array", k, typeName(pts)));
    if (pts.empty())
        fieldError(fmt::format("{}.points is empty", k));
    if (pts.size() > kMaxShapePoints)
        fieldError(
            fmt::format("{}.points has {} points, more than {}", k, pts.size(), kMaxShapePoints));
    s.points.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
        s.points.push_back(readPair(pts[i], fmt::format("{}.points[{}]", k, i)));
    if (j.contains("radius"))
    {
        s.radius = readNumber(j["radius"], k + ".radius");
        if (s.radius < 0)
            fieldError(fmt::format("{}.radius is negative ({})", k, s.radius));
    }
    if (j.contains("transform"))
    {
        const RJson& t = j["transform"];
        if (!t.is_object())
            fieldError(fmt::format("{}.transform is {}, expected an object", k, typeName(t)));
        if (t.contains("p"))
        {
            const auto p = readPair(t["p"], k + ".transform.p");
            s.px = p[0];
            s.py = p[1];
        }
        if (t.contains("q"))
        {
            const auto q = readPair(t["q"], k + ".transform.q");
            s.c = q[0];
            s.s = q[1];
            // Any finite (c, s) other than (0, 0) is a transform (x' = c x - s y + p scales by
            // sqrt(c^2 + s^2)): GJK and the exact side both apply it as given. A float engine's
            // (cos, sin) is a unit vector only to float rounding. (0, 0) maps the whole
            // shape to one point: not a transform.
            if (s.c == 0 && s.s == 0)
                fieldError(fmt::format("{}.transform.q is (0, 0): not a rotation", k));
        }
    }
    return s;
}

// An optional provenance field ("source", "comment"): a string of at most kMaxCommentBytes, or
// absent (empty). Printed by `explain` and kept in a case's detail, so bounded like a file comment.
std::string readText(const RJson& c, const char* key)
{
    if (!c.contains(key))
        return {};
    const RJson& j = c[key];
    if (!j.is_string())
        fieldError(fmt::format("{} is {}, expected a string", key, typeName(j)));
    const std::string& s = j.get_ref<const std::string&>();
    if (s.size() > kMaxCommentBytes)
        fieldError(
            fmt::format("{} is {} bytes long, more than {}", key, s.size(), kMaxCommentBytes));
    return s;
}

} // namespace

bool isControl(std::string_view s)
{
    for (std::size_t i = 0; i < s.size();)
    {
        const std::size_t n = utf8SequenceLength(s, i);
        const unsigned c = static_cast<unsigned char>(s[i]);
        if (n == 0 || c < 0x20 || c == 0x7F ||
            (n == 2 && c == 0xC2 && static_cast<unsigned char>(s[i + 1]) < 0xA0))
            return true;
        i += n;
    }
    return false;
}

namespace
{
// How long a label's quote of a case name is at most (excerpt's cut).
constexpr std::size_t kQuotedNameBytes = 60;

// "BASE#INDEX (case 'NAME')", NAME quoted by excerpt. A name of printable ASCII without a
// backslash and not longer than the cut is its own excerpt: that label, the one of nearly every
// case of a large file, is put together directly (its formatting showed in the reader's
// profile: docs/speed.md, "Case files").
std::string namedLabel(const std::string& base, std::size_t index, const std::string& name)
{
    const bool plain = name.size() <= kQuotedNameBytes &&
                       std::all_of(name.begin(), name.end(),
                                   [](char c) { return c >= 0x20 && c < 0x7F && c != '\\'; });
    if (!plain)
        return fmt::format("{}#{} (case '{}')", base, index, excerpt(name, kQuotedNameBytes));
    char digits[24];
    const auto end = std::to_chars(digits, digits + sizeof digits, index).ptr;
    std::string label;
    label.reserve(base.size() + std::size_t(end - digits) + name.size() + 10);
    label.append(base)
        .append(1, '#')
        .append(digits, end)
        .append(" (case '")
        .append(name)
        .append("')");
    return label;
}

std::string duplicateName(const std::string& name)
{
    return fmt::format("duplicate case name '{}'", excerpt(name));
}
} // namespace

CaseEntry acceptCase(Case&& c, std::size_t index, const std::string& base, NameSet& names)
{
    CaseEntry e;
    e.label = namedLabel(base, index, c.name);
    if (names.insert(c.name))
        e.c = std::move(c);
    else
    {
        e.rejected = duplicateName(c.name);
        e.c.name = e.label;
    }
    return e;
}

CaseEntry readCase(const RJson& c, std::size_t index, bool truncated, const std::string& base,
                   NameSet& names)
{
    CaseEntry e;
    e.label = fmt::format("{}#{}", base, index);
    try
    {
        const std::string tooLarge =
            fmt::format("the case has more than {} JSON values", kMaxCaseJsonValues);
        if (truncated && !(c.is_object() && c.contains("name")))
            fieldError(tooLarge);
        if (!c.is_object())
            fieldError(fmt::format("the case is {}, expected an object", typeName(c)));
        if (!c.contains("name"))
            fieldError("missing field 'name'");
        if (!c["name"].is_string() || c["name"].get_ref<const std::string&>().empty())
            fieldError("name is not a non-empty string");
        // The name is quoted in labels, reports and terminals and looked up by `explain`: short,
        // printable, and (as every JSON string nlohmann reads) valid UTF-8.
        const std::string& name = c["name"].get_ref<const std::string&>();
        e.label = namedLabel(base, index, name);
        if (name.size() > kMaxCaseNameBytes)
            fieldError(
                fmt::format("name is {} bytes long, more than {}", name.size(), kMaxCaseNameBytes));
        if (!isValidUtf8(name) || isControl(name))
            fieldError("name contains a control character or is not valid UTF-8");
        if (!names.insert(name))
            fieldError(duplicateName(name));
        e.c.name = name;
        if (truncated) // named when the name came before the cut
            fieldError(tooLarge);
        e.c.a = readShape(c, "a");
        e.c.b = readShape(c, "b");
        e.c.source = readText(c, "source");
        e.c.comment = readText(c, "comment");
    }
    catch (const FieldError& err)
    {
        e.rejected = err.message;
        if (e.c.name.empty())
            e.c.name = e.label;
    }
    return e;
}

} // namespace gjkval
