// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <gjk/rescale.hpp> forwards to <gjk2d/rescale.hpp> for one release, with a warning, and is removed
// in the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/rescale.hpp> is deprecated: include <gjk2d/rescale.hpp>")
#else
#warning "<gjk/rescale.hpp> is deprecated: include <gjk2d/rescale.hpp>"
#endif

#include "gjk2d/rescale.hpp"
