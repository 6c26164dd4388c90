// report_render: renders a page with gjk_html, for the browser tests
// (tests/report/browser_check.py).
//   report_render report REPORT.json OUT.html        index.html for a report.json
//   report_render case   FILE.json   OUT.html [N]    viewer page for a CaseDetail, or for the
//   report's
//                                                    worst[N] when FILE.json is a report (default
//                                                    0)
#include "gjk_html/html.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char** argv)
{
    if (argc < 4)
    {
        std::cerr << "usage: report_render report|case IN.json OUT.html [N]\n";
        return 2;
    }
    const std::string mode = argv[1];
    try
    {
        std::ifstream in(argv[2]);
        if (!in)
        {
            std::cerr << "report_render: cannot read " << argv[2] << "\n";
            return 2;
        }
        const nlohmann::json data = nlohmann::json::parse(in);
        std::string html;
        if (mode == "report")
            html =
                gjk_html::renderReport(data, "gjk-report/1"); // kReportSchema (report/report.hpp)
        else if (mode == "case")
        {
            if (data.contains("worst"))
            {
                const std::size_t n = argc > 4 ? std::strtoul(argv[4], nullptr, 10) : 0;
                if (!data["worst"].is_array() || data["worst"].size() <= n)
                {
                    std::cerr << "report_render: the report has no worst[" << n << "]\n";
                    return 3;
                }
                html = gjk_html::renderCase(data["worst"][n]);
            }
            else
                html = gjk_html::renderCase(data);
        }
        else
        {
            std::cerr << "report_render: unknown mode " << mode << "\n";
            return 2;
        }
        std::ofstream out(argv[3], std::ios::binary);
        out << html;
        if (!out)
        {
            std::cerr << "report_render: cannot write " << argv[3] << "\n";
            return 2;
        }
    }
    catch (const std::exception& e)
    {
        std::cerr << "report_render: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
