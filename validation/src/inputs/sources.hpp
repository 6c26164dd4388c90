// The campaign's inputs as streams: each generated family and each case file yields its cases in
// case order, in chunks of bounded size, so that a campaign's memory does not grow with its number
// of cases (docs/judgement.md, "Statistics").
#pragma once

#include "common/common.hpp"
#include "inputs/cases.hpp"
#include "inputs/families.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gjkval
{

// Consecutive cases of one input.
struct CaseChunk
{
    std::size_t first = 0;             // the input's index of cases[0]
    std::vector<Case> cases;           // a rejected entry as far as it could be read
    std::vector<std::string> labels;   // how a rejected entry is named ("file.json#3 (case 'x')")
    std::vector<std::string> rejected; // per case: why the reader rejected it, or empty
    std::size_t size() const { return cases.size(); }
};

// One input: a generated family ("random", "hard/sliver") or a case file ("file:talk.json").
struct CampaignInput
{
    std::string name;
    std::string reason;
    std::string source; // "generated" or "file"
    Json input;         // its entry in the report's context.inputs
    std::uint64_t seed = 0;
    std::vector<MakeupSpec> makeup;
    std::size_t count = 0;
    // A case file's count, comments (the reason) and its entry in context.inputs are known once
    // it has been read to its end: up front (FileCheck::Whole), else when its stream ends, and
    // settleFileInput then sets them from `read`. Null for a generated family.
    std::shared_ptr<CaseFileSummary> read;
    bool counted = true; // false for a case file until its stream has ended
    // Calls consume(chunk) for every chunk of at most chunkCases cases, in case order. Chunk j
    // (cases j*chunkCases ..) may be left out, neither made nor passed on, when skip(j) is true
    // (a shard's, a resumed run's): generated families do so, case files pass every chunk. A
    // generated family makes each chunk's cases on up to `threads` threads (each case is made
    // from its index alone: the same cases on any number); a case file is read on one.
    using SkipChunk = std::function<bool(std::size_t chunk)>;
    std::function<void(std::size_t chunkCases, const std::function<void(CaseChunk&)>& consume,
                       const SkipChunk& skip, int threads)>
        stream;
};

// How much of a case file is read before the campaign starts:
// - Start: its beginning, up to its first entry. A file that does not open as a case file (not
//   JSON, not the binary form, its first entry not reached) is still refused before any work, and
//   so is a JSON file that does not end with its closing brace (a file cut short: it is then read
//   whole up front, for the message). A fault further in (JSON broken mid-file, a wrong "format"
//   after "cases") stops the campaign when the stream reaches it, with the same message and exit
//   code, and no report. Each file is read once.
// - Whole: the whole file, once up front and once more as it is streamed (merge, which streams
//   nothing, reads it for its count and comments).
enum class FileCheck
{
    Start,
    Whole
};

// The inputs of a campaign, in order: the families of each spec, then the case files, checked as
// `check` says. Throws InputError (a family or file given twice, a file refused).
std::vector<CampaignInput> campaignInputs(const std::vector<std::string>& familySpecs,
                                          const std::vector<std::string>& caseFiles,
                                          std::uint64_t seed, FileCheck check = FileCheck::Start);

// A case file's count, reason and context entry, from what its read found (in.read).
void settleFileInput(CampaignInput& in);

// An input held whole, for the commands that need every case at once (bench, search); a case
// file is read once.
struct FamilyData
{
    std::string name, reason, source;
    Json input;
    std::vector<Case> cases;
    std::vector<std::string> labels;
    std::vector<std::string> rejected;
    std::vector<MakeupSpec> makeup;
    std::uint64_t seed = 0;
};
std::vector<FamilyData> collectInputs(const std::vector<std::string>& familySpecs,
                                      const std::vector<std::string>& caseFiles,
                                      std::uint64_t seed);

} // namespace gjkval
