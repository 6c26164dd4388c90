// The staging directories of StagedDir (common/output.hpp): their names, and the removal of those
// that earlier runs left behind when they died (a run killed by SIGKILL leaves .DIR.tmp-XXXXXX
// beside DIR, which would otherwise stay for ever, even across --resume).
#include "common/output.hpp"

#include <algorithm>
#include <cerrno>
#include <ctime>
#include <fstream>
#include <signal.h>
#include <sstream>

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;

std::string hostName()
{
    char buf[256] = {};
    if (::gethostname(buf, sizeof buf - 1) != 0 || buf[0] == '\0')
        return "unknown";
    std::string h = buf;
    for (char& c : h) // a file name's part: no '/'
        if (c == '/')
            c = '_';
    return h;
}

// The last change of `p` in seconds since the epoch; -1 when it cannot be read.
double changedAt(const fs::path& p)
{
    struct stat st
    {
    };
    if (::lstat(p.c_str(), &st) != 0)
        return -1;
    return double(st.st_mtim.tv_sec) + 1e-9 * double(st.st_mtim.tv_nsec);
}

// When process `pid` started, in seconds since the epoch (/proc/PID/stat's starttime, in clock
// ticks after the boot time of /proc/stat); -1 when it cannot be read.
double processStart(long pid)
{
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line))
        return -1;
    const std::size_t close = line.rfind(')'); // the command name may hold spaces and ')'
    if (close == std::string::npos)
        return -1;
    std::istringstream fields(line.substr(close + 2));
    std::string f;
    for (int i = 3; i < 22 && fields >> f; ++i) // fields 3..21; starttime is field 22
    {
    }
    unsigned long long ticks = 0;
    if (!(fields >> ticks))
        return -1;
    std::ifstream procStat("/proc/stat");
    double boot = -1;
    for (std::string key; procStat >> key;)
        if (key == "btime")
        {
            procStat >> boot;
            break;
        }
    const long hz = ::sysconf(_SC_CLK_TCK);
    return boot < 0 || hz <= 0 ? -1 : boot + double(ticks) / double(hz);
}

// Whether the run that made `staging` (by its pid) may still be running: the process exists and
// started before the directory's last change (a later process holds a reused pid). Unknown counts
// as running.
bool ownerMayRun(long pid, const fs::path& staging)
{
    if (::kill(pid_t(pid), 0) != 0 && errno == ESRCH)
        return false;
    const double started = processStart(pid), changed = changedAt(staging);
    if (started < 0 || changed < 0)
        return true;
    return started <= changed + 1; // ticks (10 ms) and one second of slack
}

bool allOf(const std::string& s, bool (*pred)(char))
{
    return !s.empty() && std::all_of(s.begin(), s.end(), pred);
}
bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}
bool isTemplateChar(char c) // mkdtemp's letters
{
    return isDigit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
} // namespace

std::string stagingTemplate(const fs::path& dir)
{
    return (dir.parent_path() /
            fmt::format(".{}.tmp-{}-{}-XXXXXX", dir.filename().string(), hostName(), ::getpid()))
        .string();
}

std::vector<fs::path> removeStaleStaging(const fs::path& dir)
{
    std::vector<fs::path> removed;
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "." + name + ".tmp-".
    std::string prefix = ".";
    prefix += dir.filename().string();
    prefix += ".tmp-";
    const std::string host = hostName();
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir.parent_path(), ec))
    {
        const std::string name = e.path().filename().string();
        if (name.size() < prefix.size() + 6 || name.compare(0, prefix.size(), prefix) != 0 ||
            !e.is_directory(ec) || e.is_symlink(ec))
            continue;
        const std::string rest = name.substr(prefix.size()); // HOST-PID-XXXXXX or XXXXXX
        bool stale = false;
        if (rest.size() == 6)
            stale = allOf(rest, isTemplateChar) && changedAt(e.path()) >= 0 &&
                    double(std::time(nullptr)) - changedAt(e.path()) > kStaleLegacyStagingSeconds;
        else if (rest.size() > 8 && rest[rest.size() - 7] == '-' &&
                 allOf(rest.substr(rest.size() - 6), isTemplateChar))
        {
            const std::string hostPid = rest.substr(0, rest.size() - 7);
            const std::size_t dash = hostPid.rfind('-');
            if (dash == std::string::npos || hostPid.substr(0, dash) != host)
                continue;
            const std::string pid = hostPid.substr(dash + 1);
            stale = allOf(pid, isDigit) && pid.size() < 10 && std::stol(pid) != ::getpid() &&
                    !ownerMayRun(std::stol(pid), e.path());
        }
        if (stale && fs::remove_all(e.path(), ec) != static_cast<std::uintmax_t>(-1))
            removed.push_back(e.path());
    }
    return removed;
}

} // namespace gjkval
