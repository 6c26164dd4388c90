// A shipped plugin's prepared shapes (gjk2d/plugin.h, gjk2d_plugin_prepared) answer as its
// distance_f / distance_d, bit for bit: status, distance, both witness points and the iteration
// count, on every case of the given families and case files, for every implementation of the
// plugin. Each case in a child process (chunks of cases, one child each, and case by case in a
// chunk whose child dies: FCL aborts on some cases of huge coordinates; a case that brings the
// library down is counted, not failed, since distance_d is the prepared form itself):
// - the plain call: distance_f / distance_d, a zeroed cache;
// - the prepared form: prepare both shapes (a `case` scope gets the other shape), query, release;
// - the same prepared shapes queried a second time (a query keeps no state);
// - `shape` scope only: the shapes prepared from copies placed elsewhere (position (7, -3),
//   rotation (0, 1)), queried with the case's own transforms (a preparation reads no transform,
//   so one serves every pose).
// Cases the description refuses (radius, max_vertices) are left out, as the runner leaves them.
// Every compared case's two shapes are then prepared and released once more in this process, so
// that under the sanitize preset LeakSanitizer checks that release frees what prepare took.
//
//     prepared_equal --plugin PATH [--family SPEC]... [--cases FILE]... [--seed N]
//                    [--within NAME TOL]
//
// --within NAME TOL: implementation NAME's distance and points are compared within TOL * max(1,
// |value|) each, not bit for bit (status and iterations still exactly), and the largest difference
// is printed: for a library whose answer is not a function of its inputs alone. FCL's signed
// distance (fcl-0.7-libccd-signed) is one: its EPA's pair moves in the last bits with the heap
// addresses its polytope gets (the same case queried twice in one process, docs/peers/fcl.md).
//
// Exit 0: every case equal; 1: a difference (the first few printed) or a plugin without the
// prepared entry point; 2: bad arguments.
#include "inputs/sources.hpp"

#include <gjk2d/plugin.h>

#include <dlfcn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace
{

// One answer in the implementation's scalar type, as raw bytes of its fields (compared bit for
// bit: NaN payloads and the sign of zero included).
struct Answer
{
    int32_t status = -1;
    double distance = 0, ax = 0, ay = 0, bx = 0, by = 0; // the scalar's value, widened exactly
    int32_t iterations = 0;
};

bool sameBits(double x, double y)
{
    return std::memcmp(&x, &y, sizeof x) == 0;
}

// The largest |x - y| / max(1, |x|) over an answer's five numbers (0 when either status is not OK
// and both are the same).
double relativeGap(const Answer& x, const Answer& y)
{
    if (x.status != GJK2D_STATUS_OK || y.status != GJK2D_STATUS_OK)
        return x.status == y.status ? 0 : INFINITY;
    double gap = 0;
    const double xs[] = {x.distance, x.ax, x.ay, x.bx, x.by};
    const double ys[] = {y.distance, y.ax, y.ay, y.bx, y.by};
    for (int i = 0; i < 5; ++i)
        if (!sameBits(xs[i], ys[i]))
            gap = std::max(gap, std::abs(xs[i] - ys[i]) / std::max(1.0, std::abs(xs[i])));
    return std::isnan(gap) ? INFINITY : gap;
}

bool operator==(const Answer& x, const Answer& y)
{
    if (x.status != y.status)
        return false;
    if (x.status != GJK2D_STATUS_OK)
        return true; // the result is unspecified when the status is not OK
    return sameBits(x.distance, y.distance) && sameBits(x.ax, y.ax) && sameBits(x.ay, y.ay) &&
           sameBits(x.bx, y.bx) && sameBits(x.by, y.by) && x.iterations == y.iterations;
}

std::string show(const Answer& a)
{
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "status %d, distance %.17g, pA (%.17g, %.17g), pB (%.17g, %.17g), "
                  "iterations %d",
                  a.status, a.distance, a.ax, a.ay, a.bx, a.by, a.iterations);
    return buf;
}

// The case in the implementation's scalar type: the points, and the two shapes over them.
template <class T, class S> struct Shapes
{
    std::vector<T> pa, pb;
    S a{}, b{};
};

