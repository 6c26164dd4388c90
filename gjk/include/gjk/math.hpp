// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install"). <gjk/math.hpp>
// forwards to <gjk2d/math.hpp> for one release, with a warning, and is removed in the release
// after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/math.hpp> is deprecated: include <gjk2d/math.hpp>")
#else
#warning "<gjk/math.hpp> is deprecated: include <gjk2d/math.hpp>"
#endif

#include "gjk2d/math.hpp"
