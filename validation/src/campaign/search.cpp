// The adversarial search (`gjk-validate search`, search.hpp): the mutations of a case, the pool of
// the best cases kept by the objective, the rounds that evaluate each candidate through the
// campaign's own truth, variants and witness checks, and the search's report.
#include "campaign/search.hpp"

#include "common/parallel.hpp"
#include "inputs/geometry.hpp"
#include "inputs/rng.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

namespace gjkval
{
namespace
{
using Clock = std::chrono::steady_clock;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double secondsSince(Clock::time_point t0)
{
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// ---------------------------------------------------------------------------------------------
// Mutations. Each changes a case in place and returns false when it does not apply (then another
// is drawn). The result need not be valid input: the candidate is checked by the reader's rules
// afterwards (validCandidate), and an invalid one is counted apart, never evaluated.

// x moved by k ulps (k < 0: downwards).
double ulps(double x, int k)
{
    const double dir =
        k > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::abs(k); ++i)
        x = std::nextafter(x, dir);
    return x;
}

int ulpCount(Rng& rng)
{
    return int(rng.sign()) * rng.integer(1, 16);
}

double extent(const ShapeIn& s)
{
    double m = 0;
    for (const auto& p : s.points)
        m = std::max({m, std::abs(p[0]), std::abs(p[1])});
    return m;
}

ShapeIn& pickShape(Case& c, Rng& rng)
{
    return (rng.next() & 1) ? c.a : c.b;
}

std::array<double, 2> randomDirection(Rng& rng)
{
    const double t = rng.range(0, 6.283185307179586);
    return {std::cos(t), std::sin(t)};
}

bool vertexUlps(Case& c, const SearchCase&, Rng& rng)
{
    ShapeIn& s = pickShape(c, rng);
    auto& p = s.points[std::size_t(rng.integer(0, int(s.points.size()) - 1))];
    const int which = rng.integer(1, 3); // x, y or both
    if (which & 1)
        p[0] = ulps(p[0], ulpCount(rng));
    if (which & 2)
        p[1] = ulps(p[1], ulpCount(rng));
    return true;
}

bool vertexStep(Case& c, const SearchCase&, Rng& rng)
{
    ShapeIn& s = pickShape(c, rng);
    auto& p = s.points[std::size_t(rng.integer(0, int(s.points.size()) - 1))];
    const double e = extent(s) > 0 ? extent(s) : 1.0;
    const double step = std::ldexp(e, -rng.integer(1, 52));
    const auto d = randomDirection(rng);
    p = {p[0] + step * d[0], p[1] + step * d[1]};
    return true;
}

bool shapeUlps(Case& c, const SearchCase&, Rng& rng)
{
    ShapeIn& s = pickShape(c, rng);
    const int which = rng.integer(1, 3);
    if (which & 1)
        s.px = ulps(s.px, ulpCount(rng));
    if (which & 2)
        s.py = ulps(s.py, ulpCount(rng));
    return true;
}

bool shapeStep(Case& c, const SearchCase&, Rng& rng)
{
    ShapeIn& s = pickShape(c, rng);
    const double m = maxAbsWorldCoordinate(c);
    const double step = std::ldexp(m > 0 ? m : 1.0, -rng.integer(1, 52));
    const auto d = randomDirection(rng);
    s.px += step * d[0];
    s.py += step * d[1];
    return true;
}

bool scalePow2(Case& c, const SearchCase&, Rng& rng)
{
    const int e = rng.integer(1, 16) * int(rng.sign());
    scaleCase(c, std::ldexp(1.0, e));
    return true;
}

bool scaleFactor(Case& c, const SearchCase&, Rng& rng)
{
    scaleCase(c, rng.range(0.5, 2.0)); // almost surely not a power of two: every number rounds
    return true;
}

// A shape turned by a tiny angle t = +-2^-k: (c, s) times (cos t, sin t), or the unit vector of
// its angle plus t recomputed, or c or s moved by ulps (a rotation of another size: still valid).
bool rotateTiny(Case& c, const SearchCase&, Rng& rng)
{
    ShapeIn& s = pickShape(c, rng);
    const double t = rng.sign() * std::ldexp(1.0, -rng.integer(8, 50));
    switch (rng.integer(0, 2))
    {
    case 0:
    {
        const double ct = std::cos(t), st = std::sin(t);
        const double nc = s.c * ct - s.s * st, ns = s.s * ct + s.c * st;
        s.c = nc;
        s.s = ns;
        break;
    }
    case 1:
    {
        const double a = std::atan2(s.s, s.c) + t;
        s.c = std::cos(a);
        s.s = std::sin(a);
        break;
    }
    default:
        if (rng.next() & 1)
            s.c = ulps(s.c, ulpCount(rng));
        else
            s.s = ulps(s.s, ulpCount(rng));
    }
    return true;
}

// B moved along the separating direction (the exact witnesses of the parent) so that the gap d
// becomes d * f, f = +-2^-k or 0: toward touching, from outside or into penetration.
bool shiftGap(Case& c, const SearchCase& parent, Rng& rng)
{
    const double dx = parent.witnessB[0] - parent.witnessA[0],
                 dy = parent.witnessB[1] - parent.witnessA[1];
    const double len = std::hypot(dx, dy);
    if (!(parent.distance > 0) || !(len > 0) || !std::isfinite(len))
        return false;
    const double f =
        rng.integer(0, 15) == 0 ? 0.0 : rng.sign() * std::ldexp(1.0, -rng.integer(1, 50));
    const double move = parent.distance * (1 - f);
    c.b.px -= dx / len * move;
    c.b.py -= dy / len * move;
    return true;
}

bool duplicateVertex(Case& c, const SearchCase&, Rng& rng)
{
    ShapeIn& s = pickShape(c, rng);
    if (s.points.size() >= 4096)
        return false;
    const auto p = s.points[std::size_t(rng.integer(0, int(s.points.size()) - 1))];
    s.points.insert(s.points.begin() + rng.integer(0, int(s.points.size())), p);
    return true;
}

// A vertex removed, or moved onto its neighbour.
bool collapseVertex(Case& c, const SearchCase&, Rng& rng)
{
    ShapeIn& s = pickShape(c, rng);
    const int n = int(s.points.size());
    if (n < 2)
        return false;
    const int i = rng.integer(0, n - 1);
    if (rng.next() & 1)
        s.points.erase(s.points.begin() + i);
    else
        s.points[std::size_t(i)] = s.points[std::size_t((i + 1) % n)];
    return true;
}

// A point on the edge (i, i+1) of the point list, moved off it by 2^-k of the edge's length, out
// or in: a nearly collinear vertex, the hull's most fragile feature.
bool vertexNearEdge(Case& c, const SearchCase&, Rng& rng)
{
    ShapeIn& s = pickShape(c, rng);
    const int n = int(s.points.size());
    if (n < 2 || n >= 4096)
        return false;
    const int i = rng.integer(0, n - 1);
    const auto p = s.points[std::size_t(i)], q = s.points[std::size_t((i + 1) % n)];
    const double t = rng.uniform(), off = rng.sign() * std::ldexp(1.0, -rng.integer(10, 60));
    const double ex = q[0] - p[0], ey = q[1] - p[1];
    s.points.insert(s.points.begin() + i + 1, {p[0] + t * ex - off * ey, p[1] + t * ey + off * ex});
    return true;
}

bool swapShapes(Case& c, const SearchCase&, Rng&)
{
    std::swap(c.a, c.b);
    return true;
}

// Every number rounded to float: the float variants then see the double variants' input.
bool floatRound(Case& c, const SearchCase&, Rng&)
{
    c.a = roundedToFloat(c.a);
    c.b = roundedToFloat(c.b);
    return true;
}

struct Mutation
{
    const char* name;
    bool (*apply)(Case&, const SearchCase&, Rng&);
    int weight;
};

// The mutations and how often each is drawn (weights out of their sum). shift-gap reads the
// parent's witnesses, so it is applied before the others of a step.
constexpr Mutation kMutations[] = {
    {"shift-gap", shiftGap, 4},
    {"vertex-ulps", vertexUlps, 4},
    {"vertex-step", vertexStep, 3},
    {"shape-ulps", shapeUlps, 2},
    {"shape-step", shapeStep, 2},
    {"rotate-tiny", rotateTiny, 3},
    {"scale-pow2", scalePow2, 1},
    {"scale-factor", scaleFactor, 2},
    {"duplicate-vertex", duplicateVertex, 1},
    {"collapse-vertex", collapseVertex, 1},
    {"vertex-near-edge", vertexNearEdge, 2},
    {"swap", swapShapes, 1},
    {"float-round", floatRound, 1},
};

std::size_t drawMutation(Rng& rng)
{
    int total = 0;
    for (const auto& m : kMutations)
        total += m.weight;
    int r = rng.integer(0, total - 1);
    for (std::size_t i = 0; i < std::size(kMutations); ++i)
        if ((r -= kMutations[i].weight) < 0)
            return i;
    return 0;
}

// ---------------------------------------------------------------------------------------------

std::uint64_t caseHash(const Case& c)
{
    std::uint64_t h = 0xcbf29ce484222325ULL;
    auto add = [&h](double v) { h = mix64(h ^ std::bit_cast<std::uint64_t>(v)); };
    for (const ShapeIn* s : {&c.a, &c.b})
    {
        add(double(s->points.size()));
        for (const auto& p : s->points)
            add(p[0]), add(p[1]);
        add(s->radius), add(s->px), add(s->py), add(s->c), add(s->s);
    }
    return h;
}

// The reader's rules, applied by the reader itself: the case written as a gjk-cases/1 file and
// read back. Empty when valid (then `c` is what a file holding it gives), else the reason.
std::string validCandidate(Case& c)
{
    CaseFile f = parseCaseFile(caseFileText({}, {c}), "search");
    if (f.entries.size() != 1)
        return "the case did not read back as one case";
    if (!f.entries[0].rejected.empty())
        return f.entries[0].rejected;
    c = std::move(f.entries[0].c);
    return {};
}

struct Candidate
{
    SearchCase sc;
    std::string invalid; // the reader's or the exact side's reason
    CaseOutcome o;
};

// One evaluation: the reader's checks, then the campaign's phases 1 to 3 (exact truth, every
// variant's query with its errors and bounds, the witness points' distances to their shapes).
void evaluate(Candidate& cand, const EvalContext& ctx)
{
    cand.invalid = validCandidate(cand.sc.c);
    if (!cand.invalid.empty())
        return;
    computeTruth(cand.sc.c, ctx, cand.o);
    if (!cand.o.rejected.empty())
    {
        cand.invalid = cand.o.rejected;
        return;
    }
    runVariants(cand.sc.c, prepare(cand.sc.c), ctx, cand.o);
    checkWitnesses(cand.sc.c, ctx, cand.o);
}

const char* failureKind(const VariantOutcome& v)
{
    if (v.nonfinite)
        return "non-finite output";
    if (v.iterationLimit)
        return "iteration limit";
    if (v.mis == Misclass::FalseOverlap || v.mis == Misclass::FalseSeparation)
        return misclassName(v.mis);
    if (v.certified && !v.intervalContains)
        return "certified interval misses the truth";
    if (v.invalid != Invalid::None)
        return invalidName(v.invalid);
    if (v.beyondDepthBound && !v.beyondBound)
        return "penetration depth beyond the depth bound";
    return "error beyond the bound";
}

// The objective of one answer: error / bound, or the witness points' error / the witness bound
// when larger (each point's distance to its shape, and the gap ||pB - pA|| against d), or, for a
// penetration answer on overlapping shapes (a variant whose contract says penetration: the
// signed variants), the depth error / gjk2d's depth bound when larger: on overlap the distance's
// ratio is 0 (the answer is measured on max(d, 0)), so the search climbs the depth's there. A
// witness bound within 1024 subnormals of its floor measures resolution (as for the distance,
// below).
double answerRatio(const VariantOutcome& v, Scalar scalar)
{
    const double depth = v.depthJudged && !std::isnan(v.depthRatio) ? v.depthRatio : 0;
    const double distance = std::max(v.boundRatio, depth);
    if (v.witnessBound < 1024 * smallestSubnormal(scalar))
        return distance;
    return std::isnan(v.witnessRatio) ? distance : std::max(distance, v.witnessRatio);
}

class Search
{
  public:
    Search(const SearchConfig& config, const std::vector<FamilyData>& inputs)
        : cfg_(config), inputs_(inputs), nv_(config.variants.size()),
          baseSeed_(mix64(config.seed ^ hashString("gjk-validate search")))
    {
        ctx_.variants = config.variants;
        ctx_.exactOptions.filter = config.truthFilter;
        res_.threads = resolveThreads(config.threads);
        res_.startBest.assign(nv_, kNaN);
        res_.best.assign(nv_, kNaN);
        res_.bestPassing.assign(nv_, kNaN);
        res_.bestCase.assign(nv_, {});
        res_.variantFailures.assign(nv_, 0);
    }

