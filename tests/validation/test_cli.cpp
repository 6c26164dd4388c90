// The gjk-validate program on hostile command lines and failing writes (the hostile-input
// hardening): what CMake's expect_exit.cmake cannot express (raw non-UTF-8 bytes, a file size
// limit, file contents before and after). Each test runs the program in a child process.
#include "cli_support.hpp"
#include "common/common.hpp"
#include "implementations/peers.hpp"
#include "report/report.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace gjkval;
namespace fs = std::filesystem;

namespace
{
using Run = CliRun;

// Runs gjk-validate with args; fileSizeLimit > 0 sets RLIMIT_FSIZE (bytes) in the child, `fault`
// the test fault hook (GJK2D_VALIDATE_TEST_FAULT).
Run runCli(const std::vector<std::string>& args, rlim_t fileSizeLimit = 0,
           const char* fault = nullptr)
{
    return runGjkValidate(args,
                          [&]
                          {
                              if (fileSizeLimit > 0)
                              {
                                  const rlimit lim{fileSizeLimit, fileSizeLimit};
                                  ::setrlimit(RLIMIT_FSIZE, &lim);
                              }
                              if (fault != nullptr)
                                  ::setenv("GJK2D_VALIDATE_TEST_FAULT", fault, 1);
                          });
}

// Every file of a directory with its contents.
std::map<std::string, std::string> snapshot(const fs::path& dir)
{
    std::map<std::string, std::string> m;
    for (const auto& e : fs::directory_iterator(dir))
        m[e.path().filename().string()] = slurp(e.path());
    return m;
}

// Entries of dir's parent whose name starts with "." + dir's name: staging leftovers.
std::vector<std::string> leftovers(const fs::path& dir)
{
    std::vector<std::string> v;
    std::string prefix = "."; // appended: GCC 12 warns (-Wrestrict, a false positive) on "." + name
    prefix += dir.filename().string();
    for (const auto& e : fs::directory_iterator(dir.parent_path()))
        if (e.path().filename().string().rfind(prefix, 0) == 0)
            v.push_back(e.path().string());
    return v;
}

fs::path freshDir(const std::string& name)
{
    const fs::path d = fs::path(VALIDATION_TEST_TMP) / "cli" / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

bool contains(const std::string& s, const std::string& part)
{
    return s.find(part) != std::string::npos;
}
} // namespace

// Defect 4: a non-UTF-8 byte in --out, --cases or --comment aborted the program (rc 134) with a
// JSON type_error while writing the report, after the whole campaign. Now every argument is
// checked first: exit 2, one line naming the argument, nothing written.
TEST_CASE("cli refuses non-UTF-8 arguments before any work", "[cli]")
{
    const fs::path d = freshDir("utf8");
    const std::string bad = std::string("r\xff");
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"run", "--family", "random:3", "--out",
                                   bad}, // relative: the
                                         // message quotes at most 60 bytes, and a long build path
                                         // would push the \xFF out of it
          std::vector<std::string>{"run", "--family", "random:3", "--cases", bad, "--out",
                                   (d / "r").string()},
          std::vector<std::string>{"generate", "--family", "random:3", "--comment", "x\xff", "-o",
                                   (d / "g.json").string()}})
    {
        const Run r = runCli(args);
        INFO("stderr: " << r.err);
        CHECK(r.code == kExitInput);
        CHECK(contains(r.err, "is not valid UTF-8"));
        CHECK(contains(r.err, "\\xFF"));
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
    CHECK(fs::is_empty(d));
    CHECK_FALSE(fs::exists(bad));
}

// Defect 4: `run --out ''` aborted. (CMake cannot pass an empty argument, hence here.)
TEST_CASE("cli refuses an empty --out", "[cli]")
{
    const Run r = runCli({"run", "--family", "random:3", "--out", ""});
    CHECK(r.code == kExitInput);
    CHECK(contains(r.err, "--out: the output directory is empty"));
}

