// gjk2d-adapter-bridge: an executable adapter (protocol version 1 or 2, docs/plugin-abi.md,
// "Executable adapters") that hosts a shared-library plugin (gjk2d/plugin.h, ABI
// version 1 or 2).
//
//   gjk2d-adapter-bridge PLUGIN.so [SUFFIX]  (or GJK2D_BRIDGE_PLUGIN=PLUGIN.so
//   gjk2d-adapter-bridge)
//
// SUFFIX, appended to every implementation's name, lets the bridged plugin run beside the
// plugin itself (variant names are unique in a run): box2d-2.4.1 and box2d-2.4.1-bridge.
//
// gjk-validate starts an executable adapter without arguments: a two-line script makes one of a
// shared library,
//
//   #!/bin/sh
//   exec /path/to/gjk2d-adapter-bridge /path/to/gjk2d-box2d.so
//
// It is the reference C++ adapter (C++17, only gjk2d/plugin.h and dlopen) and the check that a
// timing through the protocol agrees with the shared library's own (docs/plugin-abi.md):
// its `time` loop is the runner's (timing.cpp timePassPlugin): each case's shapes built before
// the clock starts, per call the cache zeroed, one call, the result read. It takes what the
// hosted plugin takes (radius, max_vertices), always cold (protocol 1 has no warm start), and
// answers `refused` or `error` when the plugin's call says so. What the plugin prints on stdout
// goes to stderr (the bridge's stdout carries the protocol only).
//
// Contracts: the bridge answers the hosted plugin's ABI version as its protocol version, so that
// the bridged plugin is held to what the plugin itself is. A version-2 plugin with contracts
// gets, after each implementation line, its three `contract` lines (overlap, tolerance, margin,
// each with its source), and a fourth, `depth`, when the plugin exports gjk2d_plugin_depth; a
// version-1 plugin, or a version-2 one whose contracts are NULL, gets
// none: gjk2d's own contract, as when the host loads the plugin itself.
//
// Prepared shapes: when the plugin exports gjk2d_plugin_prepared, the bridge speaks protocol
// version 2 (at least) and declares `prepared NAME shape|case` per implementation, by its scope.
// Then every answer goes through the plugin's prepare, distance and release: a `distance` request
// prepares its two shapes, queries and releases them (so what is judged is what is timed); a
// `time` request prepares its 2m shapes once, timed apart (PREPARE_NS), then times K loops of
// queries alone on them (NS), cache zeroed per query, and answers `timed ID NS PREPARE_NS`.
// A shape the plugin cannot prepare (NULL) answers `error`. Without it, the plugin's distance_f
// or distance_d answers, every figure includes the shapes' set-up, and `timed ID NS` says so.
#include <gjk2d/plugin.h>

#include <dlfcn.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
std::FILE* g_out = nullptr; // the protocol's stream: the original stdout

void say(const std::string& line)
{
    std::fputs(line.c_str(), g_out);
    std::fputc('\n', g_out);
    std::fflush(g_out);
}

[[noreturn]] void die(const std::string& why)
{
    std::fprintf(stderr, "gjk2d-adapter-bridge: %s\n", why.c_str());
    std::exit(1);
}

const gjk2d_plugin* g_plugin = nullptr;
const gjk2d_prepared* g_prepared = nullptr;    // the optional gjk2d_plugin_prepared table
const gjk2d_depth_contract* g_depth = nullptr; // the optional gjk2d_plugin_depth clauses
std::string g_library;
std::string g_suffix; // appended to every implementation's name (the second argument)

