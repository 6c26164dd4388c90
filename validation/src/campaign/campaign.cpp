#include "campaign/campaign.hpp"

#include "build_info.hpp"
#include "common/output.hpp"
#include "common/parallel.hpp"
#include "report/report.hpp"
#include "timing/timing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <unistd.h>

#if defined(GJK2D_HAVE_HTML)
#include "gjk_html/html.hpp"
#endif

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

std::string runCommand(const std::string& cmd)
{
    std::string out;
    if (FILE* p = popen(cmd.c_str(), "r"))
    {
        char buf[256];
        while (std::fgets(buf, sizeof buf, p))
            out += buf;
        if (pclose(p) != 0)
            return {};
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r'))
        out.pop_back();
    return out;
}

std::string gitRevisionImpl()
{
    const std::string dir = GJK2D_SOURCE_DIR;
    const std::string rev =
        runCommand("git -C '" + dir + "' rev-parse --short=12 HEAD 2>/dev/null");
    if (rev.empty())
        return "unknown";
    const std::string dirty =
        runCommand("git -C '" + dir + "' status --porcelain --untracked-files=no 2>/dev/null");
    return dirty.empty() ? rev : rev + " (dirty)";
}

std::string isoDateUtcImpl()
{
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

std::string hostName()
{
    char buf[256] = {};
    if (gethostname(buf, sizeof buf - 1) != 0)
        return "unknown";
    return buf;
}

void accumulate(Stats& s, const VariantOutcome& v, const std::string& name, const VariantInfo& vi,
                const CaseOutcome& o)
{
    if (v.skipped)
    {
        ++s.skipped;
        s.notApplicable += v.notApplicable ? 1 : 0;
        return;
    }
    ++s.cases;
    s.failures += v.failed ? 1 : 0;
    s.outOfRange += v.outOfRange ? 1 : 0;
    s.nonfinite += v.nonfinite ? 1 : 0;
    s.iterationLimit += v.iterationLimit ? 1 : 0;
    if (!v.outOfRange) // cases GJK flags out of range are counted apart, not judged
    {
        s.falseOverlap += v.mis == Misclass::FalseOverlap ? 1 : 0;
        s.falseSeparation += v.mis == Misclass::FalseSeparation ? 1 : 0;
        s.undecidable += v.mis == Misclass::Undecidable ? 1 : 0;
        s.beyondBound += v.beyondBound ? 1 : 0;
        if (!v.nonfinite)
        {
            s.abs.add(v.abs, name);
            s.rel.add(v.rel, name); // NaN (not applicable) is ignored by add()
            s.ulps.add(v.ulps, name);
            s.normalized.add(v.normalized, name);
            s.boundRatio.add(v.boundRatio, name);
            s.witness.add(v.witness, name);
            s.witnessGap.add(v.witnessGap, name);
        }
    }
    if (vi.scalar == Scalar::Float)
    {
        s.hasInputRounding = true;
        s.inputRounding.add(o.inputRounding, name);
    }
    if (vi.options.certify)
    {
        s.hasInterval = true;
        if (v.certified)
        {
            ++s.certified;
            s.contains += v.intervalContains ? 1 : 0;
            if (v.truth > 0)
                s.widthUlps.add((v.upper - v.lower) / ulpOf(vi.scalar, v.truth), name);
        }
        else
            ++s.uncertified;
    }
    s.iterations.add(v.iterations);
    ++s.stops[std::size_t(v.stop)];
}

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
            j["skipped"] =
                fmt::format("fewer than {} cases: reported, not judged", kMinCasesForStatistics);
        a.push_back(std::move(j));
    }
    return a;
}

} // namespace

std::string gitRevision()
{
    return gitRevisionImpl();
}
std::string isoDateUtc()
{
    return isoDateUtcImpl();
}

Json contextJson(const std::string& date, const std::string& revision, const std::string& command,
                 std::uint64_t seed, int threads, Json inputs, std::size_t casesTotal,
                 std::size_t casesRejected)
{
    Json context;
    context["date"] = date;
    context["host"] = hostName();
    context["compiler"] = GJK2D_BUILD_COMPILER;
    context["flags"] = GJK2D_BUILD_FLAGS;
    context["build_type"] = GJK2D_BUILD_TYPE;
#if defined(GJK2D_CHECKED)
    context["gjk_checked"] = true;
#else
    context["gjk_checked"] = false;
#endif
    context["git_revision"] = revision;
    context["command"] = command;
    context["seed"] = seed;
    context["threads"] = threads;
    context["inputs"] = std::move(inputs);
    context["cases_total"] = casesTotal;
    context["cases_rejected"] = casesRejected;
    return context;
}

