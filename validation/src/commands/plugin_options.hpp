// The options every subcommand that runs implementations shares: --plugin PATH (repeatable),
// --judge NAME, --plugin-timeout SECONDS, --no-default-plugins (docs/validate-your-gjk.md),
// --peers (docs/peers.md); the plugins they name loaded, and --variants chosen among them.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace gjkval
{

struct VariantInfo;

// Whether the shipped plugins' variants join the command's default variant list (run), or are
// loaded only for --variants to name them.
enum class ShippedPlugins
{
    JoinDefaultList,
    OnlyNamed
};
// Whether the command judges variants (--judge); bench does not, and refuses it (exit 2).
enum class Judging
{
    Judges,
    RefusesJudge
};
struct PluginOptions
{
    std::vector<std::string> paths, judge;
    double timeoutSeconds = 5; // kDefaultPluginTimeoutSeconds
    bool noDefault = false;
    bool peers = false; // --peers: every installed shipped peer, its variants added
    bool judges = true;
};
void addPluginOptions(CLI::App& sub, PluginOptions& o, ShippedPlugins shipped,
                      Judging judging = Judging::Judges);
// The shipped plugins (unless --no-default-plugins; those of the default campaign, every installed
// one with --peers) and the --plugin ones, loaded: InputError (exit 2) naming the file when one
// cannot be used or a --plugin file is given twice, or with both --peers and --no-default-plugins.
struct LoadedPlugins
{
    std::vector<const VariantInfo*> shipped, given;
};
LoadedPlugins loadPlugins(const PluginOptions& o);
// --variants LIST with the plugins: loadPlugins(), so that LIST can name their implementations;
// then LIST's variants, the shipped plugins' when they join the default list and LIST is the
// default or --peers is given, and every --plugin one; then --judge.
std::vector<const VariantInfo*> selectVariants(const std::string& list, const PluginOptions& o,
                                               ShippedPlugins shipped);

} // namespace gjkval
