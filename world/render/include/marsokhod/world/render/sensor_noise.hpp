// Camera sensor noise: Gaussian deviates that are the same on every standard library.
#pragma once

#include <cstdint>
#include <random>

namespace marsokhod::world {

/// Standard normal deviates for camera sensor noise, drawn from std::mt19937_64's raw output by
/// the polar Box-Muller transform, so a seed gives the same numbers with every standard library
/// (std::normal_distribution does not promise that).
class GaussianNoise {
public:
  explicit GaussianNoise(std::uint64_t seed) : engine_(seed) {}

  /// The next deviate (mean 0, standard deviation 1).
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    return next_pair();
  }

private:
  double next_pair();      // draws two, keeps the second as the spare
  double uniform_signed(); // in [-1, 1)

  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

} // namespace marsokhod::world
