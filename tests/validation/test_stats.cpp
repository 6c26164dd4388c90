// Statistics on hand-made data: histogram bins and percentiles, means, and that merging two shards
// gives exactly the statistics of the whole.
#include "evaluate/evaluate.hpp"
#include "statistics/stats.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <utility>
#include <vector>

using namespace gjkval;

TEST_CASE("histogram counts, extrema, mean and bins", "[stats]")
{
    Hist h(-40, 40, 10);
    h.add(0.0, "z1");
    h.add(0.0, "z2");
    h.add(1.0, "one");
    h.add(0.5, "half");
    h.add(4.0, "four");
    h.add(-1.0, "negative ignored");
    h.add(std::nan(""), "nan ignored");
    h.add(INFINITY, "inf ignored");
    CHECK(h.count == 5);
    CHECK(h.zeros == 2);
    CHECK(h.max == 4.0);
    CHECK(h.maxCase == "four");
    CHECK(h.sum() == 5.5);
    CHECK(h.mean() == 1.1);
    // 1.0: log10 = 0 -> bin (0 + 40) * 10 = 400; 4.0: log10 = 0.602 -> bin 406; 0.5: -0.301 -> 396.
    CHECK(h.binOf(1.0) == 400);
    CHECK(h.binOf(4.0) == 406);
    CHECK(h.binOf(0.5) == 396);
    CHECK(h.counts[400] == 1);
    CHECK(h.counts[406] == 1);
    CHECK(h.counts[396] == 1);
    // Clamped at both ends.
    CHECK(h.binOf(1e-300) == 0);
    CHECK(h.binOf(1e300) == h.binCount() - 1);
}

TEST_CASE("percentiles are bin upper edges, zeros first", "[stats]")
{
    Hist h(-40, 40, 10);
    for (int i = 0; i < 50; ++i)
        h.add(0.0);
    for (int i = 0; i < 49; ++i)
        h.add(2e-16);
    h.add(1.0);
    REQUIRE(h.count == 100);
    CHECK(h.percentile(500, 1000) == 0.0); // rank 50: among the zeros
    // rank 51: first 2e-16 (log10 = -15.699: bin 243 holds [10^-15.7, 10^-15.6)): edge 10^-15.6.
    CHECK(h.binOf(2e-16) == 243);
    CHECK(h.percentile(510, 1000) == Approx(std::pow(10.0, -15.6)).epsilon(1e-12));
    CHECK(h.percentile(990, 1000) == Approx(std::pow(10.0, -15.6)).epsilon(1e-12)); // rank 99
    CHECK(h.percentile(999, 1000) == Approx(std::pow(10.0, 0.1)).epsilon(1e-12));   // rank 100
    Hist empty;
    CHECK(empty.percentile(500, 1000) == 0.0);
    const Json j = h.toJson();
    CHECK(j["p50"] == 0.0);
    CHECK(j["count"] == 100);
    CHECK(j["zeros"] == 50);
    CHECK(j["counts"].size() == 401); // trailing empty bins left out; bin 400 holds 1.0
}

namespace
{
Hist filled(int from, int to)
{
    Hist h(-40, 40, 10);
    for (int i = from; i < to; ++i)
        h.add(i % 7 == 0 ? 0.0 : std::ldexp(1.0, (i * 37) % 40 - 20),
              std::to_string(i)); // sums exact
    return h;
}
} // namespace

