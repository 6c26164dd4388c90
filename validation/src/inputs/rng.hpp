// The families' deterministic generator: SplitMix64 with its distributions written out, so that
// the same seed gives the same cases on every platform. Used by families.cpp and engine.cpp.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

namespace gjkval
{

// SplitMix64's output function: the hash of a state (Steele, Lea, Flood 2014). Also derives the
// families' seeds from names and indices.
inline std::uint64_t mix64(std::uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

inline std::uint64_t hashString(const std::string& s)
{
    std::uint64_t h = 0xcbf29ce484222325ULL; // FNV-1a
    for (unsigned char c : s)
        h = (h ^ c) * 0x100000001b3ULL;
    return h;
}

struct Rng
{
    std::uint64_t state;
    // The family's own seed (set by generate()): generators that need the same geometry in
    // several cases (a configuration swept over scales, a pair in every point order) derive it
    // from this, not from the case's own stream.
    std::uint64_t family = 0;
    explicit Rng(std::uint64_t seed) : state(seed) {}
    // SplitMix64: the state advances by the golden-ratio increment (which mix64 adds first).
    std::uint64_t next()
    {
        const std::uint64_t z = mix64(state);
        state += 0x9e3779b97f4a7c15ULL;
        return z;
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
