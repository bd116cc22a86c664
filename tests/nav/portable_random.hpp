// Test support for the nav tests: random numbers that are the same on every library.
#pragma once

// Random numbers that are the same on every standard library: std::mt19937_64's sequence is
// fixed by the standard, its distributions are not.

#include <random>

namespace marsokhod::nav::testing {

/// Uniform in [0, 1) from the generator's top 53 bits.
inline double unit(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

} // namespace marsokhod::nav::testing