void openPlugin(const char* path)
{
    void* h = ::dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (h == nullptr)
        die(std::string("cannot load ") + path + ": " + ::dlerror());
    auto describe =
        reinterpret_cast<gjk2d_plugin_describe_fn>(::dlsym(h, GJK2D_PLUGIN_ENTRY_POINT));
    if (describe == nullptr || (g_plugin = describe()) == nullptr)
        die(std::string(path) + " does not describe a gjk2d plugin");
    if (g_plugin->abi_version < GJK2D_PLUGIN_ABI_MIN_VERSION ||
        g_plugin->abi_version > GJK2D_PLUGIN_ABI_VERSION)
        die(std::string(path) + ": plugin ABI version " + std::to_string(g_plugin->abi_version) +
            ", the bridge reads " + std::to_string(GJK2D_PLUGIN_ABI_MIN_VERSION) + " to " +
            std::to_string(GJK2D_PLUGIN_ABI_VERSION));
    auto library =
        reinterpret_cast<gjk2d_plugin_library_fn>(::dlsym(h, GJK2D_PLUGIN_LIBRARY_ENTRY));
    g_library = library && library() ? library() : std::string(path);
    auto prepared =
        reinterpret_cast<gjk2d_plugin_prepared_fn>(::dlsym(h, GJK2D_PLUGIN_PREPARED_ENTRY));
    if (prepared != nullptr)
    {
        g_prepared = prepared();
        if (g_prepared == nullptr || g_prepared->scope == nullptr ||
            g_prepared->prepare == nullptr || g_prepared->distance == nullptr ||
            g_prepared->release == nullptr)
            die(std::string(path) + ": " GJK2D_PLUGIN_PREPARED_ENTRY
                                    " returns a table without its four functions");
    }
    auto depth = reinterpret_cast<gjk2d_plugin_depth_fn>(::dlsym(h, GJK2D_PLUGIN_DEPTH_ENTRY));
    if (depth != nullptr && (g_depth = depth()) == nullptr)
        die(std::string(path) + ": " GJK2D_PLUGIN_DEPTH_ENTRY " returns NULL");
}

// The index of the implementation called `name` (suffix included); -1 when none is.
int findImpl(const std::string& name)
{
    for (int i = 0; i < g_plugin->count; ++i)
        if (name == g_plugin->implementations[i].name + g_suffix)
            return i;
    return -1;
}

// Implementation i's scope: GJK2D_PREPARED_SHAPE or GJK2D_PREPARED_CASE (checked at the
// handshake), or -1 when the plugin has no prepared shapes.
int32_t scopeOf(int i)
{
    return g_prepared ? g_prepared->scope(i) : -1;
}

std::string num(double x)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

// A source as the rest of a protocol line: line breaks become spaces; a space before it unless
// it is empty (a clause the library does not state).
std::string sourceText(const char* source)
{
    std::string s = source ? source : "";
    for (char& c : s)
        if (c == '\n' || c == '\r')
            c = ' ';
    return s.empty() ? s : " " + s;
}

// A tolerance as the protocol writes it: the number, or `none` when negative (none stated).
std::string tolerance(double x)
{
    return x < 0 ? std::string("none") : num(x);
}

// The version-2 `contract` lines of implementation `name` (gjk2d_contract's three clauses, and
// the depth clause when the plugin states one: `depth` may be NULL).
void sayContract(const std::string& name, const gjk2d_contract& c,
                 const gjk2d_depth_contract* depth)
{
    static const char* const kOverlap[] = {"common-point", "zero", "midpoint", "penetration",
                                           "perimeter"}; // gjk2d_overlap's order
    if (c.overlap < 0 || c.overlap >= int32_t(sizeof kOverlap / sizeof kOverlap[0]))
        die("implementation " + name + ": overlap " + std::to_string(c.overlap) +
            " is not a gjk2d_overlap");
    say("contract " + name + " overlap " + kOverlap[c.overlap] + sourceText(c.overlap_source));
    say("contract " + name + " tolerance " + tolerance(c.distance_abs_tolerance) + " " +
        tolerance(c.distance_rel_tolerance) + sourceText(c.tolerance_source));
    say("contract " + name + " margin " + num(c.margin) + sourceText(c.margin_source));
    if (depth != nullptr)
        say("contract " + name + " depth " + tolerance(depth->abs_tolerance) + " " +
            tolerance(depth->rel_tolerance) + sourceText(depth->source));
}

