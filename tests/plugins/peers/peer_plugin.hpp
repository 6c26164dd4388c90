// Calls one implementation of a shipped peer's shared library (gjk2d/plugin.h) as gjk-validate
// does: dlopen, gjk2d_plugin_describe, the implementation's distance function on one case, in the
// implementation's scalar type, and reads its declared contract. For the tests of the FCL and
// Bullet adapters (docs/peers.md).
#pragma once

#include <gjk2d/plugin.h>

#include <dlfcn.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace peers
{

// A case's shape in double: points x0, y0, x1, y1, ..., radius, world = R * local + p, R from (c,
// s).
struct Shape
{
    std::vector<double> points;
    double radius = 0;
    double px = 0, py = 0;
    double c = 1, s = 0;
};

struct Answer
{
    int32_t status = -1;
    double distance = 0;
    double ax = 0, ay = 0, bx = 0, by = 0; // witness points on A and on B (world)
};

// The library's description and the named implementation; throws when either is missing.
class Plugin
{
  public:
    Plugin(const std::string& path, const std::string& name)
    {
        handle_ = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle_)
            throw std::runtime_error("cannot load " + path + ": " + ::dlerror());
        auto describe =
            reinterpret_cast<gjk2d_plugin_describe_fn>(::dlsym(handle_, GJK2D_PLUGIN_ENTRY_POINT));
        if (!describe)
            throw std::runtime_error(path + " does not export " GJK2D_PLUGIN_ENTRY_POINT);
        const gjk2d_plugin* d = describe();
        auto depth =
            reinterpret_cast<gjk2d_plugin_depth_fn>(::dlsym(handle_, GJK2D_PLUGIN_DEPTH_ENTRY));
        const gjk2d_depth_contract* clauses = depth ? depth() : nullptr;
        for (int32_t i = 0; i < d->count; ++i)
            if (name == d->implementations[i].name)
            {
                impl_ = &d->implementations[i];
                if (d->abi_version >= 2 && d->contracts != nullptr)
                    contract_ = &d->contracts[i];
                if (clauses != nullptr)
                    depth_ = &clauses[i];
            }
        if (!impl_)
            throw std::runtime_error(path + " has no implementation " + name);
        auto library =
            reinterpret_cast<const char* (*)()>(::dlsym(handle_, "gjk2d_plugin_library"));
        library_ = library ? library() : "";
    }
    Plugin(const Plugin&) = delete;
    Plugin& operator=(const Plugin&) = delete;
    ~Plugin() { ::dlclose(handle_); }

    const gjk2d_implementation& implementation() const { return *impl_; }
    // The implementation's declared contract (ABI version 2); nullptr: gjk2d's own.
    const gjk2d_contract* contract() const { return contract_; }
    // Its depth clause (gjk2d_plugin_depth); nullptr when the plugin does not export one.
    const gjk2d_depth_contract* depth() const { return depth_; }
    const std::string& library() const { return library_; }

    // The case in the implementation's scalar type (a float implementation gets it rounded).
    Answer distance(const Shape& a, const Shape& b) const
    {
        if (impl_->scalar == GJK2D_SCALAR_FLOAT)
            return call<float, gjk2d_shape_f, gjk2d_result_f>(a, b, impl_->distance_f,
                                                              impl_->cache_bytes);
        return call<double, gjk2d_shape_d, gjk2d_result_d>(a, b, impl_->distance_d,
                                                           impl_->cache_bytes);
    }

  private:
    // A cold start: cache_bytes zeroed bytes (NULL when 0), as the runner calls it.
    template <class T, class S, class R, class Fn>
    static Answer call(const Shape& a, const Shape& b, Fn fn, int32_t cacheBytes)
    {
        std::vector<unsigned char> cache(std::size_t(cacheBytes > 0 ? cacheBytes : 0), 0);
        const std::vector<T> pa(a.points.begin(), a.points.end());
        const std::vector<T> pb(b.points.begin(), b.points.end());
        const auto shape = [](const Shape& s, const std::vector<T>& p) {
            return S{
                p.data(), int32_t(p.size() / 2), T(s.radius), {T(s.px), T(s.py)}, {T(s.c), T(s.s)}};
        };
        const S sa = shape(a, pa), sb = shape(b, pb);
        R r{};
        Answer out;
        out.status = fn(&sa, &sb, cache.empty() ? nullptr : cache.data(), &r);
        out.distance = r.distance;
        out.ax = r.point_a[0];
        out.ay = r.point_a[1];
        out.bx = r.point_b[0];
        out.by = r.point_b[1];
        return out;
    }

    void* handle_ = nullptr;
    const gjk2d_implementation* impl_ = nullptr;
    const gjk2d_contract* contract_ = nullptr;
    const gjk2d_depth_contract* depth_ = nullptr;
    std::string library_;
};

// The unit square [0, 1]^2 placed at (px, py) with rotation (c, s).
inline Shape unitSquare(double px = 0, double py = 0, double c = 1, double s = 0)
{
    return Shape{{0, 0, 1, 0, 1, 1, 0, 1}, 0, px, py, c, s};
}

// Leaves `byte` in the stack below the caller, where the adapter's locals will be (the tests of
// answers that must not depend on memory left by earlier calls).
[[gnu::noinline]] inline void dirtyStack(unsigned char byte)
{
    volatile unsigned char junk[1 << 16];
    for (auto& b : junk)
        b = byte;
}

} // namespace peers
