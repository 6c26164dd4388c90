// The shipped peers: the adapters of validation/plugins/ around distance routines people use
// (docs/peers.md). A peer is one folder there, whose peer.txt holds its rows of this table
// (docs/code-map.md, "A peer is one folder"); validation/cmake/shipped_peers.cmake generates the
// table from them. It says which files gjk-validate looks for, which of them join the default
// campaign, and what each needs to be built. A file is loaded with loadPlugin()
// (implementations/plugins.hpp), whatever its kind.
#pragma once

#include "common/common.hpp" // Json

#include <span>
#include <string>
#include <vector>

namespace gjkval
{

struct ShippedPeer
{
    const char* file; // its file name in the plugin directory
    // run joins its variants to the default variant list without --peers: the peers that keep
    // scripts/run.sh's campaign under about 60 s on the 2-core development machine
    // (docs/peers.md, "Which peers join the default campaign").
    bool inDefaultCampaign;
    const char* needs; // what building it needs: `list` says so when it is not built
    // Its name for `bench --against NAME` (docs/speed.md): set for a peer whose adapter has its
    // own timing loop (gjk2d_plugin_timing, gjk2d/plugin.h), else null.
    const char* againstName;
};

// Every row of every validation/plugins/*/peer.txt, in the folders' order by name.
std::span<const ShippedPeer> shippedPeers();

// Where a shipped peer's file is: next to the program (<dir>/plugins/, the build tree) or
// <dir>/../<libdir>/gjk2d/plugins/ (an installed prefix; libdir is GNUInstallDirs'
// CMAKE_INSTALL_LIBDIR, "lib" unless the prefix is /usr), the first that holds it; "" when
// neither does (not built, or not installed).
std::string shippedPeerPath(const ShippedPeer& peer);
// The shipped peers found there, in the table's order: those in the default campaign, or every
// one when `peers` (run --peers).
std::vector<std::string> shippedPluginPaths(bool peers = false);

// A template `gjk-validate repro` fills for a shipped peer's variant (commands/repro.cpp): a
// peer.txt `repro` line (docs/code-map.md, "A peer is one folder").
struct ShippedRepro
{
    const char* file;    // the plugin file whose variants it serves
    const char* variant; // a variant's name, or "*": every variant of `file`
    const char* path;    // "<folder>/<template>.in", beside the plugins
    const char* values;  // "NAME=VALUE NAME=VALUE": placeholders of its own, or ""
};
// Every `repro` line of every validation/plugins/*/peer.txt, in the folders' order by name.
std::span<const ShippedRepro> shippedRepros();
// The templates for the variant `name` of the plugin file `pluginPath` (a shipped peer's file, the
// one shippedPeerPath finds),
// in their lines' order, each with the path where it is found: beside the plugins (the build
// tree's <dir>/plugins/ or the install's GJK2D_INSTALL_PLUGIN_DIR, as shippedPeerPath finds them);
// empty when none is (a user's own plugin, or a template missing from the install).
struct FoundRepro
{
    const ShippedRepro* line;
    std::string path;
};
std::vector<FoundRepro> reproTemplates(const std::string& pluginPath, const std::string& name);

struct VariantInfo;
// A report's context.plugins (docs/report-schema.md): every plugin file whose variants are among
// `variants`, in their order, with its kind, its library (name and version, as the plugin gives
// it, or "") and every variant it gave; an in-process variant (implementations/in_process.hpp) is
// an entry of its own, its file what its caller says.
Json pluginsJson(const std::vector<const VariantInfo*>& variants);

} // namespace gjkval
