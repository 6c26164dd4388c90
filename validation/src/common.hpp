// Shared vocabulary of the validation runner: the JSON type, the input error, number helpers.
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace gjkval
{

// Every JSON the runner writes keeps its keys in insertion order (report.json reads top-down).
using Json = nlohmann::ordered_json;

// A usage or input error: the program prints what() and exits with code 2.
class InputError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

// Exit codes of gjk-validate: the one home of their meanings. The --help footer and the table
// in docs/validation.md are written from kExitCodeTable (a test compares the docs with it).
inline constexpr int kExitPass = 0;     // every case within its variant's bound
inline constexpr int kExitFail = 1;     // some case failed (error beyond bound, non-finite, limit)
inline constexpr int kExitInput = 2;    // usage or input error (bad file, bad option, rejected case)
inline constexpr int kExitSetup = 3;    // scripts/setup.sh only: missing Debian packages, not root
inline constexpr int kExitInternal = 4; // a broken invariant of gjk2d itself (a bug, not the input)
inline constexpr int kExitResources = 5; // out of memory, or writing the outputs failed

struct ExitCodeInfo
{
    int code;
    const char* meaning; // one sentence, plain text (the --help footer wraps it)
};

inline constexpr ExitCodeInfo kExitCodeTable[] = {
    {kExitPass, "pass: every case is within its judged variant's error bound and every family "
                "make-up check holds (run); success (other commands). Comparison variants' "
                "failures are reported, never judged."},
    {kExitFail, "some case failed for a judged variant (error beyond the bound, misclassification "
                "beyond it, non-finite output, iteration limit, a certified interval missing the "
                "truth), or a family make-up check failed."},
    {kExitInput, "usage or input error: a bad option or argument, an unreadable or invalid case "
                 "file, an unknown case name, an output path that cannot be used, a run too large "
                 "for this machine's memory (all detected before any work starts); also rejected "
                 "cases (the report is still written, the other cases still run)."},
    {kExitSetup, "used only by scripts/setup.sh: missing Debian packages and not root."},
    {kExitInternal, "internal error: a broken invariant of gjk2d itself (std::logic_error or any "
                    "unexpected exception), printed as 'gjk-validate: internal error: ...'. A bug "
                    "to report, never a verdict on the input."},
    {kExitResources, "out of resources: out of memory, or writing the outputs failed (disk full); "
                     "a previous report or output file stays in place, whole."},
};

// A double as the report writes it: a JSON number when finite, else "inf", "-inf" or "nan".
inline Json num(double v)
{
    if (std::isfinite(v))
        return v;
    if (std::isnan(v))
        return "nan";
    return v > 0 ? "inf" : "-inf";
}

// A metric that may not apply (e.g. a relative error when the truth is 0): NaN means "n/a" -> null.
inline Json optNum(double v)
{
    return std::isnan(v) ? Json(nullptr) : num(v);
}

inline Json pt(double x, double y)
{
    return Json::array({num(x), num(y)});
}

// SplitMix64: the families' deterministic generator (same seed, same cases, on any machine).
inline std::uint64_t mix64(std::uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

inline std::uint64_t hashString(const std::string& s)
{
    std::uint64_t h = 0xcbf29ce484222325ULL; // FNV-1a
    for (unsigned char c : s)
        h = (h ^ c) * 0x100000001b3ULL;
    return h;
}

} // namespace gjkval