TEST_CASE("merging two shards equals the whole", "[stats]")
{
    const Hist whole = filled(0, 1000);
    Hist left = filled(0, 437);
    left.merge(filled(437, 1000));
    CHECK(left.toJson() == whole.toJson());

    Hist emptyFirst;
    emptyFirst.merge(whole);
    CHECK(emptyFirst.toJson() == whole.toJson());

    IterHist a, b, all;
    for (int i = 0; i < 100; ++i)
    {
        (i < 30 ? a : b).add(i % 9);
        all.add(i % 9);
    }
    a.merge(b);
    CHECK(a.toJson() == all.toJson());
    CHECK(all.max == 8);
    CHECK(all.counts[0] == 12);

    Stats s1, s2, sAll;
    auto fill = [](Stats& s, int from, int to)
    {
        for (int i = from; i < to; ++i)
        {
            const std::string name =
                std::to_string(i); // ("c" + to_string trips a GCC 12 -Wrestrict false positive)
            ++s.cases;
            s.failures += i % 50 == 0;
            s.undecidable += i % 17 == 0;
            s.abs.add(std::ldexp(1.0, -(i % 40)), name);
            s.normalized.add(std::ldexp(1.0, i % 5), name);
            s.iterations.add(i % 6);
            ++s.stops[std::size_t(i % 3)];
        }
    };
    fill(s1, 0, 123);
    fill(s2, 123, 300);
    fill(sAll, 0, 300);
    s1.merge(s2);
    CHECK(s1.toJson() == sAll.toJson());
    CHECK(sAll.toJson()["failures"] == 6);
    CHECK(sAll.toJson()["failure_rate_upper95"].is_null());
}

TEST_CASE("zero failures give the 3/N upper bound on the failure rate", "[stats]")
{
    Stats s;
    s.cases = 20000;
    CHECK(s.toJson()["failure_rate_upper95"] ==
          1.5e-4); // 3.0 / 20000, rounded once like the literal
    CHECK(s.toJson()["pass"] == true);
}

TEST_CASE("merging adds every counter into its own field", "[stats][merge]")
{
    // Every counter of the two shards a different value, so a counter added into another field
    // (or dropped) shows: the merged value is the sum of that field alone.
    auto counters = [](Stats& s) -> std::vector<std::uint64_t*>
    {
        return {&s.cases,
                &s.failures,
                &s.falseOverlap,
                &s.falseSeparation,
                &s.undecidable,
                &s.nonfinite,
                &s.outOfRange,
                &s.iterationLimit,
                &s.beyondBound,
                &s.skipped,
                &s.notApplicable,
                &s.certified,
                &s.contains,
                &s.uncertified,
                &s.invalid,
                &s.invalidReasons[0],
                &s.invalidReasons[1],
                &s.invalidReasons[2],
                &s.contractViolations,
                &s.beyondBoundKeepingContract,
                &s.violationReasons[0],
                &s.violationReasons[std::size_t(kViolationReasons) - 1]};
    };
    Stats a, b;
    const auto ca = counters(a), cb = counters(b);
    for (std::size_t i = 0; i < ca.size(); ++i)
    {
        *ca[i] = 1 + i;         // 1, 2, 3, ...
        *cb[i] = 100 * (1 + i); // 100, 200, 300, ...
    }
    for (std::size_t i = 0; i < a.stops.size(); ++i)
    {
        a.stops[i] = 1000 + i;
        b.stops[i] = 2000 * (1 + i);
    }
    a.merge(b);
    for (std::size_t i = 0; i < ca.size(); ++i)
    {
        INFO("counter " << i);
        CHECK(*ca[i] == 101 * (1 + i));
    }
    for (std::size_t i = 0; i < a.stops.size(); ++i)
        CHECK(a.stops[i] == 1000 + i + 2000 * (1 + i));
    const Json j = a.toJson();
    CHECK(j["false_overlap"] == 303);
    CHECK(j["false_separation"] == 404);
    CHECK(j["undecidable"] == 505);
    // invalid (counter 14) and its reasons (15 to 17), by name.
    CHECK(j["invalid"] == 1515);
    CHECK(j["invalid_reasons"]["negative_distance"] == 1616);
    CHECK(j["invalid_reasons"]["witness_off_shape"] == 1717);
    CHECK(j["invalid_reasons"]["witness_gap"] == 1818);
}

