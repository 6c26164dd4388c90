// Distance routines that are not gjk2d's, loaded from shared libraries (gjk2d/plugin.h,
// docs/plugin-abi.md): each implementation a plugin describes becomes a variant
// (VariantInfo::plugin), evaluated in a child process so that a crash or a hang costs one case.
// A third kind answers in this process, from a callback registered at run time
// (implementations/in_process.hpp: the Python package's gjk2d.validate).
#pragma once

#include "implementations/contract.hpp"
#include "implementations/variants.hpp"

#include <gjk2d/plugin.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gjkval
{

struct PreparedCase;

// The per-case time limit of a plugin call (`--plugin-timeout`): generous against a loaded
// machine, since the Box2D adapter answers in under a microsecond; a hang costs this long.
inline constexpr double kDefaultPluginTimeoutSeconds = 5;

// The two kinds of plugin `--plugin FILE` takes, told apart by the file's content: a shared
// library exporting gjk2d_plugin_describe (gjk2d/plugin.h), or an executable adapter spoken to
// over pipes (implementations/adapter.hpp, protocol versions 1 and 2, docs/plugin-abi.md); and the
// kind no file gives, a callback of this process (registerInProcessVariant,
// implementations/in_process.hpp).
enum class PluginKind
{
    SharedLibrary,
    Executable,
    InProcess,
};
// "shared-library", "executable-adapter" or "in-process" (the report's context.plugins[].kind).
const char* pluginKindName(PluginKind k);

// One implementation of a loaded plugin.
struct InProcessCalls; // implementations/in_process.hpp

// What a variant's shape preparation is, and so what its ns/query includes (the report's
// variants[].timing, timingJson below):
// - None: gjk2d's plain query takes the points as given; there is nothing to prepare.
// - Shape: shapes prepared once in their own frame (GJK2D_PREPARED_SHAPE, or an adapter's
//   `prepared NAME shape`); ns/query is the query alone, the preparation timed apart per shape.
// - Case: the library cannot take the case's transform exactly, so a prepared shape holds the
//   case's world points, one per case and shape (GJK2D_PREPARED_CASE, `prepared NAME case`);
//   ns/query is the query alone, the preparation timed apart per shape.
// - InCall: no preparation step offered (a plugin without gjk2d_plugin_prepared, an adapter
//   without a `prepared` line, an in-process callback): ns/query includes shape set-up.
enum class Preparation
{
    None,
    Shape,
    Case,
    InCall,
};
const char* preparationName(Preparation p);      // "none", "shape", "case", "in-call"
Preparation preparationOf(const VariantInfo& v); // None for gjk2d's own variants
// Whether the variant's ns/query is the implementation's own measurement (an executable adapter's
// `timed` answers), not gjk-validate's clock.
bool selfTimed(const VariantInfo& v);
// report.json's variants[].timing: {"preparation": preparationName, "includes": what ns/query
// includes in words, "timed_by": "gjk-validate" or "adapter"}; for gjk2d's own variants also
// "prepared": {"timed": hasPreparedForm, "includes": what prepared_ns_per_query is, or why none}.
Json timingJson(const VariantInfo& v);

struct PluginImpl
{
    // The plugin file: absolute, symbolic links resolved (the report's). An in-process variant's:
    // what its caller says it is ("python:module.function").
    std::string path;
    std::string logName; // its output's log in the report directory: "plugin-<file stem>.log"
    // A shared library's: its description, functions included. An executable adapter's: name,
    // description, scalar, accepts (GJK2D_ACCEPTS_RADIUS or 0) and max_vertices from its
    // handshake (name and description point into the strings below), no functions.
    gjk2d_implementation impl{};
    PluginKind kind = PluginKind::SharedLibrary;
    // The library it wraps, name and version: the handshake's `library` line, or a shared
    // library's optional gjk2d_plugin_library(); "" when it does not say.
    std::string library;
    std::string name, description; // an executable adapter's (impl.name, impl.description)
    // A shared library's optional timing loop (gjk2d_plugin_timing, gjk2d/plugin.h; null without
    // it) and the implementation's index in its description, which the loop is given.
    const gjk2d_timing* timing = nullptr;
    int index = 0;
    // A shared library's optional prepared shapes (gjk2d_plugin_prepared; null without it): the
    // accuracy run and the timing both answer through them.
    const gjk2d_prepared* prepared = nullptr;
    // Its preparation: a shared library's from prepared->scope(index), an adapter's from its
    // handshake's `prepared` line; InCall without either.
    Preparation preparation = Preparation::InCall;
    // What it promises: a version-2 plugin's or adapter's declaration, else gjk2d's own.
    Contract contract = ownContract();
    // An in-process variant's callbacks; null once released (releaseInProcessVariant).
    std::shared_ptr<InProcessCalls> calls;
};

// Loads the plugin at `path` and registers one variant per implementation it describes,
// comparison variants (judged = false): a shared library (dlopen), or else an executable file,
// started and asked for its description (the handshake, at most max(10 s, handshakeSeconds)).
// Throws InputError, one line naming the file: missing file, not loadable, missing entry
// point, wrong ABI or protocol version, bad description, a name already taken, an adapter that
// exits or hangs in its handshake. Loading the same file again (a shipped plugin also given
// with --plugin) registers it once; the command line refuses a --plugin given twice
// (selectVariants).
std::vector<const VariantInfo*> loadPlugin(const std::string& path,
                                           double handshakeSeconds = kDefaultPluginTimeoutSeconds);
// Every plugin variant registered so far, in load order.
std::vector<const VariantInfo*> pluginVariants();
const VariantInfo* findPluginVariant(const std::string& name); // null when none
// `--judge NAME`: the plugin variant becomes judged (its failures decide the exit code). Throws
// InputError when no loaded plugin has an implementation of that name.
void judgePluginVariant(const std::string& name);

// The shipped plugins, and where gjk-validate finds them: implementations/peers.hpp.

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

// The child processes that answer shared-library plugins' tasks (answerContained): up to `count`
// of them, forked when first needed and kept for later calls, each answering a slice of a call's
// tasks; they end with this object. Forked again when the registry has changed since (a plugin
// loaded, another log directory): a child knows what its parent knew when it was forked.
class PluginServers
{
  public:
    explicit PluginServers(int count);
    ~PluginServers();
    PluginServers(const PluginServers&) = delete;
    PluginServers& operator=(const PluginServers&) = delete;
    void answer(const std::vector<PluginTask>& tasks, double timeoutSeconds);

  private:
    struct Server;
    bool matchesRegistry() const;
    bool exchange(std::size_t k, double timeoutSeconds);
    int count_;
    std::vector<std::unique_ptr<Server>> servers_;
    std::size_t variantsAtFork_ = 0;
    std::string logDirAtFork_;
};

// Runs the tasks: a shared library's in `servers`' children, which take the tasks through a pipe
// and stream their answers back in blocks of up to 64; an executable adapter's through its
// adapter process (answerThroughAdapters, implementations/adapter.hpp); an in-process variant's in
// this thread, never forked (answerInProcess, implementations/in_process.hpp). When a child dies or
// does not answer within timeoutSeconds, a new one answers the next 64 tasks one by one, and the
// task that one loses is answered Crashed or Hung (a line on stderr names the variant and the
// case); the others are answered. Never throws for what a plugin does; std::runtime_error when
// fork, pipe or poll fail. Without `servers`: children for this call only.
void answerContained(const std::vector<PluginTask>& tasks, double timeoutSeconds,
                     PluginServers& servers);
void answerContained(const std::vector<PluginTask>& tasks, double timeoutSeconds);

// What plugins print (their stdout and stderr in the child processes) is kept apart from
// gjk-validate's own output (a plugin printing on every call would bury the summary):
// with a directory set, each plugin's goes to <dir>/<its logName>, at most kPluginLogCapBytes
// (RLIMIT_FSIZE in the child: the rest is dropped); without one (bench, explain, search), to
// gjk-validate's stderr, never its stdout. `run` sets its staged report directory.
inline constexpr std::uintmax_t kPluginLogCapBytes = 1 << 20; // 1 MiB per plugin
void setPluginLogDirectory(const std::string& dir);           // "" for stderr
struct PluginLog
{
    std::string plugin; // PluginImpl::path
    std::string file;   // its logName
    std::uintmax_t bytes = 0;
    bool capped = false; // reached kPluginLogCapBytes: a closing line says so
};
// The logs of the plugins that printed; empty logs are removed. Call once the plugins' work is
// done, before the directory is committed.
std::vector<PluginLog> finishPluginLogs();

// A child process for plugin calls, fed by fork: it sees the parent's memory (the cases) as it
// was, runs `work` writing its answers to the pipe `fd`, and leaves with _exit (no atexit
// handlers). Crash signals are at their defaults in it, and its stdout and stderr go where
// setPluginLogDirectory() says (routePluginOutput). It leads a process group of its own, ended
// with it (implementations/containment.hpp). The campaign forks between its parallel phases, when
// no worker thread runs.
class PluginChild
{
  public:
    // `plugin`: whose log the child's output goes to first (null: none yet).
    static PluginChild start(const PluginImpl* plugin, const std::function<void(int fd)>& work);
    // The same with a second pipe, from the parent to the child: `work` reads the parent's
    // commands from `in` (end of file once the parent calls finish() or dies) and answers on `out`.
    static PluginChild serve(const PluginImpl* plugin,
                             const std::function<void(int out, int in)>& work);
    // Writes n bytes to the child's `in` (serve() only); false when the pipe is gone.
    bool send(const void* data, std::size_t n) const;
    // Reads up to n bytes, waiting at most timeoutSeconds: >0 bytes read, 0 end of file, -1
    // timeout.
    long read(void* buf, std::size_t n, double timeoutSeconds) const;
    int answerFd() const { return fd_; }   // what the child writes
    int commandFd() const { return cmd_; } // serve(): what it reads
    // How the child ended, after its pipe closed: "" for a clean exit 0. Whatever it left in its
    // process group is killed once it has exited.
    std::string finish();
    void kill(); // SIGKILL to its process group, then finish()

  private:
    static PluginChild serveOrStart(const PluginImpl* plugin, bool commands,
                                    const std::function<void(int out, int in)>& work);
    int pid_ = -1, fd_ = -1, cmd_ = -1;
};
// In a child: its stdout and stderr to `plugin`'s log from here on (stdio flushed first).
void routePluginOutput(const PluginImpl& plugin);
// In a fresh child: its output where setPluginLogDirectory() says, the log capped at
// kPluginLogCapBytes (SIGXFSZ ignored, RLIMIT_FSIZE); `plugin` null: gjk-validate's stderr.
void firstOutputRoute(const PluginImpl* plugin);
// In a child: writes n bytes to the parent; false when the pipe is gone.
bool writeToParent(int fd, const void* data, std::size_t n);

} // namespace gjkval
