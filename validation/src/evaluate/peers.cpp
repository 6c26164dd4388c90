#include "evaluate/peers.hpp"

#include <filesystem>
#include <system_error>

namespace gjkval
{

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

} // namespace gjkval
