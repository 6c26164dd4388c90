#include "evaluate/adapter.hpp"

#include "evaluate/evaluate.hpp"
#include "evaluate/plugins.hpp"

#include <fmt/format.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <stdexcept>

namespace gjkval
{
namespace
{
using Clock = std::chrono::steady_clock;

Clock::time_point deadlineIn(double seconds)
{
    return Clock::now() + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(std::min(seconds, 1e7)));
}

// Milliseconds left until `deadline` for poll(): 0 when it has passed.
int msLeft(Clock::time_point deadline)
{
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return int(std::clamp<long long>(left + 1, 0, INT_MAX));
}

// ---- Text: tokens separated by one or more spaces, strict numbers ----

std::vector<std::string> tokens(const std::string& line)
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
std::string restAfter(const std::string& line, std::size_t n)
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
bool parseNumber(const std::string& t, double& x)
{
    if (t.empty() || t[0] == ' ')
        return false;
    char* end = nullptr;
    errno = 0;
    x = std::strtod(t.c_str(), &end);
    return end == t.c_str() + t.size(); // ERANGE: a subnormal or an overflow to inf, kept
}

// A whole token as an integer in [lo, hi].
bool parseInteger(const std::string& t, long long lo, long long hi, long long& x)
{
    if (t.empty() || t.size() > 20 || !(t[0] == '-' || (t[0] >= '0' && t[0] <= '9')))
        return false;
    char* end = nullptr;
    errno = 0;
    x = std::strtoll(t.c_str(), &end, 10);
    return end == t.c_str() + t.size() && errno == 0 && x >= lo && x <= hi;
}

std::string quoted80(const std::string& line)
{
    return fmt::format("\"{}\"", line.substr(0, 80));
}

// ---- The process: stdin and stdout through pipes, stderr to the plugin's log ----

enum class Io
{
    Ok,
    Gone,    // the adapter closed its end (it exited, or is about to)
    Timeout, // nothing within the limit
};

struct Process
{
    int pid = -1;
    int toAdapter = -1, fromAdapter = -1;
    std::string buffer; // read, not yet taken as lines
};

// A failed start or handshake: what went wrong, as the one line says it.
struct AdapterFailure : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

// In the child: stdin and stdout the pipes, stderr where the plugin's log is, signals as a fresh
// program expects them; then the adapter itself (exit 127 when it cannot be executed).
[[noreturn]] void execAdapter(const std::string& path, const PluginImpl* plugin, int in, int out,
                              int err)
{
    firstOutputRoute(plugin);
    if (::dup2(in, STDIN_FILENO) < 0 || ::dup2(out, STDOUT_FILENO) < 0 ||
        (err >= 0 && ::dup2(err, STDERR_FILENO) < 0))
        ::_exit(127);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    for (const int sig : {SIGPIPE, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGINT, SIGTERM})
        ::signal(sig, SIG_DFL);
    ::execl(path.c_str(), path.c_str(), static_cast<char*>(nullptr));
    ::_exit(127); // as a shell says "cannot execute": howEnded() adds the hint
}

// `err` >= 0: the adapter's stderr goes there rather than to the plugin's log.
Process startProcess(const std::string& path, const PluginImpl* plugin, int err = -1)
{
    int in[2], out[2];
    if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0)
        throw std::runtime_error(
            fmt::format("adapter {}: pipe failed: {}", path, std::strerror(errno)));
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = ::fork();
    if (pid < 0)
        throw std::runtime_error(
            fmt::format("adapter {}: fork failed: {}", path, std::strerror(errno)));
    if (pid == 0)
        execAdapter(path, plugin, in[0], out[1], err);
    ::close(in[0]);
    ::close(out[1]);
    ::fcntl(in[1], F_SETFL, ::fcntl(in[1], F_GETFL) | O_NONBLOCK); // a write never blocks
    Process p;
    p.pid = pid;
    p.toAdapter = in[1];
    p.fromAdapter = out[0];
    return p;
}

// How the process ended, once it has: "exit code N", "signal N (name)".
std::string howEnded(int status)
{
    if (WIFSIGNALED(status))
        return fmt::format("signal {} ({})", WTERMSIG(status), ::strsignal(WTERMSIG(status)));
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return fmt::format("exit code {}{}", code,
                       code == 127 ? ", also that of a file that cannot be executed: is its #! "
                                     "interpreter installed?"
                                   : "");
}

