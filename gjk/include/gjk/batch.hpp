// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <gjk/batch.hpp> forwards to <gjk2d/batch.hpp> for one release, with a warning, and is removed in
// the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/batch.hpp> is deprecated: include <gjk2d/batch.hpp>")
#else
#warning "<gjk/batch.hpp> is deprecated: include <gjk2d/batch.hpp>"
#endif

#include "gjk2d/batch.hpp"
