// The lit surface: Lambertian shading and cast shadows of the terrain under a lighting.

#include "marsokhod/world/lighting/lit_surface.hpp"

#include "marsokhod/world/terrain/seeded_random.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::world {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
/// Tolerance of the shadow test, far below the regolith roughness.
constexpr float kShadowEpsilonM = 1e-5f;

void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument("LitSurface: " + what);
}

void validate(const Terrain& terrain, const Lighting& light) {
  require(terrain.height.nx() >= 2 && terrain.height.ny() >= 2, "the terrain is empty");
  require(terrain.albedo.width() == terrain.height.nx() &&
              terrain.albedo.height() == terrain.height.ny(),
          "albedo and height grids differ in size");
  require(light.sun >= 0.0 && std::isfinite(light.sun), "sun must be >= 0");
  require(light.ambient >= 0.0 && std::isfinite(light.ambient), "ambient must be >= 0");
  require(light.albedo_scale >= 0.0 && std::isfinite(light.albedo_scale),
          "albedo_scale must be >= 0");
  require(light.albedo_contrast >= 0.0 && std::isfinite(light.albedo_contrast),
          "albedo_contrast must be >= 0");
  require(light.sun_elevation_deg >= -90.0 && light.sun_elevation_deg <= 90.0,
          "sun_elevation_deg must be within -90..90");
  require(std::isfinite(light.sun_azimuth_deg), "sun_azimuth_deg must be finite");
  require(light.fine_texture >= 0.0 && light.fine_texture < 1.0, "fine_texture must be in [0, 1)");
  require(light.exposure > 0.0 && std::isfinite(light.exposure), "exposure must be positive");
}

imaging::Image<float> transposed(const imaging::Image<float>& image) {
  imaging::Image<float> out(image.height(), image.width());
  for (int j = 0; j < image.height(); ++j)
    for (int i = 0; i < image.width(); ++i)
      out(j, i) = image(i, j);
  return out;
}

imaging::Image<std::uint8_t> transposed(const imaging::Image<std::uint8_t>& image) {
  imaging::Image<std::uint8_t> out(image.height(), image.width());
  for (int j = 0; j < image.height(); ++j)
    for (int i = 0; i < image.width(); ++i)
      out(j, i) = image(i, j);
  return out;
}

/// Cast shadows for a sun whose horizontal direction advances `toward_sun` rows (+1 or -1) and
/// `shift` columns (|shift| <= 1) per row. Rows are swept from the sun side; each keeps the
/// horizon surface H = max(ground, shadow surface), and a row's shadow surface is the previous
/// row's H, interpolated at the shifted column, lowered by the sun ray's drop over one step.
imaging::Image<std::uint8_t> sweep_rows(const imaging::Image<float>& z, int toward_sun,
                                        double shift, double drop) {
  const int nx = z.width();
  const int ny = z.height();
  imaging::Image<std::uint8_t> lit(nx, ny, 1, 1);
  std::vector<float> horizon(z.row(toward_sun > 0 ? ny - 1 : 0),
                             z.row(toward_sun > 0 ? ny - 1 : 0) + nx);
  std::vector<float> next(static_cast<std::size_t>(nx));
  constexpr float kOpenSky = -std::numeric_limits<float>::infinity();
  for (int step = 1; step < ny; ++step) {
    const int j = toward_sun > 0 ? ny - 1 - step : step;
    const float* ground = z.row(j);
    for (int i = 0; i < nx; ++i) {
      const double from = i + shift;
      float shadow = kOpenSky;
      if (from >= 0.0 && from <= nx - 1) {
        const int i0 = std::min(static_cast<int>(from), nx - 2);
        const auto t = static_cast<float>(from - i0);
        shadow = horizon[static_cast<std::size_t>(i0)] * (1.0f - t) +
                 horizon[static_cast<std::size_t>(i0) + 1] * t - static_cast<float>(drop);
      }
      if (ground[i] < shadow - kShadowEpsilonM)
        lit(i, j) = 0;
      next[static_cast<std::size_t>(i)] = std::max(ground[i], shadow);
    }
    horizon.swap(next);
  }
  return lit;
}

