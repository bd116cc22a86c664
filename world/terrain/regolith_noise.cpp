// Value noise on grid images: Catmull-Rom lattice noise, fractal sums and white noise.

#include "marsokhod/world/terrain/regolith_noise.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace marsokhod::world {
namespace {

/// Catmull-Rom weights of the four lattice values around a point at fraction t in [0, 1).
std::array<float, 4> catmull_rom_weights(double t) {
  const double t2 = t * t;
  const double t3 = t2 * t;
  return {static_cast<float>(0.5 * (-t3 + 2.0 * t2 - t)),
          static_cast<float>(0.5 * (3.0 * t3 - 5.0 * t2 + 2.0)),
          static_cast<float>(0.5 * (-3.0 * t3 + 4.0 * t2 + t)),
          static_cast<float>(0.5 * (t3 - t2))};
}

/// The lattice columns (or rows) one grid axis touches, and per node its first tap and weights.
struct AxisTaps {
  std::int64_t first_lattice = 0; ///< lattice index of entry 0
  int lattice_count = 0;
  std::vector<int> first_tap;                ///< per node, entry of its tap 0
  std::vector<std::array<float, 4>> weights; ///< per node
};

AxisTaps axis_taps(double origin, double cell, int nodes, double inv_wavelength) {
  AxisTaps taps;
  const double start = origin * inv_wavelength;
  const double step = cell * inv_wavelength;
  const auto lo = static_cast<std::int64_t>(std::floor(start)) - 1;
  const auto hi = static_cast<std::int64_t>(std::floor(start + (nodes - 1) * step)) + 2;
  taps.first_lattice = lo;
  taps.lattice_count = static_cast<int>(hi - lo + 1);
  taps.first_tap.resize(static_cast<std::size_t>(nodes));
  taps.weights.resize(static_cast<std::size_t>(nodes));
  for (int n = 0; n < nodes; ++n) {
    const double u = start + n * step;
    const double cell_floor = std::floor(u);
    taps.first_tap[static_cast<std::size_t>(n)] =
        static_cast<int>(static_cast<std::int64_t>(cell_floor) - 1 - lo);
    taps.weights[static_cast<std::size_t>(n)] = catmull_rom_weights(u - cell_floor);
  }
  return taps;
}

} // namespace

void add_value_noise(imaging::Image<float>& field, const GridFrame& frame,
                     const NoiseOctave& octave, std::uint64_t seed) {
  if (!(octave.wavelength_m > 0.0) || !std::isfinite(octave.wavelength_m))
    throw std::invalid_argument("add_value_noise: wavelength must be positive");
  const double inv_wavelength = 1.0 / octave.wavelength_m;
  const AxisTaps xs = axis_taps(frame.origin.x(), frame.cell_m, field.width(), inv_wavelength);
  const AxisTaps ys = axis_taps(frame.origin.y(), frame.cell_m, field.height(), inv_wavelength);

  const auto lattice_width = static_cast<std::size_t>(xs.lattice_count);
  std::vector<float> lattice(lattice_width * static_cast<std::size_t>(ys.lattice_count));
  for (int b = 0; b < ys.lattice_count; ++b)
    for (int a = 0; a < xs.lattice_count; ++a)
      lattice[static_cast<std::size_t>(b) * lattice_width + static_cast<std::size_t>(a)] =
          lattice_value(seed, xs.first_lattice + a, ys.first_lattice + b);

  // Interpolate along y once per row into a lattice-wide line, then along x per node.
  std::vector<float> line(lattice_width);
  const auto amplitude = static_cast<float>(octave.amplitude);
  for (int j = 0; j < field.height(); ++j) {
    const auto& wy = ys.weights[static_cast<std::size_t>(j)];
    const float* rows =
        lattice.data() +
        static_cast<std::size_t>(ys.first_tap[static_cast<std::size_t>(j)]) * lattice_width;
    for (std::size_t a = 0; a < lattice_width; ++a)
      line[a] = wy[0] * rows[a] + wy[1] * rows[a + lattice_width] +
                wy[2] * rows[a + 2 * lattice_width] + wy[3] * rows[a + 3 * lattice_width];
    float* out = field.row(j);
    for (int i = 0; i < field.width(); ++i) {
      const auto& wx = xs.weights[static_cast<std::size_t>(i)];
      const float* taps = line.data() + xs.first_tap[static_cast<std::size_t>(i)];
      out[i] += amplitude * (wx[0] * taps[0] + wx[1] * taps[1] + wx[2] * taps[2] + wx[3] * taps[3]);
    }
  }
}

void add_fractal_noise(imaging::Image<float>& field, const GridFrame& frame,
                       std::span<const NoiseOctave> octaves, std::uint64_t seed) {
  for (std::size_t k = 0; k < octaves.size(); ++k)
    add_value_noise(field, frame, octaves[k], substream_seed(seed, k));
}

void add_white_noise(imaging::Image<float>& field, double amplitude, std::uint64_t seed) {
  const auto scale = static_cast<float>(amplitude);
  for (int j = 0; j < field.height(); ++j) {
    float* out = field.row(j);
    for (int i = 0; i < field.width(); ++i)
      out[i] += scale * lattice_value(seed, i, j);
  }
}

} // namespace marsokhod::world
