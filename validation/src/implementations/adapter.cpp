// The host side of the executable-adapter protocol (versions 1 and 2, docs/plugin-abi.md,
// "Executable adapters"): the handshake, requests and answers, pipelining and a lost answer
// recovered, over the process and pipes of implementations/adapter_process.hpp.
#include "implementations/adapter.hpp"

#include "implementations/adapter_wire.hpp"

#include "implementations/adapter_process.hpp"
#include "implementations/containment.hpp"
#include "implementations/plugins.hpp"
#include "implementations/prepared.hpp"
#include "inputs/geometry.hpp"

#include <fmt/format.h>

#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

namespace gjkval
{
namespace
{
using namespace adapterio;
using namespace adapterwire;

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
void appendShape(std::string& out, const CasePoints<T>& pts, T radius, const gjk::Transform<T>& xf)
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

// ---- The `distance` requests of one adapter, pipelined ----
// Up to kAdapterWindowRequests requests are unanswered at a time; the answers come in order, so
// the first unanswered request (the head) is the one the adapter is on. The host never waits on a
// write: it polls the adapter's stdout (answers) and stdin (requests not yet taken) together.

struct Sent
{
    std::size_t task = 0; // index into Pipeline::tasks
    std::uint64_t id = 0;
    std::size_t bytes = 0;
    Clock::time_point at; // when it was handed to the pipe
};

struct Pipeline
{
    Pipeline(Slot& slot, const std::vector<const PluginTask*>& list, double seconds)
        : s(slot), tasks(list), timeoutSeconds(seconds)
    {
    }
    Slot& s;
    const std::vector<const PluginTask*>& tasks; // one adapter's, in order
    double timeoutSeconds = 0;
    std::size_t next = 0;      // the first task not sent
    std::deque<Sent> inFlight; // sent, unanswered, in order
    std::size_t inFlightBytes = 0;
    std::string outgoing;         // request text the pipe has not taken yet
    bool stdinClosed = false;     // EPIPE: only the answers already written are left to read
    Clock::time_point lastAnswer; // or the process's start
};

// Requests join the window while fewer than kAdapterWindowRequests are unanswered and their text
// is under kAdapterWindowBytes (one request always goes, however long).
void fillWindow(Pipeline& q)
{
    while (q.next < q.tasks.size() && q.inFlight.size() < kAdapterWindowRequests &&
           q.inFlightBytes < kAdapterWindowBytes)
    {
        const PluginTask& t = *q.tasks[q.next];
        const std::uint64_t id = q.s.nextId++;
        const std::size_t before = q.outgoing.size();
        fmt::format_to(std::back_inserter(q.outgoing), "distance {} {} {}\n", id, t.v->name,
                       adapterCaseText(*t.v, *t.p));
        const std::size_t bytes = q.outgoing.size() - before;
        q.inFlight.push_back({q.next++, id, bytes, Clock::now()});
        q.inFlightBytes += bytes;
    }
}

// Hands the pipe what it takes now.
void writeOutgoing(Pipeline& q)
{
    while (!q.outgoing.empty() && !q.stdinClosed)
    {
        const long n = writeSome(q.s.proc, q.outgoing.data(), q.outgoing.size());
        if (n < 0)
            q.stdinClosed = true;
        if (n <= 0)
            return;
        q.outgoing.erase(0, std::size_t(n));
    }
}

// The head is lost (its status and detail given; the process already ended): one stderr line,
// and every later request in flight goes again, to the next process.
void loseHead(Pipeline& q, PluginStatus status, const std::string& detail, const char* more = "")
{
    const PluginTask& t = *q.tasks[q.inFlight.front().task];
    *t.out = ExternalAnswer{};
    t.out->status = status;
    t.out->detail = detail;
    reportLoss(t, detail + more);
    q.next = q.inFlight.front().task + 1;
    q.inFlight.clear();
    q.inFlightBytes = 0;
    q.outgoing.clear();
}

// The whole lines read so far, each the answer to the head; false when one is malformed (the
// head is then an Error and the process is ended: the stream cannot be trusted).
bool takeAnswers(Pipeline& q)
{
    std::string line;
    while (!q.inFlight.empty() && takeLine(q.s.proc, line))
    {
        const Sent head = q.inFlight.front();
        if (!distanceAnswer(line, head.id, *q.tasks[head.task]->out))
        {
            reap(q.s.proc, 0);
            loseHead(q, PluginStatus::Error, "malformed answer: " + quoted80(line),
                     ", the adapter is started again");
            return false;
        }
        q.inFlight.pop_front();
        q.inFlightBytes -= head.bytes;
        q.lastAnswer = Clock::now();
    }
    return true;
}

// One wait on both pipes, and what came of it: answers taken, requests written, or the head lost
// (Crashed when the adapter's stdout ends, Hung when the head's limit passes).
void step(Pipeline& q)
{
    const Clock::time_point deadline =
        std::max(q.lastAnswer, q.inFlight.front().at) + durationOf(q.timeoutSeconds);
    const bool writing = !q.outgoing.empty() && !q.stdinClosed;
    pollfd fds[2] = {{q.s.proc.fromAdapter, POLLIN, 0},
                     {writing ? q.s.proc.toAdapter : -1, POLLOUT, 0}};
    const int r = ::poll(fds, 2, msLeft(deadline));
    if (r < 0 && errno != EINTR)
        throw std::runtime_error(fmt::format("poll failed: {}", std::strerror(errno)));
    if (r == 0 && Clock::now() >= deadline)
    {
        reap(q.s.proc, 0);
        loseHead(q, PluginStatus::Hung,
                 fmt::format("no answer within {} s, killed", q.timeoutSeconds));
        return;
    }
    if (r > 0 && fds[1].revents != 0)
        writeOutgoing(q);
    if (r <= 0 || fds[0].revents == 0)
        return;
    if (readSome(q.s.proc) == Io::Ok)
        takeAnswers(q);
    else
        loseHead(q, PluginStatus::Crashed,
                 "the adapter ended before answering (" + reap(q.s.proc, kAdapterCloseSeconds) +
                     ")");
}

// One adapter's tasks, in order, through its process (started again after each loss).
void answerPipelined(Slot& s, const std::vector<const PluginTask*>& tasks, double timeoutSeconds)
{
    Pipeline q(s, tasks, timeoutSeconds);
    while (q.next < tasks.size() || !q.inFlight.empty())
    {
        const bool starting = s.proc.pid < 0;
        if (!ensureRunning(s, *tasks.front()->v->plugin, timeoutSeconds))
        {
            const std::size_t from = q.inFlight.empty() ? q.next : q.inFlight.front().task;
            for (std::size_t i = from; i < tasks.size(); ++i)
            {
                *tasks[i]->out = ExternalAnswer{};
                tasks[i]->out->status = PluginStatus::Crashed;
                tasks[i]->out->detail = s.failed;
            }
            return;
        }
        if (starting)
        {
            q.lastAnswer = Clock::now();
            q.stdinClosed = false;
        }
        fillWindow(q);
        writeOutgoing(q);
        step(q);
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

namespace
{
// The case of p's double inputs (the numbers prepare() copied from it, bit for bit).
ShapeIn shapeOf(const CasePoints<double>& pts, double radius, const gjk::Transform<double>& xf)
{
    ShapeIn s;
    for (const auto& q : pts)
        s.points.push_back({q.x, q.y});
    s.radius = radius;
    s.px = xf.p.x;
    s.py = xf.p.y;
    s.c = xf.q.c;
    s.s = xf.q.s;
    return s;
}

// An implementation that takes the world case (InputForm::World): its world points in its scalar
// type, identity transforms (inputs/geometry.hpp, worldCase). Only cases whose world case fits
// are sent (skipReason, PreparedCase::worldOk).
void appendWorldCase(std::string& out, const VariantInfo& v, const PreparedCase& p)
{
    Case c;
    c.a = shapeOf(p.ad, p.rad, p.xad);
    c.b = shapeOf(p.bd, p.rbd, p.xbd);
    const std::optional<Case> w = worldCase(c, v.scalar == Scalar::Float);
    if (!w)
        throw std::logic_error(fmt::format(
            "variant {}: a case whose world case does not fit its scalar type was sent", v.name));
    for (const ShapeIn* s : {&w->a, &w->b})
    {
        CasePoints<double> pts;
        for (const auto& q : s->points)
            pts.push_back({q[0], q[1]});
        out += s == &w->a ? "A " : " B ";
        appendShape(out, pts, s->radius, gjk::Transform<double>{{0, 0}, {1, 0}});
    }
}
} // namespace

std::string adapterCaseText(const VariantInfo& v, const PreparedCase& p)
{
    std::string out;
    if (contractOf(v).input == InputForm::World)
        appendWorldCase(out, v, p);
    else if (v.scalar == Scalar::Float)
    {
        out = "A ";
        appendShape(out, p.af, p.raf, p.xaf);
        out += " B ";
        appendShape(out, p.bf, p.rbf, p.xbf);
    }
    else
    {
        out = "A ";
        appendShape(out, p.ad, p.rad, p.xad);
        out += " B ";
        appendShape(out, p.bd, p.rbd, p.xbd);
    }
    return out;
}

void answerThroughAdapters(const std::vector<PluginTask>& tasks, double timeoutSeconds)
{
    std::vector<std::pair<std::string, std::vector<const PluginTask*>>> byAdapter; // first seen
    for (const PluginTask& t : tasks)
    {
        auto it = std::find_if(byAdapter.begin(), byAdapter.end(),
                               [&](const auto& a) { return a.first == t.v->plugin->path; });
        if (it == byAdapter.end())
            it = byAdapter.insert(byAdapter.end(), {t.v->plugin->path, {}});
        it->second.push_back(&t);
    }
    const SigpipeBlocked quiet;
    for (const auto& [path, list] : byAdapter)
        answerPipelined(pool().slots[path], list, timeoutSeconds);
}

namespace
{
// A `timed` answer to request `id` of K x m queries: the figures (ns, and prepareNs when the
// adapter declared `prepared`), or why they are refused (`why`, the stream still in step: one
// line answered one request). `malformed`: a line that is no `timed` answer to `id` at all.
struct TimedAnswer
{
    AdapterTime time;
    std::string why;
    bool malformed = false;
};

TimedAnswer timedAnswer(const std::string& line, std::uint64_t id, bool prepared, int K,
                        std::size_t m)
{
    TimedAnswer a;
    const std::vector<std::string> t = tokens(line);
    long long got = -1;
    double ns = -1, prepareNs = -1;
    auto figure = [&](std::size_t k, double& x)
    { return parseNumber(t[k], x) && std::isfinite(x) && x >= 0; };
    if (t.size() < 3 || t.size() > 4 || t[0] != "timed" || !parseInteger(t[1], 0, LLONG_MAX, got) ||
        std::uint64_t(got) != id || !figure(2, ns) || (t.size() == 4 && !figure(3, prepareNs)))
    {
        const bool said = !t.empty() && (t[0] == "error" || t[0] == "refused");
        a.why = (said ? "it answered " : "malformed answer: ") + quoted80(line);
        a.malformed = !said;
        return a;
    }
    if (prepared && t.size() == 3)
        a.why = fmt::format("it answered {}, without the preparation's figure that its `prepared` "
                            "line promises (`timed ID NS PREPARE_NS`)",
                            quoted80(line));
    else if (!prepared && t.size() == 4)
        a.why = fmt::format("it answered {}, a second figure without a `prepared` line in its "
                            "handshake (`timed ID NS`)",
                            quoted80(line));
    else if (ns < double(K) * double(m))
        a.why = fmt::format("it answered {} ns for {} x {} queries: below 1 ns a query, which no "
                            "distance query reaches",
                            ns, K, m);
    else
        a.time = {ns, prepareNs};
    return a;
}
} // namespace

AdapterTime adapterTime(const VariantInfo& v, int K, std::size_t m, const std::string& casesText,
                        double timeoutSeconds, const std::string& what)
{
    Slot& s = pool().slots[v.plugin->path];
    if (!ensureRunning(s, *v.plugin, timeoutSeconds))
        return {};
    const std::uint64_t id = s.nextId++;
    const Exchange e = exchange(
        s, fmt::format("time {} {} {} {} {}\n", id, v.name, K, m, casesText), timeoutSeconds);
    std::string why = e.how;
    if (e.io == Io::Ok)
    {
        const bool prepared = v.plugin->preparation == Preparation::Shape ||
                              v.plugin->preparation == Preparation::Case;
        const TimedAnswer a = timedAnswer(e.line, id, prepared, K, m);
        if (a.why.empty())
            return a.time;
        why = a.why;
        if (a.malformed)
            reap(s.proc, 0); // the stream cannot be trusted
    }
    std::fprintf(stderr, "gjk-validate: executable adapter %s, variant '%s', %s: %s; no ns/query\n",
                 v.plugin->path.c_str(), v.name.c_str(), what.c_str(), why.c_str());
    return {};
}

void closeAdapters()
{
    for (auto& [path, s] : pool().slots)
        reap(s.proc, kAdapterCloseSeconds);
    sweepInherited(); // what left an adapter's group (setsid) has come back to gjk-validate
}

} // namespace gjkval