// Ends the process: its pipes closed, up to waitSeconds for it to exit, then SIGKILL. How it
// ended ("exit code 0" for a clean exit).
std::string reap(Process& p, double waitSeconds)
{
    if (p.pid < 0)
        return {};
    ::close(p.toAdapter);
    ::close(p.fromAdapter);
    const auto deadline = deadlineIn(waitSeconds);
    int status = 0;
    pid_t r = 0;
    while ((r = ::waitpid(p.pid, &status, WNOHANG)) == 0 && Clock::now() < deadline)
        ::usleep(2000);
    if (r == 0)
    {
        ::kill(p.pid, SIGKILL);
        while (::waitpid(p.pid, &status, 0) < 0 && errno == EINTR)
        {
        }
    }
    p = Process{};
    return howEnded(status);
}

// Writes all of `text` by the deadline. SIGPIPE is blocked meanwhile (a gone adapter is EPIPE,
// not the end of gjk-validate) and a pending one taken back.
Io writeText(Process& p, const std::string& text, Clock::time_point deadline)
{
    sigset_t pipeSet, old;
    sigemptyset(&pipeSet);
    sigaddset(&pipeSet, SIGPIPE);
    ::pthread_sigmask(SIG_BLOCK, &pipeSet, &old);
    Io result = Io::Ok;
    for (std::size_t done = 0; done < text.size() && result == Io::Ok;)
    {
        const ssize_t n = ::write(p.toAdapter, text.data() + done, text.size() - done);
        if (n > 0)
            done += std::size_t(n);
        else if (n < 0 && errno == EPIPE)
            result = Io::Gone;
        else if (n < 0 && errno != EAGAIN && errno != EINTR)
            result = Io::Gone;
        else if (n < 0 && errno == EAGAIN)
        {
            pollfd pfd{p.toAdapter, POLLOUT, 0};
            if (::poll(&pfd, 1, msLeft(deadline)) == 0)
                result = Io::Timeout;
        }
    }
    const timespec zero{0, 0};
    while (::sigtimedwait(&pipeSet, nullptr, &zero) > 0)
    {
    }
    ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
    return result;
}

// The next non-empty line (its "\n" and a "\r" before it removed), by the deadline. A line
// longer than kMaxLine is cut there (it is no answer the host asks for: malformed).
Io readLine(Process& p, std::string& line, Clock::time_point deadline)
{
    constexpr std::size_t kMaxLine = 1 << 20;
    for (;;)
    {
        const std::size_t nl = p.buffer.find('\n');
        if (nl != std::string::npos || p.buffer.size() >= kMaxLine)
        {
            line = p.buffer.substr(0, std::min(nl, kMaxLine));
            p.buffer.erase(0, nl == std::string::npos ? kMaxLine : nl + 1);
            if (!line.empty() && line.back() == '\r')
                line.pop_back();
            if (line.empty())
                continue;
            return Io::Ok;
        }
        pollfd pfd{p.fromAdapter, POLLIN, 0};
        const int r = ::poll(&pfd, 1, msLeft(deadline));
        if (r < 0 && errno == EINTR)
            continue;
        if (r == 0)
            return Io::Timeout;
        char buf[65536];
        const ssize_t n = ::read(p.fromAdapter, buf, sizeof buf);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return Io::Gone;
        p.buffer.append(buf, std::size_t(n));
    }
}

// ---- The handshake ----

