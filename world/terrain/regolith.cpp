// The bare regolith: undulation, regional slope and roughness of the heights, and albedo.

#include "marsokhod/world/terrain/regolith.hpp"

#include "marsokhod/world/terrain/regolith_noise.hpp"
#include "marsokhod/world/terrain/seeded_random.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace marsokhod::world {
namespace {

/// Undulation octaves: relative amplitudes halve with the wavelength (a fractal surface).
constexpr std::array<NoiseOctave, 6> kUndulation{
    {{24.0, 1.0}, {12.0, 0.5}, {6.0, 0.25}, {3.0, 0.125}, {1.5, 0.0625}, {0.75, 0.03125}}};
/// Roughness octaves in metres of amplitude, plus per-node jitter.
constexpr std::array<NoiseOctave, 4> kRoughness{
    {{0.32, 0.006}, {0.16, 0.004}, {0.08, 0.0025}, {0.04, 0.0015}}};
constexpr double kRoughnessJitterM = 0.001;
/// Albedo octaves (absolute albedo units), plus per-node speckle.
constexpr std::array<NoiseOctave, 5> kAlbedoVariation{
    {{6.0, 0.06}, {2.0, 0.04}, {0.6, 0.03}, {0.15, 0.03}, {0.05, 0.025}}};
constexpr double kAlbedoSpeckle = 0.02;

GridFrame frame_of(const HeightField& height) {
  return {height.origin(), height.cell_m()};
}

/// The octaves a grid can carry: those at least two cells long, scaled by `scale`.
template <std::size_t N>
std::vector<NoiseOctave> resolvable(const std::array<NoiseOctave, N>& octaves, double cell_m,
                                    double scale) {
  std::vector<NoiseOctave> kept;
  for (const NoiseOctave& octave : octaves)
    if (octave.wavelength_m >= 2.0 * cell_m)
      kept.push_back({octave.wavelength_m, octave.amplitude * scale});
  return kept;
}

void add_regional_slope(const TerrainSettings& settings, HeightField& height) {
  if (settings.regional_slope_deg == 0.0)
    return;
  RandomStream rng = terrain_stream(settings.seed, TerrainStream::regional_slope);
  const double downhill = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double gradient = std::tan(settings.regional_slope_deg * std::numbers::pi / 180.0);
  const double gx = -gradient * std::cos(downhill);
  const double gy = -gradient * std::sin(downhill);
  for (int j = 0; j < height.ny(); ++j) {
    const double y = height.origin().y() + j * height.cell_m();
    for (int i = 0; i < height.nx(); ++i) {
      const double x = height.origin().x() + i * height.cell_m();
      height.at(i, j) += static_cast<float>(gx * x + gy * y);
    }
  }
}

} // namespace

void shape_regolith(const TerrainSettings& settings, HeightField& height) {
  const GridFrame frame = frame_of(height);
  double weight = 0.0;
  for (const NoiseOctave& octave : kUndulation)
    weight += octave.amplitude;
  add_fractal_noise(height.nodes(), frame,
                    resolvable(kUndulation, frame.cell_m, settings.undulation_m / weight),
                    terrain_stream_seed(settings.seed, TerrainStream::undulation));
  add_regional_slope(settings, height);
  const std::uint64_t roughness_seed = terrain_stream_seed(settings.seed, TerrainStream::roughness);
  add_fractal_noise(height.nodes(), frame, resolvable(kRoughness, frame.cell_m, 1.0),
                    roughness_seed);
  add_white_noise(height.nodes(), kRoughnessJitterM, substream_seed(roughness_seed, 1000));
}

imaging::Image<float> regolith_albedo(const HeightField& height, std::uint64_t seed) {
  imaging::Image<float> albedo(height.nx(), height.ny(), 1, static_cast<float>(kRegolithAlbedo));
  add_fractal_noise(albedo, frame_of(height), resolvable(kAlbedoVariation, height.cell_m(), 1.0),
                    seed);
  add_white_noise(albedo, kAlbedoSpeckle, substream_seed(seed, 1000));
  return albedo;
}

} // namespace marsokhod::world