// Defect 4: `generate --comment $'x\xff' -o keep.json` first emptied keep.json, then aborted.
// A failed generate (here a 4 KB file size limit) leaves the old file whole and no temporary
// file beside it: exit 5.
TEST_CASE("cli generate leaves an existing file whole when it fails", "[cli]")
{
    const fs::path d = freshDir("keep");
    const fs::path keep = d / "keep.json";
    std::ofstream(keep) << "the previous file\n";
    Run r = runCli({"generate", "--family", "random:3", "--comment", "x\xff", "-o", keep.string()});
    CHECK(r.code == kExitInput);
    CHECK(slurp(keep) == "the previous file\n");

    r = runCli({"generate", "--family", "random:2000", "-o", keep.string()}, 4096);
    CHECK(r.code == kExitResources);
    CHECK(contains(r.err, "write failed"));
    CHECK(slurp(keep) == "the previous file\n");
    CHECK(leftovers(keep).empty());

    r = runCli({"generate", "--family", "random:3", "-o", keep.string()});
    CHECK(r.code == kExitPass);
    CHECK(contains(slurp(keep), "gjk-cases/1"));
}

// Defect 5: a report written in place could be cut (killed, disk full) or mix two runs. Now the
// directory is staged beside DIR and swapped in: a failing write (a 64 KB file size limit: the
// report.json of 60 cases is ~0.5 MB) leaves every previous file as it was, and no staging
// directory behind; a successful run replaces every file (a stale cases.jsonl disappears).
TEST_CASE("cli report directory holds one whole run", "[cli]")
{
    const fs::path d = freshDir("report") / "latest";
    const std::vector<std::string> first = {"run",        "--family", "random:60",
                                            "--seed",     "1",        "--no-timing",
                                            "--per-case", "--out",    d.string()};
    REQUIRE(runCli(first).code == kExitPass);
    const auto before = snapshot(d);
    REQUIRE(before.count("report.json") == 1);
    REQUIRE(before.count("cases.jsonl") == 1);

    const std::vector<std::string> second = {"run", "--family",    "random:60", "--seed",
                                             "2",   "--no-timing", "--out",     d.string()};
    const Run failed = runCli(second, 64 * 1024);
    INFO(failed.err);
    CHECK(failed.code == kExitResources);
    CHECK(contains(failed.err, "report.json: write failed"));
    CHECK(snapshot(d) == before);
    CHECK(leftovers(d).empty());

    REQUIRE(runCli(second).code == kExitPass);
    const auto after = snapshot(d);
    CHECK(after.count("cases.jsonl") == 0);
    for (const auto& [name, text] : after)
    {
        INFO(name);
        CHECK(before.count(name) == 1);
        CHECK(text != before.at(name));
    }
    CHECK(contains(after.at("report.json"), "\"seed\": 2"));
    CHECK(leftovers(d).empty());
}

// elapsed_s accounts for the run: its phases add up to its total. They are laps of one clock
// (PhaseClock), so only the rounding of nine sums of seconds may part them: 1e-9 of the total is
// far above that and far below any moment left to no phase. (With a clock per phase, the moments
// between phases went to none: 4.1 ms of a 0.46 s run on a loaded CI machine, 0.9 %.)
TEST_CASE("cli report's elapsed_s phases add up to its total", "[cli]")
{
    const fs::path d = freshDir("elapsed") / "out";
    for (const std::string source : {"generated", "file"})
    {
        INFO(source);
        std::vector<std::string> args = {
            "run",       "--variants", "double", "--no-timing", "--no-default-plugins",
            "--threads", "1",          "--out",  d.string()};
        if (source == "generated")
            args.insert(args.end(), {"--family", "random:20000", "--seed", "5"});
        else
        {
            const std::string cases = (d.parent_path() / "r.json").string();
            REQUIRE(runCli({"generate", "--family", "random:20000", "--seed", "5", "--out", cases})
                        .code == kExitPass);
            args.insert(args.end(), {"--cases", cases});
        }
        REQUIRE(runCli(args).code == kExitPass);
        const Json e = Json::parse(slurp(d / "report.json"))["context"]["elapsed_s"];
        double phases = 0;
        for (const auto& [key, v] : e.items())
            if (key != "total")
                phases += v.get<double>();
        const double total = e["total"].get<double>();
        CHECK(total > 0);
        CHECK(std::abs(total - phases) <= 1e-9 * total);
    }
}

