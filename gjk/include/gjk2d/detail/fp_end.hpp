// Floating-point epilogue of every gjk/ header: closes the region gjk2d/detail/fp_begin.hpp opened
// (the reasons are there), restoring the user's own floating-point options. No include guard.
#if defined(__clang__)
#pragma float_control(pop)
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif
