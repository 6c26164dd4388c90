// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <gjk/exact_arithmetic.hpp> forwards to <gjk2d/exact_arithmetic.hpp> for one release, with a
// warning, and is removed in the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/exact_arithmetic.hpp> is deprecated: include <gjk2d/exact_arithmetic.hpp>")
#else
#warning "<gjk/exact_arithmetic.hpp> is deprecated: include <gjk2d/exact_arithmetic.hpp>"
#endif

#include "gjk2d/exact_arithmetic.hpp"
