// gjk-validate list: the families and the variants, the plugins' among them.
#include "campaign/campaign.hpp"
#include "commands/command_line.hpp"
#include "commands/outputs.hpp"
#include "commands/plugin_options.hpp"
#include "implementations/peers.hpp"
#include "implementations/plugins.hpp"
#include "implementations/variants.hpp"
#include "inputs/families.hpp"
#include "report/report.hpp"

#include <cstdio>
#include <memory>

namespace gjkval
{
namespace
{
// Every shipped peer, installed or not: "default" (run loads it), "--peers" (only run --peers
// does), or "not built" with what building it needs.
void printShippedPeers()
{
    std::printf("shipped peers (docs/peers.md; run loads the default ones, run --peers every "
                "built one; --peers lists their variants above):\n");
    for (const ShippedPeer& peer : shippedPeers())
    {
        const std::string path = shippedPeerPath(peer);
        if (path.empty())
            std::printf("  %-22s not built (needs %s)\n", peer.file, peer.needs);
        else
            std::printf("  %-22s %-9s %s\n", peer.file,
                        peer.inDefaultCampaign ? "default" : "--peers", path.c_str());
    }
}

int listCommand(const PluginOptions& plugins)
{
    const LoadedPlugins loaded = loadPlugins(plugins); // before any output: a bad one exits 2
    // One line, read by scripts/peers_doc.py: run's options for the default campaign.
    std::printf("default campaign (run without --family and --cases): %s --default-cases\n",
                defaultFamilyOptions().c_str());
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
    // The plugins' (shipped, then --plugin): comparison variants unless run --judge names them.
    for (const auto* group : {&loaded.shipped, &loaded.given})
        for (const VariantInfo* v : *group)
            std::printf("  %-22s %-6s %-10s %s (%s%s)\n", v->name.c_str(), scalarName(v->scalar),
                        "comparison", v->description.c_str(),
                        group == &loaded.shipped ? "shipped, " : "", v->plugin->path.c_str());
    printShippedPeers();
    flushStdout();
    return kExitPass;
}
} // namespace

Subcommand addList(CLI::App& app, const CommandLine&)
{
    auto o = std::make_shared<PluginOptions>();
    auto* list = app.add_subcommand(
        "list", "List the families (with their reasons) and the variants, the shipped plugins' "
                "and those of --plugin included.");
    list->add_option("--plugin", o->paths,
                     "also list this plugin's implementations (gjk2d/plugin.h); repeatable")
        ->allow_extra_args(false);
    list->add_flag("--no-default-plugins", o->noDefault,
                   "leave out the shipped plugins of the default campaign");
    list->add_flag("--peers", o->peers,
                   "also load every built shipped peer and list its variants; not with "
                   "--no-default-plugins");
    list->footer(exitCodesHelp());
    return {list, [o] { return listCommand(*o); }};
}

} // namespace gjkval