// The whole directory is replaced, so one that holds anything else is refused up front (exit 2)
// and left alone: `--out .` must never swap away a user's files.
TEST_CASE("cli refuses an output directory holding other files", "[cli]")
{
    const fs::path d = freshDir("foreign");
    std::ofstream(d / "notes.txt") << "mine\n";
    const Run r = runCli({"run", "--family", "random:3", "--no-timing", "--out", d.string()});
    CHECK(r.code == kExitInput);
    CHECK(contains(r.err, "notes.txt"));
    CHECK(slurp(d / "notes.txt") == "mine\n");
    CHECK(leftovers(d).empty());
}

// Defect 4: only InputError was caught; a broken invariant or bad_alloc aborted (rc 134). The
// test-only fault hook throws after the arguments are checked.
TEST_CASE("cli top-level handlers give exit codes 4 and 5", "[cli]")
{
    const fs::path d = freshDir("fault") / "r";
    const std::vector<std::string> args = {"run",         "--family", "random:3",
                                           "--no-timing", "--out",    d.string()};
    Run r = runCli(args, 0, "logic_error");
    CHECK(r.code == kExitInternal);
    CHECK(contains(r.err, "gjk-validate: internal error: test fault"));
    r = runCli(args, 0, "unknown");
    CHECK(r.code == kExitInternal);
    CHECK(contains(r.err, "internal error"));
    r = runCli(args, 0, "bad_alloc");
    CHECK(r.code == kExitResources);
    CHECK(contains(r.err, "out of memory"));
    CHECK(!fs::exists(d));
}

// Defect D: the exit codes have one home, kExitCodeTable; docs/cli.md holds its table.
TEST_CASE("docs list every exit code as kExitCodeTable says", "[cli]")
{
    const std::string docs = slurp(fs::path(GJK2D_SOURCE_DIR) / "docs" / "cli.md");
    CHECK(contains(docs, exitCodesMarkdown()));
    const std::string help = exitCodesHelp();
    for (const auto& e : kExitCodeTable)
        CHECK(contains(help, "\n  " + std::to_string(e.code) + "  "));
}

