// One entry of a gjk-cases/1 file checked field by field (inputs/case_reader.cpp hands each
// case's JSON here). Internal to inputs/: the interface is inputs/cases.hpp.
#pragma once

#include "inputs/cases.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <set>
#include <string>

namespace gjkval
{

using RJson = nlohmann::json; // reading: key order does not matter

// "an object", "a number", ...: what a JSON value is, as messages name it.
const char* typeName(const RJson& j);

// One entry of "cases", from its JSON (at most kMaxCaseJsonValues values of it; `truncated` when
// the rest was not kept). An invalid field rejects the entry, naming it; `names` holds the names
// seen so far (a duplicate is rejected). `base` is the file as labels name it.
CaseEntry readCase(const RJson& c, std::size_t index, bool truncated, const std::string& base,
                   std::set<std::string>& names);

} // namespace gjkval