    SearchResult run()
    {
        t0_ = Clock::now();
        startPhase();
        for (std::size_t k = 0; k < nv_; ++k)
            res_.startBest[k] = res_.best[k];
        if (cfg_.progress)
            std::fprintf(stderr, "search: %llu start cases evaluated (%.1f s): %s\n",
                         (unsigned long long)res_.evaluations, secondsSince(t0_),
                         bestText().c_str());
        reportImprovements_ = true;
        if (!start_.empty())
            while (!budgetSpent())
                generation();
        res_.seconds = secondsSince(t0_);
        res_.population = std::move(population_);
        res_.exitCode = res_.failures.cases > 0  ? kExitFail
                        : res_.inputRejected > 0 ? kExitInput
                                                 : kExitPass;
        return std::move(res_);
    }

  private:
    std::uint64_t remaining() const
    {
        return cfg_.evaluations > 0
                   ? cfg_.evaluations - std::min(cfg_.evaluations, res_.evaluations)
                   : std::numeric_limits<std::uint64_t>::max();
    }

    bool budgetSpent()
    {
        if (remaining() == 0)
        {
            res_.stoppedBy = "evaluations";
            return true;
        }
        if (cfg_.seconds > 0 && secondsSince(t0_) >= cfg_.seconds)
        {
            res_.stoppedBy = "seconds";
            return true;
        }
        return false;
    }