std::vector<std::string> defaultFamilies()
{
    return {"random:" + std::to_string(kDefaultRandomCount), "hard", "engine"};
}

std::vector<std::string> defaultCaseFiles()
{
    std::vector<std::string> files;
    const fs::path dir = fs::path(GJK2D_SOURCE_DIR) / "validation" / "cases";
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file() && e.path().extension() == ".json")
            files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<FamilyData> loadInputs(const CampaignConfig& config)
{
    std::vector<FamilyData> out;
    std::set<std::string> names;
    for (const auto& spec : config.families)
    {
        for (auto& g : generateFamilies(spec, config.seed))
        {
            if (!names.insert(g.name).second)
                throw InputError(fmt::format("family '{}' is given twice", g.name));
            FamilyData f;
            f.name = g.name;
            f.reason = g.reason;
            f.source = "generated";
            f.seed = g.seed;
            f.input = {{"family", g.name}, {"count", g.cases.size()}, {"seed", config.seed}};
            f.labels.reserve(g.cases.size());
            for (const auto& c : g.cases)
                f.labels.push_back(c.name);
            f.rejected.assign(g.cases.size(), {});
            f.cases = std::move(g.cases);
            f.makeup = std::move(g.makeup);
            out.push_back(std::move(f));
        }
    }
    for (const auto& path : config.caseFiles)
    {
        CaseFile file = readCaseFile(path);
        FamilyData f;
        const std::string base = fs::path(path).filename().string();
        f.name = "file:" + base;
        if (!names.insert(f.name).second)
        {
            f.name = "file:" + path;
            if (!names.insert(f.name).second)
                throw InputError(fmt::format("case file '{}' is given twice", path));
        }
        f.source = "file";
        f.reason =
            file.comments.empty() ? std::string("cases from ") + path : file.comments.front();
        f.input = {{"file", path}, {"count", file.entries.size()}};
        for (auto& e : file.entries)
        {
            f.cases.push_back(std::move(e.c));
            f.labels.push_back(e.label);
            f.rejected.push_back(e.rejected);
        }
        out.push_back(std::move(f));
    }
    return out;
}

