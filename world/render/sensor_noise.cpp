// Camera sensor noise: the polar Box-Muller transform over std::mt19937_64's raw output.

#include "marsokhod/world/render/sensor_noise.hpp"

#include <cmath>

namespace marsokhod::world {

double GaussianNoise::uniform_signed() {
  // The top 53 bits fill a double's mantissa exactly.
  return static_cast<double>(engine_() >> 11) * 0x1.0p-52 - 1.0;
}

double GaussianNoise::next_pair() {
  // Marsaglia's polar form of Box-Muller: a point uniform in the unit disc gives two
  // independent deviates without trigonometry.
  double a = 0.0;
  double b = 0.0;
  double s = 0.0;
  do {
    a = uniform_signed();
    b = uniform_signed();
    s = a * a + b * b;
  } while (s >= 1.0 || s == 0.0);
  const double scale = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = b * scale;
  has_spare_ = true;
  return a * scale;
}

} // namespace marsokhod::world
