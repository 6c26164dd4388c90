// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <gjk/simplex.hpp> forwards to <gjk2d/simplex.hpp> for one release, with a warning, and is removed
// in the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/simplex.hpp> is deprecated: include <gjk2d/simplex.hpp>")
#else
#warning "<gjk/simplex.hpp> is deprecated: include <gjk2d/simplex.hpp>"
#endif

#include "gjk2d/simplex.hpp"