Campaign runCampaign(const CampaignConfig& config, std::vector<FamilyData> families)
{
    const auto tStart = Clock::now();
    const int threads = resolveThreads(config.threads);
    EvalContext ctx;
    ctx.variants = config.variants;
    ctx.exactOptions.route = config.route;

    // Flat work list in campaign order.
    struct Item
    {
        std::size_t f, i;
    };
    std::vector<Item> items;
    std::vector<std::vector<CaseOutcome>> outcomes(families.size());
    std::vector<std::vector<PreparedCase>> prepared(families.size());
    for (std::size_t f = 0; f < families.size(); ++f)
    {
        outcomes[f].resize(families[f].cases.size());
        prepared[f].resize(families[f].cases.size());
        for (std::size_t i = 0; i < families[f].cases.size(); ++i)
        {
            items.push_back({f, i});
            if (!families[f].rejected[i].empty())
                outcomes[f][i].rejected = families[f].rejected[i];
        }
    }
    const auto tGenerated = Clock::now();

    // Phase 1: exact truths. Phase 2: GJK. Phase 3: witness points (exact).
    {
        Progress p(config.progress, "exact", items.size());
        parallelFor(items.size(), threads, p,
                    [&](std::size_t k)
                    {
                        const Item it = items[k];
                        CaseOutcome& o = outcomes[it.f][it.i];
                        if (o.rejected.empty())
                            computeTruth(families[it.f].cases[it.i], ctx, o);
                    });
    }
    const auto tExact = Clock::now();
    {
        Progress p(config.progress, "gjk", items.size());
        parallelFor(items.size(), threads, p,
                    [&](std::size_t k)
                    {
                        const Item it = items[k];
                        const Case& c = families[it.f].cases[it.i];
                        CaseOutcome& o = outcomes[it.f][it.i];
                        if (!o.rejected.empty())
                        {
                            o.variants.assign(ctx.variants.size(), {});
                            return;
                        }
                        prepared[it.f][it.i] = prepare(c);
                        runVariants(c, prepared[it.f][it.i], ctx, o);
                    });
    }
    const auto tGjk = Clock::now();
    {
        Progress p(config.progress, "witness", items.size());
        parallelFor(items.size(), threads, p,
                    [&](std::size_t k)
                    {
                        const Item it = items[k];
                        checkWitnesses(families[it.f].cases[it.i], ctx, outcomes[it.f][it.i]);
                    });
    }
    const auto tWitness = Clock::now();

    // Statistics, in case order (single thread: identical whatever the thread count).
    const std::size_t nv = ctx.variants.size();
    std::vector<std::vector<Stats>> stats(families.size(), std::vector<Stats>(nv));
    std::vector<std::vector<MakeupResult>> makeups(families.size());
    Json rejectedJson = Json::array();
    std::size_t totalCases = 0, totalRejected = 0;
    bool anyFailure = false;
    for (std::size_t f = 0; f < families.size(); ++f)
    {
        const FamilyData& fam = families[f];
        std::vector<const Case*> valid;
        std::vector<const exact::Result*> truths;
        for (std::size_t i = 0; i < fam.cases.size(); ++i)
        {
            ++totalCases;
            const CaseOutcome& o = outcomes[f][i];
            if (!o.rejected.empty())
            {
                ++totalRejected;
                rejectedJson.push_back(
                    {{"name", fam.labels[i]}, {"family", fam.name}, {"reason", o.rejected}});
                continue;
            }
            valid.push_back(&fam.cases[i]);
            truths.push_back(&o.exact);
            for (std::size_t k = 0; k < nv; ++k)
                accumulate(stats[f][k], o.variants[k], fam.cases[i].name, *ctx.variants[k], o);
        }
        makeups[f] = evaluateMakeup(fam.makeup, valid, truths);
    }

    // Timing: single-threaded, apart from everything else.
    if (config.timing)
    {
        TimingConfig tc;
        tc.minPasses = config.minPasses;
        tc.maxPasses = config.maxPasses;
        tc.budgetSeconds = config.timingBudgetSeconds;
        Progress p(config.progress, "timing", families.size() * nv);
        for (std::size_t f = 0; f < families.size(); ++f)
        {
            for (std::size_t k = 0; k < nv; ++k)
            {
                std::vector<const PreparedCase*> cases;
                for (std::size_t i = 0; i < families[f].cases.size(); ++i)
                {
                    const CaseOutcome& o = outcomes[f][i];
                    if (o.rejected.empty() && !o.variants[k].skipped)
                        cases.push_back(&prepared[f][i]);
                }
                const TimingResult t = timeQueries(cases, *ctx.variants[k], tc);
                Stats& s = stats[f][k];
                s.nsPerQuery = t.nsPerQuery;
                s.nsMin = t.nsMin;
                s.nsMax = t.nsMax;
                s.timingPasses = t.passes;
                p.add(1);
            }
        }
    }
    const auto tTiming = Clock::now();

    // Baseline for ratios: "double" when selected, else the first variant.
    std::size_t baseline = 0;
    for (std::size_t k = 0; k < nv; ++k)
        if (ctx.variants[k]->name == "double")
            baseline = k;
    for (auto& fs : stats)
        for (auto& s : fs)
            if (s.nsPerQuery > 0 && fs[baseline].nsPerQuery > 0)
                s.ratioToBaseline = s.nsPerQuery / fs[baseline].nsPerQuery;

    // Worst cases of each family.
    Campaign camp;
    Json worst = Json::array();
    std::set<std::string> worstNames;
    const std::string date = isoDateUtc();
    const std::string revision = gitRevision();
    camp.worstComments.push_back(
        fmt::format("Worst cases of `{}` ({}), git {}, seed {}: per family the {} "
                    "cases with the largest normalised error over the variants.",
                    config.command, date, revision, config.seed, config.worstPerFamily));
    for (std::size_t f = 0; f < families.size(); ++f)
    {
        const FamilyData& fam = families[f];
        std::vector<std::size_t> order;
        for (std::size_t i = 0; i < fam.cases.size(); ++i)
            if (outcomes[f][i].rejected.empty())
                order.push_back(i);
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t x, std::size_t y)
                         { return outcomes[f][x].worstKey() > outcomes[f][y].worstKey(); });
        if (order.size() > std::size_t(std::max(0, config.worstPerFamily)))
            order.resize(std::size_t(std::max(0, config.worstPerFamily)));
        for (std::size_t r = 0; r < order.size(); ++r)
        {
            const std::size_t i = order[r];
            const CaseOutcome& o = outcomes[f][i];
            Case c = fam.cases[i];
            std::string name = c.name;
            for (int k = 2; !worstNames.insert(name).second; ++k)
                name = fmt::format("{}#{}", c.name, k);
            c.name = name;
            // Which variant is worst, for the comment.
            std::size_t wk = 0;
            double wv = -1;
            for (std::size_t k = 0; k < nv; ++k)
            {
                const auto& v = o.variants[k];
                const double key =
                    v.skipped || (v.outOfRange && !v.failed)
                        ? -1
                        : ((v.nonfinite || v.iterationLimit) ? INFINITY : v.normalized);
                if (key > wv)
                {
                    wv = key;
                    wk = k;
                }
            }
            camp.worstComments.push_back(
                fmt::format("{}: family {}, normalised error {:.3g} ({}), exact distance {:.17g}",
                            c.name, fam.name, wv, ctx.variants[wk]->name, o.exact.distance));
            camp.worstCases.push_back(std::move(c));
            if (r == 0)
                worst.push_back(caseDetail(fam.cases[i], fam.name, ctx, o, "normalized"));
        }
    }

    // Per-case lines.
    if (config.perCase)
        for (std::size_t f = 0; f < families.size(); ++f)
            for (std::size_t i = 0; i < families[f].cases.size(); ++i)
                camp.perCaseLines.push_back(
                    perCaseJson(families[f].cases[i], families[f].name, ctx, outcomes[f][i])
                        .dump());

    // Families.
    Json famJson = Json::array();
    for (std::size_t f = 0; f < families.size(); ++f)
    {
        const FamilyData& fam = families[f];
        Json j;
        j["name"] = fam.name;
        j["source"] = fam.source;
        j["reason"] = fam.reason;
        if (fam.source == "generated")
            j["seed"] = fam.seed;
        std::size_t rej = 0;
        for (const auto& o : outcomes[f])
            rej += o.rejected.empty() ? 0 : 1;
        j["cases"] = fam.cases.size();
        j["rejected"] = rej;
        j["makeup"] = makeupJson(makeups[f]);
        bool makeupOk = true;
        for (const auto& m : makeups[f])
            makeupOk = makeupOk && m.ok;
        bool variantsOk = true;
        Json vs = Json::object();
        for (std::size_t k = 0; k < nv; ++k)
        {
            vs[ctx.variants[k]->name] = stats[f][k].toJson();
            // Comparison variants (not judged) are reported, never failed.
            if (ctx.variants[k]->judged)
                variantsOk = variantsOk && stats[f][k].failures == 0;
        }
        j["makeup_ok"] = makeupOk;
        j["pass"] = makeupOk && variantsOk;
        anyFailure = anyFailure || !makeupOk || !variantsOk;
        j["variants"] = std::move(vs);
        famJson.push_back(std::move(j));
    }

    // Variants.
    Json varJson = Json::array();
    for (auto* v : ctx.variants)
    {
        Json j;
        j["name"] = v->name;
        j["type"] = scalarName(v->scalar);
        j["description"] = v->description;
        j["judged"] = v->judged;
        j["warm"] = v->warm;
        j["options"] = optionsJson(v->options);
        j["bound"] = {{"formula", boundFormula(*v)}, {"unit_roundoff", unitRoundoff(v->scalar)}};
        varJson.push_back(std::move(j));
    }

    camp.exitCode = anyFailure ? kExitFail : (totalRejected > 0 ? kExitInput : kExitPass);

    const auto tEnd = Clock::now();
    Json inputs = Json::array();
    std::set<std::string> seenInputs;
    for (const auto& fam : families)
        inputs.push_back(fam.input);
    const double tExactS = seconds(tGenerated, tExact), tGjkS = seconds(tExact, tGjk),
                 tWitnessS = seconds(tGjk, tWitness);
    std::size_t validCases = totalCases - totalRejected;
    double queries = 0, queryNs = 0;
    for (std::size_t f = 0; f < families.size(); ++f)
        for (std::size_t k = 0; k < nv; ++k)
            if (stats[f][k].nsPerQuery > 0)
            {
                queries += double(stats[f][k].cases);
                queryNs += stats[f][k].nsPerQuery * double(stats[f][k].cases);
            }

    Json context = contextJson(date, revision, config.command, config.seed, threads,
                               std::move(inputs), totalCases, totalRejected);
    context["exact_route"] = exact::routeName(config.route);
    context["elapsed_s"] = {{"generate", seconds(tStart, tGenerated)},
                            {"exact", tExactS},
                            {"gjk", tGjkS},
                            {"witness", tWitnessS},
                            {"timing", seconds(tWitness, tTiming)},
                            {"total", seconds(tStart, tEnd)}};
    context["throughput"] = {
        {"exact_cases_per_s", tExactS > 0 ? double(validCases) / tExactS : 0.0},
        {"gjk_cases_per_s", tGjkS > 0 ? double(validCases) / tGjkS : 0.0},
        {"witness_cases_per_s", tWitnessS > 0 ? double(validCases) / tWitnessS : 0.0},
        {"gjk_ns_per_query_mean", queries > 0 ? Json(queryNs / queries) : Json(nullptr)},
        {"note",
         "exact: truths (double input, plus float-rounded input when a float variant runs); "
         "gjk: every variant's query and its error metrics; witness: exact point-to-shape "
         "checks; all on `threads` threads. ns per query: single-threaded timed passes."}};

    Json report;
    report["schema"] = "gjk-report/1";
    report["context"] = std::move(context);
    report["variants"] = std::move(varJson);
    report["baseline_variant"] = ctx.variants[baseline]->name;
    report["families"] = std::move(famJson);
    report["rejected"] = std::move(rejectedJson);
    report["worst_cases_file"] = "worst-cases.json";
    report["worst"] = std::move(worst);
    report["exit_code"] = camp.exitCode;
    report["passed"] = camp.exitCode == kExitPass;
    camp.report = std::move(report);
    return camp;
}

