// Timing of GJK queries, shared by `run` (ns_per_query per family and variant) and `bench`:
// single-threaded, the cases copied into one contiguous array, repeated timed passes, the median.
#pragma once

#include "evaluate/evaluate.hpp"
#include "implementations/variants.hpp"

#include <functional>
#include <vector>

#include <sched.h>

namespace gjkval
{

struct TimingConfig
{
    int minPasses = 5, maxPasses = 15;
    double budgetSeconds = 0.5;    // no new pass after this, once minPasses are done
    double minPassSeconds = 0.002; // each pass repeats the loop over the cases to last this long
    bool warm = false;             // time warm-started queries (also when the variant is warm)
};

struct TimingResult
{
    double nsPerQuery = -1; // median pass, per query
    double nsMin = -1, nsMax = -1;
    int passes = 0;
    int repsPerPass = 0; // loops over the cases in one pass
    std::size_t cases = 0;
    bool warm = false; // warm-started queries were timed
    // A variant with a preparation step (Preparation::Shape or Case): the preparation of all the
    // timed cases' shapes, once, over their number; -1: not measured.
    double prepareNsPerShape = -1;
};

// Times the variant's query over `cases` (none skipped for it: see skipReason()): the one timing
// of `run` (per family) and `bench`. Cold queries (fresh SimplexCache), or warm ones when v.start
// is Start::Warm or cfg.warm: the caches are prepared by a cold query of each case before timing,
// and each timed query starts from a copy of its case's cache. A plugin variant (cold only) is
// timed by the same loop and passes, in a child process (timeContained); an executable adapter's
// and an in-process variant's by their own loops (timeAdapter, timeInProcess).
TimingResult timeQueries(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                         const TimingConfig& cfg, double pluginTimeoutSeconds);

// A plugin variant's timeQueries(): its timed loop built here, its passes run in a child process
// (PluginChild, implementations/plugins.hpp), which sends back only the result. A crash, or no pass
// finished within pluginTimeoutSeconds + 30 s (+ the pass's expected length), gives
// nsPerQuery = -1 and a line on stderr.
TimingResult timeContained(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                           const TimingConfig& cfg, double pluginTimeoutSeconds);

// An executable adapter's timeQueries() (implementations/adapter.hpp): each pass splits the cases
// into chunks of m and sends one `time` request per chunk, K = the pass's reps; the pass's time is
// the sum of the adapter's totals (the pipe is outside every timed region), per query sum / (K *
// cases); calibration and passes as medianOfPasses(). A request without its answer (crash, hang,
// error) gives nsPerQuery = -1 and a line on stderr. It times the first kAdapterTimingCases of the
// sample only (TimingResult::cases says how many): every pass sends the cases' text again and the
// adapter parses it outside its timed loop, which in a slow language costs far more than the loop.
// Measured at 15ef9ad on the default campaign: GEOS through shapely (about 250 us a query) took 121
// s of timing on the whole samples, planck.js 12.6 s; one chunk (2,048 cases) is still a sample of
// the random family as the others are.
inline constexpr std::size_t kAdapterTimingCases = 2048;
TimingResult timeAdapter(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                         const TimingConfig& cfg, double pluginTimeoutSeconds);

// An in-process variant's timeQueries() (implementations/in_process.hpp): a plain timed loop in
// this process, over the first kAdapterTimingCases of the sample (its callbacks are typically a
// Python function's, tens of microseconds a query, as slow as an adapter's), calibrated and
// repeated as medianOfPasses(). A per-case callback: one call per case, the loop's time over the
// cases; a batch callback: one call with the whole sample per loop, its time over the cases. What
// the callback's caller adds (the Python layer's conversions of each case) is in the time. A
// callback that throws a std::exception gives nsPerQuery = -1 and a line on stderr; any other
// exception propagates (it ends the campaign).
TimingResult timeInProcess(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                           const TimingConfig& cfg);

// A variant's timed loop over `cases`, prepared as timeQueries() does: pass(reps) runs `reps`
// loops over the cases and returns the nanoseconds taken (empty `pass` when there are no cases).
// The inputs are copied into contiguous arrays first, for gjk2d's variants and plugins alike, so
// that the time does not depend on where the campaign's threads happened to allocate each case.
struct TimedLoop
{
    std::size_t cases = 0;
    bool warm = false;
    std::function<double(int)> pass;
};
TimedLoop timedLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                    const TimingConfig& cfg);

// A plugin's own timing loop (gjk2d_plugin_timing, gjk2d/plugin.h; v.plugin->timing set) over
// `cases`, cold or warm, as a TimedLoop to alternate with gjk2d's (`bench --against`): the cases'
// shapes built into the ABI's structs here, then handed once to the plugin's prepare() in a child
// process (PluginChild::serve), which runs one pass() per pass(reps) of the loop and sends back
// only its nanoseconds (the plugin's clock, its loop alone: the pipe is outside it). A crash, a
// failed prepare() or pass(), or no answer within pluginTimeoutSeconds + 30 s (+ the pass's
// expected length) makes pass() return -1 from then on, with a line on stderr.
TimedLoop ownTimingLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                        bool warm, const TimingConfig& cfg, double pluginTimeoutSeconds);

// `bench`'s timing on the one CPU it runs on when made, with every child forked meanwhile (a
// peer's own loop, a plugin's server: they inherit the mask), the previous mask back when it ends.
// Unpinned, the process sleeps while a peer's child runs its pass and wakes on either core, and
// its own passes split into a fast and a slow group (the figures: docs/speed.md, "Against Box2D v3
// on a quiet machine"). cpu() is -1 where pinning failed (then nothing changed).
class PinnedToOneCpu
{
  public:
    PinnedToOneCpu();
    ~PinnedToOneCpu();
    PinnedToOneCpu(const PinnedToOneCpu&) = delete;
    PinnedToOneCpu& operator=(const PinnedToOneCpu&) = delete;
    int cpu() const { return cpu_; }

  private:
    int cpu_ = -1;
    cpu_set_t previous_; // the mask before, valid when cpu_ >= 0
};

// The passes of several loops alternated (`bench`): one calibration pass each, then pass k of
// every loop before pass k + 1 of any, so that a drift of the machine's speed falls on all of
// them alike and their ratios hold within one run. Stops as medianOfPasses() does. A loop whose
// pass returns a negative time is dropped from then on (its result: nsPerQuery = -1).
std::vector<TimingResult> medianOfAlternatedPasses(const std::vector<TimedLoop>& loops,
                                                   const TimingConfig& cfg);

// The pass loop of timeQueries(), for any timed loop: pass(reps) runs `reps` loops over the
// `cases` queries and returns the nanoseconds taken. One calibration pass sets reps so that a pass
// lasts cfg.minPassSeconds; then minPasses..maxPasses passes (no new one after budgetSeconds);
// the median, min and max per query. Plugin variants (implementations/plugins.cpp) are timed by it
// too.
TimingResult medianOfPasses(std::size_t cases, const TimingConfig& cfg,
                            const std::function<double(int)>& pass,
                            const std::function<void()>& afterPass = {});

} // namespace gjkval
