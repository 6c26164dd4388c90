// Shards: a shard's state (what `run --shard` writes and `merge` reads), and the merge of every
// shard's state into the campaign (docs/cli.md, "Shards, merge, MPI, resume").
#include "campaign/state.hpp"

#include "common/output.hpp"
#include "implementations/peers.hpp"
#include "implementations/plugins.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <istream>
#include <string_view>

namespace gjkval
{
Json campaignIdentity(const CampaignConfig& config)
{
    Json variants = Json::array();
    for (const auto* v : config.variants)
        variants.push_back(v->name);
    return Json{{"families", config.families},
                {"case_files", config.caseFiles},
                {"seed", config.seed},
                {"variants", std::move(variants)},
                {"exact_route", exact::routeName(config.route)},
                {"worst_per_family", config.worstPerFamily},
                {"timing", config.timing},
                {"chunk_cases", config.chunkCases},
                {"per_case", config.perCase},
                {"git_revision", gitRevision()}};
}

Json shardState(const CampaignState& state, const CampaignConfig& config, Shard shard, int threads)
{
    Json families = Json::array();
    for (const auto& f : state.families)
    {
        Json stats = Json::array(), timing = Json::array();
        for (const auto& s : f.stats)
        {
            stats.push_back(s.state());
            timing.push_back({s.nsPerQuery, s.nsMin, s.nsMax, s.timingPasses, s.prepareNsPerShape,
                              s.preparedNsPerQuery});
        }
        std::vector<Case> worst;
        Json worstAt = Json::array();
        for (const auto& w : f.worst.cases())
        {
            worst.push_back(w.c);
            worstAt.push_back(w.index);
        }
        families.push_back({{"name", f.input->name},
                            {"cases", f.cases},
                            {"rejected", f.rejected},
                            {"stats", std::move(stats)},
                            {"timing", std::move(timing)},
                            {"makeup", f.makeup.state()},
                            {"worst_index", std::move(worstAt)},
                            {"worst", caseFileText({}, worst)}});
    }
    Json rejected = Json::array();
    for (const auto& r : state.rejected)
        rejected.push_back({{"input", r.input}, {"index", r.index}, {"entry", r.entry}});
    const PhaseSeconds& t = state.seconds;
    return Json{
        {"schema", kShardSchema},
        {"campaign", campaignIdentity(config)},
        {"shard", {{"index", shard.index}, {"count", shard.count}}},
        {"command", config.command},
        {"threads", threads},
        {"elapsed_s", {t.inputs, t.exact, t.gjk, t.witness, t.timing, t.setup, t.fold, t.report}},
        {"families", std::move(families)},
        {"rejected", std::move(rejected)}};
}

void checkStateSchema(const Json& j, const char* schema, const std::string& file, const char* redo)
{
    const std::string found = j.is_object() ? j.value("schema", "") : "";
    if (found == schema)
        return;
    const std::string_view name(schema);
    const std::string_view kind = name.substr(0, name.find('/') + 1); // "gjk-shard/"
    for (const OldStateVersion& old : kOldStateVersions)
        if (found == fmt::format("{}{}", kind, old.version))
            throw InputError(fmt::format("{}: a {} file, written by gjk2d up to {} (which reads "
                                         "it); this release writes {}: {}",
                                         file, found, old.lastRevision, schema, redo));
    throw InputError(fmt::format("{}: not a {} file", file, schema));
}

std::string identityDifference(const Json& other, const Json& identity, const std::string& theirs)
{
    for (const auto& [key, value] : identity.items())
        if (other.value(key, Json()) != value)
            return fmt::format("its {} is {}, {}'s is {}", key,
                               excerpt(other.value(key, Json()).dump()), theirs,
                               excerpt(value.dump()));
    return {};
}

namespace
{
// The shard states' campaign configuration (the command line of `merge` gives the rest).
CampaignConfig configOf(const Json& identity, const CampaignConfig& base)
{
    CampaignConfig c = base;
    c.families = identity.at("families").get<std::vector<std::string>>();
    c.caseFiles = identity.at("case_files").get<std::vector<std::string>>();
    c.seed = identity.at("seed").get<std::uint64_t>();
    c.variants.clear();
    for (const auto& n : identity.at("variants"))
    {
        const std::string name = n.get<std::string>();
        const VariantInfo* v = findVariant(name);
        if (!v) // a shipped peer's variant (run, --peers): load every built peer, look again
            for (const auto& path : shippedPluginPaths(true))
                loadPlugin(path);
        v = findVariant(name);
        if (!v)
            throw InputError(fmt::format("merge: the shards ran variant '{}', which is neither "
                                         "gjk2d's nor a shipped plugin's",
                                         name));
        c.variants.push_back(v);
    }
    if (!exact::parseRoute(identity.at("exact_route").get<std::string>(), c.route))
        throw InputError("merge: an unknown exact route");
    c.worstPerFamily = identity.at("worst_per_family").get<int>();
    c.timing = identity.at("timing").get<bool>();
    c.chunkCases = identity.at("chunk_cases").get<std::size_t>();
    c.perCase = identity.at("per_case").get<bool>();
    return c;
}
} // namespace

// One shard's state folded into `state` (whose inputs are the campaign's): statistics, make-up,
// the rejected cases, the worst cases (evaluated again here: the same code gives the same
// outcome), and the timing of the inputs whose first chunk the shard held.
void mergeShard(CampaignState& state, const Json& j, Shard shard, const EvalContext& ctx,
                std::size_t worstPerFamily)
{
    const Json& families = j.at("families");
    if (families.size() != state.families.size())
        throw InputError("merge: the shards hold different inputs");
    for (std::size_t i = 0; i < state.families.size(); ++i)
    {
        FamilyResult& f = state.families[i];
        const Json& s = families[i];
        if (s.at("name").get<std::string>() != f.input->name)
            throw InputError(fmt::format("merge: input {} is '{}' in a shard, '{}' here", i,
                                         excerpt(s.at("name").get<std::string>()),
                                         excerpt(f.input->name)));
        f.cases += s.at("cases").get<std::size_t>();
        f.rejected += s.at("rejected").get<std::size_t>();
        const Json& stats = s.at("stats");
        if (stats.size() != f.stats.size())
            throw InputError("merge: the shards ran different variants");
        const bool timedFirstChunk = shard.owns(i, 0);
        for (std::size_t k = 0; k < f.stats.size(); ++k)
        {
            f.stats[k].merge(Stats::fromState(stats[k]));
            if (timedFirstChunk)
            {
                const Json& t = s.at("timing")[k];
                f.stats[k].nsPerQuery = t[0].get<double>();
                f.stats[k].nsMin = t[1].get<double>();
                f.stats[k].nsMax = t[2].get<double>();
                f.stats[k].timingPasses = t[3].get<int>();
                // A shard of gjk-shard/3 before the preparation was timed has four numbers,
                // before gjk2d's prepared shapes were timed five.
                f.stats[k].prepareNsPerShape = t.size() > 4 ? t[4].get<double>() : -1.0;
                f.stats[k].preparedNsPerQuery = t.size() > 5 ? t[5].get<double>() : -1.0;
            }
        }
        f.makeup.merge(MakeupFold::fromState(f.input->makeup, s.at("makeup")));
        const CaseFile worst = parseCaseFile(s.at("worst").get<std::string>(), "shard worst");
        const Json& at = s.at("worst_index");
        for (std::size_t w = 0; w < worst.entries.size() && w < worstPerFamily; ++w)
        {
            const Case& c = worst.entries[w].c;
            f.worst.offer(at.at(w).get<std::size_t>(), c, evaluateCase(c, ctx));
        }
    }
    for (const auto& r : j.at("rejected"))
        state.rejected.push_back(
            {r.at("input").get<std::size_t>(), r.at("index").get<std::size_t>(), r.at("entry")});
    const Json& e = j.at("elapsed_s");
    state.seconds.inputs += e[0].get<double>();
    state.seconds.exact += e[1].get<double>();
    state.seconds.gjk += e[2].get<double>();
    state.seconds.witness += e[3].get<double>();
    state.seconds.timing += e[4].get<double>();
    if (e.size() >= 8) // setup, fold, report
    {
        state.seconds.setup += e[5].get<double>();
        state.seconds.fold += e[6].get<double>();
        state.seconds.report += e[7].get<double>();
    }
}

namespace
{
// A shard file's campaign identity; InputError when it is not a shard state.
const Json& shardIdentity(const Json& shard, const std::string& name)
{
    checkStateSchema(shard, kShardSchema, shownPath(name), "run the shards again with it");
    return shard.at("campaign");
}

// Every shard of one campaign, each once, none missing: InputError otherwise. Returns the number
// of shards the campaign was split into.
std::size_t checkShardSet(const std::vector<Json>& shards, const std::vector<std::string>& names)
{
    const Json& identity = shardIdentity(shards[0], names[0]);
    const std::size_t count = shards[0].at("shard").at("count").get<std::size_t>();
    std::vector<bool> seen(count, false);
    for (std::size_t i = 0; i < shards.size(); ++i)
    {
        const std::string difference =
            identityDifference(shardIdentity(shards[i], names[i]), identity, shownPath(names[0]));
        if (!difference.empty())
            throw InputError(fmt::format("{}: a shard of another campaign: {}", shownPath(names[i]),
                                         difference));
        const Json& sh = shards[i].at("shard");
        const auto index = sh.at("index").get<std::size_t>();
        if (sh.at("count").get<std::size_t>() != count || index >= count)
            throw InputError(fmt::format("{}: shard {}/{} is not one of {} shards",
                                         shownPath(names[i]), index,
                                         sh.at("count").get<std::size_t>(), count));
        if (seen[index])
            throw InputError(
                fmt::format("{}: shard {}/{} is given twice", shownPath(names[i]), index, count));
        seen[index] = true;
    }
    for (std::size_t i = 0; i < count; ++i)
        if (!seen[i])
            throw InputError(fmt::format("merge: shard {}/{} is missing", i, count));
    return count;
}

// The shards' rejected cases in the campaign's case order, the first kMaxRejectedListed kept: the
// one-process run's list.
void orderRejected(CampaignState& state)
{
    std::sort(state.rejected.begin(), state.rejected.end(),
              [](const RejectedCase& a, const RejectedCase& b)
              { return a.input != b.input ? a.input < b.input : a.index < b.index; });
    if (state.rejected.size() > kMaxRejectedListed)
        state.rejected.resize(kMaxRejectedListed);
}

// The campaign's threads: every shard's.
int shardThreads(const std::vector<Json>& shards)
{
    int threads = 0;
    for (const auto& j : shards)
        threads += j.at("threads").get<int>();
    return threads;
}
} // namespace

Campaign mergeShards(const std::vector<Json>& shards, const std::vector<std::string>& names,
                     const CampaignConfig& base, double wallSeconds)
{
    const auto tStart = Clock::now();
    if (shards.empty())
        throw InputError("merge: no shard given");
    const std::size_t count = checkShardSet(shards, names);
    CampaignConfig config = configOf(shards[0].at("campaign"), base);
    const EvalContext ctx = evalContext(config);
    CampaignState state;
    // Read whole: merge streams nothing, and needs each case file's count and comments.
    state.inputs = campaignInputs(config, FileCheck::Whole); // not resized: families point into it
    for (const auto& in : state.inputs)
        state.families.push_back(emptyResult(in, config, ctx));
    for (const auto& shard : shards)
        mergeShard(state, shard, Shard{shard.at("shard").at("index").get<std::size_t>(), count},
                   ctx, std::size_t(std::max(0, config.worstPerFamily)));
    orderRejected(state);
    return finishCampaign(state, config, ctx, shardThreads(shards),
                          wallSeconds >= 0 ? wallSeconds : elapsed(tStart, Clock::now()));
}

void joinPerCase(const Json& report, std::size_t chunkCases,
                 const std::vector<std::istream*>& shardLines, std::ostream& out)
{
    const Shard rule{0, shardLines.size()};
    std::string line;
    const Json& families = report.at("families");
    for (std::size_t f = 0; f < families.size(); ++f)
    {
        const auto cases = families[f].at("cases").get<std::size_t>();
        for (std::size_t first = 0, j = 0; first < cases; first += chunkCases, ++j)
        {
            const std::size_t s = (f + j) % rule.count; // Shard::owns
            for (std::size_t i = first; i < std::min(cases, first + chunkCases); ++i)
            {
                if (!std::getline(*shardLines[s], line))
                    throw InputError(fmt::format("merge: shard {}'s cases.jsonl ends before "
                                                 "case {} of {}",
                                                 s, i, excerpt(families[f].at("name").dump())));
                out << line << '\n';
            }
        }
    }
    for (std::size_t s = 0; s < shardLines.size(); ++s)
        if (std::getline(*shardLines[s], line))
            throw InputError(fmt::format("merge: shard {}'s cases.jsonl has more lines than its "
                                         "cases",
                                         s));
}

} // namespace gjkval
