// The example plugin (examples/plugin/), built with PRINT_EVERY_CALL: each call of either
// implementation prints a line on stdout and one on stderr before answering as the example does.
// It checks that what a plugin prints is kept apart from gjk-validate's output (issue 30): in
// DIR/plugin-<file>.log, capped (kPluginLogCapBytes), with one line on the terminal naming it
// (plugin_output.py).
#if !defined(PRINT_EVERY_CALL)
#error "built with PRINT_EVERY_CALL only (tests/plugins/CMakeLists.txt)"
#endif

#include <cstdio>

// The example's own entry point, renamed: this file exports one that hands out printing copies.
#define gjk2d_plugin_describe example_plugin_describe
#include "../../examples/plugin/example_gjk_plugin.cpp"
#undef gjk2d_plugin_describe

namespace
{
// About 150 bytes on stdout and 60 on stderr per call.
void say(const char* impl, int countA, int countB)
{
    std::printf("printing plugin: %s called with %d and %d points; a line an engine's debug build "
                "might print on every query, padded to about 150 bytes\n",
                impl, countA, countB);
    std::fprintf(stderr, "printing plugin: %s says this on stderr\n", impl);
}

int32_t printingGjk(const gjk2d_shape_d* a, const gjk2d_shape_d* b, void* c, gjk2d_result_d* out)
{
    say("printing-gjk", a->count, b->count);
    return kImplementations[0].distance_d(a, b, c, out);
}

int32_t printingNaive(const gjk2d_shape_f* a, const gjk2d_shape_f* b, void* c, gjk2d_result_f* out)
{
    say("printing-naive-f32", a->count, b->count);
    return kImplementations[1].distance_f(a, b, c, out);
}

const gjk2d_implementation kPrinting[] = {
    {"printing-gjk", "the example's example-gjk, printing on every call", GJK2D_SCALAR_DOUBLE,
     GJK2D_ACCEPTS_RADIUS, 0, 0, nullptr, &printingGjk},
    {"printing-naive-f32", "the example's example-naive-f32, printing on every call",
     GJK2D_SCALAR_FLOAT, GJK2D_ACCEPTS_RADIUS, 0, 0, &printingNaive, nullptr},
};
const gjk2d_plugin kPrintingPlugin = {GJK2D_PLUGIN_ABI_VERSION, 2, kPrinting, nullptr};
} // namespace

extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
{
    return &kPrintingPlugin;
}
