// Careless plugins (issue 30): the example plugin (examples/plugin/example_gjk_plugin.cpp) with ONE
// misbehaviour, chosen by the compile definition CARELESS_<KIND>, as one double implementation
// named "careless-<kind>" (CARELESS_NAME). careless_check.py runs each under --judge and checks
// the verdict of every case against what the misbehaviour must get:
//   NEGATIVE       distance -1 - d                       fails every case
//   NAN_WITNESS    witness points NaN                    fails every case (non-finite)
//   SHIFT_WITNESS  both witness points moved by (10, 0)  fails every case (off their shapes)
//   SWAP_WITNESS   A's point and B's point swapped       fails where d > the witness bound
//   REL_ERROR      distance times 1 + 1e-3               fails where 1e-3 d > a bound
// The example is included whole, its entry point renamed, so that the careless one wraps exactly
// the code a user starts from.
#define gjk2d_plugin_describe example_plugin_describe
#include "example_gjk_plugin.cpp"
#undef gjk2d_plugin_describe

#include <cmath>
#include <limits>
#include <utility>

namespace
{

int32_t careless(const gjk2d_shape_d* a, const gjk2d_shape_d* b, void* cache, gjk2d_result_d* out)
{
    const int32_t status = exampleGjk(a, b, cache, out);
    if (status != GJK2D_STATUS_OK)
        return status;
#if defined(CARELESS_NEGATIVE)
    out->distance = -1 - out->distance;
#elif defined(CARELESS_NAN_WITNESS)
    out->point_a[0] = out->point_a[1] = std::numeric_limits<double>::quiet_NaN();
    out->point_b[0] = out->point_b[1] = std::numeric_limits<double>::quiet_NaN();
#elif defined(CARELESS_SHIFT_WITNESS)
    out->point_a[0] += 10;
    out->point_b[0] += 10;
#elif defined(CARELESS_SWAP_WITNESS)
    std::swap(out->point_a[0], out->point_b[0]);
    std::swap(out->point_a[1], out->point_b[1]);
#elif defined(CARELESS_REL_ERROR)
    out->distance *= 1 + 1e-3;
#else
#error "define one CARELESS_<KIND>"
#endif
    return GJK2D_STATUS_OK;
}

const gjk2d_implementation kCareless[] = {
    {CARELESS_NAME, "the example plugin with one misbehaviour (tests/plugins/careless_plugin.cpp)",
     GJK2D_SCALAR_DOUBLE, GJK2D_ACCEPTS_RADIUS, 0, 0, nullptr, &careless},
};

const gjk2d_plugin kCarelessPlugin = {GJK2D_PLUGIN_ABI_VERSION, 1, kCareless, nullptr};

} // namespace

extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
{
    return &kCarelessPlugin;
}
