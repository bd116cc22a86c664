// Seeded random numbers for the terrain: hash mixing, substreams and lattice values.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <random>

namespace marsokhod::world {

/// SplitMix64 finaliser: a strong, cheap 64-bit mix used for lattice values and stream seeds.
constexpr std::uint64_t hash_mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// A seed derived from a parent seed and a label, so each component draws its own stream.
constexpr std::uint64_t substream_seed(std::uint64_t seed, std::uint64_t label) {
  return hash_mix(seed ^ hash_mix(label + 0x632be59bd9b4e019ULL));
}

/// Hash of an integer lattice point, as a float in [-1, 1).
inline float lattice_value(std::uint64_t seed, std::int64_t ix, std::int64_t iy) {
  const std::uint64_t h = hash_mix(seed ^ (static_cast<std::uint64_t>(ix) * 0x9e3779b97f4a7c15ULL) ^
                                   (static_cast<std::uint64_t>(iy) * 0xc2b2ae3d27d4eb4fULL));
  return static_cast<float>(static_cast<std::int64_t>(h >> 40) - (1 << 23)) * (1.0f / (1 << 23));
}

/// The generator's random numbers. Values are derived from raw std::mt19937_64 output by hand
/// (never std::uniform_*_distribution), so every standard library gives the same terrain.
class RandomStream {
public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  std::uint64_t bits() { return engine_(); }

private:
  std::mt19937_64 engine_;
};

/// A point uniform in the rectangle of sides `extent` (east-west, north-south) centred on the
/// origin. North is drawn before east, in sequence: an argument list would leave the order to
/// the compiler, and this is the order the sites have always been generated in.
inline Eigen::Vector2d uniform_in_rectangle(const Eigen::Vector2d& extent, RandomStream& rng) {
  const double north = rng.uniform(-0.5, 0.5) * extent.y();
  const double east = rng.uniform(-0.5, 0.5) * extent.x();
  return {east, north};
}

/// Labels of the generator's independent random streams; a component's numbers do not move
/// when another component's settings change (a site without rocks has the same craters).
enum class TerrainStream : std::uint64_t {
  undulation = 1,
  roughness = 2,
  regional_slope = 3,
  craters = 4,
  rocks = 5,
  albedo = 6,
  fine_texture = 7,
};

inline RandomStream terrain_stream(std::uint64_t seed, TerrainStream label) {
  return RandomStream(substream_seed(seed, static_cast<std::uint64_t>(label)));
}
inline std::uint64_t terrain_stream_seed(std::uint64_t seed, TerrainStream label) {
  return substream_seed(seed, static_cast<std::uint64_t>(label));
}

} // namespace marsokhod::world
