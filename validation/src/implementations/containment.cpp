// The owned children, their process groups, the subreaper and the sweep at the end of the run.
#include "implementations/containment.hpp"

#include <fmt/format.h>

#include <dirent.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace gjkval
{
namespace
{
// The owned children: a PID leading its own group, or minus the PID of one that shares this
// process's group; 0 a free slot. Atomics without a lock, so that the signal handler reads them.
std::atomic<int> g_owned[kMaxOwnedChildren];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots");

// The process containDescendants() ran in (a forked child is another), and whether it became the
// subreaper.
std::atomic<int> g_containing{0};
std::atomic<bool> g_subreaper{false};

// The first time each kind of failure happens, one line on stderr.
void sayOnce(std::once_flag& once, const std::string& line)
{
    std::call_once(once, [&] { std::fprintf(stderr, "gjk-validate: %s\n", line.c_str()); });
}

std::atomic<int>* slotOf(int pid)
{
    for (auto& s : g_owned)
    {
        const int v = s.load(std::memory_order_relaxed);
        if (v == pid || v == -pid)
            return &s;
    }
    return nullptr;
}

// Before the signal's default action ends this process: every owned group ended, as the
// terminal's Ctrl-C once reached the children in this process's group. Async-signal-safe: kill,
// signal and raise only.
extern "C" void endGroupsThenDie(int sig)
{
    if (::getpid() == g_containing.load(std::memory_order_relaxed))
        for (auto& s : g_owned)
            if (const int v = s.load(std::memory_order_relaxed); v > 0)
                ::kill(-v, SIGKILL);
    ::signal(sig, SIG_DFL);
    ::raise(sig); // delivered when the handler returns, the signal being blocked in it
}

// The parent PID in /proc/<pid>/stat ("pid (comm) state ppid ..."; comm may hold spaces and
// parentheses, the last ')' ends it); -1 when the process is gone or the file unreadable.
int parentOf(int pid)
{
    char path[64];
    std::snprintf(path, sizeof path, "/proc/%d/stat", pid);
    std::FILE* f = std::fopen(path, "re");
    if (!f)
        return -1;
    char buf[1024];
    const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
    std::fclose(f);
    buf[n] = '\0';
    const char* close = std::strrchr(buf, ')');
    char state = 0;
    int ppid = -1;
    if (!close || std::sscanf(close + 1, " %c %d", &state, &ppid) != 2)
        return -1;
    return ppid;
}

// This process's children that it does not own, from /proc.
std::vector<int> inheritedChildren()
{
    std::vector<int> found;
    DIR* proc = ::opendir("/proc");
    if (!proc)
    {
        static std::once_flag once;
        sayOnce(once, fmt::format("cannot read /proc ({}): what the run's processes left behind "
                                  "outside their groups is not ended",
                                  std::strerror(errno)));
        return found;
    }
    const int self = ::getpid();
    while (const dirent* e = ::readdir(proc))
    {
        char* end = nullptr;
        const long pid = std::strtol(e->d_name, &end, 10);
        if (*end != '\0' || pid <= 0 || pid == self)
            continue;
        if (parentOf(int(pid)) == self && !slotOf(int(pid)))
            found.push_back(int(pid));
    }
    ::closedir(proc);
    return found;
}
} // namespace

void containDescendants()
{
    g_containing = ::getpid();
    if (::prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0)
        g_subreaper = true;
    else
        std::fprintf(stderr,
                     "gjk-validate: cannot become the subreaper of its children's children "
                     "(prctl: %s): a process an adapter moves out of its process group may "
                     "outlive the run\n",
                     std::strerror(errno));
    for (const int sig : {SIGINT, SIGTERM, SIGHUP})
    {
        struct sigaction old = {};
        if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL)
            continue; // ignored (nohup) or handled by whoever set it: left as it is
        struct sigaction act = {};
        act.sa_handler = endGroupsThenDie;
        sigemptyset(&act.sa_mask);
        act.sa_flags = SA_RESTART;
        ::sigaction(sig, &act, nullptr);
    }
}

void inForkedChild()
{
    ::setpgid(0, 0); // the parent checks the outcome (ownChild) and says so if it failed
    for (auto& s : g_owned)
        s.store(0, std::memory_order_relaxed);
}

void ownChild(int pid)
{
    const int setErrno = ::setpgid(pid, pid) == 0 ? 0 : errno;
    // EACCES: the child has run execve already, after its own setpgid.
    const bool ownGroup = setErrno == 0 || ::getpgid(pid) == pid;
    if (!ownGroup)
    {
        static std::once_flag once;
        sayOnce(once, fmt::format("a child process cannot have a process group of its own "
                                  "(setpgid: {}): what it starts is ended at the end of the run "
                                  "only",
                                  std::strerror(setErrno)));
    }
    for (auto& s : g_owned)
    {
        int free = 0;
        if (s.compare_exchange_strong(free, ownGroup ? pid : -pid))
            return;
    }
    throw std::logic_error(
        fmt::format("more than {} child processes owned at once", kMaxOwnedChildren));
}

bool killChildGroup(int pid)
{
    const std::atomic<int>* s = pid > 0 ? slotOf(pid) : nullptr;
    if (!s)
        return false;
    // A child sharing this process's group: the child alone.
    ::kill(s->load() > 0 ? -pid : pid, SIGKILL);
    return true;
}

void disownChild(int pid)
{
    if (std::atomic<int>* s = pid > 0 ? slotOf(pid) : nullptr)
        s->store(0);
}

bool childExited(int pid, bool wait)
{
    for (;;)
    {
        siginfo_t info{};
        if (::waitid(P_PID, id_t(pid), &info, WEXITED | WNOWAIT | (wait ? 0 : WNOHANG)) == 0)
            return info.si_pid != 0;
        if (errno != EINTR)
            return true; // ECHILD: not a child of this process
    }
}

void sweepInherited()
{
    if (!g_subreaper || ::getpid() != g_containing)
        return;
    // Each round ends the children found; their own children come to this process then, for the
    // next round. A bound, for descendants that keep starting others faster than that.
    constexpr int kRounds = 100;
    for (int round = 0; round < kRounds; ++round)
    {
        const std::vector<int> found = inheritedChildren();
        if (found.empty())
            return;
        for (const int pid : found)
            ::kill(pid, SIGKILL);
        for (const int pid : found)
            while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR)
            {
            }
    }
    std::fprintf(stderr, "gjk-validate: the processes the run's children left behind kept starting "
                         "others: some may outlive it\n");
}

} // namespace gjkval
