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
    // A variant with a preparation step (Preparation::Shape or Case), or gjk2d's own with a
    // prepared form (gjk::prepare): the preparation of all the timed cases' shapes, once, over
    // their number; -1: not measured.
    double prepareNsPerShape = -1;
    // gjk2d's own variant with a prepared form (hasPreparedForm; timeAlternated): the median per
    // query of the same queries on prepared shapes (preparedLoop), nsPerQuery staying the plain
    // query's; -1: not measured.
    double preparedNsPerQuery = -1;
};

// A variant's timed loop over `cases` (none skipped for it: see skipReason()): pass(reps) runs
// `reps` loops over the cases and returns the nanoseconds taken (empty `pass` when there are no
// cases; a negative time when the loop is lost). The inputs are copied into contiguous arrays
// first, for gjk2d's variants and plugins alike, so that the time does not depend on where the
// campaign's threads happened to allocate each case.
struct TimedLoop
{
    std::size_t cases = 0;
    bool warm = false;
    std::function<double(int)> pass;
    // The preparation of one shape, timed apart from the passes (a variant with a preparation
    // step: Preparation::Shape or Case); empty: none.
    std::function<double()> prepareNsPerShape;
};

// The one timed loop of every kind of variant, for `run` (per family) and `bench`:
// - gjk2d's: the plain query (Preparation::None: the points as given), cold (fresh SimplexCache),
//   or warm when v.start is Start::Warm or cfg.warm (the caches prepared by a cold query of each
//   case before timing, each timed query starting from a copy of its case's cache);
// - a shared library's, in a served child (timing/plugin_timing.hpp, sharedLibraryLoop): on
//   prepared shapes where it exports gjk2d_plugin_prepared, else through distance_f/distance_d;
// - an executable adapter's (adapterLoop, its own figures) and an in-process callback's
//   (inProcessLoop), on the first kAdapterTimingCases cases.
TimedLoop variantLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                      const TimingConfig& cfg, double pluginTimeoutSeconds);

// gjk2d's own variant's second loop, on prepared shapes (hasPreparedForm; an empty loop without
// one): as a peer's prepared shapes are timed (plugin_timing.hpp, sharedLibraryLoop), every case's
// two shapes prepared once by gjk::prepare, timed apart (prepareNsPerShape: the whole preparation
// over the number of shapes); a pass is the same queries as variantLoop's, cold or warm alike, on
// the prepared shapes and the case's transforms.
TimedLoop preparedLoop(const std::vector<const PreparedCase*>& cases, const VariantInfo& v,
                       const TimingConfig& cfg);

// Times every variant k over cases[k], their passes alternated (medianOfAlternatedPasses): the
// timing of `run` (per family) and of `bench`. A variant with a prepared form has its
// preparedLoop alternated with the others too (TimingResult::preparedNsPerQuery and
// prepareNsPerShape). A loop that is lost (a plugin's crash or hang, an adapter's refused figure)
// gives nsPerQuery = -1, with a line on stderr.
std::vector<TimingResult> timeAlternated(const std::vector<std::vector<const PreparedCase*>>& cases,
                                         const std::vector<const VariantInfo*>& variants,
                                         const TimingConfig& cfg, double pluginTimeoutSeconds);

// An executable adapter's and an in-process variant's loops time the first kAdapterTimingCases of
// the sample only (TimingResult::cases says how many): every pass sends the cases' text again and
// the adapter parses it outside its timed loop, which in a slow language costs far more than the
// loop (GEOS through shapely: hundreds of microseconds a query). One chunk (2,048 cases) is still a
// sample of the random family as the others are.
inline constexpr std::size_t kAdapterTimingCases = 2048;

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

// The median of ascending values (the mean of the middle two when their count is even); -1 when
// there are none.
double medianOfSorted(const std::vector<double>& xs);

// The passes of several loops alternated: one calibration pass each (reps so that a pass lasts
// cfg.minPassSeconds), then pass p of every loop before pass p + 1 of any, round p starting at
// loop p mod n, so that a drift of the machine's speed falls on all of them alike and their
// ratios hold within one run; minPasses..maxPasses rounds, no new one after budgetSeconds per
// loop. The median, min and max per query, and each loop's preparation figure. A loop whose pass
// returns a negative time is dropped from then on (its result: nsPerQuery = -1).
std::vector<TimingResult> medianOfAlternatedPasses(const std::vector<TimedLoop>& loops,
                                                   const TimingConfig& cfg);

} // namespace gjkval
