// Outputs that appear whole or not at all (STYLE.md, "The runner"; hostile-input hardening: a
// failed write left a mix of two reports).
//   a file      is written to a temporary file beside it, flushed and fsync'ed, then renamed over
//               it (writeFileAtomic);
//   a directory is written into a temporary directory beside it, then swapped in with
//               renameat2(RENAME_EXCHANGE) and the old one removed (StagedDir).
// A failed write throws OutputError (exit code 5, kExitResources) and leaves the previous output
// in place, whole. Paths that cannot be used at all (empty, a directory where a file is wanted, a
// missing or unwritable parent) are refused up front, before any work, as InputError (exit 2).
#pragma once

#include "common/common.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace gjkval
{

// Writing an output failed (disk full, file size limit, I/O error): exit code 5.
class OutputError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

// Writes all n bytes to fd, through short writes and EINTR. False when a write fails, with errno
// set (ENOSPC for a write that wrote nothing). Throws nothing and allocates nothing: a forked child
// (implementations/plugins.cpp) calls it before _exit.
inline bool writeAllBytes(int fd, const void* data, std::size_t n) noexcept
{
    const char* p = static_cast<const char*>(data);
    while (n > 0)
    {
        const ssize_t w = ::write(fd, p, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
        {
            if (w == 0)
                errno = ENOSPC;
            return false;
        }
        p += w;
        n -= std::size_t(w);
    }
    return true;
}

namespace output_detail
{
namespace fs = std::filesystem;

inline std::string errnoText(int e)
{
    return std::strerror(e);
}

// The permission bits a new file or directory gets from open(2)/mkdir(2) under the umask.
inline mode_t defaultMode(mode_t base)
{
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return base & ~mask;
}

inline void writeAll(int fd, const std::string& text, const std::string& what)
{
    if (!writeAllBytes(fd, text.data(), text.size()))
    {
        const int e = errno;
        throw OutputError(fmt::format("{}: write failed: {}", what, errnoText(e)));
    }
}

inline void fsyncPath(const fs::path& p)
{
    const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return;
    ::fsync(fd); // a directory's fsync may be unsupported: durability, not correctness
    ::close(fd);
}

// Writes text to a new file `path` (O_EXCL: it must not exist), fsync'ed; messages name `shown`.
inline void writeNewFile(const fs::path& path, const std::string& shown, const std::string& text,
                         mode_t mode)
{
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (fd < 0)
        throw OutputError(fmt::format("{}: cannot create the file: {}", shown, errnoText(errno)));
    try
    {
        writeAll(fd, text, shown);
        if (::fsync(fd) != 0 && errno != EINVAL)
            throw OutputError(fmt::format("{}: write failed: {}", shown, errnoText(errno)));
    }
    catch (...)
    {
        ::close(fd);
        throw;
    }
    if (::close(fd) != 0)
        throw OutputError(fmt::format("{}: write failed: {}", shown, errnoText(errno)));
}
} // namespace output_detail

// Up front: refuses (InputError) a file output path that cannot be used: empty, a directory, or
// in a directory that does not exist or is not writable. "-" (stdout) and existing non-regular
// files (a terminal, /dev/null, a pipe) are accepted: they are written in place.
inline void checkOutputFile(const std::string& option, const std::string& path)
{
    namespace fs = std::filesystem;
    if (path.empty())
        throw InputError(fmt::format("{}: the output path is empty", option));
    if (path == "-")
        return;
    std::error_code ec;
    const auto st = fs::status(path, ec);
    if (fs::is_directory(st))
        throw InputError(
            fmt::format("{} {}: is a directory, expected a file", option, excerpt(path)));
    if (fs::exists(st) && !fs::is_regular_file(st))
        return;
    const fs::path parent = fs::absolute(fs::path(path)).parent_path();
    if (!fs::is_directory(parent, ec))
        throw InputError(fmt::format("{} {}: the directory {} does not exist", option,
                                     excerpt(path), excerpt(parent.string())));
    if (::access(parent.c_str(), W_OK | X_OK) != 0)
        throw InputError(fmt::format("{} {}: cannot write in {}: {}", option, excerpt(path),
                                     excerpt(parent.string()), std::strerror(errno)));
}

// Writes text to path whole or not at all: a temporary file beside it, then rename(2). A path
// that exists and is not a regular file (a terminal, /dev/null, /dev/full, a pipe) is written in
// place, every write checked; "-" is stdout. Throws OutputError.
// The streamed form: `produce` hands the bytes to its argument piece by piece, in order (a file
// larger than memory); the pieces go to the file as they come.
using ByteSink = std::function<void(std::string_view)>;
inline void writeFileAtomic(const std::string& path,
                            const std::function<void(const ByteSink&)>& produce)
{
    namespace fs = std::filesystem;
    using namespace output_detail;
    if (path == "-")
    {
        produce(
            [](std::string_view text)
            {
                if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size())
                    throw OutputError(
                        fmt::format("standard output: write failed: {}", errnoText(errno)));
            });
        if (std::fflush(stdout) != 0)
            throw OutputError(fmt::format("standard output: write failed: {}", errnoText(errno)));
        return;
    }
    const auto toFd = [&](int fd)
    {
        return [fd, &path](std::string_view text)
        {
            if (!writeAllBytes(fd, text.data(), text.size()))
                throw OutputError(
                    fmt::format("{}: write failed: {}", excerpt(path), errnoText(errno)));
        };
    };
    std::error_code ec;
    const auto st = fs::status(path, ec);
    if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st))
    {
        const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0)
            throw OutputError(fmt::format("{}: cannot open: {}", excerpt(path), errnoText(errno)));
        try
        {
            produce(toFd(fd));
        }
        catch (...)
        {
            ::close(fd);
            throw;
        }
        ::close(fd);
        return;
    }
    const fs::path target = fs::absolute(fs::path(path));
    std::string tmpl =
        (target.parent_path() / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0)
        throw OutputError(fmt::format("{}: cannot create a temporary file beside it: {}",
                                      excerpt(path), errnoText(errno)));
    bool open = true;
    try
    {
        ::fchmod(fd, defaultMode(0666));
        produce(toFd(fd));
        if (::fsync(fd) != 0 && errno != EINVAL)
            throw OutputError(fmt::format("{}: write failed: {}", excerpt(path), errnoText(errno)));
        open = false;
        if (::close(fd) != 0)
            throw OutputError(fmt::format("{}: write failed: {}", excerpt(path), errnoText(errno)));
        if (std::rename(tmpl.c_str(), target.c_str()) != 0)
            throw OutputError(fmt::format("{}: cannot rename the temporary file over it: {}",
                                          excerpt(path), errnoText(errno)));
    }
    catch (...)
    {
        if (open)
            ::close(fd);
        ::unlink(tmpl.c_str());
        throw;
    }
    fsyncPath(target.parent_path());
}