bool validName(const std::string& s)
{
    if (s.empty() || s.size() > 64)
        return false;
    return std::all_of(s.begin(), s.end(),
                       [](char c)
                       {
                           return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                                  (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '+' ||
                                  c == '-';
                       });
}

// One `implementation` line, checked; AdapterFailure says what is wrong.
AdapterImplementation implementationLine(const std::string& line,
                                         const std::vector<AdapterImplementation>& before)
{
    const std::vector<std::string> t = tokens(line);
    if (t.size() < 5)
        throw AdapterFailure(
            fmt::format("bad description: {} has fewer than 5 fields", quoted80(line)));
    AdapterImplementation im;
    im.name = t[1];
    if (!validName(im.name))
        throw AdapterFailure(
            fmt::format("bad description: name '{}' is not 1 to 64 characters of [A-Za-z0-9._+-]",
                        im.name.substr(0, 80)));
    for (const auto& b : before)
        if (b.name == im.name)
            throw AdapterFailure(
                fmt::format("bad description: the name '{}' is taken (given twice)", im.name));
    if (t[2] != "float" && t[2] != "double")
        throw AdapterFailure(fmt::format(
            "bad description: implementation {}: scalar '{}' is neither float nor double", im.name,
            t[2].substr(0, 80)));
    im.scalar = t[2] == "float" ? Scalar::Float : Scalar::Double;
    if (t[3] != "radius" && t[3] != "no-radius")
        throw AdapterFailure(
            fmt::format("bad description: implementation {}: '{}' is neither radius nor no-radius",
                        im.name, t[3].substr(0, 80)));
    im.radius = t[3] == "radius";
    long long maxVertices = 0;
    if (!parseInteger(t[4], 0, INT32_MAX, maxVertices))
        throw AdapterFailure(fmt::format(
            "bad description: implementation {}: max_vertices '{}' is not an integer >= 0", im.name,
            t[4].substr(0, 80)));
    im.maxVertices = int(maxVertices);
    im.description = restAfter(line, 5);
    return im;
}

// The first line: `gjk2d-adapter 1`.
void versionLine(const std::string& line)
{
    const std::vector<std::string> t = tokens(line);
    if (t.size() != 2 || t[0] != "gjk2d-adapter")
        throw AdapterFailure(
            fmt::format("bad description: the first line is {}, expected 'gjk2d-adapter {}'",
                        quoted80(line), kAdapterProtocolVersion));
    if (t[1] != std::to_string(kAdapterProtocolVersion))
        throw AdapterFailure(fmt::format(
            "executable adapter speaks protocol version {}, this gjk-validate speaks {}",
            t[1].substr(0, 20), kAdapterProtocolVersion));
}

// Why the handshake stopped short: the adapter's exit, or the limit.
[[noreturn]] void handshakeCut(Process& p, Io io, double limit)
{
    if (io == Io::Timeout)
    {
        reap(p, 0);
        throw AdapterFailure(fmt::format("no 'ready' within {} s of the handshake", limit));
    }
    const std::string how = reap(p, kAdapterCloseSeconds);
    throw AdapterFailure(fmt::format("executable adapter exited during the handshake ({})", how));
}

// The host's line and the adapter's description, to its `ready`, within `limit` seconds.
AdapterDescription handshake(Process& p, double limit)
{
    const auto deadline = deadlineIn(limit);
    Io io = writeText(p, fmt::format("gjk2d-adapter {}\n", kAdapterProtocolVersion), deadline);
    std::string line;
    if (io != Io::Ok || (io = readLine(p, line, deadline)) != Io::Ok)
        handshakeCut(p, io, limit);
    versionLine(line);
    AdapterDescription d;
    bool haveLibrary = false;
    for (;;)
    {
        if ((io = readLine(p, line, deadline)) != Io::Ok)
            handshakeCut(p, io, limit);
        const std::vector<std::string> t = tokens(line);
        if (t.empty())
            continue; // spaces only: an empty line
        if (t[0] == "ready" && t.size() == 1)
            break;
        if (t[0] == "library" && !haveLibrary)
        {
            d.library = restAfter(line, 1);
            haveLibrary = true;
        }
        else if (t[0] == "implementation" && d.implementations.size() < 64)
            d.implementations.push_back(implementationLine(line, d.implementations));
        else
            throw AdapterFailure(fmt::format(
                "bad description: unexpected line {} (a second library, a 65th implementation, "
                "or an unknown word)",
                quoted80(line)));
    }
    if (!haveLibrary)
        throw AdapterFailure("bad description: no 'library' line before 'ready'");
    if (d.implementations.empty())
        throw AdapterFailure("bad description: no 'implementation' line before 'ready'");
    return d;
}

// ---- The adapters' processes during the run ----

struct Slot
{
    Process proc;
    std::string failed; // why its last start failed: every later task is Crashed with it
    AdapterDescription loaded;
    std::uint64_t nextId = 0;
};

struct Pool
{
    std::map<std::string, Slot> slots; // by the adapter's canonical path
    ~Pool()
    {
        for (auto& [path, s] : slots)
            reap(s.proc, kAdapterCloseSeconds);
    }
};

Pool& pool()
{
    static Pool p;
    return p;
}

double handshakeLimit(double timeoutSeconds)
{
    return std::max(kAdapterHandshakeSeconds, timeoutSeconds);
}

// The slot's process running and shaken hands with, the same description as at load; false (and
// s.failed, one line on stderr) when it fails.
bool ensureRunning(Slot& s, const PluginImpl& plugin, double timeoutSeconds)
{
    if (!s.failed.empty())
        return false;
    if (s.proc.pid >= 0)
        return true;
    try
    {
        s.proc = startProcess(plugin.path, &plugin);
        const AdapterDescription d = handshake(s.proc, handshakeLimit(timeoutSeconds));
        if (!(d == s.loaded))
            throw AdapterFailure("its description differs from the one it gave when loaded");
        return true;
    }
    catch (const AdapterFailure& e)
    {
        reap(s.proc, 0);
        s.failed = fmt::format("the adapter's start for the cases failed: {}", e.what());
        std::fprintf(stderr,
                     "gjk-validate: executable adapter %s: %s; its remaining cases are "
                     "counted as crashed\n",
                     plugin.path.c_str(), s.failed.c_str());
        return false;
    }
}

// One request and its answer line: Ok with the line, or how the process was lost (then it is
// ended, and `how` says how: its exit, or the limit).
struct Exchange
{
    Io io = Io::Ok;
    std::string line, how;
};

Exchange exchange(Slot& s, const std::string& request, double timeoutSeconds)
{
    Exchange e;
    const auto deadline = deadlineIn(timeoutSeconds);
    e.io = writeText(s.proc, request, deadline);
    if (e.io == Io::Ok)
        e.io = readLine(s.proc, e.line, deadline);
    if (e.io == Io::Timeout)
    {
        reap(s.proc, 0);
        e.how = fmt::format("no answer within {} s, killed", timeoutSeconds);
    }
    else if (e.io == Io::Gone)
        e.how = "the adapter ended before answering (" + reap(s.proc, kAdapterCloseSeconds) + ")";
    return e;
}

// ---- Requests and answers ----

template <class T>
void appendShape(std::string& out, const std::vector<gjk::Vec2<T>>& pts, T radius,
                 const gjk::Transform<T>& xf)
{
    fmt::format_to(std::back_inserter(out), "{} {} {} {} {} {}", double(radius), double(xf.p.x),
                   double(xf.p.y), double(xf.q.c), double(xf.q.s), pts.size());
    for (const auto& q : pts)
        fmt::format_to(std::back_inserter(out), " {} {}", double(q.x), double(q.y));
}

// An `ok` answer's values into `a`; false when a field is missing or does not parse.
bool okAnswer(const std::vector<std::string>& t, ExternalAnswer& a)
{
    double v[5];
    long long iterations = 0;
    if (t.size() != 8 || !parseInteger(t[7], -1, INT32_MAX, iterations))
        return false;
    for (int i = 0; i < 5; ++i)
        if (!parseNumber(t[2 + std::size_t(i)], v[i]))
            return false;
    a.status = PluginStatus::Ok;
    a.distance = v[0];
    a.pointA = {v[1], v[2]};
    a.pointB = {v[3], v[4]};
    a.iterations = int(iterations);
    return true;
}

// The answer to `distance <id>`: false when the line is not a well-formed one.
bool distanceAnswer(const std::string& line, std::uint64_t id, ExternalAnswer& a)
{
    const std::vector<std::string> t = tokens(line);
    long long got = -1;
    if (t.size() < 2 || !parseInteger(t[1], 0, LLONG_MAX, got) || std::uint64_t(got) != id)
        return false;
    if (t[0] == "ok")
        return okAnswer(t, a);
    if (t[0] == "refused" || t[0] == "error")
    {
        a.status = t[0] == "refused" ? PluginStatus::Refused : PluginStatus::Error;
        a.detail = restAfter(line, 2);
        return true;
    }
    return false;
}

// The one stderr line of a lost or malformed case.
void reportLoss(const PluginTask& t, const std::string& what)
{
    std::fprintf(stderr,
                 "gjk-validate: executable adapter %s, variant '%s', %s on case '%s': %s; the "
                 "other cases go on\n",
                 t.v->plugin->path.c_str(), t.v->name.c_str(), pluginStatusName(t.out->status),
                 t.caseName ? t.caseName->c_str() : "?", what.c_str());
}

// One task through its adapter's process.
void answerOne(const PluginTask& t, double timeoutSeconds)
{
    Slot& s = pool().slots[t.v->plugin->path];
    if (!ensureRunning(s, *t.v->plugin, timeoutSeconds))
    {
        t.out->status = PluginStatus::Crashed;
        t.out->detail = s.failed;
        return;
    }
    const std::uint64_t id = s.nextId++;
    std::string request = fmt::format("distance {} {} ", id, t.v->name);
    request += adapterCaseText(*t.v, *t.p) + "\n";
    const Exchange e = exchange(s, request, timeoutSeconds);
    if (e.io != Io::Ok)
    {
        t.out->status = e.io == Io::Timeout ? PluginStatus::Hung : PluginStatus::Crashed;
        t.out->detail = e.how;
        reportLoss(t, e.how);
        return;
    }
    if (!distanceAnswer(e.line, id, *t.out))
    {
        *t.out = ExternalAnswer{};
        t.out->status = PluginStatus::Error;
        t.out->detail = "malformed answer: " + quoted80(e.line);
        reportLoss(t, t.out->detail + ", the adapter is started again");
        reap(s.proc, 0); // the stream cannot be trusted
    }
}

} // namespace

