// Distance routines that are not gjk2d's, loaded from shared libraries (gjk2d/plugin.h,
// docs/validate-your-gjk.md): each implementation a plugin describes becomes a variant
// (VariantInfo::plugin), evaluated in a child process so that a crash or a hang costs one case.
#pragma once

#include "evaluate/variants.hpp"

#include <gjk2d/plugin.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace gjkval
{

struct PreparedCase;
struct TimingConfig;
struct TimingResult;

// One implementation of a loaded plugin.
struct PluginImpl
{
    std::string path; // the shared library, as given
    gjk2d_implementation impl{};
};

// Loads the plugin at `path` (dlopen) and registers one variant per implementation it describes,
// comparison variants (judged = false). Throws InputError, one line naming the file: missing
// file, not loadable, missing entry point, wrong ABI version, bad description, a name already
// taken. Loading the same path twice registers it once.
std::vector<const VariantInfo*> loadPlugin(const std::string& path);
// Every plugin variant registered so far, in load order.
std::vector<const VariantInfo*> pluginVariants();
const VariantInfo* findPluginVariant(const std::string& name); // null when none
// `--judge NAME`: the plugin variant becomes judged (its failures decide the exit code). Throws
// InputError when no loaded plugin has an implementation of that name.
void judgePluginVariant(const std::string& name);

// The shipped plugins gjk-validate loads by default (the Box2D 2.4.1 adapter): next to the
// program (<dir>/plugins/, the build tree) or <dir>/../<libdir>/gjk2d/plugins/ (an installed
// prefix; libdir is GNUInstallDirs' CMAKE_INSTALL_LIBDIR, "lib" unless the prefix is /usr).
// Empty when neither holds them.
std::vector<std::string> shippedPluginPaths();
inline constexpr const char* kShippedPlugins[] = {"gjk2d-box2d.so"};

// How a plugin variant answered one case.
enum class PluginStatus
{
    NotRun,
    Ok,
    Refused, // by the implementation (status), or by what it accepts (radius, vertex limit)
    Error,   // GJK2D_STATUS_ERROR, or a status outside the enum
    Crashed, // the child process died on this case (signal, or exit)
    Hung,    // no answer within the per-case time limit: the child was killed
};
const char* pluginStatusName(PluginStatus s);

struct ExternalAnswer
{
    PluginStatus status = PluginStatus::NotRun;
    double distance = 0;
    std::array<double, 2> pointA{}, pointB{};
    int iterations = -1; // -1: the implementation does not say
    std::string detail;  // crashed/hung: how ("signal 11 (Segmentation fault)")
};

// Whether the variant's implementation declines this case by what it accepts (radius > 0
// without GJK2D_ACCEPTS_RADIUS, more points than max_vertices): a refusal, without calling it.
bool refusedByDescription(const VariantInfo& v, const PreparedCase& p);

// One call to make: variant `v` on case `p`, its answer into `out`.
struct PluginTask
{
    const VariantInfo* v = nullptr;
    const PreparedCase* p = nullptr;
    ExternalAnswer* out = nullptr;
    const std::string* caseName = nullptr; // for the message of a crash or a hang
};

// The per-case time limit of a plugin call (`--plugin-timeout`): generous against a loaded
// machine, since the Box2D adapter answers in under a microsecond; a hang costs this long.
inline constexpr double kDefaultPluginTimeoutSeconds = 5;

// Runs the tasks in order in a forked child that streams one answer per task through a pipe.
// When the child dies or does not answer within timeoutSeconds, that task is answered Crashed
// or Hung (a line on stderr names the variant and the case) and a new child continues from the
// next task. Never throws for what a plugin does; std::runtime_error when fork or pipe fail.
void answerContained(const std::vector<PluginTask>& tasks, double timeoutSeconds);

// ns per query of a plugin variant over `cases` (cold starts), measured in a child process as
// timeQueries() measures gjk2d's: a crashed or hung timing gives nsPerQuery = -1.
TimingResult timeContained(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                           const TimingConfig& cfg, double timeoutSeconds);

} // namespace gjkval
