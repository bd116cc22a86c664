// Benchmark: generating, shading and querying the synthetic Mars site.
// Cost of the synthetic Mars site: generation of the default 48 m x 48 m, 2 cm terrain, its
// shading under a lighting, and the per-pixel queries the renderer makes.
#include "marsokhod/world/terrain/terrain.hpp"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

namespace {

using marsokhod::world::LightPreset;
using marsokhod::world::LitSurface;
using marsokhod::world::Terrain;
using marsokhod::world::TerrainSettings;

const Terrain& default_site() {
  static const Terrain site = Terrain::generate(TerrainSettings{});
  return site;
}

/// Deterministic query points spread over the central 40 m x 40 m.
std::vector<Eigen::Vector2d> query_points() {
  std::vector<Eigen::Vector2d> points;
  std::uint64_t state = 12345;
  for (int k = 0; k < 4096; ++k) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = static_cast<double>(state >> 40) / static_cast<double>(1ULL << 24);
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double v = static_cast<double>(state >> 40) / static_cast<double>(1ULL << 24);
    points.emplace_back(40.0 * u - 20.0, 40.0 * v - 20.0);
  }
  return points;
}

void BM_GenerateDefaultTerrain(benchmark::State& state) {
  TerrainSettings settings;
  for (auto _ : state) {
    settings.seed = static_cast<std::uint64_t>(state.iterations()) + 1;
    benchmark::DoNotOptimize(Terrain::generate(settings));
  }
}
BENCHMARK(BM_GenerateDefaultTerrain)->Unit(benchmark::kMillisecond)->Iterations(5);

void BM_ObstacleMapDefaultTerrain(benchmark::State& state) {
  const Terrain& site = default_site();
  for (auto _ : state)
    benchmark::DoNotOptimize(marsokhod::world::obstacle_map(site.height, {}));
}
BENCHMARK(BM_ObstacleMapDefaultTerrain)->Unit(benchmark::kMillisecond)->Iterations(5);

void BM_LitSurfaceLowSun(benchmark::State& state) {
  const Terrain& site = default_site();
  const auto light = marsokhod::world::lighting_preset(LightPreset::low_sun);
  for (auto _ : state)
    benchmark::DoNotOptimize(LitSurface(site, light));
}
BENCHMARK(BM_LitSurfaceLowSun)->Unit(benchmark::kMillisecond)->Iterations(5);

void BM_RadiancePerPoint(benchmark::State& state) {
  const LitSurface surface(default_site(),
                           marsokhod::world::lighting_preset(LightPreset::high_sun));
  const std::vector<Eigen::Vector2d> points = query_points();
  std::size_t k = 0;
  for (auto _ : state) {
    const Eigen::Vector2d& p = points[k++ & 4095];
    benchmark::DoNotOptimize(surface.radiance(p.x(), p.y()));
  }
}
BENCHMARK(BM_RadiancePerPoint);

void BM_HeightPerPoint(benchmark::State& state) {
  const Terrain& site = default_site();
  const std::vector<Eigen::Vector2d> points = query_points();
  std::size_t k = 0;
  for (auto _ : state) {
    const Eigen::Vector2d& p = points[k++ & 4095];
    benchmark::DoNotOptimize(site.height.height(p.x(), p.y()));
  }
}
BENCHMARK(BM_HeightPerPoint);

} // namespace
