// Value noise on grid images for the regolith: octaves, fractal sums and white noise.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/world/terrain/seeded_random.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <span>

namespace marsokhod::world {

/// Where the samples of a grid image sit in the world: node (i, j) at origin + (i, j) * cell.
struct GridFrame {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  double cell_m = 0.02;
};

/// One octave of value noise: random lattice values every wavelength_m, scaled by amplitude.
struct NoiseOctave {
  double wavelength_m = 1.0;
  double amplitude = 1.0;
};

/// Adds amplitude * N(x / wavelength) to every node, where N is value noise with values in
/// [-1, 1) on an integer lattice, interpolated by separable Catmull-Rom cubics (C1, so shading
/// shows no lattice creases). The lattice is anchored to the world, not to the grid.
void add_value_noise(imaging::Image<float>& field, const GridFrame& frame,
                     const NoiseOctave& octave, std::uint64_t seed);

/// Sum of octaves (fractal noise); octave k draws its lattice from substream_seed(seed, k).
void add_fractal_noise(imaging::Image<float>& field, const GridFrame& frame,
                       std::span<const NoiseOctave> octaves, std::uint64_t seed);

/// Adds independent uniform noise in [-amplitude, amplitude) to every node.
void add_white_noise(imaging::Image<float>& field, double amplitude, std::uint64_t seed);

/// std::floor, with a shortcut for the non-negative coordinates of grid points (truncation).
inline double lattice_floor(double u) {
  if (u >= 0.0 && u < 0x1p52)
    return static_cast<double>(static_cast<std::int64_t>(u));
  return std::floor(u);
}

/// Point-evaluable value noise in [-1, 1): bilinear between lattice values at integer (u, v).
/// Cheap (four hashes), for texture finer than any stored grid.
inline float lattice_noise(std::uint64_t seed, double u, double v) {
  const double fu = lattice_floor(u);
  const double fv = lattice_floor(v);
  const auto iu = static_cast<std::int64_t>(fu);
  const auto iv = static_cast<std::int64_t>(fv);
  const auto tu = static_cast<float>(u - fu);
  const auto tv = static_cast<float>(v - fv);
  const float a = lattice_value(seed, iu, iv);
  const float b = lattice_value(seed, iu + 1, iv);
  const float c = lattice_value(seed, iu, iv + 1);
  const float d = lattice_value(seed, iu + 1, iv + 1);
  const float lower = a + tu * (b - a);
  const float upper = c + tu * (d - c);
  return lower + tv * (upper - lower);
}

} // namespace marsokhod::world