namespace
{
// Every file a report directory holds; writeCampaign replaces the directory as a whole.
const char* const kReportFiles[] = {"report.json", "report.md", "worst-cases.json", "cases.jsonl",
                                    "index.html"};
} // namespace

void checkReportDir(const std::string& outDir)
{
    if (outDir.empty())
        throw InputError("--out: the output directory is empty");
    const fs::path dir = reportDirPath(outDir);
    std::error_code ec;
    const auto st = fs::status(dir, ec);
    if (fs::exists(st))
    {
        if (!fs::is_directory(st))
            throw InputError(fmt::format("--out {}: exists and is not a directory", excerpt(outDir)));
        // The whole directory is replaced: refuse one that holds anything else than a report.
        for (const auto& e : fs::directory_iterator(dir, ec))
        {
            const std::string name = e.path().filename().string();
            if (std::find(std::begin(kReportFiles), std::end(kReportFiles), name) ==
                std::end(kReportFiles))
                throw InputError(fmt::format(
                    "--out {}: holds '{}', which is not part of a report (the directory is "
                    "replaced as a whole: give a new or a report directory)",
                    excerpt(outDir), excerpt(name)));
        }
        if (ec)
            throw InputError(
                fmt::format("--out {}: cannot read the directory: {}", excerpt(outDir), ec.message()));
    }
    // The parent must exist or be creatable, and be writable: the report is staged beside DIR.
    fs::path parent = dir.parent_path();
    while (!fs::exists(parent, ec) && parent.has_relative_path())
        parent = parent.parent_path();
    if (!fs::is_directory(parent, ec))
        throw InputError(fmt::format("--out {}: {} is not a directory", excerpt(outDir),
                                     excerpt(parent.string())));
    if (::access(parent.c_str(), W_OK | X_OK) != 0)
        throw InputError(fmt::format("--out {}: cannot write in {}: {}", excerpt(outDir),
                                     excerpt(parent.string()), std::strerror(errno)));
}