    // The start cases, in input order, in chunks (the time budget is checked between them).
    void startPhase()
    {
        std::vector<Candidate> all;
        for (const auto& f : inputs_)
            for (std::size_t i = 0; i < f.cases.size(); ++i)
            {
                if (!f.rejected[i].empty())
                {
                    ++res_.inputRejected;
                    std::fprintf(stderr, "gjk-validate: rejected %s: %s\n", f.labels[i].c_str(),
                                 f.rejected[i].c_str());
                    continue;
                }
                Candidate c;
                c.sc.c = f.cases[i];
                c.sc.origin = f.cases[i].name;
                c.sc.lastMutation = "start";
                all.push_back(std::move(c));
            }
        const std::size_t chunk = 256;
        for (std::size_t s = 0; s < all.size(); s += chunk)
        {
            if (budgetSpent())
            {
                res_.stoppedBy = "start cases (" + res_.stoppedBy + ")";
                return;
            }
            std::vector<Candidate> batch;
            for (std::size_t i = s;
                 i < std::min(all.size(), s + chunk) && batch.size() < remaining(); ++i)
                batch.push_back(std::move(all[i]));
            evaluateAll(batch);
            for (auto& c : batch)
            {
                ++res_.startCases;
                if (!c.invalid.empty())
                {
                    ++res_.inputRejected;
                    std::fprintf(stderr, "gjk-validate: rejected %s: %s\n", c.sc.c.name.c_str(),
                                 c.invalid.c_str());
                    continue;
                }
                merge(c);
                start_.push_back(std::move(c.sc));
            }
            sortPopulation();
        }
    }