// The last non-empty line of what the adapter printed on stderr (at most 160 characters).
std::string lastLine(std::FILE* f)
{
    std::string all, line;
    std::rewind(f);
    for (int c = 0; (c = std::fgetc(f)) != EOF;)
        all.push_back(char(c));
    while (!all.empty() && (all.back() == '\n' || all.back() == '\r' || all.back() == ' '))
        all.pop_back();
    line = all.substr(all.find_last_of('\n') == std::string::npos ? 0 : all.find_last_of('\n') + 1);
    return line.substr(0, 160);
}

// The one line of a failed handshake at load: what went wrong, and the adapter's last word on
// stderr (a Python traceback's last line, say), which has no log yet.
[[noreturn]] void loadFailure(const std::string& path, const std::string& what, std::FILE* err)
{
    const bool named = what.rfind("executable adapter", 0) == 0;
    const std::string said = err ? lastLine(err) : std::string();
    throw InputError(fmt::format("plugin {}: {}{}{}{}", path, named ? "" : "executable adapter: ",
                                 what, said.empty() ? "" : "; its stderr ends: ", said));
}

AdapterDescription describeAdapter(const std::string& path, const std::string& canonical,
                                   double timeoutSeconds)
{
    // What it prints on stderr during the handshake, kept for the error line (else dropped).
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> err(std::tmpfile(), &std::fclose);
    Process p;
    try
    {
        p = startProcess(canonical, nullptr, err ? ::fileno(err.get()) : -1);
        AdapterDescription d = handshake(p, handshakeLimit(timeoutSeconds));
        reap(p, kAdapterCloseSeconds);
        pool().slots[canonical].loaded = d;
        return d;
    }
    catch (const AdapterFailure& e)
    {
        reap(p, 0);
        loadFailure(path, e.what(), err.get());
    }
}

