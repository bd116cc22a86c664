// The lit surface: terrain radiance under a lighting, with cast shadows, on the terrain grid.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/world/lighting/lighting.hpp"
#include "marsokhod/world/terrain/height_field.hpp"
#include "marsokhod/world/terrain/regolith_noise.hpp"

#include <Eigen/Core>

#include <cstdint>

namespace marsokhod::world {

struct Terrain;

/// Terrain radiance under a lighting, with cast shadows, precomputed on the terrain grid.
class LitSurface {
public:
  /// Throws std::invalid_argument for an empty terrain or a lighting with negative or
  /// non-finite irradiances, albedo scale or contrast.
  LitSurface(const Terrain& terrain, const Lighting& lighting);
  /// Radiance at (x, y) before exposure: albedo * (ambient + sun * cos * lit), plus fine
  /// procedural texture below the grid spacing so that close range stays matchable. Clamps to
  /// the border outside the grid like HeightField::height().
  float radiance(double x, double y) const;
  const Lighting& lighting() const { return lighting_; }
  /// Radiance at the nodes, without the sub-grid texture.
  const imaging::Image<float>& nodes() const { return radiance_; }
  /// 1 where a node sees the sun (not in a cast shadow), 0 where it does not.
  const imaging::Image<std::uint8_t>& sunlit() const { return sunlit_; }

private:
  const Terrain* terrain_;
  Lighting lighting_;
  imaging::Image<float> radiance_;
  imaging::Image<std::uint8_t> sunlit_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  double inv_cell_ = 1.0;
  std::uint64_t texture_seed_ = 0;
  float texture_amplitude_ = 0.0f;
};

/// Lattice points of the sub-grid texture per grid cell: a 1 cm pitch on a 2 cm grid, about the
/// ground footprint of a pixel at the nearest visible range (2 m); finer texture only aliases.
inline constexpr double kFineTexturePerCell = 2.0;

inline float LitSurface::radiance(double x, double y) const {
  const int nx = radiance_.width();
  const int ny = radiance_.height();
  const double u = clamp_grid_coordinate((x - origin_.x()) * inv_cell_, nx - 1);
  const double v = clamp_grid_coordinate((y - origin_.y()) * inv_cell_, ny - 1);
  const int i = static_cast<int>(u) < nx - 1 ? static_cast<int>(u) : nx - 2;
  const int j = static_cast<int>(v) < ny - 1 ? static_cast<int>(v) : ny - 2;
  const auto fx = static_cast<float>(u - i);
  const auto fy = static_cast<float>(v - j);
  const float* p = radiance_.data() + static_cast<std::ptrdiff_t>(j) * nx + i;
  const float lower = p[0] + fx * (p[1] - p[0]);
  const float upper = p[nx] + fx * (p[nx + 1] - p[nx]);
  const float base = lower + fy * (upper - lower);
  if (texture_amplitude_ == 0.0f)
    return base;
  const float texture =
      lattice_noise(texture_seed_, u * kFineTexturePerCell, v * kFineTexturePerCell);
  return base * (1.0f + texture_amplitude_ * texture);
}

} // namespace marsokhod::world
