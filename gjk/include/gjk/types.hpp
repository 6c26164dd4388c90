// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <gjk/types.hpp> forwards to <gjk2d/types.hpp> for one release, with a warning, and is removed in
// the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/types.hpp> is deprecated: include <gjk2d/types.hpp>")
#else
#warning "<gjk/types.hpp> is deprecated: include <gjk2d/types.hpp>"
#endif

#include "gjk2d/types.hpp"