inline void writeFileAtomic(const std::string& path, const std::string& text)
{
    writeFileAtomic(path, [&](const ByteSink& sink) { sink(text); });
}

// The absolute path of a report directory as it will be replaced: normalised, without a trailing
// slash, through a symbolic link when `outDir` is one (the link's target is replaced).
inline std::filesystem::path reportDirPath(const std::string& outDir)
{
    namespace fs = std::filesystem;
    fs::path p = fs::absolute(fs::path(outDir)).lexically_normal();
    if (p.filename().empty())
        p = p.parent_path();
    std::error_code ec;
    if (fs::is_symlink(p, ec))
    {
        const fs::path c = fs::canonical(p, ec);
        if (!ec)
            p = c;
    }
    return p;
}

// The staging directories of DIR's earlier runs that died without removing theirs (SIGKILL, a
// power cut), beside DIR: ".NAME.tmp-HOST-PID-XXXXXX" of this host whose process PID is gone, or
// is a later process than the directory (its start after the directory's last change: the pid
// was reused); and ".NAME.tmp-XXXXXX" (the name before the owner was in it) untouched for
// kStaleLegacyStagingSeconds. A live run's directory, another host's (a shared file system) and
// anything else are left alone. The paths removed (best effort: errors are ignored).
inline constexpr double kStaleLegacyStagingSeconds = 7 * 24 * 3600;
std::vector<std::filesystem::path> removeStaleStaging(const std::filesystem::path& dir);
// The name of this process's staging directory of DIR, for mkdtemp: ".NAME.tmp-HOST-PID-XXXXXX".
std::string stagingTemplate(const std::filesystem::path& dir);