TEST_CASE("merging histograms: zeros add, the maximum stays, ties keep the first shard's case",
          "[stats][merge]")
{
    Hist first(-40, 40, 10), second(-40, 40, 10);
    first.add(0.0, "f0");
    first.add(3.0, "f-max");
    first.add(0.0, "f1");
    second.add(0.0, "s0");
    second.add(3.0, "s-max"); // ties with the first shard's maximum: the first shard's case stays
    second.add(1.0, "s1");
    first.merge(second);
    CHECK(first.count == 6);
    CHECK(first.zeros == 3);
    CHECK(first.max == 3.0);
    CHECK(first.maxCase == "f-max");
    CHECK(first.sum() == 7.0);

    // A larger maximum in the second shard wins.
    Hist low(-40, 40, 10), high(-40, 40, 10);
    low.add(2.0, "low");
    high.add(5.0, "high");
    low.merge(high);
    CHECK(low.max == 5.0);
    CHECK(low.maxCase == "high");

    // Iteration counts: the larger maximum stays whichever shard holds it.
    IterHist big, small;
    big.add(9);
    big.add(2);
    small.add(3);
    IterHist bigFirst = big;
    bigFirst.merge(small);
    CHECK(bigFirst.max == 9);
    CHECK(bigFirst.count == 3);
    CHECK(bigFirst.counts.size() == 10);
    IterHist smallFirst = small;
    smallFirst.merge(big);
    CHECK(smallFirst.max == 9);
    CHECK(smallFirst.toJson() == bigFirst.toJson());
}

TEST_CASE("statistics survive their state: what a shard or a checkpoint writes", "[stats]")
{
    Stats s;
    s.cases = 3;
    s.failures = 1;
    s.falseOverlap = 1;
    s.hasInterval = true;
    s.certified = 2;
    s.contains = 2;
    s.abs.add(1e-17, "a", 0);
    s.abs.add(3e-16, "b", 1);
    s.abs.add(0.0, "c", 2);
    s.rel.add(2e-16, "a", 0);
    s.widthUlps.add(3.0, "b", 1);
    s.iterations.add(2);
    s.iterations.add(5);
    s.stops[1] = 3;
    s.invalid = 3;
    s.invalidReasons = {1, 0, 2};
    const Json state = s.state();
    const Stats back = Stats::fromState(Json::parse(state.dump())); // through text, as on disk
    CHECK(back.state() == state);
    CHECK(back.toJson() == s.toJson());
    CHECK(back.abs.maxCase == "b");
    CHECK(back.iterations.sum == 7);
    CHECK(back.invalid == 3);
    CHECK(back.invalidReasons == std::array<std::uint64_t, kInvalidReasons>{1, 0, 2});
    // Every row is read back by its name: a state without one (another version's) is refused.
    Json missing = state;
    missing["counts"].erase("witness_exact");
    CHECK_THROWS(Stats::fromState(missing));
    Json counted = state;
    counted["counts"]["witness_exact"] = 7;
    CHECK(Stats::fromState(counted).witnessExact == 7);
    Json wrongReasons = state;
    wrongReasons["invalid_reasons"] = std::vector<std::uint64_t>{1, 2};
    CHECK_THROWS(Stats::fromState(wrongReasons));
    Json broken = state;
    broken["histograms"]["abs"]["counts"] = std::vector<std::uint64_t>{1, 2};
    CHECK_THROWS(Stats::fromState(broken));
}

TEST_CASE("every row of the Stats tables merges, survives the state and reaches the report",
          "[stats][merge]")
{
    // Each row a different value in each shard, so a row merged into another field, dropped by
    // the state or written under another name shows.
    Stats a, b;
    std::uint64_t k = 1;
    for (const CountField& f : kCountFields)
    {
        a.*f.member = k;
        b.*f.member = 100 * k++;
    }
    for (const PathField& f : kPathFields)
    {
        a.*f.member = k;
        b.*f.member = 100 * k++;
    }
    for (const HistField& f : kHistFields)
    {
        (a.*f.member).add(double(k), "a", 0);
        (b.*f.member).add(double(100 * k++), "b", 1);
    }
    b.hasInterval = b.hasInputRounding = b.hasPaths = true;
    a.merge(b);
    const Stats back = Stats::fromState(Json::parse(a.state().dump()));
    CHECK(back.state() == a.state());
    const Json j = back.toJson();
    k = 1;
    for (const CountField& f : kCountFields)
    {
        INFO(f.name);
        const Json& at = f.section == Section::Interval  ? j["interval"]
                         : f.section == Section::Correct ? j["correct"]
                         : f.section == Section::Truth   ? j["truth"]
                                                         : j;
        if (f.member == &Stats::contractViolations) // an object: {"count", "reasons", "worst"}
            CHECK(at[f.name]["count"] == 101 * k++);
        else
            CHECK(at[f.name] == 101 * k++);
    }
    for (const PathField& f : kPathFields)
        CHECK(j["correct"]["paths"][gjk::correctPathName(f.path)] == 101 * k++);
    for (const HistField& f : kHistFields)
    {
        INFO(f.name);
        const Json& at = f.section == Section::Interval ? j["interval"] : j["errors"];
        CHECK(at[f.name]["count"] == 2);
        CHECK(at[f.name]["max"] == double(100 * k++));
    }
}

