#include "commands/command_line.hpp"

#include "campaign/campaign.hpp"
#include "common/output.hpp"
#include "evaluate/peers.hpp"
#include "evaluate/plugins.hpp"
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

static_assert(PluginOptions{}.timeoutSeconds == kDefaultPluginTimeoutSeconds);

void addPluginOptions(CLI::App& sub, PluginOptions& o, ShippedPlugins shipped, Judging judging)
{
    const bool judges = judging == Judging::Judges;
    sub.add_option("--plugin", o.paths,
                   "a shared library implementing gjk2d/plugin.h, or an executable adapter (any "
                   "executable file speaking the gjk2d-adapter protocol 1 over its stdin and "
                   "stdout: docs/validate-your-gjk.md, \"Executable adapters\"): each "
                   "implementation it describes becomes a comparison variant (evaluated in a child "
                   "process); repeatable, each file once")
        ->allow_extra_args(false);
    auto* judge =
        sub.add_option("--judge", o.judge,
                       "judge this plugin implementation like gjk2d's judged variants: a "
                       "case fails beyond the error bound of gjk2d's reference options in "
                       "its scalar type; repeatable")
            ->allow_extra_args(false);
    if (!judges) // parsed, to be refused with a line that says why (selectVariants)
        judge->group("");
    sub.add_option("--plugin-timeout", o.timeoutSeconds,
                   "seconds a plugin may take on one case before it counts as hung, 0.01..3600")
        ->capture_default_str();
    sub.add_flag("--no-default-plugins", o.noDefault,
                 shipped == ShippedPlugins::JoinDefaultList
                     ? "leave out the shipped plugins of the default campaign (`gjk-validate "
                       "list`), which run joins when --variants is left at its default"
                     : "do not load the shipped plugins of the default campaign (`gjk-validate "
                       "list`), which --variants can name");
    sub.add_flag("--peers", o.peers,
                 "also load every installed shipped peer (docs/peers.md; `gjk-validate list` "
                 "says which are installed) and add their variants to the variants, whatever "
                 "--variants says; not with --no-default-plugins");
    o.judges = judges;
}

LoadedPlugins loadPlugins(const PluginOptions& o)
{
    for (std::size_t i = 0; i < o.paths.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
        {
            std::error_code ec;
            if (o.paths[i] == o.paths[j] || fs::equivalent(o.paths[i], o.paths[j], ec))
                throw InputError(fmt::format("--plugin {}: given twice (also as {}); each plugin "
                                             "file is loaded once",
                                             o.paths[i], o.paths[j]));
        }
    if (o.peers && o.noDefault)
        throw InputError(
            "--peers loads every shipped peer, --no-default-plugins leaves them "
            "out: give one of them (a single peer: --no-default-plugins --plugin FILE)");
    LoadedPlugins loaded;
    if (!o.noDefault)
        for (const auto& path : shippedPluginPaths(o.peers))
            for (const VariantInfo* v : loadPlugin(path, o.timeoutSeconds))
                loaded.shipped.push_back(v);
    for (const auto& path : o.paths)
        for (const VariantInfo* v : loadPlugin(path, o.timeoutSeconds))
            loaded.given.push_back(v);
    return loaded;
}

std::vector<const VariantInfo*> selectVariants(const std::string& list, const PluginOptions& o,
                                               ShippedPlugins shipped)
{
    if (!o.judges && !o.judge.empty())
        throw InputError(fmt::format("--judge {}: this command judges no variant (bench times "
                                     "them); judge a plugin with `gjk-validate run --judge NAME`",
                                     excerpt(o.judge.front())));
    if (!(o.timeoutSeconds >= 0.01 && o.timeoutSeconds <= 3600))
        throw InputError("--plugin-timeout: expected seconds in 0.01..3600");
    // Loaded first, so that --variants can name their implementations.
    const LoadedPlugins loaded = loadPlugins(o);
    std::vector<const VariantInfo*> variants;
    try
    {
        variants = parseVariants(list);
    }
    catch (const InputError& e) // a peer not in the default campaign is loaded by --peers only
    {
        if (o.peers || o.noDefault)
            throw;
        throw InputError(std::string(e.what()) + "; the variants of a shipped peer that is not in "
                                                 "the default campaign need --peers (see `list`)");
    }
    auto add = [&](const std::vector<const VariantInfo*>& vs)
    {
        for (const VariantInfo* v : vs)
            if (std::find(variants.begin(), variants.end(), v) == variants.end())
                variants.push_back(v);
    };
    if (o.peers || (shipped == ShippedPlugins::JoinDefaultList && list == kDefaultVariants))
        add(loaded.shipped);
    add(loaded.given);
    for (const auto& name : o.judge)
        judgePluginVariant(name);
    return variants;
}

void testFault()
{
    const char* f = std::getenv("GJK2D_VALIDATE_TEST_FAULT");
    if (f == nullptr)
        return;
    const std::string fault = f;
    if (fault == "logic_error")
        throw std::logic_error("test fault: a broken invariant");
    if (fault == "bad_alloc")
        throw std::bad_alloc();
    if (fault == "unknown")
        throw 42;
}

void writeOutput(const char* label, const std::string& path,
                 const std::function<std::string()>& text)
{
    if (path.empty())
        return;
    writeFileAtomic(path, text());
    std::printf("%s: %s\n", label, path.c_str());
}

void flushStdout()
{
    if (std::fflush(stdout) != 0 || std::ferror(stdout))
        throw OutputError(fmt::format("standard output: write failed: {}", std::strerror(errno)));
}
void printPluginLogs(const std::vector<PluginLog>& logs, const fs::path& dir)
{
    for (const PluginLog& l : logs)
    {
        const std::string how =
            l.capped
                ? fmt::format("at least {} bytes (the log's cap; the rest was dropped)", l.bytes)
                : fmt::format("{} bytes", l.bytes);
        std::fprintf(stderr,
                     "gjk-validate: plugin %s printed %s on its stdout and stderr: see %s\n",
                     l.plugin.c_str(), how.c_str(), (dir / l.file).c_str());
    }
}

void writeReportAndSummary(const CampaignReport& result, StagedDir& out, bool verbose)
{
    const std::vector<PluginLog> logs = finishPluginLogs(); // into the directory before its commit
    const std::string page = writeReportPages(result, out);
    printPluginLogs(logs, out.dir());
    if (verbose)
        std::fputs(terminalTable(result.report).c_str(), stdout);
    std::fputs(terminalSummary(result.report).c_str(), stdout);
    std::printf("report: %s\n", page.c_str());
    flushStdout();
}

void writeJoinedPerCase(const Campaign& camp, std::size_t chunkCases,
                        const std::vector<std::string>& files, StagedDir& out,
                        const std::string& hint)
{
    std::vector<std::ifstream> in(files.size());
    std::vector<std::istream*> inOrder;
    for (std::size_t s = 0; s < files.size(); ++s)
    {
        in[s].open(files[s], std::ios::binary);
        if (!in[s])
            throw InputError(fmt::format("{}: cannot open: {}{}", shownPath(files[s]),
                                         std::strerror(errno), hint));
        inOrder.push_back(&in[s]);
    }
    std::ofstream joined(out.staged("cases.jsonl"), std::ios::binary);
    joinPerCase(camp.report, chunkCases, inOrder, joined);
    joined.close();
    if (!joined)
        throw OutputError(fmt::format("{}/cases.jsonl: write failed: {}",
                                      excerpt(out.dir().string()), std::strerror(errno)));
}

} // namespace gjkval
