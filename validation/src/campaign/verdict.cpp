// The verdict and report.json: each family judged, the campaign's exit code, and the report
// built from the folded (or merged) state.
#include "campaign/state.hpp"
#include "common/context.hpp"

#include "implementations/peers.hpp"
#include "report/report.hpp"

#include <fmt/format.h>

#include <set>

namespace gjkval
{
namespace
{

// Index of the variant timing ratios are given against: kBaselineVariant when selected, else the
// first.
std::size_t baselineIndex(const EvalContext& ctx)
{
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
        if (ctx.variants[k]->name == kBaselineVariant)
            return k;
    return 0;
}

void setTimingRatios(CampaignState& state, std::size_t baseline)
{
    for (auto& f : state.families)
        for (auto& s : f.stats)
            if (s.nsPerQuery > 0 && f.stats[baseline].nsPerQuery > 0)
                s.ratioToBaseline = s.nsPerQuery / f.stats[baseline].nsPerQuery;
}

// --- Judgement ---------------------------------------------------------------------------------

// A family passes when its make-up checks hold and no judged variant broke its contract on a case
// (for gjk2d's own contract: failed a case; a plugin judged with --judge: its own contract's
// violations); comparison variants are reported, never failed.
struct Verdict
{
    bool makeupOk = true, variantsOk = true;
    bool pass() const { return makeupOk && variantsOk; }
};

Verdict judgeFamily(const std::vector<MakeupResult>& makeup, const std::vector<Stats>& stats,
                    const EvalContext& ctx)
{
    Verdict v;
    for (const auto& m : makeup)
        v.makeupOk = v.makeupOk && m.ok;
    for (std::size_t k = 0; k < stats.size(); ++k)
        if (ctx.variants[k]->judged)
            v.variantsOk = v.variantsOk && stats[k].contractViolations == 0;
    return v;
}

// Any failing family fails the campaign (1); else any rejected case makes it an input error (2).
int campaignExitCode(bool anyFamilyFailed, std::size_t rejected)
{
    return anyFamilyFailed ? kExitFail : (rejected > 0 ? kExitInput : kExitPass);
}

// --- The report --------------------------------------------------------------------------------

Json makeupJson(const std::vector<MakeupResult>& m)
{
    Json a = Json::array();
    for (const auto& r : m)
    {
        Json j;
        j["check"] = r.check;
        j["value"] = num(r.value);
        j["min"] = num(r.min);
        j["max"] = num(r.max);
        j["ok"] = r.ok;
        if (r.skipped)
            j["skipped"] = r.note;
        else if (!r.note.empty())
            j["scaled"] = r.note; // min and max are the range judged at this count
        a.push_back(std::move(j));
    }
    return a;
}

Json familyJson(const FamilyResult& f, const std::vector<MakeupResult>& makeup,
                const Verdict& verdict, const EvalContext& ctx)
{
    const CampaignInput& in = *f.input;
    Json j;
    j["name"] = in.name;
    j["source"] = in.source;
    j["reason"] = in.reason;
    if (in.source == "generated")
        j["seed"] = in.seed;
    j["cases"] = f.cases;
    j["rejected"] = f.rejected;
    j["makeup"] = makeupJson(makeup);
    j["makeup_ok"] = verdict.makeupOk;
    j["pass"] = verdict.pass();
    Json vs = Json::object();
    for (std::size_t k = 0; k < f.stats.size(); ++k)
        vs[ctx.variants[k]->name] = f.stats[k].toJson();
    j["variants"] = std::move(vs);
    return j;
}

// Variant k's worst contract violation over the families, {"case", "family", "reason", "excess"}
// (the largest measured excess, a break without a size only where none is measured: statistics'
// WorstViolation order; ties to the earlier family), or null: the case `gjk-validate repro` and
// `explain` take.
Json worstViolationJson(const CampaignState& state, std::size_t k)
{
    const FamilyResult* worstFamily = nullptr;
    for (const auto& f : state.families)
    {
        const WorstViolation& w = f.stats[k].worstViolation;
        if (worstFamily == nullptr ? w.any : w.outranks(worstFamily->stats[k].worstViolation))
            worstFamily = &f;
    }
    if (worstFamily == nullptr)
        return nullptr;
    Json j = worstFamily->stats[k].worstViolation.toJson();
    j["family"] = worstFamily->input->name;
    return j;
}

// report.json's variants[].input: what the variant was given of each case, in its contract's words
// ({"form", "source"}), with "given" (givenInput's words) and "cases": how many of the campaign's
// cases it ran on (Stats::cases, every family), each given in that form.
Json inputJson(const CampaignState& state, std::size_t k, const VariantInfo& v)
{
    std::uint64_t cases = 0;
    for (const auto& f : state.families)
        cases += f.stats[k].cases;
    const Contract& c = contractOf(v);
    return Json{{"form", inputFormName(c.input)},
                {"source", c.inputSource},
                {"given", givenInput(v)},
                {"cases", cases}};
}

Json variantsJson(const CampaignState& state, const EvalContext& ctx)
{
    Json out = Json::array();
    for (std::size_t k = 0; k < ctx.variants.size(); ++k)
    {
        const VariantInfo* v = ctx.variants[k];
        Json j;
        j["name"] = v->name;
        j["type"] = scalarName(v->scalar);
        j["description"] = v->description;
        j["judged"] = v->judged;
        j["warm"] = v->start == Start::Warm;
        j["batch"] = v->batch;
        j["options"] = optionsJson(v->options);
        if (v->plugin) // the options name the bound it is compared with; the answer is the plugin's
        {
            j["plugin"] = {
                {"path", v->plugin->path},
                {"accepts_radius", (v->plugin->impl.accepts & GJK2D_ACCEPTS_RADIUS) != 0},
                {"accepts_warm_start", (v->plugin->impl.accepts & GJK2D_ACCEPTS_WARM_START) != 0},
                {"max_vertices", v->plugin->impl.max_vertices}};
        }
        j["bound"] = {{"formula", boundFormula(*v)}, {"unit_roundoff", unitRoundoff(v->scalar)}};
        j["witness_bound"] = {{"formula", witnessBoundFormula(*v)}};
        if (contractOf(*v).overlap == Overlap::Penetration) // its depth is judged
            j["depth_bound"] = {{"formula", depthBoundFormula(*v)}};
        j["contract"] = contractJson(*v);
        j["input"] = inputJson(state, k, *v);
        j["timing"] = timingJson(*v);
        j["worst_contract_violation"] = worstViolationJson(state, k);
        out.push_back(std::move(j));
    }
    return out;
}

// worst-cases.json (every family's kept cases, names made unique) and the report's "worst" (each
// family's worst case in detail).
Json worstCases(const CampaignState& state, const CampaignConfig& config, const EvalContext& ctx,
                const std::string& date, const std::string& revision, Campaign& camp)
{
    Json detail = Json::array();
    std::set<std::string> names;
    camp.worstComments.push_back(
        fmt::format("Worst cases of `{}` ({}), git {}, seed {}: per family the {} "
                    "cases with the largest normalised error over the variants.",
                    config.command, date, revision, config.seed, config.worstPerFamily));
    for (const auto& f : state.families)
        for (const auto& w : f.worst.cases())
        {
            Case c = w.c;
            for (int k = 2; !names.insert(c.name).second; ++k)
                c.name = fmt::format("{}#{}", w.c.name, k);
            const std::size_t wk = w.outcome.worstVariant();
            camp.worstComments.push_back(
                fmt::format("{}: family {}, normalised error {:.3g} ({}), exact distance {:.17g}",
                            c.name, f.input->name, worstKey(w.outcome.variants[wk]),
                            ctx.variants[wk]->name, w.outcome.exact.distance));
            if (&w == &f.worst.cases().front())
                detail.push_back(caseDetail(w.c, f.input->name, ctx, w.outcome, "normalized"));
            camp.worstCases.push_back(std::move(c));
        }
    return detail;
}

Json contextOf(const CampaignState& state, const CampaignConfig& config, int threads,
               const std::string& date, const std::string& revision, double totalSeconds)
{
    Json inputs = Json::array();
    std::size_t cases = 0, rejected = 0;
    double queries = 0, queryNs = 0;
    for (const auto& f : state.families)
    {
        inputs.push_back(f.input->input);
        cases += f.cases;
        rejected += f.rejected;
        for (const auto& s : f.stats)
            if (s.nsPerQuery > 0)
            {
                queries += double(s.cases);
                queryNs += s.nsPerQuery * double(s.cases);
            }
    }
    const PhaseSeconds& t = state.seconds;
    const double valid = double(cases - rejected);
    const auto perSecond = [&](double s) { return s > 0 ? valid / s : 0.0; };
    Json context = contextJson(date, revision, config.command, config.seed, threads,
                               std::move(inputs), cases, rejected);
    context["exact_route"] = exact::routeName(config.route);
    context["truth"] = config.truthFilter ? "filtered" : "exact";
    context["plugins"] = pluginsJson(config.variants);
    context["elapsed_s"] = {{"setup", t.setup},   {"generate", t.inputs}, {"exact", t.exact},
                            {"gjk", t.gjk},       {"witness", t.witness}, {"fold", t.fold},
                            {"timing", t.timing}, {"report", t.report},   {"total", totalSeconds}};
    context["throughput"] = {
        {"exact_cases_per_s", perSecond(t.exact)},
        {"gjk_cases_per_s", perSecond(t.gjk)},
        {"witness_cases_per_s", perSecond(t.witness)},
        {"gjk_ns_per_query_mean", queries > 0 ? Json(queryNs / queries) : Json(nullptr)},
        {"note",
         "exact: truths (double input, plus float-rounded input when a float variant runs); "
         "gjk: every variant's query and its error metrics; witness: exact point-to-shape "
         "checks; all on `threads` threads. generate: making or reading the cases. ns per query: "
         "single-threaded timed passes over each family's first cases."}};
    return context;
}
} // namespace

// Judgement and the report, from the folded (or merged) state.
Campaign finishCampaign(CampaignState& state, const CampaignConfig& config, const EvalContext& ctx,
                        int threads, double seconds)
{
    const std::size_t baseline = baselineIndex(ctx);
    setTimingRatios(state, baseline);

    Campaign camp;
    Json families = Json::array();
    bool anyFailed = false;
    std::size_t rejected = 0;
    for (const auto& f : state.families)
    {
        const std::vector<MakeupResult> makeup = f.makeup.results();
        const Verdict verdict = judgeFamily(makeup, f.stats, ctx);
        anyFailed = anyFailed || !verdict.pass();
        rejected += f.rejected;
        families.push_back(familyJson(f, makeup, verdict, ctx));
    }
    camp.exitCode = campaignExitCode(anyFailed, rejected);

    const std::string date = isoDateUtc(), revision = gitRevision();
    Json worst = worstCases(state, config, ctx, date, revision, camp);
    Json rejectedList = Json::array();
    for (const auto& r : state.rejected)
        rejectedList.push_back(r.entry);
    Json report;
    report["schema"] = kReportSchema;
    report["context"] = contextOf(state, config, threads, date, revision, seconds);
    report["variants"] = variantsJson(state, ctx);
    report["baseline_variant"] = ctx.variants[baseline]->name;
    report["families"] = std::move(families);
    report["rejected"] = std::move(rejectedList);
    report["worst_cases_file"] = "worst-cases.json";
    report["worst"] = std::move(worst);
    report["exit_code"] = camp.exitCode;
    report["passed"] = camp.exitCode == kExitPass;
    if (seconds == kSinceCommandStart) // the report's lap: the phases and the total end together
    {
        Json& e = report["context"]["elapsed_s"];
        state.clock.lap(state.seconds.report);
        e["report"] = state.seconds.report;
        e["total"] = elapsed(commandStart(), state.clock.last);
    }
    camp.report = std::move(report);
    return camp;
}

Json stripVolatile(Json r)
{
    Json& c = r["context"];
    for (const char* k : {"date", "host", "threads", "elapsed_s", "throughput", "command"})
        c.erase(k);
    for (auto& f : r["families"])
        for (auto& [name, s] : f["variants"].items())
            for (const char* k : {"ns_per_query", "ns_spread", "ratio_to_baseline", "timing_passes",
                                  "prepare_ns_per_shape", "prepared_ns_per_query"})
                s.erase(k);
    return r;
}

} // namespace gjkval
