// One entry of a gjk-cases/1 file checked field by field (inputs/case_reader.cpp hands each
// case's JSON here). Internal to inputs/: the interface is inputs/cases.hpp.
#pragma once

#include "inputs/cases.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace gjkval
{

using RJson = nlohmann::json; // reading: key order does not matter

// "an object", "a number", ...: what a JSON value is, as messages name it.
const char* typeName(const RJson& j);

// True when s holds a control character (C0, DEL, C1) or is not valid UTF-8: what a case name
// may not hold (names are printed, and looked up by `explain`), in either form of case file.
bool isControl(std::string_view s);

// The case names of a file seen so far, for the duplicate check, in memory that does not grow
// with the file when its names are a stem and a counter, as `generate`'s and gjk2d.write_cases'
// are, and by about 6 bytes a case otherwise (a file of any number of cases is read in one
// process):
// - a name that ends in a counter (1 to 18 decimal digits, no leading 0) is kept exactly, as a
//   range of its stem's counters, for the first kCountedStems stems, while a stem's ranges are at
//   most kMaxRanges (past that, its counters seen so far move to the hashes);
// - any other name is kept as its 64-bit hash, the top 16 bits choosing one of 65,536 buckets
//   that each hold the other 48 bits sorted. Two different names are taken for the same when
//   their hashes are equal: for n names a chance of about n^2 / 2^65 in the whole file (the hash
//   mixes every byte of the name).
class NameSet
{
  public:
    static constexpr std::size_t kCountedStems = 64;
    static constexpr std::size_t kMaxRanges = 1024;

    NameSet();
    // True when `name` was not seen before (it is now).
    bool insert(std::string_view name);

  private:
    struct Stem
    {
        std::map<std::uint64_t, std::uint64_t> ranges; // first counter -> one past the last
        bool hashed = false;                           // its counters moved to the hashes
    };
    bool insertHashed(std::string_view name);
    bool insertCounted(std::map<std::string, Stem, std::less<>>::iterator stem,
                       std::uint64_t counter);

    std::map<std::string, Stem, std::less<>> stems_;
    std::vector<std::vector<unsigned char>> buckets_;
};

// One entry of "cases", from its JSON (at most kMaxCaseJsonValues values of it; `truncated` when
// the rest was not kept). An invalid field rejects the entry, naming it; `names` holds the names
// seen so far (a duplicate is rejected). `base` is the file as labels name it.
CaseEntry readCase(const RJson& c, std::size_t index, bool truncated, const std::string& base,
                   NameSet& names);

// A case whose every field was already found valid (the fast reader, case_reader.cpp) as entry
// `index`: labelled as readCase labels it, and rejected as readCase rejects it when its name was
// seen before.
CaseEntry acceptCase(Case&& c, std::size_t index, const std::string& base, NameSet& names);

} // namespace gjkval
