// The run context: the date, the host, the build's facts (build_info.hpp, generated at configure)
// and the batch's instruction set, as report.json's and bench's context blocks record them.
#include "common/context.hpp"

#include "build_info.hpp"

#include "gjk2d/batch.hpp"

#include <ctime>
#include <unistd.h>

namespace gjkval
{
namespace
{

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

} // namespace

std::string isoDateUtc()
{
    return isoDateUtcImpl();
}

namespace
{
std::chrono::steady_clock::time_point& startMark()
{
    static std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
    return t;
}
} // namespace

void markCommandStart()
{
    startMark() = std::chrono::steady_clock::now();
}

std::chrono::steady_clock::time_point commandStart()
{
    return startMark();
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
    // The instruction set the batch variants' lanes run (gjk2d/batch.hpp), chosen at run time.
    context["batch_isa"] = gjk::batchIsaName(gjk::bestBatchIsa());
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

} // namespace gjkval
