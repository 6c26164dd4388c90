// Deprecated path: gjk2d installs its headers under gjk2d/ (docs/gjk.md, "Install").
// <gjk/certify.hpp> forwards to <gjk2d/certify.hpp> for one release, with a warning, and is removed
// in the release after.
#pragma once

#if defined(_MSC_VER) && !defined(__clang__)
#pragma message("<gjk/certify.hpp> is deprecated: include <gjk2d/certify.hpp>")
#else
#warning "<gjk/certify.hpp> is deprecated: include <gjk2d/certify.hpp>"
#endif

#include "gjk2d/certify.hpp"