TEST_CASE("the report's Stats keys keep their order", "[stats]")
{
    // The order main's report.json had before the tables (gjk-validate run --no-timing, variants
    // double-certified and double-correct): the tables and their exceptions must reproduce it.
    Stats s;
    s.hasInterval = s.hasPaths = s.hasInputRounding = true;
    s.penetration.any = true;
    const Json j = s.toJson();
    std::vector<std::string> keys, errors, interval, correct;
    for (const auto& [key, _] : j.items())
        keys.push_back(key);
    for (const auto& [key, _] : j["errors"].items())
        errors.push_back(key);
    for (const auto& [key, _] : j["interval"].items())
        interval.push_back(key);
    for (const auto& [key, _] : j["correct"].items())
        correct.push_back(key);
    CHECK(keys == std::vector<std::string>{"cases",
                                           "failures",
                                           "pass",
                                           "false_overlap",
                                           "false_separation",
                                           "undecidable",
                                           "nonfinite",
                                           "out_of_range",
                                           "iteration_limit",
                                           "beyond_bound",
                                           "invalid",
                                           "invalid_reasons",
                                           "skipped",
                                           "not_applicable",
                                           "refused",
                                           "plugin_errors",
                                           "crashed",
                                           "hung",
                                           "witness_points",
                                           "witness_exact",
                                           "contract_violations",
                                           "beyond_bound_keeping_contract",
                                           "failure_rate_upper95",
                                           "errors",
                                           "iterations",
                                           "interval",
                                           "correct",
                                           "penetration", // issue 51
                                           "stops",
                                           "ns_per_query",
                                           "ns_spread",
                                           "timing_passes",
                                           "prepare_ns_per_shape",
                                           "prepared_ns_per_query",
                                           "ratio_to_baseline",
                                           "truth"}); // issue 34: appended
    std::vector<std::string> truth;
    for (const auto& [key, _] : j["truth"].items())
        truth.push_back(key);
    CHECK(truth == std::vector<std::string>{"gmp_route", "hull", "merge", "feature", "squared",
                                            "distance", "witness"});
    CHECK(errors == std::vector<std::string>{"abs", "rel", "ulps", "normalized", "bound_ratio",
                                             "witness", "witness_gap", "witness_ratio",
                                             "input_rounding"});
    CHECK(interval ==
          std::vector<std::string>{"certified", "contains", "misses", "uncertified", "width_ulps"});
    CHECK(correct == std::vector<std::string>{"paths", "bit_mismatches"});
    std::vector<std::string> paths;
    for (const auto& [key, _] : j["correct"]["paths"].items())
        paths.push_back(key);
    CHECK(paths == std::vector<std::string>{"double", "extended", "double-double", "exact"});
}

