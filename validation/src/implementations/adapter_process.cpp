// An executable adapter's process: started with pipes to its stdin and stdout, read with a time
// limit, ended and reaped; how it died, said in one line.
#include "implementations/adapter_process.hpp"

#include "implementations/containment.hpp"
#include "implementations/plugins.hpp"

#include <fmt/format.h>

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>

namespace gjkval::adapterio
{

Clock::duration durationOf(double seconds)
{
    return std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(std::min(seconds, 1e7)));
}

Clock::time_point deadlineIn(double seconds)
{
    return Clock::now() + durationOf(seconds);
}

int msLeft(Clock::time_point deadline)
{
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return int(std::clamp<long long>(left + 1, 0, INT_MAX));
}

namespace
{
// In the child: a process group of its own (what the adapter starts is ended with it), stdin and
// stdout the pipes, stderr where the plugin's log is, signals as a fresh program expects them; then
// the adapter itself (exit 127 when it cannot be executed).
[[noreturn]] void execAdapter(const std::string& path, const PluginImpl* plugin, int in, int out,
                              int err)
{
    inForkedChild();
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
} // namespace

Process startProcess(const std::string& path, const PluginImpl* plugin, int err)
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
    ownChild(pid);
    ::close(in[0]);
    ::close(out[1]);
    ::fcntl(in[1], F_SETFL, ::fcntl(in[1], F_GETFL) | O_NONBLOCK); // a write never blocks
    Process p;
    p.pid = pid;
    p.toAdapter = in[1];
    p.fromAdapter = out[0];
    return p;
}

std::string reap(Process& p, double waitSeconds)
{
    if (p.pid < 0)
        return {};
    ::close(p.toAdapter);
    ::close(p.fromAdapter);
    // Up to waitSeconds for the adapter to exit, left a zombie: its PID names its group until
    // the group is ended, whether the adapter exited or is killed with it now.
    const auto deadline = deadlineIn(waitSeconds);
    while (!childExited(p.pid, false) && Clock::now() < deadline)
        ::usleep(2000);
    killChildGroup(p.pid);
    disownChild(p.pid); // before its PID is freed: no signal is sent to that group again
    int status = 0;
    while (::waitpid(p.pid, &status, 0) < 0 && errno == EINTR)
    {
    }
    p = Process{};
    return howEnded(status);
}

SigpipeBlocked::SigpipeBlocked()
{
    sigset_t pipeSet;
    sigemptyset(&pipeSet);
    sigaddset(&pipeSet, SIGPIPE);
    ::pthread_sigmask(SIG_BLOCK, &pipeSet, &old_);
}

SigpipeBlocked::~SigpipeBlocked()
{
    sigset_t pipeSet;
    sigemptyset(&pipeSet);
    sigaddset(&pipeSet, SIGPIPE);
    const timespec zero{0, 0};
    while (::sigtimedwait(&pipeSet, nullptr, &zero) > 0)
    {
    }
    ::pthread_sigmask(SIG_SETMASK, &old_, nullptr);
}

long writeSome(Process& p, const char* data, std::size_t n)
{
    for (;;)
    {
        const ssize_t w = ::write(p.toAdapter, data, n);
        if (w >= 0)
            return long(w);
        if (errno == EAGAIN)
            return 0;
        if (errno != EINTR)
            return -1; // EPIPE, or the pipe is otherwise unusable: as gone
    }
}

Io readSome(Process& p)
{
    char buf[65536];
    for (;;)
    {
        const ssize_t n = ::read(p.fromAdapter, buf, sizeof buf);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return Io::Gone;
        p.buffer.append(buf, std::size_t(n));
        return Io::Ok;
    }
}

bool takeLine(Process& p, std::string& line)
{
    for (;;)
    {
        const std::size_t nl = p.buffer.find('\n');
        if (nl == std::string::npos && p.buffer.size() < kMaxLine)
            return false;
        line = p.buffer.substr(0, std::min(nl, kMaxLine));
        p.buffer.erase(0, nl == std::string::npos ? kMaxLine : nl + 1);
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (!line.empty())
            return true;
    }
}

Io writeText(Process& p, const std::string& text, Clock::time_point deadline)
{
    const SigpipeBlocked quiet;
    for (std::size_t done = 0; done < text.size();)
    {
        const long n = writeSome(p, text.data() + done, text.size() - done);
        if (n < 0)
            return Io::Gone;
        done += std::size_t(n);
        pollfd pfd{p.toAdapter, POLLOUT, 0};
        if (n == 0 && ::poll(&pfd, 1, msLeft(deadline)) == 0)
            return Io::Timeout;
    }
    return Io::Ok;
}

Io readLine(Process& p, std::string& line, Clock::time_point deadline)
{
    for (;;)
    {
        if (takeLine(p, line))
            return Io::Ok;
        pollfd pfd{p.fromAdapter, POLLIN, 0};
        const int r = ::poll(&pfd, 1, msLeft(deadline));
        if (r < 0 && errno == EINTR)
            continue;
        if (r == 0)
            return Io::Timeout;
        if (readSome(p) == Io::Gone)
            return Io::Gone;
    }
}

} // namespace gjkval::adapterio
