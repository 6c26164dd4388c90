// --plugin, --judge, --plugin-timeout, --no-default-plugins and --peers: registered, the plugins
// loaded, the variants selected (commands/plugin_options.hpp).
#include "commands/plugin_options.hpp"

#include "common/common.hpp"
#include "implementations/peers.hpp"
#include "implementations/plugins.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace gjkval
{
namespace fs = std::filesystem;

static_assert(PluginOptions{}.timeoutSeconds == kDefaultPluginTimeoutSeconds);

void addPluginOptions(CLI::App& sub, PluginOptions& o, ShippedPlugins shipped, Judging judging)
{
    const bool judges = judging == Judging::Judges;
    sub.add_option("--plugin", o.paths,
                   "a shared library implementing gjk2d/plugin.h, or an executable adapter (any "
                   "executable file speaking the gjk2d-adapter protocol 1 over its stdin and "
                   "stdout: docs/plugin-abi.md, \"Executable adapters\"): each "
                   "implementation it describes becomes a comparison variant (evaluated in a child "
                   "process); repeatable, each file once")
        ->allow_extra_args(false);
    auto* judge =
        sub.add_option("--judge", o.judge,
                       "judge this plugin implementation like gjk2d's judged variants: a "
                       "case fails where the answer breaks its contract (its declared one, with "
                       "gjk2d's bound in its scalar type where it states no tolerance; a "
                       "version-1 plugin: gjk2d's own); repeatable")
            ->allow_extra_args(false);
    if (!judges) // parsed, to be refused with a line that says why (selectVariants)
        judge->group("");
    sub.add_option("--plugin-timeout", o.timeoutSeconds,
                   "seconds a plugin may take on one case before it counts as hung, 0.01..3600")
        ->capture_default_str();
    sub.add_flag("--no-default-plugins", o.noDefault,
                 shipped == ShippedPlugins::JoinDefaultList
                     ? "leave out the shipped plugins of the default campaign (`gjk-validate "
                       "list`), which run joins when --variants is left at its default"
                     : "do not load the shipped plugins of the default campaign (`gjk-validate "
                       "list`), which --variants can name");
    sub.add_flag("--peers", o.peers,
                 "also load every installed shipped peer (docs/peers.md; `gjk-validate list` "
                 "says which are installed) and add their variants to the variants, whatever "
                 "--variants says; not with --no-default-plugins");
    o.judges = judges;
}

LoadedPlugins loadPlugins(const PluginOptions& o)
{
    for (std::size_t i = 0; i < o.paths.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
        {
            std::error_code ec;
            if (o.paths[i] == o.paths[j] || fs::equivalent(o.paths[i], o.paths[j], ec))
                throw InputError(fmt::format("--plugin {}: given twice (also as {}); each plugin "
                                             "file is loaded once",
                                             o.paths[i], o.paths[j]));
        }
    if (o.peers && o.noDefault)
        throw InputError(
            "--peers loads every shipped peer, --no-default-plugins leaves them "
            "out: give one of them (a single peer: --no-default-plugins --plugin FILE)");
    LoadedPlugins loaded;
    if (!o.noDefault)
        for (const auto& path : shippedPluginPaths(o.peers))
            for (const VariantInfo* v : loadPlugin(path, o.timeoutSeconds))
                loaded.shipped.push_back(v);
    for (const auto& path : o.paths)
        for (const VariantInfo* v : loadPlugin(path, o.timeoutSeconds))
            loaded.given.push_back(v);
    return loaded;
}

std::vector<const VariantInfo*> selectVariants(const std::string& list, const PluginOptions& o,
                                               ShippedPlugins shipped)
{
    if (!o.judges && !o.judge.empty())
        throw InputError(fmt::format("--judge {}: this command judges no variant (bench times "
                                     "them); judge a plugin with `gjk-validate run --judge NAME`",
                                     excerpt(o.judge.front())));
    if (!(o.timeoutSeconds >= 0.01 && o.timeoutSeconds <= 3600))
        throw InputError("--plugin-timeout: expected seconds in 0.01..3600");
    // Loaded first, so that --variants can name their implementations.
    const LoadedPlugins loaded = loadPlugins(o);
    std::vector<const VariantInfo*> variants;
    try
    {
        variants = parseVariants(list);
    }
    catch (const InputError& e) // a peer not in the default campaign is loaded by --peers only
    {
        if (o.peers || o.noDefault)
            throw;
        throw InputError(std::string(e.what()) + "; the variants of a shipped peer that is not in "
                                                 "the default campaign need --peers (see `list`)");
    }
    auto add = [&](const std::vector<const VariantInfo*>& vs)
    {
        for (const VariantInfo* v : vs)
            if (std::find(variants.begin(), variants.end(), v) == variants.end())
                variants.push_back(v);
    };
    if (o.peers || (shipped == ShippedPlugins::JoinDefaultList && list == kDefaultVariants))
        add(loaded.shipped);
    add(loaded.given);
    for (const auto& name : o.judge)
        judgePluginVariant(name);
    return variants;
}

} // namespace gjkval
