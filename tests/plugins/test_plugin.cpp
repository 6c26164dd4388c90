// Plugins that misbehave on purpose, for the containment and bad-plugin tests
// (tests/plugins/CMakeLists.txt). One source, one behaviour per compile definition:
//   GOOD_BUT_QUIRKY  answers with gjk2d's reference options (double), but refuses cases where A
//                    has a multiple of 3 points and answers GJK2D_STATUS_ERROR when A has 3k+1
//                    points and B a multiple of 3
//   CRASH            like the above, but raises SIGSEGV where (countA + countB) % 5 == 0
//   HANG             like the above, but never returns where (countA + countB) % 5 == 0
//   FORK_HANG        like HANG, but first leaves two children that sleep 300 s, their PIDs
//                    appended to the file $GJK2D_TEST_PIDS: one in the plugin child's process
//                    group, one out of it (setsid)
//   WRONG_ABI        describes itself with abi_version GJK2D_PLUGIN_ABI_VERSION + 1
//   BAD_DESCRIPTION  an implementation with scalar 7
//   NO_ENTRY         exports no gjk2d_plugin_describe
#include <gjk2d/plugin.h>

#include <gjk2d/distance.hpp>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace
{

#if defined(FORK_HANG)
// Each child has left the group, when it does, before its PID is written.
void leaveSleepers()
{
    for (const bool leave : {false, true})
    {
        int ready[2];
        if (::pipe(ready) != 0)
            return;
        const pid_t pid = ::fork();
        if (pid == 0)
        {
            if (leave)
                ::setsid();
            (void)!::write(ready[1], "1", 1);
            ::sleep(300);
            ::_exit(0);
        }
        char c;
        ::close(ready[1]);
        (void)!::read(ready[0], &c, 1);
        ::close(ready[0]);
        if (std::FILE* f = std::fopen(std::getenv("GJK2D_TEST_PIDS"), "a"))
        {
            std::fprintf(f, "%d\n", int(pid));
            std::fclose(f);
        }
    }
}
#endif

int32_t answer(const gjk2d_shape_d* a, const gjk2d_shape_d* b, void*, gjk2d_result_d* out)
{
#if defined(CRASH) || defined(HANG) || defined(FORK_HANG)
    if ((a->count + b->count) % 5 == 0)
    {
#if defined(CRASH)
        std::raise(SIGSEGV);
#else
#if defined(FORK_HANG)
        leaveSleepers();
#endif
        for (;;)
            ::pause();
#endif
    }
#endif
    if (a->count % 3 == 0)
        return GJK2D_STATUS_REFUSED;
    if (a->count % 3 == 1 && b->count % 3 == 0)
        return GJK2D_STATUS_ERROR;
    auto poly = [](const gjk2d_shape_d& s)
    {
        return gjk::Polygon<double>{reinterpret_cast<const gjk::Vec2<double>*>(s.points), s.count,
                                    s.radius};
    };
    auto xf = [](const gjk2d_shape_d& s) {
        return gjk::Transform<double>{{s.position[0], s.position[1]},
                                      {s.rotation[0], s.rotation[1]}};
    };
    gjk::SimplexCache cache;
    const auto o =
        gjk::distance(gjk::DistanceInput<double>{poly(*a), poly(*b), xf(*a), xf(*b)}, cache);
    out->distance = o.distance;
    out->point_a[0] = o.pointA.x;
    out->point_a[1] = o.pointA.y;
    out->point_b[0] = o.pointB.x;
    out->point_b[1] = o.pointB.y;
    out->iterations = o.iterations;
    return GJK2D_STATUS_OK;
}

const gjk2d_implementation kImplementations[] = {
    {TEST_PLUGIN_NAME, "a test plugin (tests/plugins)",
#if defined(BAD_DESCRIPTION)
     7,
#else
     GJK2D_SCALAR_DOUBLE,
#endif
     GJK2D_ACCEPTS_RADIUS, 0, 0, nullptr, &answer},
};

const gjk2d_plugin kPlugin = {
#if defined(WRONG_ABI)
    GJK2D_PLUGIN_ABI_VERSION + 1,
#else
    GJK2D_PLUGIN_ABI_VERSION,
#endif
    1, kImplementations, nullptr};

} // namespace

#if defined(NO_ENTRY)
extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe_misspelt(void)
#else
extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_plugin* gjk2d_plugin_describe(void)
#endif
{
    return &kPlugin;
}

#if defined(BAD_DEPTH)
// A depth clause that is no number (gjk2d_plugin_depth): refused, exit 2, one line.
extern "C" GJK2D_PLUGIN_EXPORT const gjk2d_depth_contract* gjk2d_plugin_depth(void)
{
    static const gjk2d_depth_contract kDepth[] = {{__builtin_nan(""), -1, "a NaN on purpose"}};
    return kDepth;
}
#endif
