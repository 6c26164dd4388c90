// The run context: the facts of the build and the run that report.json's and bench's context
// blocks record (docs/report-schema.md, "context"). Below every layer that writes a report.
#pragma once

#include "common/common.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

namespace gjkval
{

// The source tree's revision when gjk-validate was built ("0123456789ab", "... (dirty)" with
// modified tracked files, "unknown" outside a git checkout): recorded by the build
// (src/common/build_info.cpp), never asked of git at run time.
std::string gitRevision();
std::string isoDateUtc();

// When the command began (runCommandLine marks it): a campaign's elapsed_s counts its phases from
// here (docs/report-schema.md, "context"). Before any mark, the time of the first call.
void markCommandStart();
std::chrono::steady_clock::time_point commandStart();

// report.json's context block up to "cases_rejected" (date, host, compiler, flags, build_type,
// gjk_checked, git_revision, command, seed, threads, inputs, cases_total, cases_rejected); `bench`
// writes the same block.
Json contextJson(const std::string& date, const std::string& revision, const std::string& command,
                 std::uint64_t seed, int threads, Json inputs, std::size_t casesTotal,
                 std::size_t casesRejected);

} // namespace gjkval