template <class T, class S> S shapeOf(const gjkval::ShapeIn& s, std::vector<T>& points)
{
    points.clear();
    for (const auto& p : s.points)
    {
        points.push_back(T(p[0]));
        points.push_back(T(p[1]));
    }
    return S{
        points.data(), int32_t(s.points.size()), T(s.radius), {T(s.px), T(s.py)}, {T(s.c), T(s.s)}};
}

template <class R> Answer answerOf(int32_t status, const R& r)
{
    return Answer{status,
                  double(r.distance),
                  double(r.point_a[0]),
                  double(r.point_a[1]),
                  double(r.point_b[0]),
                  double(r.point_b[1]),
                  r.iterations};
}

// The four answers of one case (see the header comment); `moved` is the prepared form on shapes
// prepared elsewhere (shape scope), else a copy of `prepared`.
struct Answers
{
    Answer plain, prepared, again, moved;
};

template <class T, class S, class R, class Fn>
Answers answer(const gjk2d_implementation& im, const gjk2d_prepared& pr, int32_t index, Fn plainFn,
               const gjkval::Case& c)
{
    Shapes<T, S> sh;
    sh.a = shapeOf<T, S>(c.a, sh.pa);
    sh.b = shapeOf<T, S>(c.b, sh.pb);
    const std::size_t cacheBytes = std::size_t(im.cache_bytes > 0 ? im.cache_bytes : 0);
    std::vector<unsigned char> cache(cacheBytes, 0);
    auto cachePtr = [&]
    {
        std::fill(cache.begin(), cache.end(), 0);
        return cache.empty() ? nullptr : cache.data();
    };
    Answers out;
    R r{};
    out.plain = answerOf(plainFn(&sh.a, &sh.b, cachePtr(), &r), r);

    const bool caseScope = pr.scope(index) == GJK2D_PREPARED_CASE;
    auto query = [&](const S& prepareA, const S& prepareB)
    {
        void* pa = pr.prepare(index, &prepareA, caseScope ? &prepareB : nullptr);
        void* pb = pr.prepare(index, &prepareB, caseScope ? &prepareA : nullptr);
        Answer first{GJK2D_STATUS_ERROR}, second{GJK2D_STATUS_ERROR};
        if (pa != nullptr && pb != nullptr)
        {
            R q{};
            first = answerOf(pr.distance(index, pa, &sh.a, pb, &sh.b, cachePtr(), &q), q);
            R q2{};
            second = answerOf(pr.distance(index, pa, &sh.a, pb, &sh.b, cachePtr(), &q2), q2);
        }
        if (pa != nullptr)
            pr.release(index, pa);
        if (pb != nullptr)
            pr.release(index, pb);
        return std::pair<Answer, Answer>{first, second};
    };
    const auto [first, second] = query(sh.a, sh.b);
    out.prepared = first;
    out.again = second;
    out.moved = first;
    if (!caseScope)
    {
        S ma = sh.a, mb = sh.b;
        for (S* m : {&ma, &mb})
        {
            m->position[0] = T(7);
            m->position[1] = T(-3);
            m->rotation[0] = T(0);
            m->rotation[1] = T(1);
        }
        out.moved = query(ma, mb).first;
    }
    return out;
}

bool refusedByDescription(const gjk2d_implementation& im, const gjkval::Case& c)
{
    const bool isFloat = im.scalar == GJK2D_SCALAR_FLOAT;
    const double ra = isFloat ? double(float(c.a.radius)) : c.a.radius;
    const double rb = isFloat ? double(float(c.b.radius)) : c.b.radius;
    if ((im.accepts & GJK2D_ACCEPTS_RADIUS) == 0 && (ra > 0 || rb > 0))
        return true;
    const std::size_t n = std::max(c.a.points.size(), c.b.points.size());
    return im.max_vertices > 0 && n > std::size_t(im.max_vertices);
}

