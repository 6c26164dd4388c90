// The shipped peers: the adapters of validation/plugins/ around distance routines people use
// (docs/peers.md), one row each. This table is their one home: which files gjk-validate looks
// for, which of them join the default campaign, and what each needs to be built. A file is
// loaded with loadPlugin() (evaluate/plugins.hpp), whatever its kind.
#pragma once

#include "common/common.hpp" // Json

#include <string>
#include <vector>

namespace gjkval
{

struct ShippedPeer
{
    const char* file;       // its file name in the plugin directory
    bool inDefaultCampaign; // run joins its variants to the default variant list without --peers
    const char* needs;      // what building it needs: `list` says so when it is not built
    // Its name for `bench --against NAME` (docs/speed.md): set for a peer whose adapter has its
    // own timing loop (gjk2d_plugin_timing, gjk2d/plugin.h), else null.
    const char* againstName = nullptr;
};

// inDefaultCampaign: the peers that keep scripts/run.sh's campaign (`gjk-validate run`, 214,000
// cases, timing on) under about 60 s on the 2-core development machine. Measured at 15ef9ad, one
// run each, alternating, `time gjk-validate run [--plugin FILE]... --out DIR` (context.elapsed_s
// total): Box2D 2.4.1 alone 37.9 s (the campaign as it was); adding Box2D v3 +7.5 s, Bullet's two
// modules +5.8 s, FCL's two solvers +14.6 s, planck.js +18.5 s (12.6 s of it timing through the
// pipe), GEOS +164 s (geos-3.11.1 answers in about 250 us, most of it shapely's Python layer). So
// Box2D 2.4.1, Box2D v3 and Bullet join (about 51 s); FCL, planck.js and GEOS run under --peers.
inline constexpr ShippedPeer kShippedPeers[] = {
    {"gjk2d-box2d.so", true, "Debian libbox2d-dev"},
    {"gjk2d-box2d3.so", true,
     "a Box2D v3 source tree named by GJK2D_BOX2D3_SOURCE (README.md, \"Box2D v3\")", "box2d-v3"},
    {"gjk2d-fcl.so", false, "Debian libfcl-dev"},
    {"gjk2d-bullet-float.so", true, "Debian libbullet-dev"},
    {"gjk2d-bullet-double.so", true, "Debian libbullet-dev"},
    {"gjk2d-planck", false, "node and npm, and planck installed by scripts/setup.sh"},
    {"gjk2d-geos", false, "Debian python3-shapely"},
};

// Where a shipped peer's file is: next to the program (<dir>/plugins/, the build tree) or
// <dir>/../<libdir>/gjk2d/plugins/ (an installed prefix; libdir is GNUInstallDirs'
// CMAKE_INSTALL_LIBDIR, "lib" unless the prefix is /usr), the first that holds it; "" when
// neither does (not built, or not installed).
std::string shippedPeerPath(const ShippedPeer& peer);
// The shipped peers found there, in the table's order: those in the default campaign, or every
// one when `peers` (run --peers).
std::vector<std::string> shippedPluginPaths(bool peers = false);

struct VariantInfo;
// A report's context.plugins (docs/report-schema.md): every plugin file whose variants are among
// `variants`, in their order, with its kind, its library (name and version, as the plugin gives
// it, or "") and every variant it gave; an in-process variant (evaluate/in_process.hpp) is an
// entry of its own, its file what its caller says.
Json pluginsJson(const std::vector<const VariantInfo*>& variants);

} // namespace gjkval
