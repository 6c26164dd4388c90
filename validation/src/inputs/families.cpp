// The registry of the families: the groups' rows (inputs/families/*.cpp) gathered into the
// tables, family specs parsed, and families planned chunk by chunk.
#include "inputs/families.hpp"

#include "inputs/engine.hpp"
#include "inputs/families/rows.hpp"
#include "inputs/rng.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace gjkval
{
namespace
{
using families::EngineRow;
using families::FamilyRow;
using families::Gen;

// Every hard sub-family, group by group (inputs/families/rows.hpp gives the order).
const std::vector<FamilyRow>& hardTable()
{
    static const std::vector<FamilyRow> table = []
    {
        std::vector<FamilyRow> rows;
        for (auto group :
             {families::numericalFamilies, families::contactFamilies, families::degenerateFamilies,
              families::shapeFamilies, families::sweepFamilies, families::scaleFamilies,
              families::startAndPoseFamilies})
            for (auto& row : group())
                rows.push_back(std::move(row));
        return rows;
    }();
    return table;
}

const std::vector<EngineRow>& engineTable()
{
    static const std::vector<EngineRow> table = families::engineFamilies();
    return table;
}

std::uint64_t familySeed(std::uint64_t seed, const std::string& name)
{
    return mix64(seed ^ hashString(name));
}

// A case's name: "family/i" or "family/i-tag".
std::string caseName(const std::string& family, int i, const std::string& tag)
{
    return family + "/" + std::to_string(i) + (tag.empty() ? "" : "-" + tag);
}

// The positions of a sweep of `sweep` cases that a family of `count` < `sweep` cases takes:
// floor(sweep frac(j phi)), j = 0, 1, ... (the golden-ratio sequence, skipping positions already
// taken), in increasing order. Any count spreads over the whole sweep, and no regular period of a
// generator's parameters (i mod 4, i / 8 mod 2, ...) aliases with it, as a stride would.
std::vector<std::size_t> spreadPositions(std::size_t count, std::size_t sweep)
{
    const double phi = (std::sqrt(5.0) - 1) / 2;
    std::vector<bool> taken(sweep, false);
    std::vector<std::size_t> out;
    for (std::uint64_t j = 0; out.size() < count; ++j)
    {
        const std::size_t i =
            std::min(sweep - 1, std::size_t(double(sweep) * std::fmod(double(j) * phi, 1.0)));
        if (!taken[i])
        {
            taken[i] = true;
            out.push_back(i);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Case i of a family: its own Rng stream from the family seed and i, so that any range of cases
// can be made alone (the campaign streams them in chunks) and comes out the same. A hard
// sub-family (sweep > 0: its built-in count) of fewer cases than its sweep takes spread positions
// of it, each the built-in case of that number (same stream, same name); of more cases, case i is
// case i, sweep position i mod sweep. The make-up ranges hold at `measuredAt` cases
// (statistics/makeup.hpp).
FamilyPlan plan(const std::string& name, const std::string& reason, int count, std::uint64_t seed,
                const Gen& gen, std::vector<MakeupSpec> makeup, std::size_t sweep,
                std::size_t measuredAt)
{
    FamilyPlan f;
    f.name = name;
    f.reason = reason;
    f.seed = familySeed(seed, name);
    f.count = std::size_t(count);
    for (auto& m : makeup)
    {
        m.measuredAt = measuredAt;
        m.sweep = sweep > 0;
    }
    f.makeup = std::move(makeup);
    auto positions = std::make_shared<const std::vector<std::size_t>>(
        sweep > f.count ? spreadPositions(f.count, sweep) : std::vector<std::size_t>());
    f.cases = [name, gen, positions, familySeed = f.seed](std::size_t begin, std::size_t end)
    {
        std::vector<Case> cases(end - begin);
        for (std::size_t k = begin; k < end; ++k)
        {
            const std::size_t i = positions->empty() ? k : (*positions)[k];
            Rng r(mix64(familySeed + std::uint64_t(i)));
            r.family = familySeed;
            std::string tag;
            Case& c = cases[k - begin];
            gen(r, int(i), c, tag);
            c.name = caseName(name, int(i), tag);
        }
        return cases;
    };
    return f;
}

// The engine families' cases come from one simulation each, not one Rng stream per case: the
// family seed builds the scene and seeds the sampling of `count` queries from the run
// (engine.hpp), so a smaller count is not a prefix of a larger one.
// The simulation runs here, whole: an engine family's cases are held in memory (2000 by default).
FamilyPlan planEngine(const families::EngineRow& e, int count, std::uint64_t seed)
{
    FamilyPlan f;
    f.name = "engine/" + e.info.name;
    f.reason = e.info.reason;
    f.seed = familySeed(seed, f.name);
    f.makeup = e.makeup;
    for (auto& m : f.makeup)
        m.measuredAt = kMinEngineCasesForMakeup; // independent draws, not a sweep
    auto queries = engineQueries(e.scene, e.kind, f.seed, count);
    auto cases = std::make_shared<std::vector<Case>>();
    cases->reserve(queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i)
    {
        cases->push_back(std::move(queries[i].c));
        cases->back().name = caseName(f.name, int(i), queries[i].tag);
    }
    f.count = cases->size();
    f.cases = [cases](std::size_t begin, std::size_t end)
    {
        return std::vector<Case>(cases->begin() + std::ptrdiff_t(begin),
                                 cases->begin() + std::ptrdiff_t(end));
    };
    return f;
}

} // namespace

const std::vector<HardSubFamilyInfo>& hardSubFamilies()
{
    static const std::vector<HardSubFamilyInfo> infos = []
    {
        std::vector<HardSubFamilyInfo> v;
        for (const auto& e : hardTable())
            v.push_back(e.info);
        return v;
    }();
    return infos;
}

const std::vector<HardSubFamilyInfo>& engineSubFamilies()
{
    static const std::vector<HardSubFamilyInfo> infos = []
    {
        std::vector<HardSubFamilyInfo> v;
        for (const auto& e : engineTable())
            v.push_back(e.info);
        return v;
    }();
    return infos;
}

FamilySpec parseFamilySpec(const std::string& spec)
{
    FamilySpec out;
    out.name = spec;
    const auto colon = spec.find(':');
    if (colon != std::string::npos)
    {
        out.name = spec.substr(0, colon);
        const std::string n = spec.substr(colon + 1);
        // Decimal digits only ("+5", "-1", " 5", "5x", "1e3" are refused), 1 .. kMaxFamilyCount.
        long long v = 0;
        bool ok = !n.empty() && n.size() <= 10;
        for (char c : n)
            ok = ok && c >= '0' && c <= '9';
        if (ok)
            v = std::stoll(n);
        if (!ok || v < 1 || v > kMaxFamilyCount)
            throw InputError(fmt::format("--family {}: the count '{}' is not a whole number in "
                                         "1..{}",
                                         excerpt(spec), excerpt(n), kMaxFamilyCount));
        out.count = int(v);
    }
    bool known = out.name == "random" || out.name == "hard" || out.name == "engine";
    for (const auto& e : hardTable())
        known = known || out.name == "hard/" + e.info.name;
    for (const auto& e : engineTable())
        known = known || out.name == "engine/" + e.info.name;
    if (!known)
    {
        std::string names = "random, hard";
        for (const auto& e : hardTable())
            names += ", hard/" + e.info.name;
        names += ", engine";
        for (const auto& e : engineTable())
            names += ", engine/" + e.info.name;
        throw InputError(fmt::format("unknown family '{}' (known: {})", excerpt(out.name), names));
    }
    return out;
}

std::vector<std::pair<std::string, std::size_t>> familyCaseCounts(const FamilySpec& spec)
{
    if (spec.name == "random")
        return {{"random", std::size_t(spec.count < 0 ? kDefaultRandomCount : spec.count)}};
    std::vector<std::pair<std::string, std::size_t>> out;
    for (const auto& e : hardTable())
        if (spec.name == "hard" || spec.name == "hard/" + e.info.name)
            out.emplace_back("hard/" + e.info.name,
                             std::size_t(spec.count < 0 ? e.info.count : spec.count));
    for (const auto& e : engineTable())
        if (spec.name == "engine" || spec.name == "engine/" + e.info.name)
            out.emplace_back("engine/" + e.info.name,
                             std::size_t(spec.count < 0 ? e.info.count : spec.count));
    return out;
}

std::vector<FamilyPlan> planFamilies(const std::string& spec, std::uint64_t seed)
{
    const FamilySpec parsed = parseFamilySpec(spec);
    const std::string& name = parsed.name;
    const int count = parsed.count;
    std::vector<FamilyPlan> out;
    if (name == "random")
    {
        const FamilyRow row = families::randomFamily();
        out.push_back(plan(row.info.name, row.info.reason, count < 0 ? row.info.count : count, seed,
                           row.gen, row.makeup, 0, kMinCasesForStatistics));
        return out;
    }
    const bool all = name == "hard";
    for (const auto& e : hardTable())
    {
        const std::string full = "hard/" + e.info.name;
        if (all || name == full)
            out.push_back(plan(full, e.info.reason, count < 0 ? e.info.count : count, seed, e.gen,
                               e.makeup, std::size_t(e.info.count), std::size_t(e.info.count)));
    }
    for (const auto& e : engineTable())
        if (name == "engine" || name == "engine/" + e.info.name)
            out.push_back(planEngine(e, count < 0 ? e.info.count : count, seed));
    if (out.empty()) // parseFamilySpec accepted the name: a broken invariant, not bad input
        throw std::logic_error("planFamilies: the family '" + name + "' generated nothing");
    return out;
}

std::vector<GeneratedFamily> generateFamilies(const std::string& spec, std::uint64_t seed)
{
    std::vector<GeneratedFamily> out;
    for (auto& p : planFamilies(spec, seed))
        out.push_back({p.name, p.reason, p.seed, p.cases(0, p.count), std::move(p.makeup)});
    return out;
}

} // namespace gjkval