// The case's two shapes prepared and released, in this process (LeakSanitizer's check).
void prepareAndRelease(const gjk2d_implementation& im, const gjk2d_prepared& pr, int32_t index,
                       const gjkval::Case& c)
{
    auto run = [&](auto* tag)
    {
        using T = std::remove_pointer_t<decltype(tag)>;
        using S = std::conditional_t<std::is_same_v<T, float>, gjk2d_shape_f, gjk2d_shape_d>;
        Shapes<T, S> sh;
        sh.a = shapeOf<T, S>(c.a, sh.pa);
        sh.b = shapeOf<T, S>(c.b, sh.pb);
        const bool caseScope = pr.scope(index) == GJK2D_PREPARED_CASE;
        for (void* p : {pr.prepare(index, &sh.a, caseScope ? &sh.b : nullptr),
                        pr.prepare(index, &sh.b, caseScope ? &sh.a : nullptr)})
            if (p != nullptr)
                pr.release(index, p);
    };
    if (im.scalar == GJK2D_SCALAR_FLOAT)
        run(static_cast<float*>(nullptr));
    else
        run(static_cast<double*>(nullptr));
}

// The answers of cases[first, first + count) computed in a child process, written back through a
// pipe. False: the child did not finish (a crash, an abort in the library).
bool answerInChild(const gjk2d_implementation& im, const gjk2d_prepared& pr, int32_t index,
                   const std::vector<const gjkval::Case*>& cases, std::size_t first,
                   std::size_t count, std::vector<Answers>& out)
{
    int fd[2];
    if (::pipe(fd) != 0)
    {
        std::perror("pipe");
        std::exit(2);
    }
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0)
    {
        std::perror("fork");
        std::exit(2);
    }
    if (pid == 0)
    {
        ::close(fd[0]);
        for (std::size_t k = first; k < first + count; ++k)
        {
            const gjkval::Case& c = *cases[k];
            const Answers a =
                im.scalar == GJK2D_SCALAR_FLOAT
                    ? answer<float, gjk2d_shape_f, gjk2d_result_f>(im, pr, index, im.distance_f, c)
                    : answer<double, gjk2d_shape_d, gjk2d_result_d>(im, pr, index, im.distance_d,
                                                                    c);
            if (::write(fd[1], &a, sizeof a) != ssize_t(sizeof a))
                ::_exit(3);
        }
        ::_exit(0); // no exit handlers: the parent's LeakSanitizer run is the one that counts
    }
    ::close(fd[1]);
    std::vector<Answers> got(count);
    std::size_t bytes = 0;
    const std::size_t want = count * sizeof(Answers);
    auto* dst = reinterpret_cast<char*>(got.data());
    for (ssize_t n; bytes < want && (n = ::read(fd[0], dst + bytes, want - bytes)) > 0;)
        bytes += std::size_t(n);
    ::close(fd[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (bytes != want || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return false;
    out = std::move(got);
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    std::string plugin, withinName;
    double withinTolerance = 0;
    std::vector<std::string> families, files;
    std::uint64_t seed = 1;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (i + 1 >= argc || (arg == "--within" && i + 2 >= argc))
        {
            std::fprintf(stderr, "prepared_equal: %s needs a value\n", arg.c_str());
            return 2;
        }
        const std::string value = argv[++i];
        if (arg == "--within")
        {
            withinName = value;
            withinTolerance = std::stod(argv[++i]);
        }
        else if (arg == "--plugin")
            plugin = value;
        else if (arg == "--family")
            families.push_back(value);
        else if (arg == "--cases")
            files.push_back(value);
        else if (arg == "--seed")
            seed = std::stoull(value);
        else
        {
            std::fprintf(stderr, "prepared_equal: unknown argument %s\n", arg.c_str());
            return 2;
        }
    }
    if (plugin.empty() || (families.empty() && files.empty()))
    {
        std::fprintf(stderr, "usage: prepared_equal --plugin PATH [--family SPEC]... "
                             "[--cases FILE]... [--seed N]\n");
        return 2;
    }
    void* handle = ::dlopen(plugin.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
    {
        std::fprintf(stderr, "prepared_equal: cannot load %s: %s\n", plugin.c_str(), ::dlerror());
        return 2;
    }
    auto describe =
        reinterpret_cast<gjk2d_plugin_describe_fn>(::dlsym(handle, GJK2D_PLUGIN_ENTRY_POINT));
    auto prepared =
        reinterpret_cast<gjk2d_plugin_prepared_fn>(::dlsym(handle, GJK2D_PLUGIN_PREPARED_ENTRY));
    if (describe == nullptr || prepared == nullptr)
    {
        std::fprintf(stderr, "prepared_equal: %s does not export %s\n", plugin.c_str(),
                     describe == nullptr ? GJK2D_PLUGIN_ENTRY_POINT : GJK2D_PLUGIN_PREPARED_ENTRY);
        return 1;
    }
    const gjk2d_plugin* d = describe();
    const gjk2d_prepared* pr = prepared();

    const std::vector<gjkval::FamilyData> inputs = gjkval::collectInputs(families, files, seed);
    int failures = 0;
    for (int32_t index = 0; index < d->count; ++index)
    {
        const gjk2d_implementation& im = d->implementations[index];
        const int32_t scope = pr->scope(index);
        std::vector<const gjkval::Case*> cases;
        std::size_t refused = 0, crashed = 0;
        for (const gjkval::FamilyData& f : inputs)
            for (std::size_t k = 0; k < f.cases.size(); ++k)
                if (f.rejected[k].empty())
                {
                    if (refusedByDescription(im, f.cases[k]))
                        ++refused;
                    else
                        cases.push_back(&f.cases[k]);
                }
        // Chunks of cases, one child each; a chunk whose child dies is answered case by case, so
        // that only the cases that bring the library down are left out.
        constexpr std::size_t kChunk = 256;
        std::vector<Answers> answers(cases.size());
        std::vector<bool> answered(cases.size(), false);
        for (std::size_t first = 0; first < cases.size(); first += kChunk)
        {
            const std::size_t count = std::min(kChunk, cases.size() - first);
            std::vector<Answers> chunk;
            if (answerInChild(im, *pr, index, cases, first, count, chunk))
            {
                std::copy(chunk.begin(), chunk.end(), answers.begin() + std::ptrdiff_t(first));
                std::fill(answered.begin() + std::ptrdiff_t(first),
                          answered.begin() + std::ptrdiff_t(first + count), true);
                continue;
            }
            for (std::size_t k = first; k < first + count; ++k)
                if (answerInChild(im, *pr, index, cases, k, 1, chunk))
                {
                    answers[k] = chunk[0];
                    answered[k] = true;
                }
                else
                    ++crashed;
        }
        std::size_t compared = 0;
        const bool within = withinName == im.name;
        double largestGap = 0;
        for (std::size_t k = 0; k < cases.size(); ++k)
        {
            if (!answered[k])
                continue;
            ++compared;
            prepareAndRelease(im, *pr, index, *cases[k]);
            const Answers& a = answers[k];
            const struct
            {
                const char* what;
                const Answer& answer;
            } forms[] = {{"prepared", a.prepared},
                         {"prepared, queried again", a.again},
                         {"prepared elsewhere (shape scope)", a.moved}};
            for (const auto& form : forms)
            {
                const double gap = within ? relativeGap(a.plain, form.answer) : 0;
                largestGap = std::max(largestGap, gap);
                const bool equal =
                    within ? gap <= withinTolerance && form.answer.iterations == a.plain.iterations
                           : form.answer == a.plain;
                if (!equal && ++failures <= 10)
                    std::printf("%s, case %s: %s differs:\n  plain:    %s\n  %s: %s\n", im.name,
                                cases[k]->name.c_str(), form.what, show(a.plain).c_str(), form.what,
                                show(form.answer).c_str());
            }
        }
        if (within)
            std::printf("%s: compared within %g: the largest difference %.3g\n", im.name,
                        withinTolerance, largestGap);
        std::printf(
            "%s (scope %s): %zu cases compared, %zu refused by the description, %zu brought "
            "the library down\n",
            im.name, scope == GJK2D_PREPARED_SHAPE ? "shape" : "case", compared, refused, crashed);
    }
    // The library stays loaded: LeakSanitizer's report at exit names its frames.
    if (failures > 0)
    {
        std::printf("%d differences\n", failures);
        return 1;
    }
    return 0;
}
