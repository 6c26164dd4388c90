// Executable adapters: the host side of the gjk2d executable-adapter protocol, versions 1
// and 2 (docs/plugin-abi.md, "Executable adapters"). An adapter is any
// executable file gjk-validate starts and talks to over its stdin and stdout, one line per
// message: a handshake (its library and implementations), then `distance` and `time` requests,
// one answer each. Contained like a shared-library plugin: a crash, a hang or a malformed answer
// costs the case in flight, and the process is started again for the next one.
#pragma once

#include "implementations/contract.hpp"
#include "implementations/plugins.hpp"
#include "implementations/variants.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace gjkval
{

struct PreparedCase; // evaluate/evaluate.hpp

// The versions the host speaks. It opens with `gjk2d-adapter 1` (the oldest, so that a version-1
// adapter that checks the line keeps working); the adapter answers the version it speaks, 1 or 2.
// Version 2 adds the `contract` lines of the handshake (implementations/contract.hpp) and the
// optional `prepared` lines (AdapterImplementation::preparation).
inline constexpr int kAdapterProtocolMinVersion = 1;
inline constexpr int kAdapterProtocolVersion = 2;
// The handshake may take max(kAdapterHandshakeSeconds, --plugin-timeout): an interpreter's start
// (Node, Python importing shapely) takes a few hundred milliseconds on an idle machine.
inline constexpr double kAdapterHandshakeSeconds = 10;
// At the end, an adapter whose stdin was closed has this long to exit before SIGKILL.
inline constexpr double kAdapterCloseSeconds = 2;
// The `distance` requests are pipelined: a request is sent while fewer than
// kAdapterWindowRequests are unanswered and their text is under kAdapterWindowBytes (one request
// always goes). A round trip through the pipes costs tens to hundreds of microseconds (Node,
// Python), a query of planck.js 1 or 2: waiting for each answer before the next request would
// make the pipe the campaign's cost. The bounds keep what is unanswered well inside a Linux pipe's
// 64 KiB buffer in both directions (64 answers of about 100 bytes), so an adapter that reads one
// request, writes its answer and reads the next never waits on its writes, and bound what a loss
// re-sends (the requests after the lost one, to the next process).
inline constexpr std::size_t kAdapterWindowRequests = 64;
inline constexpr std::size_t kAdapterWindowBytes = 32 * 1024;

// One `implementation` line of the handshake.
struct AdapterImplementation
{
    std::string name;
    Scalar scalar = Scalar::Double;
    bool radius = false; // `radius`: takes radius > 0
    int maxVertices = 0; // 0: no limit
    std::string description;
    // Version 2's `contract NAME ...` lines, and its `input NAME world SOURCE` line
    // (Contract::input); version 1: gjk2d's own.
    Contract contract = ownContract();
    // Version 2's optional `prepared NAME shape|case` line: Shape or Case; InCall without it.
    Preparation preparation = Preparation::InCall;
    bool operator==(const AdapterImplementation&) const = default;
};

// What the handshake says.
struct AdapterDescription
{
    std::string library;
    int version = kAdapterProtocolVersion; // the version the adapter answered
    std::vector<AdapterImplementation> implementations;
    bool operator==(const AdapterDescription&) const = default;
};

// Starts the adapter (its canonical path), reads its description and closes it. Throws
// InputError, one line naming the file as given (`path`), for another protocol version, a bad
// description, an adapter that exits or does not say `ready` within
// max(kAdapterHandshakeSeconds, timeoutSeconds). The names are checked here for their form and
// among themselves; against other variants by the caller.
AdapterDescription describeAdapter(const std::string& path, const std::string& canonical,
                                   double timeoutSeconds);

// answerContained() for the tasks of executable adapters (every task's variant has
// plugin->kind == PluginKind::Executable): one `distance` request each, through the adapter's
// process (started at its first task, kept for the run), pipelined (kAdapterWindowRequests). The
// answers come in order, so the first unanswered request is the one the adapter is on: a crash
// (Crashed), no answer within timeoutSeconds of the previous answer, or of that request's
// sending if later (Hung), or a malformed answer (Error, "malformed answer: ...") costs that
// task, with one line on stderr naming the adapter and the case; the process is started again
// and the later tasks it was sent go again; when that start fails, every later task of the
// adapter is Crashed.
void answerThroughAdapters(const std::vector<PluginTask>& tasks, double timeoutSeconds);

// The "A ... B ..." part of a request for case p, in v's scalar type: each shape as radius,
// position, rotation (c, s), point count and points, each number the shortest decimal that reads
// back as the same double.
std::string adapterCaseText(const VariantInfo& v, const PreparedCase& p);

// One `time` request: v's implementation runs the m cases of casesText (adapterCaseText, joined
// by spaces) K times in its own timed loop. The total in nanoseconds, or a negative number when
// the adapter did not answer `timed` within timeoutSeconds (crash, hang, `error`, malformed): a
// line on stderr says so, naming `what`, and the process is started again for the next request.
// An adapter that declared `prepared NAME shape|case` (Preparation::Shape or Case) builds the
// chunk's shapes once, before its timed loop, and answers `timed ID NS PREPARE_NS`: NS the K loops
// of queries alone, PREPARE_NS the preparation of the chunk's 2m shapes (AdapterTime::prepareNs);
// one without answers `timed ID NS`. A missing or extra figure is refused, and so is an NS below
// 1 ns a query (NS < K m: no distance query is that fast, so the adapter's clock or loop is
// wrong), each with one line on stderr; the answer is then no time ({}), the process kept.
struct AdapterTime
{
    double ns = -1;        // the K loops; negative: no answer
    double prepareNs = -1; // the preparation of the chunk's shapes; -1: not given
};
AdapterTime adapterTime(const VariantInfo& v, int K, std::size_t m, const std::string& casesText,
                        double timeoutSeconds, const std::string& what);

// Ends every adapter process: stdin closed, kAdapterCloseSeconds to exit, then SIGKILL to its
// process group; then the processes that left the groups (sweepInherited, implementations/
// containment.hpp). Called when the plugins' work is done (finishPluginLogs), by gjk-validate's
// main at its end and, at the latest, at exit.
void closeAdapters();

} // namespace gjkval
