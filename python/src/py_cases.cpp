// Cases from Python: the families of `gjk-validate generate` by name, seed and count, and
// gjk-cases/1 files read and written by the runner's own reader and writer (inputs/cases.hpp).
// A case is a dict {"name", "a", "b", "source", "comment"}, a shape {"points": (n, 2) float64
// array, "radius", "position": (x, y), "rotation": (c, s)} (docs/python.md, "Cases").
#include "arrays.hpp"
#include "bindings.hpp"

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

void writeCases(const std::string& path, const py::iterable& items,
                const std::vector<std::string>& comments)
{
    std::vector<gjkval::Case> cases;
    for (const auto& item : items)
        cases.push_back(caseOf(item, cases.size()));
    py::gil_scoped_release release;
    gjkval::writeCaseFile(path, comments, cases);
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
          "The cases of a gjk-cases/1 file; a bad file or case raises gjk2d.InputError (a "
          "ValueError) with the runner's one-line message naming file, case and field.");
    m.def("write_cases", &writeCases, "path"_a, "cases"_a,
          "comments"_a = std::vector<std::string>{},
          "Writes cases (dicts as read_cases returns) to a gjk-cases/1 file, whole or not at all.");
}

} // namespace gjk2d_python