void handshake()
{
    std::string line;
    char buf[256];
    if (std::fgets(buf, sizeof buf, stdin) == nullptr)
        std::exit(0);
    line = buf;
    if (line.rfind("gjk2d-adapter 1", 0) != 0)
        die("the host does not speak protocol 1: " + line);
    // The plugin's ABI version is the protocol version spoken, version 2 at least when it has
    // prepared shapes (the `prepared` line is version 2's; the header comment).
    say("gjk2d-adapter " +
        std::to_string(g_prepared && g_plugin->abi_version < 2 ? 2 : g_plugin->abi_version));
    say("library " + g_library);
    const gjk2d_contract* contracts = g_plugin->abi_version >= 2 ? g_plugin->contracts : nullptr;
    for (int i = 0; i < g_plugin->count; ++i)
    {
        const gjk2d_implementation& im = g_plugin->implementations[i];
        const std::string name = im.name + g_suffix;
        say("implementation " + name + " " +
            (im.scalar == GJK2D_SCALAR_FLOAT ? "float" : "double") + " " +
            ((im.accepts & GJK2D_ACCEPTS_RADIUS) ? "radius" : "no-radius") + " " +
            std::to_string(im.max_vertices) + " " + (im.description ? im.description : ""));
        if (contracts != nullptr)
            sayContract(name, contracts[i], g_depth ? &g_depth[i] : nullptr);
        const int32_t scope = scopeOf(i);
        if (g_prepared && scope != GJK2D_PREPARED_SHAPE && scope != GJK2D_PREPARED_CASE)
            die("implementation " + name + ": prepared scope " + std::to_string(scope) +
                " is neither GJK2D_PREPARED_SHAPE (0) nor GJK2D_PREPARED_CASE (1)");
        if (g_prepared)
            say("prepared " + name + (scope == GJK2D_PREPARED_SHAPE ? " shape" : " case"));
    }
    say("ready");
}

// A request's tokens, read in place with strtod (no copy of a line that can be megabytes long).
struct Reader
{
    const char* p;
    void skip()
    {
        while (*p == ' ' || *p == '\r')
            ++p;
    }
    bool word(std::string& w)
    {
        skip();
        const char* q = p;
        while (*p != '\0' && *p != ' ' && *p != '\r')
            ++p;
        w.assign(q, p);
        return !w.empty();
    }
    bool number(double& x)
    {
        skip();
        char* end = nullptr;
        x = std::strtod(p, &end);
        const bool ok = end != p && (*end == ' ' || *end == '\0' || *end == '\r');
        p = end;
        return ok;
    }
    bool integer(long& x)
    {
        double v = 0;
        if (!number(v) || v != double(long(v)))
            return false;
        x = long(v);
        return true;
    }
};

// The cases' shapes in the implementation's scalar type, all their points in one contiguous
// array (as the runner's timing set: scattered per-shape arrays timed a few % slower).
template <class T, class Shape> struct Cases
{
    std::vector<T> coords;
    std::vector<std::size_t> at; // each shape's first coordinate in coords
    std::vector<Shape> a, b;

    bool readShape(Reader& in, char tag, std::vector<Shape>& to)
    {
        std::string t;
        double r, px, py, c, s;
        long n = -1;
        if (!in.word(t) || t.size() != 1 || t[0] != tag || !in.number(r) || !in.number(px) ||
            !in.number(py) || !in.number(c) || !in.number(s) || !in.integer(n) || n < 0)
            return false;
        at.push_back(coords.size());
        for (long k = 0; k < 2 * n; ++k)
        {
            double v;
            if (!in.number(v))
                return false;
            coords.push_back(T(v)); // exact: a float implementation's case holds floats
        }
        Shape sh{};
        sh.count = int32_t(n);
        sh.radius = T(r);
        sh.position[0] = T(px);
        sh.position[1] = T(py);
        sh.rotation[0] = T(c);
        sh.rotation[1] = T(s);
        to.push_back(sh);
        return true;
    }
    bool read(Reader& in, long m)
    {
        for (long k = 0; k < m; ++k)
            if (!readShape(in, 'A', a) || !readShape(in, 'B', b))
                return false;
        for (std::size_t k = 0; k < a.size(); ++k) // coords no longer grows: point into it
        {
            a[k].points = coords.data() + at[2 * k];
            b[k].points = coords.data() + at[2 * k + 1];
        }
        return true;
    }
};

