// The checks of gjk-validate's arguments that every subcommand shares (each failing with an
// InputError, exit code 2, before any work starts).
#include "commands/command_line.hpp"

#include "campaign/campaign.hpp"
#include "common/output.hpp"
#include "implementations/peers.hpp"
#include "implementations/plugins.hpp"
#include "inputs/families.hpp"
#include "report/pages.hpp"
#include "report/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <stdexcept>
#include <unistd.h>

namespace gjkval
{
namespace fs = std::filesystem;

std::string CommandLine::text() const
{
    std::string s = program;
    for (int i = 1; i < argc; ++i)
    {
        std::string a = argv[i];
        s += " " + (a.find_first_of(" \t'\"") == std::string::npos ? a : "'" + a + "'");
    }
    return s;
}

exact::Route parseRouteOrThrow(const std::string& name)
{
    exact::Route r = exact::Route::Default;
    if (!exact::parseRoute(name, r))
        throw InputError(
            fmt::format("unknown exact route '{}' (hull-of-differences, minkowski-sum-2, "
                        "edge-merge, default)",
                        excerpt(name)));
    return r;
}

bool parseTruthOrThrow(const std::string& name)
{
    if (name == "filtered" || name == "exact")
        return name == "filtered";
    throw InputError(fmt::format("--truth {}: expected filtered or exact", excerpt(name)));
}

void checkArgsUtf8(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
        if (!isValidUtf8(argv[i]))
        {
            const std::string prev = i > 1 ? argv[i - 1] : "";
            throw InputError(fmt::format(
                "argument {} ('{}'{}) is not valid UTF-8", i, excerpt(argv[i]),
                !prev.empty() && prev[0] == '-' ? fmt::format(", the value of {}", excerpt(prev))
                                                : std::string()));
        }
}

std::uint64_t parseSeed(const std::string& text)
{
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v, 10);
    const bool digits = !text.empty() && std::all_of(text.begin(), text.end(),
                                                     [](char c) { return c >= '0' && c <= '9'; });
    if (!digits || ec != std::errc() || ptr != end)
        throw InputError(fmt::format("--seed '{}': expected a whole number in 0..{}", excerpt(text),
                                     std::numeric_limits<std::uint64_t>::max()));
    return v;
}

void checkRange(const char* option, int value, int lo, int hi)
{
    if (value < lo || value > hi)
        throw InputError(fmt::format("{} {}: expected {}..{}", option, value, lo, hi));
}

void checkComments(const std::vector<std::string>& comments)
{
    for (const auto& c : comments)
        if (c.size() > kMaxCommentArgBytes)
            throw InputError(fmt::format("--comment '{}': {} bytes, at most {} allowed", excerpt(c),
                                         c.size(), kMaxCommentArgBytes));
}

void checkCaseFiles(const std::vector<std::string>& files)
{
    for (std::size_t i = 0; i < files.size(); ++i)
    {
        if (files[i].empty())
            throw InputError("--cases: the file name is empty");
        std::ifstream in(files[i], std::ios::binary);
        if (!in)
            throw InputError(fmt::format("{}: cannot open the file: {}", shownPath(files[i]),
                                         std::strerror(errno)));
        for (std::size_t j = 0; j < i; ++j)
        {
            std::error_code ec;
            if (fs::equivalent(files[i], files[j], ec))
                throw InputError(fmt::format("--cases: '{}' and '{}' are the same file",
                                             shownPath(files[j]), shownPath(files[i])));
        }
    }
}

void checkFamilies(const std::vector<std::string>& specs, bool streamed)
{
    double need = 0;
    std::string biggest;
    double biggestBytes = -1;
    for (const auto& spec : specs)
    {
        double bytes = 0;
        for (const auto& [name, count] : familyCaseCounts(parseFamilySpec(spec)))
            if (!streamed || name.rfind("engine/", 0) == 0)
                bytes += double(count) * (name == "hard/many-vertices"
                                              ? kLargeCaseBytes + kHeldBytesPerCase
                                              : kHeldBytesPerCase);
        need += bytes;
        if (bytes > biggestBytes)
            biggestBytes = bytes, biggest = spec;
    }
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0)
        return; // unknown: bad_alloc, if it comes, still ends the run with exit code 5
    const double have = double(pages) * double(pageSize);
    if (need > have)
        throw InputError(fmt::format(
            "--family {}: this command needs about {:.3g} GB of memory (about {:.2g} KB per case "
            "it holds), more than this machine's {:.3g} GB; give fewer cases",
            excerpt(biggest), need / 1e9, kHeldBytesPerCase / 1e3, have / 1e9));
}

} // namespace gjkval
