// The process of an executable adapter (implementations/adapter.hpp): started with its stdin and
// stdout through pipes and its stderr to the plugin's log, lines read and written with deadlines,
// ended. Used by implementations/adapter.cpp only; no protocol here, only bytes and lines.
#pragma once

#include <chrono>
#include <csignal>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace gjkval
{
struct PluginImpl; // implementations/plugins.hpp
}

namespace gjkval::adapterio
{

using Clock = std::chrono::steady_clock;

// `seconds` as a clock duration (at most 1e7 s: "no limit" without overflow).
Clock::duration durationOf(double seconds);
Clock::time_point deadlineIn(double seconds);

// Milliseconds left until `deadline` for poll(): 0 when it has passed.
int msLeft(Clock::time_point deadline);

enum class Io
{
    Ok,
    Gone,    // the adapter closed its end (it exited, or is about to)
    Timeout, // nothing within the limit
};

struct Process
{
    int pid = -1;
    int toAdapter = -1, fromAdapter = -1; // toAdapter is non-blocking: a write never waits
    std::string buffer;                   // read, not yet taken as lines
};

// A failed start or handshake: what went wrong, as the one line says it.
struct AdapterFailure : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

// Starts `path` with no arguments, in a process group of its own (implementations/
// containment.hpp). `err` >= 0: the adapter's stderr goes there rather than to the plugin's log
// (`plugin` null: gjk-validate's stderr).
Process startProcess(const std::string& path, const PluginImpl* plugin, int err = -1);

// Ends the process: its pipes closed, up to waitSeconds for it to exit, then SIGKILL to its
// process group (the adapter if it still runs, and whatever it started there), whose leader is
// then reaped. How it ended ("exit code 0" for a clean exit, "signal 11 (Segmentation fault)";
// "signal 9 (Killed)" when it was killed).
std::string reap(Process& p, double waitSeconds);

// While one lives, SIGPIPE is blocked in this thread (a write to a gone adapter is EPIPE, not
// the end of gjk-validate); at its end a pending one is taken back and the mask restored.
class SigpipeBlocked
{
  public:
    SigpipeBlocked();
    ~SigpipeBlocked();
    SigpipeBlocked(const SigpipeBlocked&) = delete;
    SigpipeBlocked& operator=(const SigpipeBlocked&) = delete;

  private:
    sigset_t old_;
};

// What the pipe to the adapter takes now, never waiting: the bytes written (0 when the pipe is
// full), or -1 when the adapter closed its stdin (EPIPE). Call with SIGPIPE blocked.
long writeSome(Process& p, const char* data, std::size_t n);

// One read() of what the adapter wrote, into p.buffer (call it when poll() says POLLIN or
// POLLHUP): Ok, or Gone at the end of the stream.
Io readSome(Process& p);

// The next non-empty line of p.buffer (its "\n" and a "\r" before it removed): false when no
// whole line is there. A line longer than kMaxLine is cut there (no answer is that long:
// malformed).
inline constexpr std::size_t kMaxLine = 1 << 20;
bool takeLine(Process& p, std::string& line);

// Writes all of `text` by the deadline.
Io writeText(Process& p, const std::string& text, Clock::time_point deadline);

// The next non-empty line (takeLine), by the deadline.
Io readLine(Process& p, std::string& line, Clock::time_point deadline);

} // namespace gjkval::adapterio
