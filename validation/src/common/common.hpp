// Shared vocabulary of the validation runner: the JSON type, the input error, number and
// string helpers.
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

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
// in docs/cli.md are written from kExitCodeTable (a test compares the docs with it).
inline constexpr int kExitPass = 0;  // every case within its variant's bound
inline constexpr int kExitFail = 1;  // some case failed (error beyond bound, non-finite, limit)
inline constexpr int kExitInput = 2; // usage or input error (bad file, bad option, rejected case)
inline constexpr int kExitSetup = 3; // scripts/setup.sh only: missing Debian packages, not root
inline constexpr int kExitInternal = 4; // a broken invariant of gjk2d itself (a bug, not the input)
inline constexpr int kExitResources = 5; // out of memory, or writing the outputs failed

struct ExitCodeInfo
{
    int code;
    const char* meaning; // one sentence, plain text (the --help footer wraps it)
};

inline constexpr ExitCodeInfo kExitCodeTable[] = {
    {kExitPass, "pass: every case is within its judged variant's error bound and every family "
                "make-up check holds (run); no statistic regressed beyond its tolerance (compare); "
                "success (other commands). Comparison variants' "
                "failures are reported, never judged."},
    {kExitFail,
     "some case failed for a judged variant (error beyond the bound, misclassification "
     "beyond it, non-finite output, iteration limit, a certified interval missing the "
     "truth), or a family make-up check failed; "
     "a judged plugin (--judge) that crashed, hung or answered an error status on a case; "
     "compare: a statistic of NEW got worse than OLD's beyond its tolerance."},
    {kExitInput, "usage or input error: a bad option or argument, an unreadable or invalid case "
                 "file, an unknown case name, an output path that cannot be used, a report compare "
                 "cannot read or two reports of different inputs, a shard or checkpoint file of "
                 "another campaign or of an earlier version, a run too large "
                 "for this machine's memory, "
                 "a plugin that cannot be used (missing, not loadable, another ABI version, a bad "
                 "description, given twice) "
                 "(all detected before any work starts, but for a case file's fault past its "
                 "first entry, met as it streams: docs/case-files.md, \"Limits\"); also rejected "
                 "cases (the report is still written, the other cases still run)."},
    {kExitSetup, "used only by scripts/setup.sh: missing Debian packages and not root."},
    {kExitInternal, "internal error: a broken invariant of gjk2d itself (std::logic_error or any "
                    "unexpected exception), printed as 'gjk-validate: internal error: ...'. A bug "
                    "to report, never a verdict on the input."},
    {kExitResources, "out of resources: out of memory, or writing the outputs failed (disk full); "
                     "a previous report or output file stays in place, whole."},
};

// Why an answer is not a valid answer (docs/judgement.md, "Failures"): one reason per answer, the
// first that applies in this order (evaluate.cpp decides; Stats counts them by name). A non-finite
// distance or witness point is `nonfinite` instead, never Invalid.
enum class Invalid
{
    None,
    NegativeDistance, // distance < 0
    WitnessOffShape,  // a witness point further from its shape than the witness bound
    WitnessGap,       // | ||pB - pA|| - distance | beyond the witness bound
};
inline constexpr int kInvalidReasons = 3; // the reasons after None
// The report's name of a reason (cases.jsonl "invalid", Stats "invalid_reasons"); null for None.
inline const char* invalidName(Invalid r)
{
    constexpr const char* names[kInvalidReasons + 1] = {nullptr, "negative_distance",
                                                        "witness_off_shape", "witness_gap"};
    return names[int(r)];
}

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

// Length in bytes of the valid UTF-8 sequence that starts at s[i], or 0 when the bytes there are
// not valid UTF-8 (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
inline std::size_t utf8SequenceLength(std::string_view s, std::size_t i)
{
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned c = byte(i);
    if (c < 0x80)
        return 1;
    std::size_t n = 0;
    unsigned lo = 0x80, hi = 0xBF; // range of the second byte
    if (c >= 0xC2 && c <= 0xDF)
        n = 2;
    else if (c == 0xE0)
        n = 3, lo = 0xA0;
    else if (c == 0xED)
        n = 3, hi = 0x9F;
    else if (c >= 0xE1 && c <= 0xEF)
        n = 3;
    else if (c == 0xF0)
        n = 4, lo = 0x90;
    else if (c >= 0xF1 && c <= 0xF3)
        n = 4;
    else if (c == 0xF4)
        n = 4, hi = 0x8F;
    else
        return 0;
    if (s.size() - i < n || byte(i + 1) < lo || byte(i + 1) > hi)
        return 0;
    for (std::size_t k = 2; k < n; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF)
            return 0;
    return n;
}

// True when s is valid UTF-8: nlohmann's dump() throws type_error 316 on anything else.
inline bool isValidUtf8(std::string_view s)
{
    for (std::size_t i = 0, n = 0; i < s.size(); i += n)
        if ((n = utf8SequenceLength(s, i)) == 0)
            return false;
    return true;
}

// How a message quotes a user-provided string: at most about maxBytes bytes of it, valid UTF-8
// and printable whatever the input. Control characters (C0, DEL, C1) and bytes that are not valid
// UTF-8 become \xHH, a backslash becomes \\; when cut, "... (N bytes)" follows with the total
// length. Never quote a user's string or JSON value any other way (hostile-input hardening: a 200
// MB value was echoed whole, a deep one crashed the dump).
inline std::string excerpt(std::string_view s, std::size_t maxBytes = 60)
{
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    std::size_t i = 0;
    while (i < s.size())
    {
        const std::size_t n = utf8SequenceLength(s, i);
        const unsigned c = static_cast<unsigned char>(s[i]);
        const bool c1 = n == 2 && c == 0xC2 && static_cast<unsigned char>(s[i + 1]) < 0xA0;
        std::string piece;
        if (n == 0 || c < 0x20 || c == 0x7F || c1)
            for (std::size_t k = 0; k < (n == 0 ? 1 : n); ++k)
            {
                const unsigned b = static_cast<unsigned char>(s[i + k]);
                piece += {'\\', 'x', kHex[b >> 4], kHex[b & 15]};
            }
        else if (c == '\\')
            piece = "\\\\";
        else
            piece = s.substr(i, n);
        if (out.size() + piece.size() > maxBytes)
            break;
        out += piece;
        i += n == 0 ? 1 : n;
    }
    if (i < s.size())
        out += "... (" + std::to_string(s.size()) + " bytes)";
    return out;
}

// How a message names a file: the path, sanitised, cut after 200 bytes (a path is quoted longer
// than other user strings: a message must tell two long paths apart).
inline std::string shownPath(std::string_view path)
{
    return excerpt(path, 200);
}

} // namespace gjkval
