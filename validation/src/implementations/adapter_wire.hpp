// Inside the implementations layer only: what the two halves of the executable-adapter host share,
// the protocol's text (tokens, strict numbers) and the handshake, which adapter.cpp runs at load
// and at every restart of an adapter's process (adapter_handshake.cpp).
#pragma once

#include "implementations/adapter.hpp"
#include "implementations/adapter_process.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace gjkval::adapterwire
{

// ---- Text: tokens separated by one or more spaces, strict numbers ----

inline std::vector<std::string> tokens(const std::string& line)
{
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < line.size())
    {
        if (line[i] == ' ')
        {
            ++i;
            continue;
        }
        const std::size_t end = std::min(line.find(' ', i), line.size());
        out.push_back(line.substr(i, end - i));
        i = end;
    }
    return out;
}

// The free text after the first n tokens (`<text...>`): "" when there is none.
inline std::string restAfter(const std::string& line, std::size_t n)
{
    std::size_t i = 0;
    for (std::size_t t = 0; t < n; ++t)
    {
        i = line.find_first_not_of(' ', i);
        if (i == std::string::npos)
            return {};
        i = line.find(' ', i);
        if (i == std::string::npos)
            return {};
    }
    i = line.find_first_not_of(' ', i);
    return i == std::string::npos ? std::string() : line.substr(i);
}

// A whole token as a number (strtod in the C locale: decimal, nan, inf, Infinity, NaN).
inline bool parseNumber(const std::string& t, double& x)
{
    if (t.empty() || t[0] == ' ')
        return false;
    char* end = nullptr;
    errno = 0;
    x = std::strtod(t.c_str(), &end);
    return end == t.c_str() + t.size(); // ERANGE: a subnormal or an overflow to inf, kept
}

// A whole token as an integer in [lo, hi].
inline bool parseInteger(const std::string& t, long long lo, long long hi, long long& x)
{
    if (t.empty() || t.size() > 20 || !(t[0] == '-' || (t[0] >= '0' && t[0] <= '9')))
        return false;
    char* end = nullptr;
    errno = 0;
    x = std::strtoll(t.c_str(), &end, 10);
    return end == t.c_str() + t.size() && errno == 0 && x >= lo && x <= hi;
}

inline std::string quoted80(const std::string& line)
{
    return fmt::format("\"{}\"", line.substr(0, 80));
}

// The host's line and the adapter's description, to its `ready`, within `limit` seconds. Throws
// adapterio::AdapterFailure saying what is wrong (another version, a bad description, an exit or
// the limit during the handshake).
AdapterDescription handshake(adapterio::Process& p, double limit);

} // namespace gjkval::adapterwire
