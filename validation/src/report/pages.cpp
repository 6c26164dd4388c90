// The report directory's pages written from a campaign's result: report.json, report.md,
// worst-cases.json and index.html (the HTML renderer's, from the report converted in memory),
// and the check that an --out directory holds nothing but a previous report.
#include "report/pages.hpp"

#include "report/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <unistd.h>

#if defined(GJK2D_HAVE_HTML)
#include "gjk_html/html.hpp"
#endif

namespace gjkval
{
namespace fs = std::filesystem;

namespace
{
// Every file a report directory holds, besides the plugins' logs (plugin-*.log,
// implementations/plugins.hpp); writeReportPages replaces the directory as a whole.
const char* const kReportFiles[] = {"report.json", "report.md",  "worst-cases.json",
                                    "cases.jsonl", "index.html", "shard.json"};
} // namespace

nlohmann::json forHtmlRenderer(const Json& j)
{
    switch (j.type())
    {
    case Json::value_t::object:
    {
        nlohmann::json o = nlohmann::json::object();
        for (const auto& [key, value] : j.items())
            o.emplace(key, forHtmlRenderer(value));
        return o;
    }
    case Json::value_t::array:
    {
        nlohmann::json a = nlohmann::json::array();
        a.get_ref<nlohmann::json::array_t&>().reserve(j.size());
        for (const Json& value : j)
            a.push_back(forHtmlRenderer(value));
        return a;
    }
    case Json::value_t::string:
        return j.get_ref<const std::string&>();
    case Json::value_t::boolean:
        return j.get<bool>();
    case Json::value_t::number_integer:
    {
        const auto v = j.get<std::int64_t>();
        return v >= 0 ? nlohmann::json(std::uint64_t(v)) : nlohmann::json(v);
    }
    case Json::value_t::number_unsigned:
        return j.get<std::uint64_t>();
    case Json::value_t::number_float:
    {
        const double v = j.get<double>();
        return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
    }
    case Json::value_t::null:
        return nullptr;
    default: // binary or discarded: the report never holds one
        throw std::logic_error("report.json holds a value the HTML report cannot take");
    }
}

void checkReportDir(const std::string& outDir)
{
    if (outDir.empty())
        throw InputError("--out: the output directory is empty");
    const fs::path dir = reportDirPath(outDir);
    std::error_code ec;
    const auto st = fs::status(dir, ec);
    if (fs::exists(st))
    {
        if (!fs::is_directory(st))
            throw InputError(
                fmt::format("--out {}: exists and is not a directory", excerpt(outDir)));
        // The whole directory is replaced: refuse one that holds anything else than a report.
        for (const auto& e : fs::directory_iterator(dir, ec))
        {
            const std::string name = e.path().filename().string();
            const bool pluginLog = name.rfind("plugin-", 0) == 0 && name.size() > 11 &&
                                   name.compare(name.size() - 4, 4, ".log") == 0;
            if (!pluginLog && std::find(std::begin(kReportFiles), std::end(kReportFiles), name) ==
                                  std::end(kReportFiles))
                throw InputError(fmt::format(
                    "--out {}: holds '{}', which is not part of a report (the directory is "
                    "replaced as a whole: give a new or a report directory)",
                    excerpt(outDir), excerpt(name)));
        }
        if (ec)
            throw InputError(fmt::format("--out {}: cannot read the directory: {}", excerpt(outDir),
                                         ec.message()));
    }
    // The parent must exist or be creatable, and be writable: the report is staged beside DIR.
    fs::path parent = dir.parent_path();
    while (!fs::exists(parent, ec) && parent.has_relative_path())
        parent = parent.parent_path();
    if (!fs::is_directory(parent, ec))
        throw InputError(fmt::format("--out {}: {} is not a directory", excerpt(outDir),
                                     excerpt(parent.string())));
    if (::access(parent.c_str(), W_OK | X_OK) != 0)
        throw InputError(fmt::format("--out {}: cannot write in {}: {}", excerpt(outDir),
                                     excerpt(parent.string()), std::strerror(errno)));
}

std::string writeReportPages(const CampaignReport& result, StagedDir& out)
{
    out.write("report.json", result.report.dump(1) + "\n"); // first: the rest is rendered from it
    out.write("report.md", renderMarkdown(result.report));
    out.write("worst-cases.json", caseFileText(result.worstComments, result.worstCases));
#if defined(GJK2D_HAVE_HTML)
    out.write("index.html", gjk_html::renderReport(forHtmlRenderer(result.report), kReportSchema));
    const std::string page = "index.html";
#else
    const std::string page = "report.md";
#endif
    out.commit();
    return (out.dir() / page).string();
}

} // namespace gjkval
