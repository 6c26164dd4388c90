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

// Ranges of the numeric options (docs/cli.md).
inline constexpr int kMaxThreads = 256;
inline constexpr int kMaxPasses = 1000;
inline constexpr int kMaxWorst = 1000;
inline constexpr std::size_t kMaxCommentArgBytes = 1000;
inline constexpr int kMaxSearchPopulation = 1000;
inline constexpr std::uint64_t kMaxSearchEvaluations = 1000000000,
                               kDefaultSearchEvaluations = 10000;
inline constexpr std::size_t kMaxChunkCases = 1000000;
inline constexpr std::size_t kMaxShards = 100000; // run --shard I/N

// Memory a command needs per case it holds: above the peak RSS growth per `random` case that
// generate and bench show (every variant), with a margin. `run` streams its cases and holds only
// the engine families whole. A `hard/many-vertices` case (up to 2 x 4096 points, their exact hulls
// and float copies) is counted as 1 MB. A guard against commands that cannot fit, not a prediction:
// a command is refused when its estimate exceeds the machine's physical memory.
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
Subcommand addRepro(CLI::App& app, const CommandLine& line);

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

} // namespace gjkval