// Issue 30: a run killed by SIGKILL left its staging directory (.DIR.tmp-...) beside DIR, and no
// later run removed it. Now a run removes those of DIR's earlier runs that are dead: of this host,
// whose pid is gone (or reused by a later process). A live run's, another host's, and one of the
// old name (.DIR.tmp-XXXXXX, before the owner was in it) changed within 7 days are kept; one of
// the old name untouched for longer is removed.
TEST_CASE("cli a later run removes the staging directory of a run killed by SIGKILL", "[cli]")
{
    const fs::path d = freshDir("killed") / "latest";
    const std::string outDir = d.string();
    const pid_t pid = ::fork();
    if (pid == 0)
    {
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::execl(GJK_VALIDATE_EXE, GJK_VALIDATE_EXE, "run", "--family", "random:2000000",
                "--variants", "double", "--no-default-plugins", "--no-timing", "--out",
                outDir.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // The run stages its directory before its first case; it is killed once the directory is there.
    std::vector<std::string> staged;
    for (int i = 0; i < 600 && staged.empty(); ++i)
    {
        ::usleep(50 * 1000);
        staged = leftovers(d);
    }
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    REQUIRE(WIFSIGNALED(status));
    REQUIRE(staged.size() == 1);
    CHECK(fs::is_directory(staged[0]));
    const std::string name = fs::path(staged[0]).filename().string();
    INFO(name);
    CHECK(name.rfind(".latest.tmp-", 0) == 0);
    const std::string owner =
        fmt::format("-{}-", pid); // fmt: GCC 12's -Wrestrict false positive on "-" + s
    CHECK(contains(name, owner));

    // Beside it: a live process's (this test's), another host's, an old-named one of today, and
    // an old-named one untouched for 8 days.
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    const fs::path parent = d.parent_path();
    const fs::path live = parent / (".latest.tmp-" + std::string(host) + "-" +
                                    std::to_string(::getpid()) + "-Abc123");
    const fs::path otherHost =
        parent / (".latest.tmp-no-such-host.example-" + std::to_string(pid) + "-Abc123");
    const fs::path legacyNew = parent / ".latest.tmp-Abc123",
                   legacyOld = parent / ".latest.tmp-Def456";
    for (const auto& p : {live, otherHost, legacyNew, legacyOld})
        fs::create_directories(p);
    fs::last_write_time(legacyOld, fs::file_time_type::clock::now() - std::chrono::hours(8 * 24));

    const Run again = runCli({"run", "--family", "random:20", "--variants", "double",
                              "--no-default-plugins", "--no-timing", "--out", outDir});
    INFO(again.err);
    REQUIRE(again.code == kExitPass);
    CHECK(fs::is_regular_file(d / "report.json"));
    CHECK(!fs::exists(staged[0]));
    CHECK(!fs::exists(legacyOld));
    CHECK(fs::is_directory(live));
    CHECK(fs::is_directory(otherHost));
    CHECK(fs::is_directory(legacyNew));
    for (const auto& p : {live, otherHost, legacyNew})
        fs::remove_all(p);
}

// Issue 30, "smaller things": the plugins on the command line.
namespace
{
const fs::path kShippedPlugin =
    fs::path(GJK_VALIDATE_EXE).parent_path() / "plugins" / "gjk2d-box2d.so";

std::string oneSpaced(const std::string& s) // help text as one line: its wrapping aside
{
    std::string out;
    for (const char c : s)
        if (!std::isspace(static_cast<unsigned char>(c)))
            out += c;
        else if (!out.empty() && out.back() != ' ')
            out += ' ';
    return out;
}

std::vector<std::string> linesWith(const std::string& text, const std::string& part)
{
    std::vector<std::string> v;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (contains(line, part))
            v.push_back(line);
    return v;
}
} // namespace

TEST_CASE("cli list shows the shipped plugin, and a --plugin one", "[cli]")
{
    const std::string real = fs::canonical(kShippedPlugin).string();
    const Run shipped = runCli({"list"});
    INFO(shipped.err);
    REQUIRE(shipped.code == kExitPass);
    auto lines = linesWith(shipped.out, "box2d-2.4.1");
    REQUIRE(lines.size() == 1);
    CHECK(contains(lines[0], "comparison"));
    CHECK(contains(lines[0], "(shipped, " + real + ")"));

    // Given by a path of another spelling: listed once, with its real path, not as shipped.
    const std::string other =
        (fs::path(GJK_VALIDATE_EXE).parent_path() / "plugins" / ".." / "plugins" / "gjk2d-box2d.so")
            .string();
    const Run given = runCli({"list", "--no-default-plugins", "--plugin", other});
    INFO(given.err);
    REQUIRE(given.code == kExitPass);
    lines = linesWith(given.out, "box2d-2.4.1");
    REQUIRE(lines.size() == 1);
    CHECK(contains(lines[0], "(" + real + ")"));
    CHECK(!contains(lines[0], "shipped"));

    const Run missing = runCli({"list", "--plugin", "no-such-plugin.so"});
    CHECK(missing.code == kExitInput);
    CHECK(missing.out.empty());
    CHECK(linesWith(missing.err, "").size() == 1);
    CHECK(contains(missing.err, "plugin no-such-plugin.so: No such file"));
}

TEST_CASE("cli bench refuses --judge, which it cannot honour", "[cli]")
{
    const Run r = runCli({"bench", "--family", "random:10", "--judge", "box2d-2.4.1"});
    CHECK(r.code == kExitInput);
    CHECK(r.out.empty());
    CHECK(linesWith(r.err, "").size() == 1);
    CHECK(contains(r.err, "--judge box2d-2.4.1: this command judges no variant"));
    CHECK(linesWith(runCli({"bench", "--help"}).out, "  --judge").empty()); // not offered
}

TEST_CASE("cli run --help names the plugins' exit codes", "[cli]")
{
    const Run r = runCli({"run", "--help"});
    REQUIRE(r.code == kExitPass);
    const std::string help = oneSpaced(r.out);
    CHECK(contains(help, "1 some case failed"));
    CHECK(contains(
        help,
        "a judged plugin (--judge) that crashed, hung or answered an error status on a case"));
    CHECK(contains(help, "2 usage or input error"));
    CHECK(contains(
        help, "a plugin that cannot be used (missing, not loadable, another ABI version, a bad "
              "description, given twice)"));
}

TEST_CASE("cli the same plugin file given twice exits 2 naming it", "[cli]")
{
    const fs::path d = freshDir("plugin-twice");
    const fs::path link = d / "box2d-link.so";
    fs::create_symlink(kShippedPlugin, link);
    for (const auto& second : {kShippedPlugin.string(), link.string()})
    {
        INFO(second);
        const Run r =
            runCli({"run", "--family", "random:10", "--no-default-plugins", "--plugin",
                    kShippedPlugin.string(), "--plugin", second, "--out", (d / "out").string()});
        CHECK(r.code == kExitInput);
        CHECK(linesWith(r.err, "").size() == 1);
        CHECK(contains(r.err, "--plugin " + second + ": given twice (also as " +
                                  kShippedPlugin.string() + ")"));
        CHECK(!fs::exists(d / "out"));
    }
}

// Issue 32: the shipped peers (validation/src/implementations/peers.hpp, docs/peers.md).
TEST_CASE("cli list shows every shipped peer, built or not", "[cli]")
{
    const Run r = runCli({"list"});
    INFO(r.out + r.err);
    REQUIRE(r.code == kExitPass);
    // The table generated from validation/plugins/*/peer.txt (tests/plugins/peer_folders_check.py
    // holds the table to those files): every row listed once, as built or not.
    REQUIRE(gjkval::shippedPeers().size() >= 7);
    for (const gjkval::ShippedPeer& peer : gjkval::shippedPeers())
    {
        const char* file = peer.file;
        const bool inDefault = peer.inDefaultCampaign;
        INFO(file);
        const auto lines = linesWith(r.out, std::string("  ") + file + " ");
        REQUIRE(lines.size() == 1);
        const fs::path built = fs::path(GJK_VALIDATE_EXE).parent_path() / "plugins" / file;
        if (!fs::exists(built))
            CHECK(contains(lines[0], "not built (needs "));
        else
            CHECK(contains(lines[0], inDefault ? " default " : " --peers "));
    }
}

TEST_CASE("cli run --peers with --no-default-plugins exits 2 with one line", "[cli]")
{
    const fs::path d = freshDir("peers-no-default");
    const Run r = runCli({"run", "--family", "random:10", "--peers", "--no-default-plugins",
                          "--out", (d / "out").string()});
    CHECK(r.code == kExitInput);
    CHECK(linesWith(r.err, "").size() == 1);
    CHECK(
        contains(r.err, "--peers loads every shipped peer, --no-default-plugins leaves them out"));
    CHECK(!fs::exists(d / "out"));
}

TEST_CASE("cli run --peers adds the peers to --variants, and the context lists the plugins",
          "[cli]")
{
    const fs::path d = freshDir("peers-run");
    const std::string real = fs::canonical(kShippedPlugin).string();
    const Run with = runCli({"run", "--family", "random:10", "--variants", "double", "--peers",
                             "--no-timing", "--out", (d / "with").string()});
    INFO(with.err);
    REQUIRE(with.code == kExitPass);
    const auto r = Json::parse(slurp(d / "with" / "report.json"));
    std::vector<std::string> names;
    for (const auto& v : r["variants"])
        names.push_back(v["name"].get<std::string>());
    CHECK(std::count(names.begin(), names.end(), "double") == 1);
    CHECK(std::count(names.begin(), names.end(), "box2d-2.4.1") == 1);
    bool listed = false;
    for (const auto& p : r["context"]["plugins"])
        if (p["file"] == real)
        {
            listed = true;
            CHECK(p["kind"] == "shared-library");
            CHECK(p["variants"] == Json::array({"box2d-2.4.1"}));
            CHECK(p.contains("library"));
        }
    CHECK(listed);
    CHECK(contains(slurp(d / "with" / "report.md"), "| plugin | `" + real + "` (shared-library"));

    // Without --peers, --variants double runs no plugin: the context lists none.
    const Run without = runCli({"run", "--family", "random:10", "--variants", "double",
                                "--no-timing", "--out", (d / "without").string()});
    REQUIRE(without.code == kExitPass);
    const auto w = Json::parse(slurp(d / "without" / "report.json"));
    CHECK(w["variants"].size() == 1);
    CHECK(w["context"]["plugins"] == Json::array());
}
