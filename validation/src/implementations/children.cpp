// The child processes that plugin calls run in (PluginChild): forked from this process, their
// output routed to each plugin's log (capped), the logs collected once the plugins are done.
#include "implementations/plugins.hpp"

#include "implementations/registry.hpp"

#include "common/output.hpp" // writeAllBytes
#include "implementations/adapter.hpp"
#include "implementations/adapter_process.hpp" // SigpipeBlocked
#include "implementations/containment.hpp"
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
        inForkedChild(); // what a plugin starts is ended with its child
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
    ownChild(pid);
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
    // Exited, not yet reaped (its PID names its group): what it left in its group goes with it.
    childExited(pid_, true);
    killChildGroup(pid_);
    disownChild(pid_); // before its PID is freed: no signal is sent to that group again
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
    if (!killChildGroup(pid_)) // the child and whatever it started in its group
        throw std::logic_error(fmt::format("plugin child {} killed when not running", pid_));
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

} // namespace gjkval
