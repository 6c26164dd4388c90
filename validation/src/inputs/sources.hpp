// The campaign's inputs as streams: each generated family and each case file yields its cases in
// case order, in chunks of bounded size, so that a campaign's memory does not grow with its number
// of cases (docs/judgement.md, "Statistics").
#pragma once

#include "common/common.hpp"
#include "inputs/cases.hpp"
#include "inputs/families.hpp"

#include <cstdint>
#include <functional>
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

// The inputs of a campaign, in order: the families of each spec, then the case files. A case file
// is read once here, to refuse it whole (InputError: not JSON, not gjk-cases/1) before any case
// is evaluated, and once more as it is streamed. Throws InputError (a family or file given twice).
std::vector<CampaignInput> campaignInputs(const std::vector<std::string>& familySpecs,
                                          const std::vector<std::string>& caseFiles,
                                          std::uint64_t seed);

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
