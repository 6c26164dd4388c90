// The timed loops of implementations that are not gjk2d's (timing/timing.hpp's variantLoop): a
// shared library's in a child process that serves one pass per command, an executable adapter's
// through its `time` requests, an in-process callback's here. Each is a TimedLoop, so that `run`
// and `bench` alternate their passes with gjk2d's (medianOfAlternatedPasses).
#pragma once

#include "timing/timing.hpp"

#include <vector>

namespace gjkval
{

// How long a plugin's pass (or an adapter's `time` request, a part of one) may take before it
// counts as hung: a pass lasts at most min_pass_s plus one loop over the cases, and the limit
// allows a loop of 50,000 cases (kTimingSampleCases) at 600 us a query, or one call that hangs.
double passLimitSeconds(const TimingConfig& cfg, double pluginTimeoutSeconds);

// A shared library's loop, in a child process (PluginChild::serve) that prepares once and then
// runs one pass per command, sending back only its nanoseconds (the pipe is outside the clock):
// - with gjk2d_plugin_prepared (Preparation::Shape or Case): every case's two shapes prepared
//   once, timed apart (TimedLoop::prepareNsPerShape: the whole preparation over the number of
//   shapes); a pass is the query on prepared shapes alone, per query the cache zeroed, one call
//   through the table's distance, the result read;
// - without it (Preparation::InCall): a pass calls distance_f/distance_d per query, the shapes'
//   set-up inside the call, as the plugin does it.
// A crash, a failed prepare() (NULL), or no answer within passLimitSeconds makes pass() return -1
// from then on, with a line on stderr.
TimedLoop sharedLibraryLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                            const TimingConfig& cfg, double pluginTimeoutSeconds);

// A plugin's own timing loop (gjk2d_plugin_timing, gjk2d/plugin.h; v.plugin->timing set) over
// `cases`, cold or warm (`bench --against`): the cases' shapes built into the ABI's structs here,
// then handed once to the plugin's prepare() in a served child, which runs one pass() per
// pass(reps) of the loop and sends back only its nanoseconds (the plugin's clock, its loop alone).
// Failures as sharedLibraryLoop's.
TimedLoop ownTimingLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                        bool warm, const TimingConfig& cfg, double pluginTimeoutSeconds);

// An executable adapter's loop (implementations/adapter.hpp) over the first kAdapterTimingCases
// of `cases`: a pass sends the sample in chunks of at most kAdapterTimeChunkCases, one `time`
// request per chunk with K = the pass's reps, and is the sum of the adapter's own totals (the
// pipe and its parsing are outside every timed region): a figure timed by the adapter
// (selfTimed). An adapter that declared `prepared` gives its preparation apart: the loop's
// prepareNsPerShape is the median over the passes of their preparation figures per shape. A
// request without a valid answer makes pass() return -1 from then on (adapterTime says why).
TimedLoop adapterLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                      const TimingConfig& cfg, double pluginTimeoutSeconds);

// An in-process variant's loop (implementations/in_process.hpp) over the first
// kAdapterTimingCases of `cases` (its callbacks are typically a Python function's, tens of
// microseconds a query): a per-case callback called once per case, a batch callback once with the
// whole sample per loop. What the callback's caller adds (the Python layer's conversions of each
// case) is in the time. A callback that throws a std::exception makes pass() return -1 from then
// on, with a line on stderr; any other exception propagates (it ends the campaign).
TimedLoop inProcessLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v);

} // namespace gjkval