    void evaluateAll(std::vector<Candidate>& batch)
    {
        Progress none = Progress::silent();
        parallelFor(batch.size(), res_.threads, none,
                    [&](std::size_t i) { evaluate(batch[i], ctx_); });
        res_.evaluations += batch.size();
    }

    // One generation: cfg_.batch candidates, each drawn from its own stream (the seed and its
    // evaluation index) and the population as it stands, evaluated in parallel, merged in order.
    void generation()
    {
        const std::size_t n =
            std::size_t(std::min<std::uint64_t>(remaining(), std::uint64_t(cfg_.batch)));
        std::vector<Candidate> batch(n);
        for (std::size_t j = 0; j < n; ++j)
            batch[j].sc = mutant(res_.evaluations + j);
        evaluateAll(batch);
        ++res_.generations;
        for (auto& c : batch)
        {
            ++res_.mutated;
            if (!c.invalid.empty())
            {
                ++res_.invalidMutations;
                continue;
            }
            merge(c);
        }
        sortPopulation();
    }

    SearchCase mutant(std::uint64_t index)
    {
        Rng rng(mix64(baseSeed_ + index));
        // Restart from a start case now and then (1 in 8), else a member, biased to the best.
        const bool restart = population_.empty() || rng.integer(0, 7) == 0;
        const SearchCase& parent = restart
                                       ? start_[std::size_t(rng.next() % start_.size())]
                                       : population_[std::size_t(double(population_.size()) *
                                                                 rng.uniform() * rng.uniform())];
        const int count = 1 + (rng.uniform() < 0.5 ? 1 : 0) + (rng.uniform() < 0.25 ? 1 : 0);
        std::vector<std::size_t> ops;
        for (int i = 0; i < count; ++i)
            ops.push_back(drawMutation(rng));
        std::stable_sort(ops.begin(), ops.end()); // shift-gap (index 0) first: parent's witnesses
        SearchCase child;
        child.c = parent.c;
        child.c.name = fmt::format("search/{}", index);
        // A mutant is not the reported case: its provenance is its start case and mutations
        // (the output's comments), not the parent's source and comment.
        child.c.source.clear();
        child.c.comment.clear();
        child.origin = parent.origin;
        child.mutations = parent.mutations;
        for (std::size_t op : ops)
        {
            for (int attempt = 0; attempt < 8 && !kMutations[op].apply(child.c, parent, rng);
                 ++attempt)
                op = drawMutation(rng);
            child.lastMutation +=
                (child.lastMutation.empty() ? "" : "+") + std::string(kMutations[op].name);
            ++child.mutations;
        }
        return child;
    }