// Case k's two shapes prepared by implementation i (a SHAPE-scoped one is given other = NULL, a
// CASE-scoped one the case's other shape); false, with nothing left prepared, when either is NULL.
template <class Shape> bool prepareCase(int i, const Shape& a, const Shape& b, void*& pa, void*& pb)
{
    const bool perCase = scopeOf(i) == GJK2D_PREPARED_CASE;
    pa = g_prepared->prepare(i, &a, perCase ? &b : nullptr);
    pb = pa ? g_prepared->prepare(i, &b, perCase ? &a : nullptr) : nullptr;
    if (pb == nullptr && pa != nullptr)
        g_prepared->release(i, pa);
    return pb != nullptr;
}

// One query of implementation i: through its prepared shapes when the plugin has them
// (prepared[0], prepared[1]), else through distance_f / distance_d.
template <class Shape, class Result> struct Query
{
    int i;
    int32_t (*fn)(const Shape*, const Shape*, void*, Result*);
    int32_t operator()(const Shape& a, void* pa, const Shape& b, void* pb, void* cache,
                       Result* out) const
    {
        return g_prepared ? g_prepared->distance(i, pa, &a, pb, &b, cache, out)
                          : fn(&a, &b, cache, out);
    }
};

template <class T, class Shape, class Result>
std::string distanceT(const std::string& id, const Query<Shape, Result>& query, int cacheBytes,
                      Reader& in)
{
    Cases<T, Shape> cs;
    if (!cs.read(in, 1))
        return "error " + id + " bad request";
    void *pa = nullptr, *pb = nullptr;
    if (g_prepared && !prepareCase(query.i, cs.a[0], cs.b[0], pa, pb))
        return "error " + id + " the plugin could not prepare the case's shapes";
    std::vector<unsigned char> cache(std::size_t(cacheBytes > 0 ? cacheBytes : 1), 0);
    Result o{};
    o.iterations = -1;
    const int32_t st = query(cs.a[0], pa, cs.b[0], pb, cacheBytes > 0 ? cache.data() : nullptr, &o);
    if (g_prepared)
    {
        g_prepared->release(query.i, pa);
        g_prepared->release(query.i, pb);
    }
    if (st == GJK2D_STATUS_REFUSED)
        return "refused " + id + " the plugin refused the case";
    if (st != GJK2D_STATUS_OK)
        return "error " + id + " the plugin returned status " + std::to_string(st);
    return "ok " + id + " " + num(o.distance) + " " + num(o.point_a[0]) + " " + num(o.point_a[1]) +
           " " + num(o.point_b[0]) + " " + num(o.point_b[1]) + " " + std::to_string(o.iterations);
}

volatile double g_sink = 0; // keeps the timed loop from being optimised away

long long nanosSince(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() -
                                                                t0)
        .count();
}

