// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <gjk/support.hpp> forwards to <gjk2d/support.hpp> for one release, with a warning, and is removed
// in the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/support.hpp> is deprecated: include <gjk2d/support.hpp>")
#else
#warning "<gjk/support.hpp> is deprecated: include <gjk2d/support.hpp>"
#endif

#include "gjk2d/support.hpp"
