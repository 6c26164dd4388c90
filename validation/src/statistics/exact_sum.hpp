// An exact sum of non-negative doubles, so that a histogram's sum and mean do not depend on the
// order of the values: on how the cases were cut into chunks, threads, shards or MPI ranks.
//
// Every finite double is an integer multiple of 2^-1074 (the smallest subnormal) below 2^1024, so a
// fixed-point integer whose least significant bit is 2^-1074 holds any such value exactly: 2098
// bits, plus 64 for up to 2^64 values. It is kept in 32-bit limbs stored in int64 words, so that
// an addition only adds to three words and carries wait: a word gains less than 2^32 per
// addition, and carries are propagated every 2^30 additions, long before a word can overflow.
// value() rounds the exact sum to the nearest double, ties to even, once.
#pragma once

#include "common/common.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace gjkval
{

class ExactSum
{
  public:
    static constexpr int kLimbBits = 32;
    static constexpr int kLsbExponent = -1074;          // the weight of bit 0 is 2^kLsbExponent
    static constexpr int kLimbs = (2098 + 64) / 32 + 2; // the value's bits, the count's, spare

    // v >= 0 and finite: a broken invariant otherwise (the histograms filter their values).
    void add(double v)
    {
        if (!(v >= 0) || !std::isfinite(v))
            throw std::logic_error("ExactSum::add: not a finite non-negative value");
        if (v == 0)
            return;
        int e = 0;
        const double f = std::frexp(v, &e); // v = f 2^e, f in [0.5, 1)
        auto m = std::uint64_t(std::ldexp(f, 53));
        int low = e - 53 - kLsbExponent; // the bit position of m's bit 0
        if (low < 0)                     // a subnormal: m's lowest -low bits are zeros
        {
            m >>= -low;
            low = 0;
        }
        const auto x = static_cast<unsigned __int128>(m) << (low % kLimbBits);
        const int i = low / kLimbBits;
        limbs_[std::size_t(i)] += std::int64_t(std::uint64_t(x) & kLimbMask);
        limbs_[std::size_t(i) + 1] += std::int64_t(std::uint64_t(x >> 32) & kLimbMask);
        limbs_[std::size_t(i) + 2] += std::int64_t(std::uint64_t(x >> 64));
        if (++pending_ == kCarryEvery)
            normalize();
    }

    void merge(const ExactSum& o)
    {
        ExactSum b = o;
        b.normalize();
        normalize();
        for (std::size_t i = 0; i < limbs_.size(); ++i)
            limbs_[i] += b.limbs_[i];
        normalize();
    }

    // The exact sum rounded to the nearest double (ties to even); +inf beyond the largest double.
    double value() const
    {
        ExactSum s = *this;
        s.normalize();
        int top = kLimbs * kLimbBits - 1; // the highest set bit
        while (top >= 0 && !s.bit(top))
            --top;
        if (top < 0)
            return 0;
        if (top < 53) // at most 53 bits from bit 0: exactly representable
            return std::ldexp(double(s.bits(0, top + 1)), kLsbExponent);
        const int low = top - 52; // the 53 bits kept: top .. low
        std::uint64_t m = s.bits(low, 53);
        const bool half = s.bit(low - 1);
        bool sticky = false;
        for (int b = low - 2; b >= 0 && !sticky; --b)
            sticky = s.bit(b);
        if (half && (sticky || (m & 1) != 0))
            ++m; // 2^53 is still exact in a double: ldexp below gives the next binade
        return std::ldexp(double(m), low + kLsbExponent);
    }

    bool operator==(const ExactSum& o) const
    {
        ExactSum a = *this, b = o;
        a.normalize();
        b.normalize();
        return a.limbs_ == b.limbs_;
    }

    // The state, for shards and checkpoints: the normalised limbs from the lowest non-zero one.
    Json toJson() const
    {
        ExactSum s = *this;
        s.normalize();
        std::size_t lo = 0, hi = s.limbs_.size();
        while (lo < hi && s.limbs_[lo] == 0)
            ++lo;
        while (hi > lo && s.limbs_[hi - 1] == 0)
            --hi;
        Json limbs = Json::array();
        for (std::size_t i = lo; i < hi; ++i)
            limbs.push_back(std::uint64_t(s.limbs_[i]));
        return Json{{"first_limb", lo}, {"limbs", limbs}};
    }
    static ExactSum fromJson(const Json& j)
    {
        ExactSum s;
        const auto lo = j.at("first_limb").get<std::size_t>();
        const Json& limbs = j.at("limbs");
        if (lo + limbs.size() > s.limbs_.size())
            throw std::runtime_error("ExactSum: too many limbs");
        for (std::size_t i = 0; i < limbs.size(); ++i)
        {
            const auto v = limbs[i].get<std::uint64_t>();
            if (v > kLimbMask)
                throw std::runtime_error("ExactSum: a limb exceeds 32 bits");
            s.limbs_[lo + i] = std::int64_t(v);
        }
        return s;
    }

  private:
    static constexpr std::uint64_t kLimbMask = 0xffffffffu;
    static constexpr std::uint32_t kCarryEvery = 1u << 30;

    // Every word back into [0, 2^32), the carries moved up.
    void normalize()
    {
        for (std::size_t i = 0; i + 1 < limbs_.size(); ++i)
        {
            limbs_[i + 1] += limbs_[i] >> kLimbBits;
            limbs_[i] &= std::int64_t(kLimbMask);
        }
        pending_ = 0;
    }
    // Normalised only.
    bool bit(int b) const
    {
        return b >= 0 && ((limbs_[std::size_t(b / kLimbBits)] >> (b % kLimbBits)) & 1) != 0;
    }
    std::uint64_t bits(int from, int n) const // n <= 64
    {
        std::uint64_t r = 0;
        for (int k = n - 1; k >= 0; --k)
            r = (r << 1) | (bit(from + k) ? 1u : 0u);
        return r;
    }

    std::array<std::int64_t, kLimbs> limbs_{};
    std::uint32_t pending_ = 0; // additions since the last normalize()
};

} // namespace gjkval
