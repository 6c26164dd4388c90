// How `explain` and `repro` name one case: FILE NAME, or --family F --seed S NAME (NAME may be
// given as --name), and the case found (InputError, exit 2, when there is none of that name or
// the case file rejects it). One home for both commands, so that a case `explain` shows is the
// case `repro` writes.
#pragma once

#include "inputs/cases.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gjkval
{

struct CaseChoice
{
    std::vector<std::string> positional;
    std::string name, family, seed = "1";
};
// Registers the positional FILE NAME and --name, --family, --seed on `sub`.
void addCaseChoiceOptions(CLI::App& sub, CaseChoice& c);

// `CMD FILE NAME`, `CMD FILE --name NAME`, `CMD --family F NAME`, `CMD --family F --name NAME`:
// anything more is refused (InputError naming `command`). Returns FILE (empty with --family) and
// sets c.name.
std::string caseFileArgument(CaseChoice& c, const char* command);
// The family spec or the case file, checked before any work (InputError).
void checkCaseSource(const CaseChoice& c, const std::string& file);

// The case named c.name, from --family (generated with `seed`) or the case file.
struct FoundCase
{
    Case c;
    std::string family, rejected; // rejected: the case file's reason, if it holds one
    bool ok = false;
};
// InputError when no case has the name (listing some that do exist) or the case is rejected.
FoundCase findCase(const CaseChoice& c, const std::string& file, std::uint64_t seed,
                   const char* command);

} // namespace gjkval
