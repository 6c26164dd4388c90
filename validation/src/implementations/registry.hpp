// Inside the implementations layer only: the registry of loaded plugins, which loading
// (plugins.cpp), the children's output routing and logs (children.cpp) and the server children
// (servers.cpp) share. Not included above this layer.
#pragma once

#include "implementations/plugins.hpp"

#include <deque>
#include <string>
#include <vector>

namespace gjkval
{

// The registry: loaded plugins' implementations and their variants, with stable addresses
// (VariantInfo pointers go into every EvalContext).
struct Registry
{
    std::deque<PluginImpl> impls;
    std::deque<VariantInfo> variants;
    std::vector<std::string> paths; // canonical paths loaded
    std::string logDir;             // setPluginLogDirectory()
};
inline Registry& registry()
{
    static Registry r;
    return r;
}

} // namespace gjkval