TEST_CASE("the shard state is the Stats tables in their order", "[stats]")
{
    // StatsState (docs/report-schema.md, gjk-shard/3): one key per table, each table's rows in
    // their order, by their report names.
    Stats s;
    s.hasPaths = true;
    const Json state = s.state();
    auto keys = [](const Json& j)
    {
        std::vector<std::string> k;
        for (const auto& [key, _] : j.items())
            k.push_back(key);
        return k;
    };
    CHECK(keys(state) == std::vector<std::string>{"counts", "flags", "histograms", "paths",
                                                  "invalid_reasons", "violation_reasons",
                                                  "worst_violation", "stops", "iterations",
                                                  "penetration"});
    CHECK(state["penetration"].is_null()); // no penetration contract
    std::vector<std::string> counts, flags, histograms;
    for (const CountField& f : kCountFields)
        counts.push_back(f.name);
    for (const FlagField& f : kFlagFields)
        flags.push_back(f.name);
    for (const HistField& f : kHistFields)
        histograms.push_back(f.name);
    CHECK(keys(state["counts"]) == counts);
    CHECK(keys(state["flags"]) == flags);
    CHECK(keys(state["histograms"]) == histograms);
    s.pathDouble = 1;
    s.pathExtended = 2;
    s.pathDoubleDouble = 3;
    s.pathExact = 4;
    CHECK(s.state()["paths"] == std::vector<std::uint64_t>{1, 2, 3, 4}); // kPathFields' order
    s.hasPaths = false;
    CHECK(s.state()["paths"].is_null());
    CHECK_FALSE(Stats::fromState(s.state()).hasPaths);
}

TEST_CASE(
    "the worst contract violation merges exactly: the largest measured excess, ties to the earlier "
    "case, one without a size only where none is measured",
    "[stats][merge][contract]")
{
    // Four violations in a family of cases 0..9: excess 5 at case 7, +inf (a crash) at case 3,
    // +inf at case 8, 2 at case 1. In any split and order the worst is case 7's 5 (a measured one
    // ranks above any without a size); of the crash and the hang alone, the earlier case 3.
    struct V
    {
        double excess;
        std::uint64_t index;
        Violation why;
    };
    const V vs[] = {{5, 7, Violation::Distance},
                    {INFINITY, 3, Violation::Crashed},
                    {INFINITY, 8, Violation::Hung},
                    {2, 1, Violation::WitnessGap}};
    auto fold = [&](const std::vector<int>& which)
    {
        Stats s;
        for (int i : which)
        {
            ++s.contractViolations;
            ++s.violationReasons[std::size_t(vs[i].why) - 1];
            s.worstViolation.add(vs[i].excess, "c" + std::to_string(vs[i].index), vs[i].index,
                                 vs[i].why);
        }
        return s;
    };
    const Stats all = fold({0, 1, 2, 3});
    const std::vector<std::pair<std::vector<int>, std::vector<int>>> splits = {{{0, 2}, {1, 3}},
                                                                               {{2, 3}, {0, 1}}};
    for (const auto& split : splits)
    {
        Stats a = fold(split.first), b = fold(split.second), ab = a, ba = b;
        ab.merge(b);
        ba.merge(a);
        CHECK(ab.toJson() == all.toJson());
        CHECK(ba.toJson() == all.toJson());
    }
    const Json j = all.toJson()["contract_violations"];
    CHECK(j["count"] == 4);
    CHECK(j["reasons"] == Json{{"crashed", 1}, {"hung", 1}, {"witness_gap", 1}, {"distance", 1}});
    CHECK(j["worst"] == Json{{"case", "c7"}, {"reason", "distance"}, {"excess", 5}});
    CHECK(fold({0, 3}).toJson()["contract_violations"]["worst"]["case"] == "c7");
    const Json sizeless = fold({2, 1}).toJson()["contract_violations"]["worst"];
    CHECK(sizeless == Json{{"case", "c3"}, {"reason", "crashed"}, {"excess", "inf"}});
    // The state keeps it exactly, +inf and all.
    const Stats back = Stats::fromState(all.state());
    CHECK(back.toJson() == all.toJson());
    CHECK(back.state() == all.state());
    // None: null, in the report and the state.
    CHECK(Stats().toJson()["contract_violations"] ==
          Json{{"count", 0}, {"reasons", Json::object()}, {"worst", nullptr}});
    CHECK(Stats().state()["worst_violation"].is_null());
}

namespace
{
// A penetration answer on an overlapping case, as judge() and judgeContracts leave it: its depth
// error |d - s|, relative error and error over gjk2d's depth bound, whether it is beyond that
// bound, and its contract verdict.
VariantOutcome depthAnswer(double abs, double rel, double ratio, Violation why = Violation::None)
{
    VariantOutcome v;
    v.depthJudged = true;
    v.depthAbs = abs;
    v.depthRel = rel;
    v.depthRatio = ratio;
    v.beyondDepthBound = ratio > 1;
    v.violation = why;
    v.violationExcess = why == Violation::None ? 0 : ratio;
    return v;
}
} // namespace

