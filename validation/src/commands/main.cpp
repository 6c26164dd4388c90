// gjk-validate: the validation runner (docs/campaign.md, docs/cli.md).
//   run       a campaign: families and case files -> exact truth, GJK variants -> reports
//   generate  write a family's cases to a gjk-cases/1 file
//   explain   one case in detail: inputs, each variant's result and trace, the exact result
//   bench     time the variants on given cases (no exact side)
//   search    mutate cases toward the worst error / bound ratio (adversarial search)
//   list      the families and variants
//   compare   two reports: the statistics that got worse or better, exit 1 on a regression
//   merge     the shards of a campaign (run --shard I/N) into its report
//   repro     one case and one peer variant as a standalone program in the peer's language
// The parsing and the dispatch are the commands layer's (runCommandLine, commands/dispatch.cpp,
// shared with the Python package's gjk2d.validate); main() reports every failure.
#include "commands/command_line.hpp"
#include "common/output.hpp"
#include "implementations/adapter.hpp"
#include "implementations/containment.hpp"
#include "report/report.hpp"

#include <csignal>
#include <cstdio>
#include <new>
#include <stdexcept>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

using namespace gjkval;

namespace
{
// A campaign streams its cases in chunks (4,096 cases by default) whose memory, a few MB, is
// freed at the end of each chunk and asked for again by the next one. With glibc's defaults the
// freed top of the heap is handed back to the kernel (above 128 KB, M_TRIM_THRESHOLD) and blocks
// of a chunk's size are mmap'd and munmap'd one by one (M_MMAP_THRESHOLD, 128 KB, raised by glibc
// up to 32 MB as such blocks are freed), so every chunk faults its pages in again, and a run spends
// a good part of its time in the kernel. Keeping up to 256 MB of freed memory and serving blocks
// below 32 MB (glibc's largest mmap threshold) from the heap avoids those faults; the peak memory
// stays a chunk's and not the count's (docs/speed.md gives the measurement).
// Set here, not in the library: a host process (the Python package) keeps its own allocator.
void keepFreedMemory()
{
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
}

// Every failure ends here with its documented exit code (kExitCodeTable) and one line on stderr.
int runReportingFailures(int argc, char** argv)
{
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
} // namespace

int main(int argc, char** argv)
{
    // A file size limit (ulimit -f) makes a write fail with EFBIG, handled as any failed write,
    // instead of killing the program with SIGXFSZ.
    std::signal(SIGXFSZ, SIG_IGN);
    keepFreedMemory();
    // No process the run starts, nor one those start, outlives gjk-validate: set here, not in the
    // library, whose host may be the Python interpreter (implementations/containment.hpp).
    containDescendants();
    const int code = runReportingFailures(argc, argv);
    closeAdapters(); // every adapter ended, then whatever the run's processes left behind
    return code;
}
