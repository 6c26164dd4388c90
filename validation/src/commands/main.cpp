// gjk-validate: the validation runner (docs/validation.md).
//   run       a campaign: families and case files -> exact truth, GJK variants -> reports
//   generate  write a family's cases to a gjk-cases/1 file
//   explain   one case in detail: inputs, each variant's result and trace, the exact result
//   bench     time the variants on given cases (no exact side)
//   search    mutate cases toward the worst error / bound ratio (adversarial search)
//   list      the families and variants
//   compare   two reports: the statistics that got worse or better, exit 1 on a regression
//   merge     the shards of a campaign (run --shard I/N) into its report
#include "commands/command_line.hpp"
#include "common/output.hpp"
#include "report/report.hpp"

#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <new>
#include <stdexcept>

using namespace gjkval;

namespace
{
// Parses the command line and runs the one subcommand it names.
int dispatch(int argc, char** argv)
{
    checkArgsUtf8(argc, argv);
    const CommandLine line{argc, argv};
    CLI::App app{"gjk-validate: checks the GJK distance library against an exact ground truth.\n"
                 "Runs case families and case files through the GJK variants and the exact\n"
                 "(CGAL/GMP) distance, and reports correctness, accuracy and speed."};
    app.require_subcommand(1);
    app.footer(exitCodesHelp());
    app.set_help_all_flag("--help-all", "help for every subcommand");
    const Subcommand subcommands[] = {
        addRun(app, line),    addGenerate(app, line), addExplain(app, line), addBench(app, line),
        addSearch(app, line), addList(app, line),     addCompare(app, line), addMerge(app, line)};
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::ParseError& e)
    {
        // --help and --version print their text; a usage error is one line on stderr, naming the
        // option, as every other error (CLI11's own app.exit(e) adds a second "Run with --help"
        // line).
        if (e.get_exit_code() == 0)
            return app.exit(e) == 0 ? kExitPass : kExitInput;
        std::fprintf(stderr, "gjk-validate: error: %s (see --help)\n", e.what());
        return kExitInput;
    }
    for (const auto& s : subcommands)
        if (*s.app)
            return s.run();
    throw std::logic_error("no subcommand ran although CLI11 requires one");
}
} // namespace

// Every failure ends here with its documented exit code (kExitCodeTable) and one line on stderr.
int main(int argc, char** argv)
{
    // A file size limit (ulimit -f) makes a write fail with EFBIG, handled as any failed write,
    // instead of killing the program with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    try
    {
        return dispatch(argc, argv);
    }
    catch (const InputError& e)
    {
        std::fprintf(stderr, "gjk-validate: error: %s\n", e.what());
        return kExitInput;
    }
    catch (const OutputError& e)
    {
        std::fprintf(stderr, "gjk-validate: error: %s (the previous output is left in place)\n",
                     e.what());
        return kExitResources;
    }
    catch (const std::bad_alloc&)
    {
        std::fputs("gjk-validate: error: out of memory (no output was written; give fewer "
                   "cases)\n",
                   stderr);
        return kExitResources;
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr,
                     "gjk-validate: internal error: %s (a bug in gjk2d, not in the "
                     "input: please report it)\n",
                     excerpt(e.what(), 300).c_str());
        return kExitInternal;
    }
    catch (...)
    {
        std::fputs("gjk-validate: internal error: an unknown exception (a bug in gjk2d, not in "
                   "the input: please report it)\n",
                   stderr);
        return kExitInternal;
    }
}
