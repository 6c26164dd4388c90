// Shared-library plugins' tasks answered in server children (PluginServers, answerContained): the
// call as a child makes it, the wire format of tasks and answers between parent and child, and the
// recovery of a lost block, one case at a time.
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

// A query on shapes prepared for it (gjk2d_plugin_prepared): both prepared, the query, both
// released, so that the accuracy run judges what the timing times. A failed prepare() (NULL) is
// GJK2D_STATUS_ERROR.
template <class Shape, class Result>
std::int32_t callPrepared(const PluginImpl& plugin, const Shape* a, const Shape* b, void* cache,
                          Result* out)
{
    const gjk2d_prepared& pp = *plugin.prepared;
    const bool perCase = plugin.preparation == Preparation::Case;
    void* pa = pp.prepare(plugin.index, a, perCase ? b : nullptr);
    void* pb = pp.prepare(plugin.index, b, perCase ? a : nullptr);
    const std::int32_t status = pa && pb ? pp.distance(plugin.index, pa, a, pb, b, cache, out)
                                         : std::int32_t(GJK2D_STATUS_ERROR);
    for (void* s : {pa, pb})
        if (s != nullptr)
            pp.release(plugin.index, s);
    return status;
}

// One case in the implementation's scalar type: through its prepared shapes when it has them,
// else its plain function.
template <class T, class Shape, class Result, class Fn>
AnswerRecord callScalar(const PluginImpl& plugin, Fn plain, const Shape& a, const Shape& b,
                        void* cache)
{
    if (plugin.prepared)
        return callIn<T, Shape, Result>([&](const Shape* x, const Shape* y, void* c, Result* o)
                                        { return callPrepared(plugin, x, y, c, o); },
                                        a, b, cache);
    return callIn<T, Shape, Result>(plain, a, b, cache);
}

// The call itself, as the child makes it. `cache`: cache_bytes zeroed bytes (a cold start).
AnswerRecord callPlugin(const VariantInfo& v, const PreparedCase& p,
                        std::vector<unsigned char>& cache)
{
    const PluginImpl& plugin = *v.plugin;
    const gjk2d_implementation& im = plugin.impl;
    std::fill(cache.begin(), cache.begin() + im.cache_bytes, 0);
    void* c = im.cache_bytes > 0 ? cache.data() : nullptr;
    if (im.scalar == GJK2D_SCALAR_FLOAT)
        return callScalar<float, gjk2d_shape_f, gjk2d_result_f>(
            plugin, im.distance_f, shapeOf<float, gjk2d_shape_f>(p.af, p.raf, p.xaf),
            shapeOf<float, gjk2d_shape_f>(p.bf, p.rbf, p.xbf), c);
    return callScalar<double, gjk2d_shape_d, gjk2d_result_d>(
        plugin, im.distance_d, shapeOf<double, gjk2d_shape_d>(p.ad, p.rad, p.xad),
        shapeOf<double, gjk2d_shape_d>(p.bd, p.rbd, p.xbd), c);
}

std::mutex g_messages; // crash and hang lines on stderr

} // namespace

namespace
{
// Shared-library plugins answer in server children (PluginServers): each is forked once, on a
// campaign's first chunk with plugin tasks, and answers the tasks of every later chunk sent to it
// through a pipe. Forking a child per chunk costs the fork's copy of the page tables and then a
// copy-on-write fault on every page the campaign writes after it (docs/speed.md gives the cost).
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
