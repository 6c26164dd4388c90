// The two macros of gjk/: GJK_ASSERT (a contract) and GJK_INLINE (a forced-inline step).
#pragma once

#include <cassert>

#if defined(GJK2D_CHECKED)
#include <cstdio>
#include <cstdlib>
#define GJK_ASSERT(c)                                                                              \
    ((c) ? (void)0                                                                                 \
         : (std::fprintf(stderr, "%s:%d: GJK contract violated: %s\n", __FILE__, __LINE__, #c),    \
            std::abort()))
#else
#define GJK_ASSERT(c) assert(c)
#endif

// The small steps of one GJK iteration (the Minkowski support, the search direction) are forced
// inline. Why: docs/speed.md, "Forced inlining".
#if defined(__GNUC__)
#define GJK_INLINE [[gnu::always_inline]] inline
#else
#define GJK_INLINE inline
#endif