// The runner's loop (timing.cpp timePassPlugin), K rounds over the m cases; only it is timed.
// With prepared shapes, their preparation comes first, timed apart, and the loop queries them.
template <class T, class Shape, class Result>
std::string timeT(const std::string& id, const Query<Shape, Result>& query, int cacheBytes, long K,
                  long m, Reader& in)
{
    Cases<T, Shape> cs;
    if (K < 1 || m < 1 || !cs.read(in, m))
        return "error " + id + " bad request";
    const std::size_t n = cs.a.size();
    std::vector<void*> pa(n, nullptr), pb(n, nullptr);
    const auto releaseAll = [&]
    {
        for (std::size_t i = 0; i < n && g_prepared; ++i)
            if (pa[i] != nullptr)
            {
                g_prepared->release(query.i, pa[i]);
                g_prepared->release(query.i, pb[i]);
            }
    };
    long long prepareNs = 0;
    if (g_prepared)
    {
        const auto p0 = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < n; ++i)
            if (!prepareCase(query.i, cs.a[i], cs.b[i], pa[i], pb[i]))
            {
                releaseAll();
                return "error " + id + " the plugin could not prepare case " +
                       std::to_string(i + 1) + "'s shapes";
            }
        prepareNs = nanosSince(p0);
    }
    std::vector<unsigned char> cache(std::size_t(cacheBytes > 0 ? cacheBytes : 1), 0);
    void* c = cacheBytes > 0 ? cache.data() : nullptr;
    const auto t0 = std::chrono::steady_clock::now();
    double acc = 0;
    for (long r = 0; r < K; ++r)
        for (std::size_t i = 0; i < n; ++i)
        {
            std::memset(cache.data(), 0, std::size_t(cacheBytes));
            Result o{};
            query(cs.a[i], pa[i], cs.b[i], pb[i], c, &o);
            acc += double(o.distance);
        }
    const long long ns = nanosSince(t0);
    g_sink = g_sink + acc;
    releaseAll();
    return "timed " + id + " " + std::to_string(ns) +
           (g_prepared ? " " + std::to_string(prepareNs) : std::string());
}

std::string answer(const std::string& line)
{
    Reader in{line.c_str()};
    std::string word, id, name;
    if (!in.word(word) || !in.word(id) || !in.word(name))
        return "error " + (id.empty() ? std::string("0") : id) + " bad request";
    const int i = findImpl(name);
    if (i < 0)
        return "error " + id + " no implementation " + name;
    const gjk2d_implementation& im = g_plugin->implementations[i];
    const bool f = im.scalar == GJK2D_SCALAR_FLOAT;
    const Query<gjk2d_shape_f, gjk2d_result_f> qf{i, im.distance_f};
    const Query<gjk2d_shape_d, gjk2d_result_d> qd{i, im.distance_d};
    if (word == "distance")
        return f ? distanceT<float>(id, qf, im.cache_bytes, in)
                 : distanceT<double>(id, qd, im.cache_bytes, in);
    long K = 0, m = 0;
    if (word != "time" || !in.integer(K) || !in.integer(m))
        return "error " + id + " unknown request " + word;
    return f ? timeT<float>(id, qf, im.cache_bytes, K, m, in)
             : timeT<double>(id, qd, im.cache_bytes, K, m, in);
}
} // namespace

int main(int argc, char** argv)
{
    // The protocol on the original stdout; the plugin's own printing on stderr.
    const int protocolFd = ::dup(STDOUT_FILENO);
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
    g_out = ::fdopen(protocolFd, "w");
    const char* env = std::getenv("GJK2D_BRIDGE_PLUGIN");
    const char* path = argc > 1 ? argv[1] : env;
    if (path == nullptr || g_out == nullptr)
        die("usage: gjk2d-adapter-bridge PLUGIN.so (or GJK2D_BRIDGE_PLUGIN=PLUGIN.so)");
    g_suffix = argc > 2 ? argv[2] : "";
    openPlugin(path);
    handshake();
    std::string line;
    for (int c; (c = std::getchar()) != EOF;)
    {
        if (c != '\n')
        {
            line.push_back(char(c));
            continue;
        }
        if (!line.empty())
            say(answer(line));
        line.clear();
    }
    return 0;
}