    // The objective of an evaluated case and every count, in evaluation order.
    // What one evaluated case showed, over its variants.
    struct CaseTally
    {
        bool counted = true, skipped = false, outOfRange = false, failed = false;
        bool nonfinite = false, limit = false, mis = false, interval = false, beyond = false,
             invalid = false;
    };

    void merge(Candidate& cand)
    {
        SearchCase& sc = cand.sc;
        const CaseOutcome& o = cand.o;
        sc.ratios.assign(nv_, kNaN);
        sc.score = kNaN; // no objective unless keepIfScored finds one
        sc.distance = o.exact.distance;
        sc.witnessA = {o.exact.witnessA.x, o.exact.witnessA.y};
        sc.witnessB = {o.exact.witnessB.x, o.exact.witnessB.y};
        CaseTally t;
        for (std::size_t k = 0; k < nv_; ++k)
            tallyVariant(k, o.variants[k], sc, t);
        res_.skipped += t.skipped ? 1 : 0;
        res_.outOfRange += t.outOfRange ? 1 : 0;
        if (t.failed)
            recordFailure(sc, t);
        keepIfScored(sc, t);
    }

    // One variant's answer: a failure is counted; a judged, finite ratio above the floor is
    // recorded (and announced when it is the best so far).
    void tallyVariant(std::size_t k, const VariantOutcome& v, SearchCase& sc, CaseTally& t)
    {
        if (v.skipped)
        {
            t.skipped = true;
            return;
        }
        if (v.failed)
        {
            t.failed = true;
            ++res_.variantFailures[k];
            t.nonfinite |= v.nonfinite;
            t.limit |= v.iterationLimit;
            t.mis |= v.mis == Misclass::FalseOverlap || v.mis == Misclass::FalseSeparation;
            t.interval |= v.certified && !v.intervalContains;
            t.beyond |= (v.beyondBound || v.beyondDepthBound) && !v.nonfinite;
            t.invalid |= v.invalid != Invalid::None;
            if (sc.failure.empty())
                sc.failure = fmt::format("{}: {}", ctx_.variants[k]->name, failureKind(v));
        }
        if (v.outOfRange)
        {
            t.outOfRange = true;
            return;
        }
        // Non-finite answers and iteration limits are failures, never ratios.
        if (v.nonfinite || v.iterationLimit || !std::isfinite(v.boundRatio))
        {
            t.counted = false;
            return;
        }
        // A bound within 1024 subnormals of its floor (bounds.cpp: + T's smallest subnormal)
        // measures the answer's resolution, not the derived bound: such a case is judged (a
        // failure above counts) but is no ratio to climb; otherwise the search settles on one
        // rounding of a subnormal distance, ratio 1.
        if (v.bound < 1024 * smallestSubnormal(ctx_.variants[k]->scalar))
        {
            t.counted = false;
            return;
        }
        const double ratio = answerRatio(v, ctx_.variants[k]->scalar);
        sc.ratios[k] = ratio;
        if (!v.failed && !(ratio <= res_.bestPassing[k]))
            res_.bestPassing[k] = ratio;
        if (!(ratio <= res_.best[k])) // NaN (no best yet) too
        {
            res_.best[k] = ratio;
            res_.bestCase[k] = sc.c.name;
            if (reportImprovements_ && cfg_.progress)
                std::fprintf(stderr,
                             "search: %llu evaluations, %.1f s: %s best ratio %s (%s, from "
                             "%s, %d mutations)\n",
                             (unsigned long long)res_.evaluations, secondsSince(t0_),
                             ctx_.variants[k]->name.c_str(), ratioText(ratio).c_str(),
                             sc.c.name.c_str(), sc.origin.c_str(), sc.mutations);
        }
    }

