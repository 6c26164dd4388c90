// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <exact/exact.hpp> forwards to <gjk2d/exact.hpp> for one release, with a warning, and is removed
// in the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<exact/exact.hpp> is deprecated: include <gjk2d/exact.hpp>")
#else
#warning "<exact/exact.hpp> is deprecated: include <gjk2d/exact.hpp>"
#endif

#include "gjk2d/exact.hpp"
