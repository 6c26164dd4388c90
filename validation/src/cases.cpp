#include "cases.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace gjkval
{
namespace
{
using RJson = nlohmann::json; // reading: key order does not matter

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
            // The GJK side inverts a rotation by transposing it: (c, s) must be a rotation to
            // within the rounding of cos and sin (write them with 17 significant digits).
            const double n = s.c * s.c + s.s * s.s - 1.0;
            if (!(std::abs(n) <= 1e-12))
                fieldError(
                    fmt::format("{}.transform.q is not a rotation: c^2 + s^2 - 1 = {:.3g}", k, n));
        }
    }
    return s;
}

std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(fmt::format("{}: cannot open the file", path));
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

bool bitsEqual(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

} // namespace

std::pair<std::size_t, std::size_t> lineColumn(const std::string& text, std::size_t byteOffset)
{
    std::size_t line = 1, column = 1;
    const std::size_t end = std::min(byteOffset, text.size());
    for (std::size_t i = 0; i < end; ++i)
    {
        if (text[i] == '\n')
        {
            ++line;
            column = 1;
        }
        else
            ++column;
    }
    return {line, column};
}

CaseFile parseCaseFile(const std::string& text, const std::string& sourceName)
{
    RJson j;
    try
    {
        j = RJson::parse(text);
    }
    catch (const RJson::parse_error& e)
    {
        // nlohmann's byte is the 1-based position of the offending character.
        const auto [line, col] = lineColumn(text, e.byte == 0 ? 0 : e.byte - 1);
        std::string what = e.what();
        const auto at = what.find("] ");
        throw InputError(fmt::format("{}:{}:{}: invalid JSON: {}", sourceName, line, col,
                                     at == std::string::npos ? what : what.substr(at + 2)));
    }
    catch (const RJson::exception& e)
    {
        throw InputError(fmt::format("{}: invalid JSON: {}", sourceName, e.what()));
    }
    if (!j.is_object())
        throw InputError(fmt::format("{}: not a {} file: the top level is {}, expected an object",
                                     sourceName, kCaseFormat, typeName(j)));
    if (!j.contains("format"))
        throw InputError(
            fmt::format("{}: not a {} file: no \"format\" field", sourceName, kCaseFormat));
    if (!j["format"].is_string() || j["format"].get<std::string>() != kCaseFormat)
        throw InputError(fmt::format("{}: not a {} file: format is {}", sourceName, kCaseFormat,
                                     j["format"].dump()));
    if (!j.contains("cases") || !j["cases"].is_array())
        throw InputError(fmt::format("{}: \"cases\" is missing or not an array", sourceName));

    CaseFile file;
    file.path = sourceName;
    if (j.contains("comments"))
    {
        const RJson& cm = j["comments"];
        if (!cm.is_array())
            throw InputError(
                fmt::format("{}: \"comments\" is not an array of strings", sourceName));
        for (const auto& s : cm)
        {
            if (!s.is_string())
                throw InputError(
                    fmt::format("{}: \"comments\" is not an array of strings", sourceName));
            file.comments.push_back(s.get<std::string>());
        }
    }

    std::string base = sourceName;
    if (const auto slash = base.find_last_of('/'); slash != std::string::npos)
        base = base.substr(slash + 1);
    std::set<std::string> names;
    const RJson& cases = j["cases"];
    for (std::size_t i = 0; i < cases.size(); ++i)
    {
        CaseEntry e;
        const RJson& c = cases[i];
        e.label = fmt::format("{}#{}", base, i);
        try
        {
            if (!c.is_object())
                fieldError(fmt::format("the case is {}, expected an object", typeName(c)));
            if (!c.contains("name"))
                fieldError("missing field 'name'");
            if (!c["name"].is_string() || c["name"].get<std::string>().empty())
                fieldError("name is not a non-empty string");
            e.c.name = c["name"].get<std::string>();
            e.label = fmt::format("{}#{} (case '{}')", base, i, e.c.name);
            if (!names.insert(e.c.name).second)
                fieldError(fmt::format("duplicate case name '{}'", e.c.name));
            e.c.a = readShape(c, "a");
            e.c.b = readShape(c, "b");
        }
        catch (const FieldError& err)
        {
            e.rejected = err.message;
            if (e.c.name.empty())
                e.c.name = e.label;
        }
        file.entries.push_back(std::move(e));
    }
    return file;
}