/// 1 where the node sees the sun over the terrain, 0 in a cast shadow.
imaging::Image<std::uint8_t> cast_shadows(const HeightField& height, const Lighting& light) {
  const int nx = height.nx();
  const int ny = height.ny();
  if (light.sun_elevation_deg <= 0.0)
    return imaging::Image<std::uint8_t>(nx, ny, 1, 0);
  if (light.sun_elevation_deg >= 90.0)
    return imaging::Image<std::uint8_t>(nx, ny, 1, 1);
  const double dx = std::cos(light.sun_azimuth_deg * kDegree);
  const double dy = std::sin(light.sun_azimuth_deg * kDegree);
  const double tan_elevation = std::tan(light.sun_elevation_deg * kDegree);
  // Sweep along the axis the sun direction follows most closely, so each step is one node.
  if (std::abs(dy) >= std::abs(dx)) {
    const double shift = dx / std::abs(dy);
    const double drop = height.cell_m() * std::sqrt(1.0 + shift * shift) * tan_elevation;
    return sweep_rows(height.nodes(), dy > 0.0 ? 1 : -1, shift, drop);
  }
  const double shift = dy / std::abs(dx);
  const double drop = height.cell_m() * std::sqrt(1.0 + shift * shift) * tan_elevation;
  return transposed(sweep_rows(transposed(height.nodes()), dx > 0.0 ? 1 : -1, shift, drop));
}

/// Unit normal at node (i, j) from central differences (one-sided at the border).
Eigen::Vector3d node_normal(const HeightField& height, int i, int j) {
  const int i0 = std::max(0, i - 1);
  const int i1 = std::min(height.nx() - 1, i + 1);
  const int j0 = std::max(0, j - 1);
  const int j1 = std::min(height.ny() - 1, j + 1);
  const double dz_dx = (height.at(i1, j) - height.at(i0, j)) / ((i1 - i0) * height.cell_m());
  const double dz_dy = (height.at(i, j1) - height.at(i, j0)) / ((j1 - j0) * height.cell_m());
  return Eigen::Vector3d(-dz_dx, -dz_dy, 1.0).normalized();
}

double mean_of(const imaging::Image<float>& image) {
  double sum = 0.0;
  for (int j = 0; j < image.height(); ++j)
    for (int i = 0; i < image.width(); ++i)
      sum += image(i, j);
  return sum / static_cast<double>(image.size());
}

} // namespace

LitSurface::LitSurface(const Terrain& terrain, const Lighting& lighting)
    : terrain_(&terrain), lighting_(lighting) {
  validate(terrain, lighting);
  const HeightField& height = terrain.height;
  origin_ = height.origin();
  inv_cell_ = 1.0 / height.cell_m();
  texture_seed_ = terrain_stream_seed(terrain.settings.seed, TerrainStream::fine_texture);
  texture_amplitude_ = static_cast<float>(lighting.fine_texture * lighting.albedo_contrast);
  sunlit_ = cast_shadows(height, lighting);

  const double elevation = lighting.sun_elevation_deg * kDegree;
  const double azimuth = lighting.sun_azimuth_deg * kDegree;
  const Eigen::Vector3d to_sun(std::cos(elevation) * std::cos(azimuth),
                               std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  const double mean_albedo = mean_of(terrain.albedo);
  radiance_ = imaging::Image<float>(height.nx(), height.ny());
  for (int j = 0; j < height.ny(); ++j)
    for (int i = 0; i < height.nx(); ++i) {
      const double albedo = lighting.albedo_scale *
                            std::max(0.0, mean_albedo + lighting.albedo_contrast *
                                                            (terrain.albedo(i, j) - mean_albedo));
      const double direct =
          sunlit_(i, j) ? std::max(0.0, node_normal(height, i, j).dot(to_sun)) : 0.0;
      radiance_(i, j) = static_cast<float>(albedo * (lighting.ambient + lighting.sun * direct));
    }
}

} // namespace marsokhod::world
