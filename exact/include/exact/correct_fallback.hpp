// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <exact/correct_fallback.hpp> forwards to <gjk2d/correct_fallback.hpp> for one release, with a
// warning, and is removed in the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<exact/correct_fallback.hpp> is deprecated: include <gjk2d/correct_fallback.hpp>")
#else
#warning "<exact/correct_fallback.hpp> is deprecated: include <gjk2d/correct_fallback.hpp>"
#endif

#include "gjk2d/correct_fallback.hpp"
