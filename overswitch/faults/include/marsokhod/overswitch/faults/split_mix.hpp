// SplitMix64: the random stream of a fault's draws and of a campaign's runs.
#pragma once

#include <cstddef>
#include <cstdint>

namespace marsokhod::overswitch {

/// SplitMix64 (Steele, Lea and Flood, 2014): a stream that depends on (seed, stream) alone, so
/// that any run of a campaign, and any draw of a fault, is replayed without the others.
class SplitMix {
public:
  SplitMix(std::uint64_t seed, std::uint64_t stream)
      : state_(seed * 0x9E3779B97F4A7C15ULL ^ (stream + 0x632BE59BD9B4E019ULL)) {
    next();
  }
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), 53 bits.
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in [0, n) (n > 0; the modulo bias is below 2^-40 for the n used here).
  std::uint64_t below(std::uint64_t n) { return next() % n; }

private:
  std::uint64_t state_;
};

} // namespace marsokhod::overswitch
