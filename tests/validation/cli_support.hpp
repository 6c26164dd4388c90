// Shared by the validation tests that run the gjk-validate program itself (test_cli.cpp,
// test_compare.cpp): one child process per run, its exit code, stdout and stderr.
#pragma once

#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace gjkval
{
struct CliRun
{
    int code = -1; // exit code; 128 + signal number when killed
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p)
{
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Runs GJK_VALIDATE_EXE with args; `inChild` runs in the child before exec (limits, environment).
// Output goes through files named after this test process (CTest runs test cases in parallel).
inline CliRun runGjkValidate(const std::vector<std::string>& args,
                             const std::function<void()>& inChild = {})
{
    const std::filesystem::path dir =
        std::filesystem::path(VALIDATION_TEST_TMP) / ("cli-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const pid_t pid = ::fork();
    if (pid == 0)
    {
        ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
        ::dup2(::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
        if (inChild)
            inChild();
        std::vector<char*> argv{const_cast<char*>(GJK_VALIDATE_EXE)};
        for (const auto& a : args)
            argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(GJK_VALIDATE_EXE, argv.data());
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), slurp(out),
            slurp(err)};
}
} // namespace gjkval
