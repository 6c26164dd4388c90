#include "evaluate/plugins.hpp"

#include "common/output.hpp" // writeAllBytes
#include "evaluate/adapter.hpp"
#include "evaluate/adapter_process.hpp" // SigpipeBlocked
#include "evaluate/evaluate.hpp"
#include "evaluate/in_process.hpp"

#include <fmt/format.h>

#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio_ext.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <deque>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace gjkval
{
namespace
{

// The registry: loaded plugins' implementations and their variants, with stable addresses
// (VariantInfo pointers go into every EvalContext).
struct Registry
{
    std::deque<PluginImpl> impls;
    std::deque<VariantInfo> variants;
    std::vector<std::string> paths; // canonical paths loaded
    std::string logDir;             // setPluginLogDirectory()
};
Registry& registry()
{
    static Registry r;
    return r;
}

bool validName(const char* s)
{
    const std::size_t n = std::strlen(s);
    if (n == 0 || n > 64)
        return false;
    for (std::size_t i = 0; i < n; ++i)
    {
        const char c = s[i];
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '+' || c == '-';
        if (!ok)
            return false;
    }
    return true;
}

// Why an implementation's description is unusable, or empty.
std::string descriptionProblem(const gjk2d_implementation& im)
{
    if (im.name == nullptr)
        return "name is NULL";
    if (!validName(im.name))
        return fmt::format("name '{}' is not 1 to 64 characters of [A-Za-z0-9._+-]", im.name);
    if (im.scalar != GJK2D_SCALAR_FLOAT && im.scalar != GJK2D_SCALAR_DOUBLE)
        return fmt::format(
            "scalar {} is neither GJK2D_SCALAR_FLOAT (0) nor GJK2D_SCALAR_DOUBLE (1)", im.scalar);
    if ((im.accepts & ~std::uint32_t(GJK2D_ACCEPTS_RADIUS | GJK2D_ACCEPTS_WARM_START)) != 0)
        return fmt::format("accepts has unknown bits 0x{:x}", im.accepts);
    if (im.max_vertices < 0)
        return fmt::format("max_vertices {} is negative", im.max_vertices);
    if (im.cache_bytes < 0 || im.cache_bytes > 4096)
        return fmt::format("cache_bytes {} is outside 0..4096", im.cache_bytes);
    if (im.scalar == GJK2D_SCALAR_FLOAT && (im.distance_f == nullptr || im.distance_d != nullptr))
        return "a float implementation needs distance_f set and distance_d NULL";
    if (im.scalar == GJK2D_SCALAR_DOUBLE && (im.distance_d == nullptr || im.distance_f != nullptr))
        return "a double implementation needs distance_d set and distance_f NULL";
    return {};
}

} // namespace

namespace
{
// The plugin file's canonical path; InputError when it is missing or not a regular file.
std::string pluginFile(const std::string& path)
{
    struct stat st
    {
    };
    if (::stat(path.c_str(), &st) != 0)
        throw InputError(fmt::format("plugin {}: {}", path, std::strerror(errno)));
    if (!S_ISREG(st.st_mode))
        throw InputError(fmt::format("plugin {}: not a regular file", path));
    return std::filesystem::canonical(path).string();
}

// A shared library's description, its optional gjk2d_plugin_library() ("" without it) and its
// optional gjk2d_plugin_timing() (null without it).
struct OpenedPlugin
{
    const gjk2d_plugin* description = nullptr;
    std::string library;
    const gjk2d_timing* timing = nullptr;
};

// Opens the plugin and reads its description, of this ABI version and with 1 .. 64
// implementations; InputError otherwise. A file dlopen cannot open but may execute (access
// X_OK): an executable adapter, description null. The handle stays open for the whole run: the
// description and the functions live in it.
OpenedPlugin openPlugin(const std::string& path)
{
    // A path without a slash would make dlopen search the library path, not this file.
    const std::string openPath = path.find('/') == std::string::npos ? "./" + path : path;
    void* handle = ::dlopen(openPath.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
    {
        const char* e = ::dlerror();
        if (::access(openPath.c_str(), X_OK) == 0)
            return {};
        throw InputError(
            fmt::format("plugin {}: cannot be loaded: {}", path, e ? e : "dlopen failed"));
    }
    auto describe =
        reinterpret_cast<gjk2d_plugin_describe_fn>(::dlsym(handle, GJK2D_PLUGIN_ENTRY_POINT));
    if (describe == nullptr)
        throw InputError(
            fmt::format("plugin {}: does not export the entry point {} (gjk2d/plugin.h)", path,
                        GJK2D_PLUGIN_ENTRY_POINT));
    const gjk2d_plugin* d = describe();
    if (d == nullptr)
        throw InputError(
            fmt::format("plugin {}: {}() returned NULL", path, GJK2D_PLUGIN_ENTRY_POINT));
    if (d->abi_version != GJK2D_PLUGIN_ABI_VERSION)
        throw InputError(fmt::format(
            "plugin {}: plugin ABI version {}, this gjk-validate reads version {} (rebuild the "
            "plugin against this SDK's gjk2d/plugin.h)",
            path, d->abi_version, GJK2D_PLUGIN_ABI_VERSION));
    if (d->count < 1 || d->count > 64 || d->implementations == nullptr)
        throw InputError(fmt::format("plugin {}: bad description: count {} is outside 1..64 or "
                                     "implementations is NULL",
                                     path, d->count));
    const auto library =
        reinterpret_cast<gjk2d_plugin_library_fn>(::dlsym(handle, GJK2D_PLUGIN_LIBRARY_ENTRY));
    const char* text = library ? library() : nullptr;
    const auto timing =
        reinterpret_cast<gjk2d_plugin_timing_fn>(::dlsym(handle, GJK2D_PLUGIN_TIMING_ENTRY));
    const gjk2d_timing* loop = timing ? timing() : nullptr;
    if (loop && (loop->prepare == nullptr || loop->pass == nullptr || loop->release == nullptr))
        throw InputError(fmt::format("plugin {}: {}() returned a table with a NULL function", path,
                                     GJK2D_PLUGIN_TIMING_ENTRY));
    return {d, text ? text : "", loop};
}

// Every implementation well described, under a name no variant and no other implementation has.
void checkImplementations(const std::string& path, const gjk2d_plugin& d)
{
    std::vector<std::string> names;
    for (int i = 0; i < d.count; ++i)
    {
        const gjk2d_implementation& im = d.implementations[i];
        const std::string problem = descriptionProblem(im);
        if (!problem.empty())
            throw InputError(fmt::format("plugin {}: bad description of implementation {}: {}",
                                         path, i, problem));
        const std::string name = im.name;
        bool taken = findVariant(name) != nullptr;
        for (const auto& n : names)
            taken = taken || n == name;
        if (taken)
            throw InputError(fmt::format(
                "plugin {}: bad description of implementation {}: the name '{}' is already taken "
                "(a gjk2d variant or another implementation)",
                path, i, name));
        names.push_back(name);
    }
}

// One log per plugin file, named after it: "plugin-gjk2d-box2d.log" (a second file of the same
// name in another directory: "plugin-gjk2d-box2d-2.log").
std::string logNameFor(const Registry& reg, const std::string& canonical)
{
    const std::string stem = std::filesystem::path(canonical).stem().string();
    std::string logName = "plugin-" + stem + ".log";
    for (int n = 2; std::any_of(reg.impls.begin(), reg.impls.end(),
                                [&](const PluginImpl& p) { return p.logName == logName; });
         ++n)
        logName = fmt::format("plugin-{}-{}.log", stem, n);
    return logName;
}

// The variant of one implementation: a comparison variant, cold, held to gjk2d's bound.
VariantInfo pluginVariant(const std::string& path, const PluginImpl& impl)
{
    const gjk2d_implementation& im = impl.impl;
    VariantInfo v;
    v.name = im.name;
    v.scalar = im.scalar == GJK2D_SCALAR_FLOAT ? Scalar::Float : Scalar::Double;
    // The options whose error bound the implementation is compared with (and judged by, with
    // --judge): gjk2d's reference options in the implementation's scalar type.
    v.options = gjk::referenceOptions;
    v.description = fmt::format("plugin {}{}{}", std::filesystem::path(path).filename().string(),
                                im.description ? ": " : "", im.description ? im.description : "");
    v.judged = false;
    v.start = Start::Cold;
    v.plugin = &impl;
    return v;
}

// An executable adapter's implementations as PluginImpls: the handshake's fields in
// gjk2d_implementation's (no functions, cold only), the strings owned by the PluginImpl.
std::vector<PluginImpl> adapterImpls(const std::string& path, const std::string& canonical,
                                     double handshakeSeconds)
{
    const AdapterDescription d = describeAdapter(path, canonical, handshakeSeconds);
    std::vector<PluginImpl> impls;
    for (std::size_t i = 0; i < d.implementations.size(); ++i)
    {
        const AdapterImplementation& a = d.implementations[i];
        if (findVariant(a.name) != nullptr)
            throw InputError(fmt::format(
                "plugin {}: bad description of implementation {}: the name '{}' is already taken "
                "(a gjk2d variant or another plugin's implementation)",
                path, i, a.name));
        PluginImpl p;
        p.kind = PluginKind::Executable;
        p.library = d.library;
        p.name = a.name;
        p.description = a.description;
        p.impl.scalar = a.scalar == Scalar::Float ? GJK2D_SCALAR_FLOAT : GJK2D_SCALAR_DOUBLE;
        p.impl.accepts = a.radius ? std::uint32_t(GJK2D_ACCEPTS_RADIUS) : 0u;
        p.impl.max_vertices = a.maxVertices;
        impls.push_back(std::move(p));
    }
    return impls;
}

// The implementations the file describes, of either kind (canonical path and log name unset).
std::vector<PluginImpl> describePlugin(const std::string& path, const std::string& canonical,
                                       double handshakeSeconds)
{
    const OpenedPlugin opened = openPlugin(path);
    if (opened.description == nullptr)
        return adapterImpls(path, canonical, handshakeSeconds);
    const gjk2d_plugin& d = *opened.description;
    checkImplementations(path, d);
    std::vector<PluginImpl> impls;
    for (int i = 0; i < d.count; ++i)
    {
        PluginImpl p;
        p.impl = d.implementations[i];
        p.library = opened.library;
        p.timing = opened.timing;
        p.index = i;
        impls.push_back(std::move(p));
    }
    return impls;
}
} // namespace

std::vector<const VariantInfo*> loadPlugin(const std::string& path, double handshakeSeconds)
{
    Registry& reg = registry();
    const std::string canonical = pluginFile(path);
    std::vector<const VariantInfo*> out;
    if (std::find(reg.paths.begin(), reg.paths.end(), canonical) != reg.paths.end())
    {
        for (std::size_t k = 0; k < reg.variants.size(); ++k)
            if (reg.impls[k].path == canonical)
                out.push_back(&reg.variants[k]);
        return out;
    }
    std::vector<PluginImpl> impls = describePlugin(path, canonical, handshakeSeconds);
    const std::string logName = logNameFor(reg, canonical);
    reg.paths.push_back(canonical);
    for (PluginImpl& p : impls)
    {
        p.path = canonical;
        p.logName = logName;
        PluginImpl& stored = reg.impls.emplace_back(std::move(p));
        if (stored.kind == PluginKind::Executable) // its strings, where they now live
        {
            stored.impl.name = stored.name.c_str();
            stored.impl.description = stored.description.c_str();
        }
        reg.variants.push_back(pluginVariant(path, stored));
        out.push_back(&reg.variants.back());
    }
    return out;
}

std::vector<const VariantInfo*> pluginVariants()
{
    std::vector<const VariantInfo*> out;
    for (const auto& v : registry().variants)
        out.push_back(&v);
    return out;
}

const VariantInfo* findPluginVariant(const std::string& name)
{
    for (const auto& v : registry().variants)
        if (v.name == name)
            return &v;
    return nullptr;
}

void judgePluginVariant(const std::string& name)
{
    for (auto& v : registry().variants)
        if (v.name == name)
        {
            v.judged = true;
            return;
        }
    std::string known;
    for (const auto& v : registry().variants)
        known += (known.empty() ? "" : ", ") + v.name;
    throw InputError(fmt::format("--judge {}: no loaded plugin has an implementation of that name "
                                 "(loaded: {})",
                                 name, known.empty() ? "none" : known));
}

const char* pluginKindName(PluginKind k)
{
    switch (k)
    {
    case PluginKind::SharedLibrary:
        return "shared-library";
    case PluginKind::Executable:
        return "executable-adapter";
    case PluginKind::InProcess:
        return "in-process";
    }
    return "?";
}

namespace
{
// An in-process variant's registry entries: its implementation (no file, no functions; the
// strings live in the PluginImpl) and its variant, a comparison variant as any plugin's.
PluginImpl inProcessImpl(InProcessVariant&& v)
{
    PluginImpl p;
    p.kind = PluginKind::InProcess;
    p.path = std::move(v.source);
    p.library = std::move(v.library);
    p.name = std::move(v.name);
    p.description = std::move(v.description);
    p.impl.scalar = v.scalar == Scalar::Float ? GJK2D_SCALAR_FLOAT : GJK2D_SCALAR_DOUBLE;
    p.impl.accepts = v.acceptsRadius ? std::uint32_t(GJK2D_ACCEPTS_RADIUS) : 0u;
    p.impl.max_vertices = std::max(0, v.maxVertices);
    p.calls = std::make_shared<InProcessCalls>(std::move(v.calls));
    return p;
}

VariantInfo inProcessVariant(const PluginImpl& impl)
{
    VariantInfo v;
    v.name = impl.name;
    v.scalar = impl.impl.scalar == GJK2D_SCALAR_FLOAT ? Scalar::Float : Scalar::Double;
    v.options = gjk::referenceOptions; // the bound it is compared with, as a plugin's
    v.description = fmt::format("in-process {}{}{}", impl.path,
                                impl.description.empty() ? "" : ": ", impl.description);
    v.judged = false;
    v.start = Start::Cold;
    v.plugin = &impl;
    return v;
}
} // namespace

const VariantInfo* registerInProcessVariant(InProcessVariant v)
{
    if (!validName(v.name.c_str()))
        throw InputError(fmt::format(
            "in-process variant '{}': the name is not 1 to 64 characters of [A-Za-z0-9._+-]",
            excerpt(v.name)));
    if (bool(v.calls.perCase) == bool(v.calls.perBatch))
        throw InputError(fmt::format(
            "in-process variant '{}': give one callback, per case or per batch", v.name));
    Registry& reg = registry();
    std::size_t k = 0;
    while (k < reg.variants.size() && reg.variants[k].name != v.name)
        ++k;
    if (k == reg.variants.size() ? findVariant(v.name) != nullptr
                                 : reg.impls[k].kind != PluginKind::InProcess)
        throw InputError(fmt::format("in-process variant '{}': the name is taken by {}", v.name,
                                     k == reg.variants.size()
                                         ? std::string("a gjk2d variant (see `gjk-validate list`)")
                                         : "the plugin " + reg.impls[k].path));
    PluginImpl impl = inProcessImpl(std::move(v));
    if (k == reg.variants.size()) // a new one; else the same name registered again, in place
    {
        reg.impls.emplace_back();
        reg.variants.emplace_back();
    }
    reg.impls[k] = std::move(impl);
    reg.impls[k].impl.name = reg.impls[k].name.c_str();
    reg.impls[k].impl.description = reg.impls[k].description.c_str();
    reg.variants[k] = inProcessVariant(reg.impls[k]);
    return &reg.variants[k];
}

void releaseInProcessVariant(const std::string& name)
{
    Registry& reg = registry();
    for (std::size_t k = 0; k < reg.variants.size(); ++k)
        if (reg.variants[k].name == name && reg.impls[k].kind == PluginKind::InProcess)
            reg.impls[k].calls.reset();
}

const char* pluginStatusName(PluginStatus s)
{
    switch (s)
    {
    case PluginStatus::NotRun:
        return "not-run";
    case PluginStatus::Ok:
        return "ok";
    case PluginStatus::Refused:
        return "refused";
    case PluginStatus::Error:
        return "error";
    case PluginStatus::Crashed:
        return "crashed";
    case PluginStatus::Hung:
        return "hung";
    }
    return "?";
}

bool refusedByDescription(const VariantInfo& v, const PreparedCase& p)
{
    const gjk2d_implementation& im = v.plugin->impl;
    const bool isFloat = v.scalar == Scalar::Float;
    const double ra = isFloat ? double(p.raf) : p.rad, rb = isFloat ? double(p.rbf) : p.rbd;
    if ((im.accepts & GJK2D_ACCEPTS_RADIUS) == 0 && (ra > 0 || rb > 0))
        return true;
    const std::size_t n = std::max(p.ad.size(), p.bd.size());
    return im.max_vertices > 0 && n > std::size_t(im.max_vertices);
}

namespace
{

static_assert(sizeof(gjk::Vec2<float>) == 2 * sizeof(float) &&
                  sizeof(gjk::Vec2<double>) == 2 * sizeof(double),
              "the plugin ABI reads Vec2 arrays as x0, y0, x1, y1, ...");

template <class T, class Shape>
Shape shapeOf(const CasePoints<T>& pts, T radius, const gjk::Transform<T>& xf)
{
    Shape s;
    s.points = reinterpret_cast<const T*>(pts.data());
    s.count = std::int32_t(pts.size());
    s.radius = radius;
    s.position[0] = xf.p.x;
    s.position[1] = xf.p.y;
    s.rotation[0] = xf.q.c;
    s.rotation[1] = xf.q.s;
    return s;
}

// What the child writes per task: fixed size, well under PIPE_BUF, so each write is atomic.
struct AnswerRecord
{
    std::uint64_t task;
    std::int32_t status;
    std::int32_t iterations;
    double distance;
    double pointA[2], pointB[2];
};

// One call in the implementation's scalar type T (its shape and result structs, its function).
template <class T, class Shape, class Result, class Fn>
AnswerRecord callIn(Fn fn, const Shape& a, const Shape& b, void* cache)
{
    Result o{};
    o.iterations = -1;
    AnswerRecord r{};
    r.status = fn(&a, &b, cache, &o);
    r.distance = o.distance;
    r.pointA[0] = o.point_a[0];
    r.pointA[1] = o.point_a[1];
    r.pointB[0] = o.point_b[0];
    r.pointB[1] = o.point_b[1];
    r.iterations = o.iterations;
    return r;
}

// The call itself, as the child makes it. `cache`: cache_bytes zeroed bytes (a cold start).
AnswerRecord callPlugin(const VariantInfo& v, const PreparedCase& p,
                        std::vector<unsigned char>& cache)
{
    const gjk2d_implementation& im = v.plugin->impl;
    std::fill(cache.begin(), cache.begin() + im.cache_bytes, 0);
    void* c = im.cache_bytes > 0 ? cache.data() : nullptr;
    if (im.scalar == GJK2D_SCALAR_FLOAT)
        return callIn<float, gjk2d_shape_f, gjk2d_result_f>(
            im.distance_f, shapeOf<float, gjk2d_shape_f>(p.af, p.raf, p.xaf),
            shapeOf<float, gjk2d_shape_f>(p.bf, p.rbf, p.xbf), c);
    return callIn<double, gjk2d_shape_d, gjk2d_result_d>(
        im.distance_d, shapeOf<double, gjk2d_shape_d>(p.ad, p.rad, p.xad),
        shapeOf<double, gjk2d_shape_d>(p.bd, p.rbd, p.xbd), c);
}

std::mutex g_messages; // crash and hang lines on stderr

} // namespace

// In a child: where its output goes until routePluginOutput() names a plugin's log.
void firstOutputRoute(const PluginImpl* plugin)
{
    // The parent's unwritten stdio buffers were copied by fork: they are the parent's to write.
    __fpurge(stdout);
    __fpurge(stderr);
    if (registry().logDir.empty())
    {
        ::dup2(STDERR_FILENO, STDOUT_FILENO); // gjk-validate's stdout carries its results only
        return;
    }
    // Each log holds at most kPluginLogCapBytes: a write beyond fails (EFBIG) instead of raising
    // SIGXFSZ, which would end the child as if the plugin had crashed.
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit cap{rlim_t(kPluginLogCapBytes), rlim_t(kPluginLogCapBytes)};
    ::setrlimit(RLIMIT_FSIZE, &cap);
    if (plugin)
        routePluginOutput(*plugin);
}

bool writeToParent(int fd, const void* data, std::size_t n)
{
    return writeAllBytes(fd, data, n);
}

void routePluginOutput(const PluginImpl& plugin)
{
    const std::string& dir = registry().logDir;
    if (dir.empty())
        return;
    std::fflush(stdout);
    std::fflush(stderr);
    const std::string file = dir + "/" + plugin.logName;
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0666);
    if (fd < 0)
        return; // the output stays where it went; the plugin's answers do not depend on it
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
}

void setPluginLogDirectory(const std::string& dir)
{
    registry().logDir = dir;
}

std::vector<PluginLog> finishPluginLogs()
{
    closeAdapters(); // their output is all in their logs
    std::vector<PluginLog> logs;
    const std::string& dir = registry().logDir;
    if (dir.empty())
        return logs;
    for (const PluginImpl& p : registry().impls)
    {
        if (p.kind == PluginKind::InProcess) // prints where the process does: no log
            continue;
        if (std::any_of(logs.begin(), logs.end(),
                        [&](const PluginLog& l) { return l.file == p.logName; }))
            continue;
        const std::filesystem::path file = std::filesystem::path(dir) / p.logName;
        std::error_code ec;
        const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
        if (ec || bytes == 0)
        {
            std::filesystem::remove(file, ec);
            continue;
        }
        PluginLog log{p.path, p.logName, bytes, bytes >= kPluginLogCapBytes};
        if (log.capped)
            if (FILE* f = std::fopen(file.c_str(), "a"))
            {
                std::fprintf(f,
                             "\n[gjk-validate: this log is capped at %ju bytes of the plugin's "
                             "output; the rest was dropped]\n",
                             std::uintmax_t(kPluginLogCapBytes));
                std::fclose(f);
            }
        logs.push_back(log);
    }
    return logs;
}

PluginChild PluginChild::start(const PluginImpl* plugin, const std::function<void(int fd)>& work)
{
    return serveOrStart(plugin, false, [&](int out, int) { work(out); });
}

PluginChild PluginChild::serve(const PluginImpl* plugin,
                               const std::function<void(int out, int in)>& work)
{
    return serveOrStart(plugin, true, work);
}

bool PluginChild::send(const void* data, std::size_t n) const
{
    const adapterio::SigpipeBlocked
        blocked; // a child gone is EPIPE here, not the end of gjk-validate
    return cmd_ >= 0 && writeAllBytes(cmd_, data, n);
}

namespace
{
// The parent's ends of the serving children's command pipes: every child forked later closes its
// copies, or a child would never read the end of file of another's commands (and never exit).
std::vector<int>& commandFds()
{
    static std::vector<int> fds;
    return fds;
}
} // namespace

PluginChild PluginChild::serveOrStart(const PluginImpl* plugin, bool commands,
                                      const std::function<void(int out, int in)>& work)
{
    int fds[2], cmds[2] = {-1, -1};
    if (::pipe(fds) != 0 || (commands && ::pipe(cmds) != 0))
        throw std::runtime_error(
            fmt::format("plugin child: pipe failed: {}", std::strerror(errno)));
    std::fflush(stdout); // written once, by the parent, not again by the child's copy of the buffer
    std::fflush(stderr);
    const pid_t pid = ::fork();
    if (pid < 0)
        throw std::runtime_error(
            fmt::format("plugin child: fork failed: {}", std::strerror(errno)));
    if (pid == 0)
    {
        ::close(fds[0]);
        if (commands)
            ::close(cmds[1]);
        for (const int fd : commandFds())
            ::close(fd);
        // A plugin's crash ends the child at once, by its signal: the program's own handlers (a
        // sanitizer's, which symbolizes a report first and would count as a hang) are not the
        // plugin's.
        for (const int sig : {SIGPIPE, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
            ::signal(sig, SIG_DFL);
        firstOutputRoute(plugin);
        work(fds[1], cmds[0]);
        std::fflush(stdout); // what the plugin printed last, into its log
        std::fflush(stderr);
        ::_exit(0);
    }
    ::close(fds[1]);
    PluginChild c;
    c.pid_ = pid;
    c.fd_ = fds[0];
    if (commands)
    {
        ::close(cmds[0]);
        ::fcntl(cmds[1], F_SETFD, FD_CLOEXEC);
        c.cmd_ = cmds[1];
        commandFds().push_back(c.cmd_);
    }
    return c;
}

std::string PluginChild::finish()
{
    if (cmd_ >= 0)
    {
        auto& open = commandFds();
        open.erase(std::remove(open.begin(), open.end(), cmd_), open.end());
        ::close(cmd_); // the child reads end of file
    }
    cmd_ = -1;
    ::close(fd_);
    int status = 0;
    while (::waitpid(pid_t(pid_), &status, 0) < 0 && errno == EINTR)
    {
    }
    if (WIFSIGNALED(status))
        return fmt::format("signal {} ({})", WTERMSIG(status), ::strsignal(WTERMSIG(status)));
    if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
        return fmt::format("exit code {}", WEXITSTATUS(status));
    return {};
}

void PluginChild::kill()
{
    ::kill(pid_t(pid_), SIGKILL);
    finish();
}

long PluginChild::read(void* buf, std::size_t n, double timeoutSeconds) const
{
    pollfd pfd{fd_, POLLIN, 0};
    const int ms = int(std::min(timeoutSeconds * 1000, 2e9));
    for (;;)
    {
        const int r = ::poll(&pfd, 1, ms);
        if (r < 0 && errno == EINTR)
            continue;
        if (r == 0)
            return -1;
        const ssize_t got = ::read(fd_, buf, n);
        if (got < 0 && errno == EINTR)
            continue;
        return got < 0 ? 0 : long(got);
    }
}

namespace
{
// Shared-library plugins answer in server children (PluginServers): each is forked once, on a
// campaign's first chunk with plugin tasks, and answers the tasks of every later chunk sent to it
// through a pipe. Forking a child per chunk cost the default campaign 5.4 s of system time on 2
// threads: the fork's copy of the page tables and then a copy-on-write fault on every page the
// campaign wrote after it, 1.1 million of them (docs/speed.md, "Plugins in server children").
// Its answers come back in blocks: one write and one read a block, not a record. A block is
// written when it holds kBlockRecords records, kBlockSeconds after its first record (a slow
// plugin's answers still reach the parent well within --plugin-timeout, whose least is 0.01 s),
// or before the child waits for more tasks.
constexpr std::size_t kBlockRecords = 64;
constexpr double kBlockSeconds = 0.002;
// The commands a server is sent ahead of its answers (bytes); the pipe holds 64 KB.
constexpr std::size_t kCommandBytesAhead = 1 << 16;
using Clock = std::chrono::steady_clock;

// One task as a command: this header, then shape A's and shape B's radius, position, rotation and
// points in the implementation's scalar. The variant is named by its address: the server is a
// fork of this process, made while the registry held it (PluginServers::matchesRegistry()).
struct TaskCommand
{
    std::uint64_t task;
    std::uint64_t variant; // const VariantInfo*
    std::int32_t countA, countB;
    std::uint32_t answerAlone; // 1: write this answer at once (finding a lost case)
    std::uint32_t bytes;       // of the whole command, a multiple of 8
};

template <class T>
void putShape(std::vector<char>& out, const CasePoints<T>& pts, T radius,
              const gjk::Transform<T>& xf)
{
    const T head[5] = {radius, xf.p.x, xf.p.y, xf.q.c, xf.q.s};
    const char* h = reinterpret_cast<const char*>(head);
    out.insert(out.end(), h, h + sizeof head);
    const char* p = reinterpret_cast<const char*>(pts.data());
    out.insert(out.end(), p, p + pts.size() * sizeof(gjk::Vec2<T>));
}

template <class T>
const char* takeShape(const char* in, std::int32_t count, CasePoints<T>& pts, T& radius,
                      gjk::Transform<T>& xf)
{
    T head[5];
    std::memcpy(head, in, sizeof head);
    radius = head[0];
    xf = {{head[1], head[2]}, {head[3], head[4]}};
    in += sizeof head;
    pts.resize(std::size_t(count));
    std::memcpy(pts.data(), in, std::size_t(count) * sizeof(gjk::Vec2<T>));
    return in + std::size_t(count) * sizeof(gjk::Vec2<T>);
}

void putCommand(std::vector<char>& out, std::uint64_t task, const PluginTask& t, bool alone)
{
    const PreparedCase& p = *t.p;
    const bool f = t.v->plugin->impl.scalar == GJK2D_SCALAR_FLOAT;
    const std::size_t start = out.size();
    TaskCommand c{task,
                  std::uint64_t(reinterpret_cast<std::uintptr_t>(t.v)),
                  std::int32_t(f ? p.af.size() : p.ad.size()),
                  std::int32_t(f ? p.bf.size() : p.bd.size()),
                  alone ? 1u : 0u,
                  0};
    out.resize(start + sizeof c);
    if (f)
    {
        putShape<float>(out, p.af, p.raf, p.xaf);
        putShape<float>(out, p.bf, p.rbf, p.xbf);
    }
    else
    {
        putShape<double>(out, p.ad, p.rad, p.xad);
        putShape<double>(out, p.bd, p.rbd, p.xbd);
    }
    out.resize((out.size() + 7) / 8 * 8);
    c.bytes = std::uint32_t(out.size() - start);
    std::memcpy(out.data() + start, &c, sizeof c);
}

// The server's side of one command: its variant and its case (the one scalar's shapes).
const VariantInfo* takeCommand(const char* in, const TaskCommand& c, PreparedCase& p)
{
    const auto* v = reinterpret_cast<const VariantInfo*>(std::uintptr_t(c.variant));
    in += sizeof c;
    if (v->plugin->impl.scalar == GJK2D_SCALAR_FLOAT)
        takeShape<float>(takeShape<float>(in, c.countA, p.af, p.raf, p.xaf), c.countB, p.bf, p.rbf,
                         p.xbf);
    else
        takeShape<double>(takeShape<double>(in, c.countA, p.ad, p.rad, p.xad), c.countB, p.bd,
                          p.rbd, p.xbd);
    return v;
}

// The answers a server has not written yet.
struct AnswerBlock
{
    int fd;
    std::vector<AnswerRecord> records;
    Clock::time_point first;
    void add(const AnswerRecord& r, bool alone)
    {
        const auto now = Clock::now();
        if (records.empty())
            first = now;
        records.push_back(r);
        if (alone || records.size() == kBlockRecords ||
            std::chrono::duration<double>(now - first).count() >= kBlockSeconds)
            flush();
    }
    void flush()
    {
        if (!records.empty() &&
            !writeToParent(fd, records.data(), records.size() * sizeof(AnswerRecord)))
            ::_exit(3);
        records.clear();
    }
};

// The commands a server reads: whole ones from buf[start, end).
struct CommandReader
{
    int fd;
    std::vector<char> buf = std::vector<char>(kCommandBytesAhead);
    std::size_t start = 0, end = 0;

    // Whether buf[start, end) begins with a whole command (its header in c).
    bool whole(TaskCommand& c) const
    {
        if (end - start < sizeof c)
            return false;
        std::memcpy(&c, buf.data() + start, sizeof c);
        return end - start >= c.bytes;
    }
    // Waits for more of the parent's commands: false at their end of file (or the parent gone).
    bool more()
    {
        std::memmove(buf.data(), buf.data() + start, end - start);
        end -= start;
        start = 0;
        TaskCommand c;
        if (end >= sizeof c && (std::memcpy(&c, buf.data(), sizeof c), c.bytes > buf.size()))
            buf.resize(c.bytes); // a command larger than the buffer (thousands of points)
        ssize_t got;
        do
            got = ::read(fd, buf.data() + end, buf.size() - end);
        while (got < 0 && errno == EINTR);
        if (got <= 0)
            return false;
        end += std::size_t(got);
        return true;
    }
};

// A server child's life: commands from `in` until their end of file, one AnswerRecord each to
// `out`, each plugin's output into its own log.
void serveTasks(int out, int in)
{
    std::vector<unsigned char> cache(4096);
    CommandReader commands{in};
    AnswerBlock block{out, {}, {}};
    block.records.reserve(kBlockRecords);
    const PluginImpl* printsTo = nullptr;
    PreparedCase p;
    for (;;)
    {
        TaskCommand c{};
        while (!commands.whole(c))
        {
            block.flush(); // what was answered goes first, then wait for more
            if (!commands.more())
                return;
        }
        const VariantInfo* v = takeCommand(commands.buf.data() + commands.start, c, p);
        commands.start += c.bytes;
        if (printsTo == nullptr || v->plugin->logName != printsTo->logName)
            routePluginOutput(*(printsTo = v->plugin));
        AnswerRecord r = callPlugin(*v, p, cache);
        r.task = c.task;
        block.add(r, c.answerAlone != 0);
    }
}
} // namespace

namespace
{
// The answer a record carries: its status (an unknown one is an error status) and its values.
void takeAnswer(const AnswerRecord& rec, ExternalAnswer& a)
{
    a.status = rec.status == GJK2D_STATUS_OK        ? PluginStatus::Ok
               : rec.status == GJK2D_STATUS_REFUSED ? PluginStatus::Refused
                                                    : PluginStatus::Error;
    if (a.status == PluginStatus::Error && rec.status != GJK2D_STATUS_ERROR)
        a.detail = fmt::format("status {} is not a gjk2d_status", rec.status);
    a.distance = rec.distance;
    a.pointA = {rec.pointA[0], rec.pointA[1]};
    a.pointB = {rec.pointB[0], rec.pointB[1]};
    a.iterations = rec.iterations;
}

// The task the child was on when it crashed or hung: its status, and one line on stderr.
void recordLoss(const PluginTask& t, PluginStatus status, const std::string& how)
{
    t.out->status = status;
    t.out->detail = how.empty() ? "the child exited before answering" : how;
    std::lock_guard lock(g_messages);
    std::fprintf(stderr,
                 "gjk-validate: plugin variant '%s' (%s) %s on case '%s': %s; "
                 "the other cases go on\n",
                 t.v->name.c_str(), t.v->plugin->path.c_str(), pluginStatusName(status),
                 t.caseName ? t.caseName->c_str() : "?", t.out->detail.c_str());
}
} // namespace

// One server child and its share of the current call's tasks.
struct PluginServers::Server
{
    PluginChild child;
    bool running = false;
    std::vector<const PluginTask*> order; // its tasks: by variant, then in the caller's order
    std::size_t next = 0;                 // the first task not answered
    std::size_t sent = 0;                 // the first task not put into `out`
    std::size_t aloneUntil = 0;           // tasks before this one are answered one record at a time
    std::vector<char> out;                // commands not written yet, from out[written]
    std::size_t written = 0;
    std::vector<char> in; // bytes of answer records read, not yet a whole record
    Clock::time_point lastAnswer;

    bool busy() const { return next < order.size(); }
    ~Server()
    {
        if (running)
            child.finish(); // its commands end: the child exits
    }

    void start()
    {
        child = PluginChild::serve(order[next]->v->plugin, [](int answers, int commands)
                                   { serveTasks(answers, commands); });
        ::fcntl(child.commandFd(), F_SETFL, ::fcntl(child.commandFd(), F_GETFL) | O_NONBLOCK);
        running = true;
        sent = next;
        out.clear();
        written = 0;
        in.clear();
        lastAnswer = Clock::now();
    }
    // Commands up to kCommandBytesAhead ahead of what the pipe took.
    void encode()
    {
        if (written == out.size())
        {
            out.clear();
            written = 0;
        }
        while (sent < order.size() && out.size() - written < kCommandBytesAhead)
        {
            putCommand(out, sent, *order[sent], sent < aloneUntil);
            ++sent;
        }
    }
    // What the command pipe takes now (nothing when the child is gone: its answers' end of file
    // tells how).
    void write()
    {
        const ssize_t n = ::write(child.commandFd(), out.data() + written, out.size() - written);
        if (n > 0)
            written += std::size_t(n);
    }
    // The answers poll() said the pipe holds: false at its end of file (the child died or
    // exited) or on a read error.
    bool read()
    {
        char buf[kBlockRecords * sizeof(AnswerRecord)];
        ssize_t got;
        do
            got = ::read(child.answerFd(), buf, sizeof buf);
        while (got < 0 && errno == EINTR);
        if (got <= 0)
            return false;
        in.insert(in.end(), buf, buf + got);
        const std::size_t whole = in.size() / sizeof(AnswerRecord);
        for (std::size_t k = 0; k < whole; ++k)
        {
            AnswerRecord r;
            std::memcpy(&r, in.data() + k * sizeof r, sizeof r);
            if (r.task != next)
                throw std::logic_error(fmt::format(
                    "plugin server answered task {} where {} was expected", r.task, next));
            takeAnswer(r, *order[next]->out);
            ++next;
        }
        in.erase(in.begin(), in.begin() + std::ptrdiff_t(whole * sizeof(AnswerRecord)));
        lastAnswer = Clock::now();
        return true;
    }
    // The child died or hung (and was killed): it may have taken a block of answers with it. In
    // blocks, the case it was on is among the next kBlockRecords tasks: a new child answers those
    // one at a time, and the case that child loses is the one recorded (a plugin answers a case
    // as a pure function of it; a case that does not fail again is answered).
    void lost(PluginStatus status, const std::string& how)
    {
        running = false;
        if (!busy()) // gone after its last answer: the next call starts another
            return;
        if (next >= aloneUntil)
            aloneUntil = next + kBlockRecords;
        else
            recordLoss(*order[next++], status, how);
    }
};

PluginServers::PluginServers(int count) : count_(std::max(1, count)) {}
PluginServers::~PluginServers() = default;

// The servers are forks of this process: they know the variants and the log directory the
// registry had then, and no later ones.
bool PluginServers::matchesRegistry() const
{
    return variantsAtFork_ == registry().variants.size() && logDirAtFork_ == registry().logDir;
}

void PluginServers::answer(const std::vector<PluginTask>& tasks, double timeoutSeconds)
{
    if (tasks.empty())
        return;
    if (!matchesRegistry())
    {
        servers_.clear();
        variantsAtFork_ = registry().variants.size();
        logDirAtFork_ = registry().logDir;
    }
    // Contiguous slices of the tasks (so of the cases), one a server, each by variant then case
    // (a child routes its output to a plugin's log when the plugin changes).
    const std::size_t k =
        std::min(std::size_t(count_), std::max<std::size_t>(1, tasks.size() / kBlockRecords));
    while (servers_.size() < k)
        servers_.push_back(std::make_unique<Server>());
    for (std::size_t s = 0; s < k; ++s)
    {
        Server& sv = *servers_[s];
        sv.order.clear();
        for (std::size_t t = tasks.size() * s / k; t < tasks.size() * (s + 1) / k; ++t)
            sv.order.push_back(&tasks[t]);
        std::stable_sort(sv.order.begin(), sv.order.end(),
                         [](const PluginTask* a, const PluginTask* b)
                         { return std::less<const VariantInfo*>()(a->v, b->v); });
        sv.next = sv.sent = sv.aloneUntil = sv.written = 0;
        sv.out.clear();
        sv.in.clear();
        sv.lastAnswer = Clock::now();
    }
    const adapterio::SigpipeBlocked blocked; // a child gone is EPIPE here, not our end
    while (exchange(k, timeoutSeconds))
    {
    }
}

// One round of the servers' pipes: commands written, answers read, losses recorded; false when
// every task is answered.
bool PluginServers::exchange(std::size_t k, double timeoutSeconds)
{
    std::vector<pollfd> fds;
    std::vector<Server*> polled;
    double wait = timeoutSeconds;
    const auto now = Clock::now();
    for (std::size_t s = 0; s < k; ++s)
    {
        Server& sv = *servers_[s];
        if (!sv.busy())
            continue;
        if (!sv.running)
            sv.start();
        sv.encode();
        fds.push_back({sv.child.answerFd(), POLLIN, 0});
        if (sv.written < sv.out.size())
            fds.push_back({sv.child.commandFd(), POLLOUT, 0});
        polled.push_back(&sv);
        wait = std::min(wait, timeoutSeconds -
                                  std::chrono::duration<double>(now - sv.lastAnswer).count());
    }
    if (polled.empty())
        return false;
    if (::poll(fds.data(), fds.size(), int(std::ceil(std::max(0.0, wait) * 1000))) < 0 &&
        errno != EINTR)
        throw std::runtime_error(
            fmt::format("plugin servers: poll failed: {}", std::strerror(errno)));
    for (Server* sv : polled)
    {
        const auto ready = [&](int fd)
        {
            return std::any_of(fds.begin(), fds.end(),
                               [&](const pollfd& p) { return p.fd == fd && p.revents != 0; });
        };
        if (ready(sv->child.commandFd()))
            sv->write();
        if (ready(sv->child.answerFd()))
        {
            if (!sv->read())
                sv->lost(PluginStatus::Crashed, sv->child.finish());
        }
        else if (std::chrono::duration<double>(Clock::now() - sv->lastAnswer).count() >=
                 timeoutSeconds)
        {
            sv->child.kill();
            sv->lost(PluginStatus::Hung,
                     fmt::format("no answer within {} s, killed", timeoutSeconds));
        }
    }
    return true;
}

void answerContained(const std::vector<PluginTask>& all, double timeoutSeconds,
                     PluginServers& servers)
{
    std::vector<PluginTask> tasks, throughAdapters, inProcess;
    for (const PluginTask& t : all)
        (t.v->plugin->kind == PluginKind::Executable  ? throughAdapters
         : t.v->plugin->kind == PluginKind::InProcess ? inProcess
                                                      : tasks)
            .push_back(t);
    answerInProcess(inProcess);
    answerThroughAdapters(throughAdapters, timeoutSeconds);
    servers.answer(tasks, timeoutSeconds);
}

void answerContained(const std::vector<PluginTask>& tasks, double timeoutSeconds)
{
    PluginServers once(1);
    answerContained(tasks, timeoutSeconds, once);
}

} // namespace gjkval
