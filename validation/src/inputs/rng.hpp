// The families' deterministic generator: SplitMix64 with its distributions written out, so that
// the same seed gives the same cases on every platform. Used by families.cpp and engine.cpp.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace gjkval
{

struct Rng
{
    std::uint64_t state;
    // The family's own seed (set by generate()): generators that need the same geometry in
    // several cases (a configuration swept over scales, a pair in every point order) derive it
    // from this, not from the case's own stream.
    std::uint64_t family = 0;
    explicit Rng(std::uint64_t seed) : state(seed) {}
    std::uint64_t next()
    {
        state += 0x9e3779b97f4a7c15ULL;
        std::uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    double range(double a, double b) { return a + (b - a) * uniform(); }
    int integer(int lo, int hi) { return lo + int(next() % std::uint64_t(hi - lo + 1)); }
    double logUniform(double e0, double e1) { return std::pow(10.0, range(e0, e1)); }
    double sign() { return (next() & 1) ? 1.0 : -1.0; }
    template <class V> void shuffle(V& v)
    {
        for (std::size_t i = v.size(); i > 1; --i)
            std::swap(v[i - 1], v[std::size_t(next() % i)]);
    }
};

} // namespace gjkval