std::string writeCampaign(const Campaign& camp, const std::string& outDir)
{
    // Staged beside DIR and swapped in: DIR holds this run or the previous one, never a mix.
    StagedDir out(reportDirPath(outDir));
    out.write("report.json", camp.report.dump(1) + "\n"); // first: the rest is rendered from it
    out.write("report.md", renderMarkdown(camp.report));
    out.write("worst-cases.json", caseFileText(camp.worstComments, camp.worstCases));
    if (!camp.perCaseLines.empty())
    {
        std::string s;
        for (const auto& l : camp.perCaseLines)
            s += l + "\n";
        out.write("cases.jsonl", s);
    }
#if defined(GJK2D_HAVE_HTML)
    out.write("index.html", gjk_html::renderReport(nlohmann::json::parse(camp.report.dump())));
    const std::string page = "index.html";
#else
    const std::string page = "report.md";
#endif
    out.commit();
    return (out.dir() / page).string();
}

Json stripVolatile(Json r)
{
    Json& c = r["context"];
    for (const char* k : {"date", "host", "threads", "elapsed_s", "throughput", "command"})
        c.erase(k);
    for (auto& f : r["families"])
        for (auto& [name, s] : f["variants"].items())
            for (const char* k :
                 {"ns_per_query", "ns_spread", "ratio_to_baseline", "timing_passes"})
                s.erase(k);
    return r;
}

} // namespace gjkval
