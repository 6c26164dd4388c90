// gjk-validate list: the families and the variants.
#include "commands/command_line.hpp"
#include "evaluate/variants.hpp"
#include "inputs/families.hpp"

#include <cstdio>

namespace gjkval
{
namespace
{
int listCommand()
{
    std::printf("families:\n  random  (default count %d)\n", kDefaultRandomCount);
    for (const auto& h : hardSubFamilies())
        std::printf("  hard/%-20s %4d cases  %s\n", h.name.c_str(), h.count, h.reason.c_str());
    for (const auto& e : engineSubFamilies())
        std::printf("  engine/%-19s %4d cases  %s\n", e.name.c_str(), e.count, e.reason.c_str());
    std::printf("variants (default %s; judged decide the exit code, comparison are "
                "reported only):\n",
                kDefaultVariants);
    for (const auto& v : variantTable())
        std::printf("  %-22s %-6s %-10s %s\n", v.name.c_str(), scalarName(v.scalar),
                    v.judged ? "judged" : "comparison", v.description.c_str());
    flushStdout();
    return kExitPass;
}
} // namespace

Subcommand addList(CLI::App& app, const CommandLine&)
{
    auto* list =
        app.add_subcommand("list", "List the families (with their reasons) and the variants.");
    return {list, [] { return listCommand(); }};
}

} // namespace gjkval
