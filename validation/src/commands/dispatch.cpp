// The subcommands, parsed and dispatched: what gjk-validate's main() and gjk2d.validate share.
#include "commands/command_line.hpp"
#include "common/context.hpp"
#include "report/report.hpp"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace gjkval
{

int runCommandLine(const CommandLine& line)
{
    markCommandStart();
    checkArgsUtf8(line.argc, line.argv);
    CLI::App app{"gjk-validate: checks the GJK distance library against an exact ground truth.\n"
                 "Runs case families and case files through the GJK variants and the exact\n"
                 "(CGAL/GMP) distance, and reports correctness, accuracy and speed."};
    app.require_subcommand(1);
    app.footer(exitCodesHelp());
    app.set_help_all_flag("--help-all", "help for every subcommand");
    const Subcommand subcommands[] = {
        addRun(app, line),     addGenerate(app, line), addExplain(app, line),
        addBench(app, line),   addSearch(app, line),   addList(app, line),
        addCompare(app, line), addMerge(app, line),    addRepro(app, line)};
    try
    {
        app.parse(line.argc, line.argv);
    }
    catch (const CLI::ParseError& e)
    {
        // --help and --version print their text; a usage error is one line, naming the option,
        // as every other error (CLI11's own app.exit(e) adds a second "Run with --help" line).
        if (e.get_exit_code() == 0)
            return app.exit(e) == 0 ? kExitPass : kExitInput;
        throw InputError(std::string(e.what()) + " (see --help)");
    }
    for (const auto& s : subcommands)
        if (*s.app)
            return s.run();
    throw std::logic_error("no subcommand ran although CLI11 requires one");
}

} // namespace gjkval
