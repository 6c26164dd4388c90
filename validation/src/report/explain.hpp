// `gjk-validate explain`'s text: one case's detail (docs/report-schema.md, "CaseDetail") in words,
// with each variant's iteration trace.
#pragma once

#include "common/common.hpp"

#include <string>

namespace gjkval
{

// `explain`'s text from a case detail (evaluate/evaluate.hpp, caseDetail).
std::string explainText(const Json& detail);

} // namespace gjkval