// A report directory written whole: files go into DIR's sibling ".NAME.tmp-HOST-PID-XXXXXX";
// commit() swaps it with DIR (renameat2 RENAME_EXCHANGE; a plain rename when DIR does not exist)
// and removes the previous one. Until commit() DIR is untouched; without commit() the staging
// directory is removed. Earlier dead runs' staging directories of DIR are removed first
// (removeStaleStaging). Throws OutputError.
class StagedDir
{
  public:
    explicit StagedDir(std::filesystem::path dir) : dir_(std::move(dir))
    {
        namespace fs = std::filesystem;
        std::error_code ec;
        fs::create_directories(dir_.parent_path(), ec);
        if (ec)
            throw OutputError(fmt::format("{}: cannot create the directory: {}",
                                          excerpt(dir_.parent_path().string()), ec.message()));
        removeStaleStaging(dir_);
        std::string tmpl = stagingTemplate(dir_);
        if (::mkdtemp(tmpl.data()) == nullptr)
            throw OutputError(fmt::format("{}: cannot create a temporary directory beside it: {}",
                                          excerpt(dir_.string()), std::strerror(errno)));
        staging_ = tmpl;
        ::chmod(staging_.c_str(), output_detail::defaultMode(0777));
    }
    StagedDir(const StagedDir&) = delete;
    StagedDir& operator=(const StagedDir&) = delete;
    ~StagedDir()
    {
        if (!staging_.empty())
        {
            std::error_code ec;
            std::filesystem::remove_all(staging_, ec);
        }
    }

    const std::filesystem::path& dir() const { return dir_; }
    // The staging directory: DIR's files until commit().
    const std::filesystem::path& staging() const { return staging_; }
    // Where a file of the staged directory is written when it is streamed rather than given whole.
    std::filesystem::path staged(const std::string& name) const { return staging_ / name; }

    void write(const std::string& name, const std::string& text)
    {
        output_detail::writeNewFile(staging_ / name, excerpt(dir_.string()) + "/" + name, text,
                                    output_detail::defaultMode(0666));
    }

    void commit()
    {
        namespace fs = std::filesystem;
        output_detail::fsyncPath(staging_);
        std::error_code ec;
        if (fs::exists(fs::symlink_status(dir_, ec)))
        {
            if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, dir_.c_str(), RENAME_EXCHANGE) !=
                0)
            {
                if (errno != EINVAL && errno != ENOSYS)
                    throw OutputError(fmt::format("{}: cannot swap the new report in: {}",
                                                  excerpt(dir_.string()), std::strerror(errno)));
                // A file system without RENAME_EXCHANGE: two renames, a short window without DIR
                // (never a mix of two reports).
                std::string old =
                    (dir_.parent_path() / ("." + dir_.filename().string() + ".old-XXXXXX"))
                        .string();
                if (::mkdtemp(old.data()) == nullptr || std::rename(dir_.c_str(), old.c_str()) != 0)
                    throw OutputError(fmt::format("{}: cannot move the previous report aside: {}",
                                                  excerpt(dir_.string()), std::strerror(errno)));
                if (std::rename(staging_.c_str(), dir_.c_str()) != 0)
                {
                    const int e = errno;
                    std::rename(old.c_str(), dir_.c_str());
                    throw OutputError(fmt::format("{}: cannot move the new report in: {}",
                                                  excerpt(dir_.string()), std::strerror(e)));
                }
                fs::remove_all(staging_, ec);
                staging_ = old;
            }
            // staging_ now holds the previous report.
        }
        else
        {
            if (std::rename(staging_.c_str(), dir_.c_str()) != 0)
                throw OutputError(fmt::format("{}: cannot move the new report in: {}",
                                              excerpt(dir_.string()), std::strerror(errno)));
            staging_.clear();
        }
        output_detail::fsyncPath(dir_.parent_path());
        if (!staging_.empty())
            fs::remove_all(staging_, ec); // the previous report
        staging_.clear();
    }

  private:
    std::filesystem::path dir_, staging_;
};

} // namespace gjkval
