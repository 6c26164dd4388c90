// Tolerances that are what they say, for every Catch2 test (docs/testing.md, "Rules every test is
// held to"). Catch's Approx(x) given only a margin m passes when |a - x| <= m OR when
// |a - x| <= epsilon |x|, and its default epsilon is 100 x FLT_EPSILON (about 1.19e-5): at x = 2 a
// double margin of 8.5e-14 becomes 2.4e-5, some 10^8 looser than written. within() sets epsilon
// to 0, so only the stated margin counts: CHECK(out.distance == within(expected, tol)) passes iff
// |out.distance - expected| <= tol (the sum rounded in double, as Catch computes it).
#pragma once

#include <catch2/catch.hpp>

template <class T, class U> Catch::Detail::Approx within(T expected, U margin)
{
    return Catch::Detail::Approx(double(expected)).epsilon(0).margin(double(margin));
}