    void recordFailure(const SearchCase& sc, const CaseTally& t)
    {
        SearchFailures& f = res_.failures;
        ++f.cases;
        f.nonfinite += t.nonfinite;
        f.iterationLimit += t.limit;
        f.misclassified += t.mis;
        f.interval += t.interval;
        f.beyondBound += t.beyond;
        f.invalid += t.invalid;
        if (cfg_.progress && f.cases <= 10)
            std::fprintf(stderr, "search: FAILURE %s (%s)\n", sc.c.name.c_str(),
                         sc.failure.c_str());
        if (res_.failing.size() < kMaxFailingKept)
            res_.failing.push_back(sc);
    }

    // The objective: only a case every variant ran on, judged, finite and passing, has one. A
    // failing case is recorded (counted, kept in `failing`) but never joins the population: the
    // search goes on climbing toward the bound instead of settling on one failure.
    void keepIfScored(SearchCase& sc, const CaseTally& t)
    {
        sc.score = kNaN;
        if (t.counted && !t.skipped && !t.outOfRange && !t.failed)
            for (std::size_t k = 0; k < nv_; ++k)
                if (!(sc.ratios[k] <= sc.score))
                    sc.score = sc.ratios[k], sc.bestVariant = k;
        if (std::isnan(sc.score))
            return;
        const std::uint64_t h = caseHash(sc.c);
        if (!hashes_.insert(h).second)
        {
            ++res_.duplicates;
            return;
        }
        population_.push_back(sc);
    }

    // Best first (ties: the earlier one), at most cfg_.population kept, and at most a quarter of
    // them from one start case: the search climbs several hills, not only the first it found.
    void sortPopulation()
    {
        std::stable_sort(population_.begin(), population_.end(),
                         [](const SearchCase& x, const SearchCase& y)
                         { return x.score > y.score; });
        const std::size_t keep = std::size_t(std::max(1, cfg_.population));
        const std::size_t perOrigin = std::max<std::size_t>(1, keep / 4);
        std::map<std::string, std::size_t> fromOrigin;
        std::vector<SearchCase> kept;
        for (auto& m : population_)
            if (kept.size() < keep && ++fromOrigin[m.origin] <= perOrigin)
                kept.push_back(std::move(m));
        population_ = std::move(kept);
        hashes_.clear();
        for (const auto& m : population_)
            hashes_.insert(caseHash(m.c));
    }

    std::string bestText() const
    {
        std::string s;
        for (std::size_t k = 0; k < nv_; ++k)
            s += fmt::format("{}{} best ratio {}", k ? ", " : "", ctx_.variants[k]->name,
                             ratioText(res_.best[k]));
        return s;
    }

    const SearchConfig& cfg_;
    const std::vector<FamilyData>& inputs_;
    std::size_t nv_;
    std::uint64_t baseSeed_;
    EvalContext ctx_;
    SearchResult res_;
    Clock::time_point t0_;
    std::vector<SearchCase> start_, population_;
    std::set<std::uint64_t> hashes_;
    bool reportImprovements_ = false;
};

} // namespace

SearchResult runSearch(const SearchConfig& config, const std::vector<FamilyData>& inputs)
{
    if (config.variants.empty())
        throw std::logic_error("search: no variant");
    SearchResult r = Search(config, inputs).run();
    r.json = searchJson(config, r, inputs);
    return r;
}

} // namespace gjkval
