// gjk-validate: the validation runner (docs/validation.md).
//   run       a campaign: families and case files -> exact truth, GJK variants -> reports
//   generate  write a family's cases to a gjk-cases/1 file
//   explain   one case in detail: inputs, each variant's result and trace, the exact result
//   bench     time the variants on given cases (no exact side)
//   search    mutate cases toward the worst error / bound ratio (adversarial search)
//   list      the families and variants
//   compare   two reports: the statistics that got worse or better, exit 1 on a regression
//   merge     the shards of a campaign (run --shard I/N) into its report
// The parsing and the dispatch are the commands layer's (runCommandLine, commands/dispatch.cpp,
// shared with the Python package's gjk2d.validate); main() reports every failure.
#include "commands/command_line.hpp"
#include "common/output.hpp"
#include "report/report.hpp"

#include <csignal>
#include <cstdio>
#include <new>
#include <stdexcept>

using namespace gjkval;

// Every failure ends here with its documented exit code (kExitCodeTable) and one line on stderr.
int main(int argc, char** argv)
{
    // A file size limit (ulimit -f) makes a write fail with EFBIG, handled as any failed write,
    // instead of killing the program with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    try
    {
        return runCommandLine({argc, argv});
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
