#include "gjk_html/html.hpp"

#include <stdexcept>
#include <string_view>

namespace gjk_html
{
namespace assets
{
// Defined in the generated gjk_html_assets.cpp (cmake/embed_assets.cmake).
std::string_view page_html();
std::string_view report_css();
std::string_view report_js();
} // namespace assets

std::string embedJson(const nlohmann::json& data)
{
    const std::string text = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    std::string out;
    out.reserve(text.size() + text.size() / 64);
    for (char c : text)
    {
        // These characters only occur inside JSON strings (never in the JSON grammar itself), where
        // the \u escape is equivalent.
        switch (c)
        {
        case '<':
            out += "\\u003c";
            break;
        case '>':
            out += "\\u003e";
            break;
        case '&':
            out += "\\u0026";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string escapeHtml(std::string_view text)
{
    std::string out;
    for (char c : text)
        switch (c)
        {
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '&':
            out += "&amp;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    return out;
}

namespace
{

// Fills the template's placeholders. Each placeholder is searched for in the template only, never
// in text already substituted, so data that happens to contain a placeholder is left alone.
std::string renderPage(std::string_view mode, std::string_view schema, const nlohmann::json& data)
{
    const std::string_view tpl = assets::page_html();
    struct Slot
    {
        std::string_view key;
        std::string value;
    };
    const Slot slots[] = {
        {"@MODE@", std::string(mode)},
        {"@SCHEMA@", escapeHtml(schema)},
        {"/*@CSS@*/", std::string(assets::report_css())},
        {"@DATA@", embedJson(data)},
        {"/*@JS@*/", std::string(assets::report_js())},
    };
    std::string out;
    std::size_t size = tpl.size();
    for (const Slot& s : slots)
        size += s.value.size();
    out.reserve(size);
    std::size_t pos = 0;
    for (const Slot& s : slots)
    {
        const std::size_t at = tpl.find(s.key, pos);
        if (at == std::string_view::npos)
            throw std::logic_error("gjk_html: page template lacks placeholder " +
                                   std::string(s.key));
        out.append(tpl.substr(pos, at - pos));
        out.append(s.value);
        pos = at + s.key.size();
    }
    out.append(tpl.substr(pos));
    return out;
}

} // namespace

std::string renderReport(const nlohmann::json& report, std::string_view schema)
{
    return renderPage("report", schema, report);
}

std::string renderCase(const nlohmann::json& caseDetail)
{
    return renderPage("case", "", caseDetail);
}

std::string_view styleSheet()
{
    return assets::report_css();
}

} // namespace gjk_html
