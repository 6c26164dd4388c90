// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <gjk/distance.hpp> forwards to <gjk2d/distance.hpp> for one release, with a warning, and is
// removed in the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/distance.hpp> is deprecated: include <gjk2d/distance.hpp>")
#else
#warning "<gjk/distance.hpp> is deprecated: include <gjk2d/distance.hpp>"
#endif

#include "gjk2d/distance.hpp"
