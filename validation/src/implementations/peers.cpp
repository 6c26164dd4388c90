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
} // namespace

std::span<const ShippedPeer> shippedPeers()
{
    return kShippedPeers;
}

std::string shippedPeerPath(const ShippedPeer& peer)
{
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec)
        return {};
    const auto dir = exe.parent_path();
    for (const auto& candidate : {dir / "plugins", dir / ".." / GJK2D_INSTALL_PLUGIN_DIR})
        if (std::filesystem::is_regular_file(candidate / peer.file, ec))
            return (candidate / peer.file).lexically_normal().string();
    return {};
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
