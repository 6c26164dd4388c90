// Writing gjk-cases/1 files, and the views of a case the variants and the exact side take (its
// numbers rounded to float, exact::Shape). Reading: case_reader.cpp, case_fields.cpp.
#include "inputs/cases.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <fstream>

namespace gjkval
{
namespace
{
bool bitsEqual(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
} // namespace

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
    if (!c.source.empty())
        j["source"] = c.source;
    if (!c.comment.empty())
        j["comment"] = c.comment;
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

double roundToFloat(double v)
{
    return double(float(v));
}

// A field added to one of the two shapes and not to the other changes one size.
static_assert(sizeof(ShapeIn) == sizeof(exact::Shape) &&
                  sizeof(ShapeIn::points) == sizeof(exact::Shape::points),
              "ShapeIn and exact::Shape must keep the same fields (cases.hpp)");

namespace
{
// Every number of `in` through f, into a shape of the same fields (ShapeIn or exact::Shape): the
// one list of a shape's fields that roundedToFloat and toExact read.
template <class Out, class F> Out mapNumbers(const ShapeIn& in, F f)
{
    Out o;
    o.points.reserve(in.points.size());
    for (const auto& p : in.points)
        o.points.push_back({f(p[0]), f(p[1])});
    o.radius = f(in.radius);
    o.px = f(in.px);
    o.py = f(in.py);
    o.c = f(in.c);
    o.s = f(in.s);
    return o;
}
} // namespace

ShapeIn roundedToFloat(const ShapeIn& s)
{
    return mapNumbers<ShapeIn>(s, roundToFloat);
}

// roundedToFloat(in) when asked, without a rounded copy of the points.
exact::Shape toExact(const ShapeIn& in, bool toFloat)
{
    return toFloat ? mapNumbers<exact::Shape>(in, roundToFloat)
                   : mapNumbers<exact::Shape>(in, [](double v) { return v; });
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
        // A rotation that underflows to (0, 0) in float is no transform (cases.cpp rejects it).
        if (float(s->c) == 0 && float(s->s) == 0)
            return false;
    }
    return true;
}

} // namespace gjkval