TEST_CASE(
    "the penetration block merges exactly across shards, and a state without it reads as none",
    "[stats][merge][penetration]")
{
    // Five overlapping cases 0..4 of a family: depth errors 0 (case 0), 2^-50 (1, ratio 0.25),
    // 2^-40 (2, ratio 3: beyond gjk2d's depth bound, keeping the contract), 2^-48 (3, ratio 1),
    // and a depth_off at case 4 (ratio 5). Split 0,2,4 | 1,3 and merged in both orders: the whole's
    // counts (5 cases, 1 violation, 2 beyond the bound of which 1 keeps the contract), its largest
    // error 2^-40 at case 2, its largest ratio 5 at case 4, its sums exact.
    const VariantOutcome vs[] = {depthAnswer(0, 0, 0), depthAnswer(0x1p-50, 0x1p-52, 0.25),
                                 depthAnswer(0x1p-40, 0x1p-42, 3), depthAnswer(0x1p-48, 0x1p-50, 1),
                                 depthAnswer(0x1p-45, 0x1p-47, 5, Violation::DepthOff)};
    auto fold = [&](const std::vector<int>& which)
    {
        PenetrationStats p;
        p.any = true;
        for (int i : which)
            p.add(vs[i], "c" + std::to_string(i), std::uint64_t(i));
        return p;
    };
    const PenetrationStats whole = fold({0, 1, 2, 3, 4});
    CHECK(whole.cases == 5);
    CHECK(whole.contractViolations == 1);
    CHECK(whole.beyondBound == 2);
    CHECK(whole.beyondBoundKeepingContract == 1);
    CHECK(whole.abs.max == 0x1p-40);
    CHECK(whole.abs.maxCase == "c2");
    CHECK(whole.boundRatio.max == 5);
    CHECK(whole.boundRatio.maxCase == "c4");
    CHECK(whole.boundRatio.zeros == 1);
    CHECK(whole.worstViolation.caseName == "c4");
    CHECK(whole.abs.sum() == 0x1p-50 + 0x1p-40 + 0x1p-48 + 0x1p-45); // exact in double
    PenetrationStats a = fold({0, 2, 4}), b = fold({1, 3}), ab = a, ba = b;
    ab.merge(b);
    ba.merge(a);
    CHECK(ab.toJson() == whole.toJson());
    CHECK(ba.toJson() == whole.toJson());
    CHECK(ab.state() == whole.state());

    // Through Stats' state, as a shard writes it: the block survives; a variant without a
    // penetration contract writes null; a state without the key (written before issue 51) reads as
    // none, and merging it leaves the other's block as it is.
    Stats s, none;
    s.penetration = whole;
    const Stats back = Stats::fromState(Json::parse(s.state().dump()));
    CHECK(back.penetration.state() == whole.state());
    CHECK(back.toJson()["penetration"] == whole.toJson());
    Json old = none.state();
    CHECK(old["penetration"].is_null());
    CHECK_FALSE(none.toJson().contains("penetration"));
    old.erase("penetration");
    Stats fromOld = Stats::fromState(old);
    CHECK_FALSE(fromOld.penetration.any);
    fromOld.merge(back);
    CHECK(fromOld.penetration.state() == whole.state());
    // An older state's violation reasons stop before DepthOff and NoDepth: they count 0 there.
    Json fewer = none.state();
    fewer["violation_reasons"] =
        std::vector<std::uint64_t>(std::size_t(int(Violation::BitMismatch)), 1);
    const Stats older = Stats::fromState(fewer);
    CHECK(older.violationReasons[std::size_t(Violation::BitMismatch) - 1] == 1);
    CHECK(older.violationReasons[std::size_t(Violation::DepthOff) - 1] == 0);
    CHECK(older.violationReasons[std::size_t(Violation::NoDepth) - 1] == 0);
}
