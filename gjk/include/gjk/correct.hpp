// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <gjk/correct.hpp> forwards to <gjk2d/correct.hpp> for one release, with a warning, and is removed
// in the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/correct.hpp> is deprecated: include <gjk2d/correct.hpp>")
#else
#warning "<gjk/correct.hpp> is deprecated: include <gjk2d/correct.hpp>"
#endif

#include "gjk2d/correct.hpp"