CaseFile readCaseFile(const std::string& path)
{
    return parseCaseFile(readFile(path), path);
}

Json shapeToJson(const ShapeIn& s)
{
    Json pts = Json::array();
    for (const auto& p : s.points)
        pts.push_back(Json::array({p[0], p[1]}));
    Json j;
    j["points"] = std::move(pts);
    if (!bitsEqual(s.radius, 0.0))
        j["radius"] = s.radius;
    if (!bitsEqual(s.px, 0.0) || !bitsEqual(s.py, 0.0) || !bitsEqual(s.c, 1.0) ||
        !bitsEqual(s.s, 0.0))
        j["transform"] = {{"p", {s.px, s.py}}, {"q", {s.c, s.s}}};
    return j;
}

Json caseToJson(const Case& c)
{
    Json j;
    j["name"] = c.name;
    j["a"] = shapeToJson(c.a);
    j["b"] = shapeToJson(c.b);
    return j;
}

std::string caseFileText(const std::vector<std::string>& comments, const std::vector<Case>& cases)
{
    // nlohmann writes doubles in a form that reads back to the same bits (tests check it).
    std::string out = fmt::format("{{\"format\": \"{}\",\n", kCaseFormat);
    if (!comments.empty())
    {
        out += " \"comments\": [\n";
        for (std::size_t i = 0; i < comments.size(); ++i)
            out += "  " + Json(comments[i]).dump() + (i + 1 < comments.size() ? ",\n" : "\n");
        out += " ],\n";
    }
    out += " \"cases\": [\n";
    for (std::size_t i = 0; i < cases.size(); ++i)
        out += "  " + caseToJson(cases[i]).dump() + (i + 1 < cases.size() ? ",\n" : "\n");
    out += " ]}\n";
    return out;
}

void writeCaseFile(const std::string& path, const std::vector<std::string>& comments,
                   const std::vector<Case>& cases)
{
    std::ofstream out(path, std::ios::binary);
    if (!out)
        throw InputError(fmt::format("{}: cannot write the file", path));
    out << caseFileText(comments, cases);
    if (!out)
        throw InputError(fmt::format("{}: write failed", path));
}

double roundToFloat(double v) { return double(float(v)); }

ShapeIn roundedToFloat(const ShapeIn& s)
{
    const auto r = roundToFloat;
    ShapeIn o = s;
    for (auto& p : o.points)
        p = {r(p[0]), r(p[1])};
    o.radius = r(s.radius);
    o.px = r(s.px);
    o.py = r(s.py);
    o.c = r(s.c);
    o.s = r(s.s);
    return o;
}

exact::Shape toExact(const ShapeIn& in, bool roundToFloat)
{
    const ShapeIn s = roundToFloat ? roundedToFloat(in) : in;
    exact::Shape e;
    e.points.reserve(s.points.size());
    for (const auto& p : s.points)
        e.points.push_back({p[0], p[1]});
    e.radius = s.radius;
    e.px = s.px;
    e.py = s.py;
    e.c = s.c;
    e.s = s.s;
    return e;
}

bool representableInFloat(const Case& c)
{
    auto ok = [](double v) { return std::isfinite(float(v)); };
    for (const ShapeIn* s : {&c.a, &c.b})
    {
        for (const auto& p : s->points)
            if (!ok(p[0]) || !ok(p[1]))
                return false;
        if (!ok(s->radius) || !ok(s->px) || !ok(s->py) || !ok(s->c) || !ok(s->s))
            return false;
    }
    return true;
}

} // namespace gjkval
