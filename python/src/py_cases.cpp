// Cases from Python: the families of `gjk-validate generate` by name, seed and count, and
// case files read and written by the runner's own reader and writer (inputs/cases.hpp, JSON, and
// inputs/case_binary.hpp, its binary form). A case is a dict {"name", "a", "b", "source",
// "comment"}, a shape {"points": (n, 2) float64 array, "radius", "position": (x, y), "rotation":
// (c, s)}; many cases at once are columns of NumPy arrays (docs/python.md, "Cases").
#include "arrays.hpp"
#include "bindings.hpp"

#include "common/output.hpp"
#include "inputs/case_binary.hpp"
#include "inputs/families.hpp"

#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace gjk2d_python
{
namespace
{
using namespace pybind11::literals;

py::dict shapeDict(const gjkval::ShapeIn& s)
{
    Array<double> points({py::ssize_t(s.points.size()), py::ssize_t(2)});
    for (std::size_t i = 0; i < s.points.size(); ++i)
        points.mutable_at(i, 0) = s.points[i][0], points.mutable_at(i, 1) = s.points[i][1];
    return py::dict("points"_a = points, "radius"_a = s.radius,
                    "position"_a = py::make_tuple(s.px, s.py),
                    "rotation"_a = py::make_tuple(s.c, s.s));
}

py::dict caseDict(const gjkval::Case& c)
{
    return py::dict("name"_a = c.name, "a"_a = shapeDict(c.a), "b"_a = shapeDict(c.b),
                    "source"_a = c.source, "comment"_a = c.comment);
}

py::list caseList(const std::vector<gjkval::Case>& cases)
{
    py::list out;
    for (const auto& c : cases)
        out.append(caseDict(c));
    return out;
}

// A dict back to a case; a bad field raises ValueError naming the case and the field.
gjkval::ShapeIn shapeIn(const py::dict& d, const std::string& where)
{
    if (!d.contains("points"))
        badArgument(where + ".points", "missing");
    gjkval::ShapeIn s;
    const Array<double> p = pointArray<double>(d["points"], where + ".points");
    for (py::ssize_t i = 0; i < p.shape(0); ++i)
        s.points.push_back({p.at(i, 0), p.at(i, 1)});
    s.radius = finiteScalar<double>(d.contains("radius") ? d["radius"].cast<double>() : 0.0,
                                    where + ".radius");
    if (!(s.radius >= 0))
        badArgument(where + ".radius", "negative");
    const py::object zero = py::make_tuple(0.0, 0.0), one = py::make_tuple(1.0, 0.0);
    const auto t =
        finitePair<double>(d.contains("position") ? d["position"] : zero, where + ".position");
    const auto q =
        finitePair<double>(d.contains("rotation") ? d["rotation"] : one, where + ".rotation");
    s.px = t.x, s.py = t.y, s.c = q.x, s.s = q.y;
    return s;
}

gjkval::Case caseOf(const py::handle& item, std::size_t index)
{
    const std::string where = "cases[" + std::to_string(index) + "]";
    if (!py::isinstance<py::dict>(item))
        badArgument(where, "not a dict");
    const auto d = py::reinterpret_borrow<py::dict>(item);
    gjkval::Case c;
    for (const char* key : {"name", "a", "b"})
        if (!d.contains(key))
            badArgument(where + "." + key, "missing");
    c.name = py::str(d["name"]);
    const std::string named = where + " (case '" + c.name + "')";
    for (const char* key : {"a", "b"})
        if (!py::isinstance<py::dict>(d[key]))
            badArgument(named + "." + key, "not a dict");
    c.a = shapeIn(d["a"], named + ".a");
    c.b = shapeIn(d["b"], named + ".b");
    c.source = d.contains("source") ? std::string(py::str(d["source"])) : "";
    c.comment = d.contains("comment") ? std::string(py::str(d["comment"])) : "";
    return c;
}

py::list generate(const std::string& family, std::uint64_t seed, std::optional<long> count)
{
    const std::string spec = count ? family + ":" + std::to_string(*count) : family;
    std::vector<gjkval::Case> cases;
    {
        py::gil_scoped_release release;
        for (auto& f : gjkval::generateFamilies(spec, seed))
            for (auto& c : f.cases)
                cases.push_back(std::move(c));
    }
    return caseList(cases);
}

// Every case of a file, or InputError: the file's own error, or its first rejected case's
// (the runner exits 2 on either: docs/case-files.md, "Case files").
py::list readCases(const std::string& path)
{
    gjkval::CaseFile file;
    {
        py::gil_scoped_release release;
        file = gjkval::readCaseFile(path);
    }
    std::vector<gjkval::Case> cases;
    for (auto& e : file.entries)
    {
        if (!e.rejected.empty())
            throw gjkval::InputError(e.label + ": " + e.rejected); // as the report names it
        cases.push_back(std::move(e.c));
    }
    return caseList(cases);
}

// Writes cases in the format named ("json", "msgpack"): JSON whole, the binary form streamed.
void writeIn(const std::string& path, const std::string& formatName,
             const std::vector<std::string>& comments, std::size_t n,
             const std::function<gjkval::Case(std::size_t)>& caseAt)
{
    const auto format = gjkval::caseFileFormatNamed(formatName, "format");
    py::gil_scoped_release release;
    if (format == gjkval::CaseFileFormat::Json)
    {
        std::vector<gjkval::Case> cases;
        for (std::size_t i = 0; i < n; ++i)
            cases.push_back(caseAt(i));
        gjkval::writeFileAtomic(path, gjkval::caseFileText(comments, cases));
        return;
    }
    gjkval::writeFileAtomic(path,
                            [&](const gjkval::ByteSink& sink)
                            {
                                gjkval::BinaryCaseWriter w(sink, comments);
                                for (std::size_t i = 0; i < n; ++i)
                                    w.add(caseAt(i));
                                w.finish();
                            });
}

// One shape column of the array form: {"points": (N, 2), "counts": (n,), "radius": (n,),
// "position": (n, 2), "rotation": (n, 2)}, the last three optional; checked whole up front.
struct ShapeColumns
{
    Array<double> points, radius, position, rotation;
    std::vector<std::size_t> first, count;
    bool hasRadius = false, hasPosition = false, hasRotation = false;

    ShapeColumns(const py::handle& value, const std::string& where, std::size_t& n)
    {
        if (!py::isinstance<py::dict>(value))
            badArgument(where, "not a dict of arrays");
        const auto d = py::reinterpret_borrow<py::dict>(value);
        for (const char* key : {"points", "counts"})
            if (!d.contains(key))
                badArgument(where + "." + key, "missing");
        points = pointArray<double>(d["points"], where + ".points", std::size_t(-1));
        const auto counts =
            py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(d["counts"]);
        if (!counts || counts.ndim() != 1)
            badArgument(where + ".counts", "expected a 1-D array of integers");
        if (n == std::size_t(-1))
            n = std::size_t(counts.shape(0));
        if (std::size_t(counts.shape(0)) != n)
            badArgument(where + ".counts",
                        std::to_string(counts.shape(0)) + " shapes, expected " + std::to_string(n));
        std::size_t total = 0;
        for (std::size_t i = 0; i < n; ++i)
        {
            const long long k = counts.at(py::ssize_t(i));
            if (k < 1 || std::size_t(k) > kMaxPoints)
                badArgument(where + ".counts[" + std::to_string(i) + "]",
                            "not between 1 and " + std::to_string(kMaxPoints));
            first.push_back(total), count.push_back(std::size_t(k));
            total += std::size_t(k);
        }
        if (total != std::size_t(points.shape(0)))
            badArgument(where + ".points", std::to_string(points.shape(0)) +
                                               " rows, but the counts add up to " +
                                               std::to_string(total));
        hasRadius = optional(d, "radius", where, n, 1, radius);
        hasPosition = optional(d, "position", where, n, 2, position);
        hasRotation = optional(d, "rotation", where, n, 2, rotation);
        for (std::size_t i = 0; hasRadius && i < n; ++i)
            if (!(radius.at(py::ssize_t(i)) >= 0))
                badArgument(where + ".radius[" + std::to_string(i) + "]", "negative");
    }

    static bool optional(const py::dict& d, const char* key, const std::string& where,
                         std::size_t n, int width, Array<double>& out)
    {
        if (!d.contains(key))
            return false;
        const std::string name = where + "." + key;
        out = Array<double>::ensure(d[key]);
        if (!out || (width == 1 ? out.ndim() != 1 : out.ndim() != 2 || out.shape(1) != width) ||
            std::size_t(out.shape(0)) != n)
            badArgument(name, width == 1 ? "expected an (n,) array" : "expected an (n, 2) array");
        for (py::ssize_t i = 0; i < out.size(); ++i)
            if (!std::isfinite(out.data()[i]))
                badArgument(name, "row " + std::to_string(i / width) + " is not finite");
        return true;
    }

    gjkval::ShapeIn at(std::size_t i) const
    {
        gjkval::ShapeIn s;
        const double* p = points.data() + 2 * first[i];
        s.points.resize(count[i]);
        for (std::size_t j = 0; j < count[i]; ++j)
            s.points[j] = {p[2 * j], p[2 * j + 1]};
        if (hasRadius)
            s.radius = radius.data()[i];
        if (hasPosition)
            s.px = position.data()[2 * i], s.py = position.data()[2 * i + 1];
        if (hasRotation)
            s.c = rotation.data()[2 * i], s.s = rotation.data()[2 * i + 1];
        return s;
    }
};

// A column of n strings, or none.
std::vector<std::string> texts(const py::dict& d, const char* key, std::size_t n)
{
    std::vector<std::string> out;
    if (!d.contains(key))
        return out;
    for (const auto& item : d[key])
        out.push_back(text(item));
    if (out.size() != n)
        badArgument(std::string("cases.") + key,
                    std::to_string(out.size()) + " strings, expected " + std::to_string(n));
    return out;
}

void writeColumns(const std::string& path, const py::dict& d,
                  const std::vector<std::string>& comments, const std::string& format)
{
    for (const char* key : {"a", "b"})
        if (!d.contains(key))
            badArgument(std::string("cases.") + key, "missing");
    std::size_t n = std::size_t(-1);
    const ShapeColumns a(d["a"], "cases.a", n), b(d["b"], "cases.b", n);
    const std::vector<std::string> names = texts(d, "names", n), source = texts(d, "source", n),
                                   comment = texts(d, "comment", n);
    writeIn(path, format, comments, n,
            [&](std::size_t i)
            {
                gjkval::Case c;
                c.name = names.empty() ? std::to_string(i) : names[i];
                c.a = a.at(i), c.b = b.at(i);
                if (!source.empty())
                    c.source = source[i];
                if (!comment.empty())
                    c.comment = comment[i];
                return c;
            });
}

void writeCases(const std::string& path, const py::object& items,
                const std::vector<std::string>& comments, const std::string& format)
{
    if (py::isinstance<py::dict>(items))
        return writeColumns(path, items.cast<py::dict>(), comments, format);
    std::vector<gjkval::Case> cases;
    for (const auto& item : items)
        cases.push_back(caseOf(item, cases.size()));
    writeIn(path, format, comments, cases.size(), [&](std::size_t i) { return cases[i]; });
}

py::list familyNames()
{
    py::list names;
    names.append("random");
    for (const auto& f : gjkval::hardSubFamilies())
        names.append("hard/" + f.name);
    for (const auto& f : gjkval::engineSubFamilies())
        names.append("engine/" + f.name);
    return names;
}

} // namespace

void bindCases(py::module_& m)
{
    py::register_exception<gjkval::InputError>(m, "InputError", PyExc_ValueError);
    m.def("families", &familyNames,
          "The built-in families' names (`gjk-validate list`); `hard` and `engine` name groups.");
    m.def("generate", &generate, "family"_a, py::kw_only(), "seed"_a = 1, "count"_a = py::none(),
          "The cases of a family spec as `gjk-validate generate --family` takes it (random, hard, "
          "hard/<sub>, engine, engine/<scene>-<kind>), count per family (None: the default), "
          "seed the campaign seed: the same cases as `gjk-validate generate`.");
    m.def("read_cases", &readCases, "path"_a,
          "The cases of a case file (gjk-cases/1, or its binary form gjk-cases-msgpack/1, told "
          "apart by content); a bad file or case raises gjk2d.InputError (a "
          "ValueError) with the runner's one-line message naming file, case and field.");
    m.def("write_cases", &writeCases, "path"_a, "cases"_a,
          "comments"_a = std::vector<std::string>{}, py::kw_only(), "format"_a = "json",
          "Writes cases to a case file, whole or not at all: format 'json' (gjk-cases/1) or "
          "'msgpack' (gjk-cases-msgpack/1). cases: dicts as read_cases returns, or a dict of "
          "NumPy columns {'names', 'a': {'points', 'counts', 'radius', 'position', 'rotation'}, "
          "'b': {...}, 'source', 'comment'} (docs/python.md, \"Cases\").");
}

} // namespace gjk2d_python
