// How `explain` and `repro` name one case and find it (commands/case_choice.hpp).
#include "commands/case_choice.hpp"

#include "commands/command_line.hpp"
#include "common/output.hpp"
#include "inputs/families.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace gjkval
{
namespace
{
namespace fs = std::filesystem;

// "3 case(s): 'a', 'b', 'c'": at most kNamesListed names, then "and N more".
std::string someNames(const std::vector<std::string>& names)
{
    constexpr std::size_t kNamesListed = 8;
    std::string s = fmt::format("{} case(s)", names.size());
    for (std::size_t i = 0; i < std::min(names.size(), kNamesListed); ++i)
        s += fmt::format("{}'{}'", i == 0 ? ": " : ", ", excerpt(names[i]));
    if (names.size() > kNamesListed)
        s += fmt::format(" and {} more", names.size() - kNamesListed);
    return s;
}

FoundCase findInFamily(const CaseChoice& o, std::uint64_t seed, std::vector<std::string>& names)
{
    FoundCase found;
    for (auto& f : generateFamilies(o.family, seed))
        for (auto& c : f.cases)
        {
            names.push_back(c.name);
            if (!found.ok && c.name == o.name)
                found = {c, f.name, {}, true};
        }
    return found;
}

FoundCase findInFile(const CaseChoice& o, const std::string& file, std::vector<std::string>& names)
{
    FoundCase found;
    CaseFile cases = readCaseFile(file);
    found.family = "file:" + fs::path(file).filename().string();
    for (auto& e : cases.entries)
    {
        names.push_back(e.c.name);
        if (!found.ok && e.c.name == o.name)
        {
            found.c = e.c;
            found.rejected = e.rejected;
            found.ok = true;
        }
    }
    return found;
}
} // namespace

void addCaseChoiceOptions(CLI::App& sub, CaseChoice& c)
{
    sub.add_option("args", c.positional,
                   "FILE NAME (the gjk-cases/1 file and the case's name), or NAME alone with "
                   "--family; NAME may be given as --name instead");
    sub.add_option("--name,-n", c.name, "the case's name");
    sub.add_option("--family", c.family,
                   "take the case from this generated family instead of a file");
    sub.add_option("--seed", c.seed, "seed for --family, 0..2^64-1")->capture_default_str();
}

std::string caseFileArgument(CaseChoice& o, const char* command)
{
    std::string file;
    const std::size_t wanted = (o.family.empty() ? 1 : 0) + (o.name.empty() ? 1 : 0);
    if (o.positional.size() > wanted)
        throw InputError(fmt::format("{}: unexpected argument '{}' (give FILE NAME, or "
                                     "--family F NAME)",
                                     command, excerpt(o.positional[wanted])));
    std::size_t next = 0;
    if (o.family.empty() && next < o.positional.size())
        file = o.positional[next++];
    if (o.name.empty() && next < o.positional.size())
        o.name = o.positional[next++];
    if (o.family.empty() && file.empty())
        throw InputError(fmt::format("{}: give a case FILE or --family", command));
    if (o.name.empty())
        throw InputError(
            fmt::format("{}: which case? give its name ({} FILE NAME)", command, command));
    return file;
}

void checkCaseSource(const CaseChoice& c, const std::string& file)
{
    if (!c.family.empty())
        checkFamilies({c.family}, false);
    else
        checkCaseFiles({file});
}

FoundCase findCase(const CaseChoice& o, const std::string& file, std::uint64_t seed,
                   const char* command)
{
    std::vector<std::string> names; // every name looked at, for the error when none matches
    FoundCase found = o.family.empty() ? findInFile(o, file, names) : findInFamily(o, seed, names);
    if (!found.ok)
        throw InputError(fmt::format(
            "{}: no case named '{}' in {}; it has {}", command, excerpt(o.name),
            o.family.empty() ? shownPath(file) : "--family " + o.family, someNames(names)));
    if (!found.rejected.empty())
        throw InputError(
            fmt::format("{}: case '{}' is rejected: {}", command, excerpt(o.name), found.rejected));
    return found;
}

} // namespace gjkval
