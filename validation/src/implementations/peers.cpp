// The shipped peers (implementations/peers.hpp): where gjk-validate finds their files, and the
// report's context.plugins.
#include "implementations/peers.hpp"

#include "implementations/plugins.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace gjkval
{

namespace
{
constexpr ShippedPeer kShippedPeers[] = {
#include "shipped_peers.inc"
};
// A vector: a build may have no `repro` line at all.
const std::vector<ShippedRepro> kShippedRepros = {
#include "shipped_repros.inc"
};

// The directories gjk-validate looks in for what ships beside it: <dir>/plugins (the build tree),
// then <dir>/../GJK2D_INSTALL_PLUGIN_DIR (an installed prefix); none when /proc/self/exe cannot
// be read.
std::vector<std::filesystem::path> pluginDirs()
{
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec)
        return {};
    const auto dir = exe.parent_path();
    return {dir / "plugins", dir / ".." / GJK2D_INSTALL_PLUGIN_DIR};
}
} // namespace

std::span<const ShippedPeer> shippedPeers()
{
    return kShippedPeers;
}

std::string shippedPeerPath(const ShippedPeer& peer)
{
    std::error_code ec;
    for (const auto& candidate : pluginDirs())
        if (std::filesystem::is_regular_file(candidate / peer.file, ec))
            return (candidate / peer.file).lexically_normal().string();
    return {};
}

std::span<const ShippedRepro> shippedRepros()
{
    return kShippedRepros;
}

std::vector<FoundRepro> reproTemplates(const std::string& pluginPath, const std::string& name)
{
    const std::string file = std::filesystem::path(pluginPath).filename().string();
    std::vector<FoundRepro> found;
    std::error_code ec;
    // Only the shipped file itself: a user's plugin of the same file name elsewhere is not the
    // peer.
    bool shipped = false;
    for (const ShippedPeer& peer : kShippedPeers)
        if (file == peer.file)
            if (const std::string at = shippedPeerPath(peer); !at.empty())
                shipped = shipped || std::filesystem::equivalent(at, pluginPath, ec);
    if (!shipped)
        return found;
    for (const ShippedRepro& line : kShippedRepros)
        if (file == line.file && (std::string(line.variant) == "*" || name == line.variant))
            for (const auto& candidate : pluginDirs())
                if (std::filesystem::is_regular_file(candidate / line.path, ec))
                {
                    found.push_back({&line, (candidate / line.path).lexically_normal().string()});
                    break;
                }
    return found;
}

std::vector<std::string> shippedPluginPaths(bool peers)
{
    std::vector<std::string> found;
    for (const ShippedPeer& peer : kShippedPeers)
        if (peers || peer.inDefaultCampaign)
            if (auto path = shippedPeerPath(peer); !path.empty())
                found.push_back(std::move(path));
    return found;
}

Json pluginsJson(const std::vector<const VariantInfo*>& variants)
{
    Json out = Json::array();
    std::vector<std::string> seen;
    for (const VariantInfo* v : variants)
    {
        if (!v->plugin)
            continue;
        const bool inProcess = v->plugin->kind == PluginKind::InProcess;
        if (!inProcess && std::find(seen.begin(), seen.end(), v->plugin->path) != seen.end())
            continue;
        seen.push_back(v->plugin->path);
        // A file's every implementation; an in-process variant is its own (its path is what its
        // caller says, and an earlier campaign's variant of the same path may still be
        // registered).
        Json names = Json::array();
        if (inProcess)
            names.push_back(v->name);
        else
            for (const VariantInfo* w : pluginVariants())
                if (w->plugin->path == v->plugin->path)
                    names.push_back(w->name);
        out.push_back({{"file", v->plugin->path},
                       {"kind", pluginKindName(v->plugin->kind)},
                       {"library", v->plugin->library},
                       {"variants", std::move(names)}});
    }
    return out;
}

} // namespace gjkval
