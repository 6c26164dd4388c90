// libFuzzer target: the case-file parser, gjkval::parseCaseFile (validation/src/inputs/cases.hpp).
//
// Invariants (docs/fuzzing.md):
//  - no sanitizer report, no crash, no stack overflow (deep nesting), no hang;
//  - a bad file throws gjkval::InputError and nothing else: any other exception escaping the
//    parser is a finding;
//  - every accepted case is valid (at least one point per shape, finite numbers, radius >= 0);
//  - writing the accepted cases back (caseFileText) and reading that text again gives the same
//    comments and cases, bit for bit (the format's numbers round-trip exactly).
#include "inputs/cases.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace
{

[[noreturn]] void finding(const char* what, const std::string& detail = {})
{
    std::fprintf(stderr, "fuzz_case_file: FINDING: %s%s%s\n", what, detail.empty() ? "" : ": ",
                 detail.substr(0, 300).c_str());
    std::abort();
}

bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

void checkValid(const gjkval::ShapeIn& s)
{
    if (s.points.empty())
        finding("an accepted shape has no points");
    auto finite = [](double v) { return std::isfinite(v); };
    for (const auto& p : s.points)
        if (!finite(p[0]) || !finite(p[1]))
            finding("an accepted point is not finite");
    if (!finite(s.radius) || !(s.radius >= 0))
        finding("an accepted radius is negative or not finite");
    if (!finite(s.px) || !finite(s.py) || !finite(s.c) || !finite(s.s))
        finding("an accepted transform is not finite");
}

bool sameShape(const gjkval::ShapeIn& x, const gjkval::ShapeIn& y)
{
    if (x.points.size() != y.points.size())
        return false;
    for (std::size_t i = 0; i < x.points.size(); ++i)
        if (!sameBits(x.points[i][0], y.points[i][0]) || !sameBits(x.points[i][1], y.points[i][1]))
            return false;
    return sameBits(x.radius, y.radius) && sameBits(x.px, y.px) && sameBits(x.py, y.py) &&
           sameBits(x.c, y.c) && sameBits(x.s, y.s);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    gjkval::CaseFile file;
    try
    {
        file = gjkval::parseCaseFile(text, "fuzz.json");
    }
    catch (const gjkval::InputError&)
    {
        return 0; // a bad file, rejected as documented
    }
    catch (const std::exception& e)
    {
        finding("an exception other than InputError escaped parseCaseFile", e.what());
    }
    catch (...)
    {
        finding("a non-standard exception escaped parseCaseFile");
    }

    std::vector<gjkval::Case> valid;
    for (const auto& entry : file.entries)
    {
        if (entry.label.empty())
            finding("an entry without a label");
        if (!entry.rejected.empty())
            continue;
        checkValid(entry.c.a);
        checkValid(entry.c.b);
        valid.push_back(entry.c);
    }

    // Round trip: what the writer makes of the accepted cases reads back to the same values.
    std::string written;
    try
    {
        written = gjkval::caseFileText(file.comments, valid);
    }
    catch (const std::exception& e)
    {
        finding("caseFileText threw on cases the parser accepted", e.what());
    }
    gjkval::CaseFile again;
    try
    {
        again = gjkval::parseCaseFile(written, "round-trip.json");
    }
    catch (const std::exception& e)
    {
        finding("the writer's text does not parse", e.what());
    }
    if (again.comments != file.comments)
        finding("comments differ after a round trip");
    if (again.entries.size() != valid.size())
        finding("the number of cases differs after a round trip");
    for (std::size_t i = 0; i < valid.size(); ++i)
    {
        const auto& e = again.entries[i];
        if (!e.rejected.empty())
            finding("a written case is rejected when read back", e.rejected);
        if (e.c.name != valid[i].name || !sameShape(e.c.a, valid[i].a) ||
            !sameShape(e.c.b, valid[i].b))
            finding("a case differs after a round trip", valid[i].name);
    }
    return 0;
}
