// What every subcommand of gjk-validate shares: the checks of its arguments (each failing with an
// InputError, exit code 2, before any work starts) and the registration of a subcommand.
#pragma once

#include "common/common.hpp"

#include <gjk2d/exact.hpp>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gjkval
{

struct VariantInfo;

// Ranges of the numeric options (docs/validation.md).
inline constexpr int kMaxThreads = 256;
inline constexpr int kMaxPasses = 1000;
inline constexpr int kMaxWorst = 1000;
inline constexpr std::size_t kMaxCommentArgBytes = 1000;
inline constexpr int kMaxSearchPopulation = 1000;
inline constexpr std::uint64_t kMaxSearchEvaluations = 1000000000,
                               kDefaultSearchEvaluations = 10000;
inline constexpr std::size_t kMaxChunkCases = 1000000;
inline constexpr std::size_t kMaxShards = 100000; // run --shard I/N

// Memory a command needs per case it holds, measured as peak RSS growth over 5000 .. 40000
// `random` cases (GCC 12 release build, every variant): generate 1.4 KB, bench 1.5 KB (rounded
// up). `run` streams its cases and holds only the engine families whole. A `hard/many-vertices`
// case (up to 2 x 4096 points, their exact hulls and float copies) is counted as 1 MB. A guard
// against commands that cannot fit, not a prediction: a command is refused when its estimate
// exceeds the machine's physical memory.
inline constexpr double kHeldBytesPerCase = 5e3, kLargeCaseBytes = 1e6;

// The program's command line, as the report's context quotes it.
struct CommandLine
{
    int argc;
    char** argv;
    // Who runs it: the program, or gjk2d.validate (python/src/py_validate.cpp) that runs `run` in
    // the Python process with an argument vector of its own.
    const char* program = "gjk-validate";
    std::string text() const; // "gjk-validate run --family random:100"
};

// What the program does, but for reporting the failures: checks the arguments (UTF-8), parses
// them, runs the one subcommand they name and returns its exit code; --help and --version print
// their text and return kExitPass. Every failure is thrown, for the caller to report with its
// exit code (main.cpp, kExitCodeTable; gjk2d.validate turns them into Python exceptions): a
// usage error as InputError ("... (see --help)"), and whatever the subcommand throws.
int runCommandLine(const CommandLine& line);

// A subcommand: its options registered on the app, and what it does once they are parsed.
struct Subcommand
{
    CLI::App* app;
    std::function<int()> run;
};
Subcommand addRun(CLI::App& app, const CommandLine& line);
Subcommand addGenerate(CLI::App& app, const CommandLine& line);
Subcommand addExplain(CLI::App& app, const CommandLine& line);
Subcommand addBench(CLI::App& app, const CommandLine& line);
Subcommand addSearch(CLI::App& app, const CommandLine& line);
Subcommand addList(CLI::App& app, const CommandLine& line);
Subcommand addCompare(CLI::App& app, const CommandLine& line);
Subcommand addMerge(CLI::App& app, const CommandLine& line);

// run's and merge's last step: the report into `out` (committed, with the plugins' logs), then
// the terminal summary (with every family x variant when `verbose`) and the page's path.
struct Campaign;
struct CampaignReport;
class StagedDir;
void writeReportAndSummary(const CampaignReport& result, StagedDir& out, bool verbose);
// One line on stderr per plugin that printed: how much, and its log in `dir`.
struct PluginLog;
void printPluginLogs(const std::vector<PluginLog>& logs, const std::filesystem::path& dir);
// merge's and mpirun's DIR/cases.jsonl: the shards' files (files[s] is shard s's) joined in case
// order (joinPerCase). InputError naming a file that cannot be opened, followed by `hint`.
void writeJoinedPerCase(const Campaign& camp, std::size_t chunkCases,
                        const std::vector<std::string>& files, StagedDir& out,
                        const std::string& hint = {});

// --plugin PATH (repeatable), --judge NAME, --plugin-timeout SECONDS, --no-default-plugins
// (docs/validate-your-gjk.md), --peers (docs/peers.md).
// Whether the shipped plugins' variants join the command's default variant list (run), or are
// loaded only for --variants to name them.
enum class ShippedPlugins
{
    JoinDefaultList,
    OnlyNamed
};
// Whether the command judges variants (--judge); bench does not, and refuses it (exit 2).
enum class Judging
{
    Judges,
    RefusesJudge
};
struct PluginOptions
{
    std::vector<std::string> paths, judge;
    double timeoutSeconds = 5; // kDefaultPluginTimeoutSeconds
    bool noDefault = false;
    bool peers = false; // --peers: every installed shipped peer, its variants added
    bool judges = true;
};
void addPluginOptions(CLI::App& sub, PluginOptions& o, ShippedPlugins shipped,
                      Judging judging = Judging::Judges);
// The shipped plugins (unless --no-default-plugins; those of the default campaign, every installed
// one with --peers) and the --plugin ones, loaded: InputError (exit 2) naming the file when one
// cannot be used or a --plugin file is given twice, or with both --peers and --no-default-plugins.
struct LoadedPlugins
{
    std::vector<const VariantInfo*> shipped, given;
};
LoadedPlugins loadPlugins(const PluginOptions& o);
// --variants LIST with the plugins: loadPlugins(), so that LIST can name their implementations;
// then LIST's variants, the shipped plugins' when they join the default list and LIST is the
// default or --peers is given, and every --plugin one; then --judge.
std::vector<const VariantInfo*> selectVariants(const std::string& list, const PluginOptions& o,
                                               ShippedPlugins shipped);

// Every argument must be valid UTF-8: paths, names and comments are copied into JSON outputs,
// which hold only UTF-8.
void checkArgsUtf8(int argc, char** argv);
// A seed: decimal digits only, 0 .. 2^64 - 1 (no sign: strtoull would wrap "-1" to 2^64 - 1).
std::uint64_t parseSeed(const std::string& text);
exact::Route parseRouteOrThrow(const std::string& name);
// --truth: "filtered" (the default route's filter where it decides, exact::Options::filter) is
// true, "exact" (the GMP route for every case, for checking) false; InputError otherwise.
bool parseTruthOrThrow(const std::string& name);
inline constexpr const char* kTruthHelp =
    "filtered (default: floating point with an error bound, GMP where it cannot decide) or exact "
    "(GMP for every case, for checking; the same results)";
void checkRange(const char* option, int value, int lo, int hi);
void checkComments(const std::vector<std::string>& comments);
// Case files: each readable, none given twice (also not under two paths).
void checkCaseFiles(const std::vector<std::string>& files);
// Parses every family spec (InputError on a bad one) and refuses a command whose estimated memory
// exceeds the machine's physical memory. streamed: the command holds only the engine families'
// cases (run); else every case (generate, bench, search, explain).
void checkFamilies(const std::vector<std::string>& specs, bool streamed);
// Test-only: GJK2D_VALIDATE_TEST_FAULT=logic_error|bad_alloc|unknown makes the program throw that
// once its arguments are checked, so that tests reach the top-level handlers (exit codes 4, 5).
void testFault();
// When path is not empty: writes text() there whole (or leaves the file as it was) and prints
// "label: path".
void writeOutput(const char* label, const std::string& path,
                 const std::function<std::string()>& text);
// The last check of a command: what it printed reached standard output.
void flushStdout();

} // namespace gjkval