std::string adapterCaseText(const VariantInfo& v, const PreparedCase& p)
{
    std::string out = "A ";
    if (v.scalar == Scalar::Float)
    {
        appendShape(out, p.af, p.raf, p.xaf);
        out += " B ";
        appendShape(out, p.bf, p.rbf, p.xbf);
    }
    else
    {
        appendShape(out, p.ad, p.rad, p.xad);
        out += " B ";
        appendShape(out, p.bd, p.rbd, p.xbd);
    }
    return out;
}

void answerThroughAdapters(const std::vector<PluginTask>& tasks, double timeoutSeconds)
{
    for (const PluginTask& t : tasks)
        answerOne(t, timeoutSeconds);
}

double adapterTimeNs(const VariantInfo& v, int K, std::size_t m, const std::string& casesText,
                     double timeoutSeconds, const std::string& what)
{
    Slot& s = pool().slots[v.plugin->path];
    if (!ensureRunning(s, *v.plugin, timeoutSeconds))
        return -1;
    const std::uint64_t id = s.nextId++;
    const Exchange e = exchange(
        s, fmt::format("time {} {} {} {} {}\n", id, v.name, K, m, casesText), timeoutSeconds);
    std::string why = e.how;
    if (e.io == Io::Ok)
    {
        const std::vector<std::string> t = tokens(e.line);
        long long got = -1;
        double ns = -1;
        if (t.size() == 3 && t[0] == "timed" && parseInteger(t[1], 0, LLONG_MAX, got) &&
            std::uint64_t(got) == id && parseNumber(t[2], ns) && std::isfinite(ns) && ns >= 0)
            return ns;
        const bool said = !t.empty() && (t[0] == "error" || t[0] == "refused");
        why = (said ? "it answered " : "malformed answer: ") + quoted80(e.line);
        if (!said)
            reap(s.proc, 0); // the stream cannot be trusted
    }
    std::fprintf(stderr, "gjk-validate: executable adapter %s, variant '%s', %s: %s; no ns/query\n",
                 v.plugin->path.c_str(), v.name.c_str(), what.c_str(), why.c_str());
    return -1;
}

void closeAdapters()
{
    for (auto& [path, s] : pool().slots)
        reap(s.proc, kAdapterCloseSeconds);
}

} // namespace gjkval
