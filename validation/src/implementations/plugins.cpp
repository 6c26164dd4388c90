// Loading the implementations under test that are not gjk2d's: shared libraries (dlopen, their
// description checked), executable adapters (their handshake, implementations/adapter.hpp) and
// in-process callables (implementations/in_process.hpp), each implementation registered as a
// variant; and what an implementation declines by its description.
#include "implementations/plugins.hpp"

#include "implementations/registry.hpp"

#include "common/output.hpp" // writeAllBytes
#include "implementations/adapter.hpp"
#include "implementations/adapter_process.hpp" // SigpipeBlocked
#include "implementations/in_process.hpp"
#include "implementations/prepared.hpp"

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

// A shared library's description, its optional gjk2d_plugin_library() ("" without it), its
// optional gjk2d_plugin_timing() and gjk2d_plugin_prepared() tables and its optional
// gjk2d_plugin_depth() clauses (null without them).
struct OpenedPlugin
{
    const gjk2d_plugin* description = nullptr;
    std::string library;
    const gjk2d_timing* timing = nullptr;
    const gjk2d_prepared* prepared = nullptr;
    const gjk2d_depth_contract* depth = nullptr; // description->count clauses
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
    if (d->abi_version < GJK2D_PLUGIN_ABI_MIN_VERSION || d->abi_version > GJK2D_PLUGIN_ABI_VERSION)
        throw InputError(fmt::format(
            "plugin {}: plugin ABI version {}, this gjk-validate reads versions {} to {} (rebuild "
            "the plugin against this SDK's gjk2d/plugin.h)",
            path, d->abi_version, GJK2D_PLUGIN_ABI_MIN_VERSION, GJK2D_PLUGIN_ABI_VERSION));
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
    const auto preparedEntry =
        reinterpret_cast<gjk2d_plugin_prepared_fn>(::dlsym(handle, GJK2D_PLUGIN_PREPARED_ENTRY));
    const gjk2d_prepared* prepared = preparedEntry ? preparedEntry() : nullptr;
    if (prepared && (prepared->scope == nullptr || prepared->prepare == nullptr ||
                     prepared->distance == nullptr || prepared->release == nullptr))
        throw InputError(fmt::format("plugin {}: {}() returned a table with a NULL function", path,
                                     GJK2D_PLUGIN_PREPARED_ENTRY));
    const auto depthEntry =
        reinterpret_cast<gjk2d_plugin_depth_fn>(::dlsym(handle, GJK2D_PLUGIN_DEPTH_ENTRY));
    const gjk2d_depth_contract* depth = depthEntry ? depthEntry() : nullptr;
    if (depthEntry && depth == nullptr)
        throw InputError(
            fmt::format("plugin {}: {}() returned NULL", path, GJK2D_PLUGIN_DEPTH_ENTRY));
    return {d, text ? text : "", loop, prepared, depth};
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
        p.contract = a.contract;
        p.preparation = a.preparation;
        impls.push_back(std::move(p));
    }
    return impls;
}

// Implementation i's contract as a version-2 plugin declares it; InputError when it is unsound.
Contract declaredContract(const std::string& path, int i, const gjk2d_contract& d)
{
    auto text = [](const char* s) { return std::string(s ? s : ""); };
    Contract c;
    c.own = false;
    // Negative: not stated. A NaN is kept (NaN < 0 is false) for checkContract to refuse.
    c.absTolerance = d.distance_abs_tolerance < 0 ? -1 : d.distance_abs_tolerance;
    c.relTolerance = d.distance_rel_tolerance < 0 ? -1 : d.distance_rel_tolerance;
    c.toleranceSource = text(d.tolerance_source);
    c.overlap = Overlap(d.overlap);
    c.overlapSource = text(d.overlap_source);
    c.margin = d.margin;
    c.marginSource = text(d.margin_source);
    return c;
}

// Implementation i's depth clause (gjk2d_plugin_depth), into its contract: negative tolerances
// are not stated, a NaN is kept for checkContract to refuse.
void declaredDepth(Contract& c, const gjk2d_depth_contract& d)
{
    c.depthAbsTolerance = d.abs_tolerance < 0 ? -1 : d.abs_tolerance;
    c.depthRelTolerance = d.rel_tolerance < 0 ? -1 : d.rel_tolerance;
    c.depthSource = d.source ? d.source : "";
}

// The contract of implementation i as the plugin declares it (gjk2d's own without contracts),
// with its depth clause; InputError when it is unsound.
Contract pluginContract(const std::string& path, int i, const OpenedPlugin& opened)
{
    const gjk2d_plugin& d = *opened.description;
    Contract c = d.abi_version >= 2 && d.contracts != nullptr
                     ? declaredContract(path, i, d.contracts[i])
                     : ownContract();
    if (opened.depth != nullptr)
        declaredDepth(c, opened.depth[i]);
    const std::string problem = checkContract(c);
    if (!problem.empty())
        throw InputError(
            fmt::format("plugin {}: bad contract of implementation {}: {}", path, i, problem));
    return c;
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
        p.contract = pluginContract(path, i, opened);
        p.library = opened.library;
        p.timing = opened.timing;
        p.index = i;
        p.prepared = opened.prepared;
        if (p.prepared)
        {
            const std::int32_t scope = p.prepared->scope(i);
            if (scope != GJK2D_PREPARED_SHAPE && scope != GJK2D_PREPARED_CASE)
                throw InputError(
                    fmt::format("plugin {}: implementation '{}': prepared scope {} is neither "
                                "GJK2D_PREPARED_SHAPE (0) nor GJK2D_PREPARED_CASE (1)",
                                path, p.impl.name, scope));
            p.preparation = scope == GJK2D_PREPARED_SHAPE ? Preparation::Shape : Preparation::Case;
        }
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

const char* preparationName(Preparation p)
{
    switch (p)
    {
    case Preparation::None:
        return "none";
    case Preparation::Shape:
        return "shape";
    case Preparation::Case:
        return "case";
    case Preparation::InCall:
        return "in-call";
    }
    return "?";
}

Preparation preparationOf(const VariantInfo& v)
{
    return v.plugin ? v.plugin->preparation : Preparation::None;
}

bool selfTimed(const VariantInfo& v)
{
    return v.plugin && v.plugin->kind == PluginKind::Executable;
}

Json timingJson(const VariantInfo& v)
{
    static constexpr const char* includes[] = {
        "the query alone: gjk2d's plain query takes the points as given, nothing to prepare",
        "the query alone, on shapes prepared once in their own frame (preparation timed apart, per "
        "shape)",
        "the query alone, on shapes prepared per case with the case's world points baked in (the "
        "library cannot take the case's transform exactly, or works in world coordinates; "
        "preparation timed apart, per shape)",
        "the query and the shapes' set-up, every call (no preparation step offered)",
    };
    const Preparation p = preparationOf(v);
    Json j = {{"preparation", preparationName(p)},
              {"includes", includes[int(p)]},
              {"timed_by", selfTimed(v) ? "adapter" : "gjk-validate"}};
    if (v.plugin == nullptr) // gjk2d's own: the second figure, on prepared shapes, or why none
        j["prepared"] = {
            {"timed", hasPreparedForm(v)},
            {"includes", hasPreparedForm(v)
                             ? "the same queries on shapes prepared once by gjk::prepare "
                               "(gjk2d/prepared.hpp), the preparation timed apart, per shape"
                         : v.batch ? "no prepared form: gjk::distanceBatchLanes takes plain inputs"
                                   : "no prepared form: with these options the query on prepared "
                                     "shapes runs the plain query"}};
    return j;
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

} // namespace gjkval
