#include "marsokhod/nav/elevation.hpp"

#include "work_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

constexpr float kUnknown = std::numeric_limits<float>::infinity();

TerrainPoints unknown_terrain(int width, int height, std::pmr::memory_resource* memory) {
  TerrainPoints terrain{Image<float>(width, height, 1, kUnknown, memory),
                        Image<float>(width, height, 1, kUnknown, memory),
                        Image<float>(width, height, 1, kUnknown, memory),
                        Image<float>(width, height, 1, kUnknown, memory), 0};
  return terrain;
}

/// The left camera's pose for the attitude, split so that a pixel's level point is
///   P = origin + (B / d) * (row_direction(v) + u * column_step),
/// which is f B / d (the depth) times the level direction of (u - cx, v - cy, f) / f.
struct PixelGeometry {
  Eigen::Vector3d origin;
  Eigen::Vector3d column_step;
  Eigen::Matrix3d rotation;
  double cx = 0.0;
  double cy = 0.0;
  double focal = 0.0;

  PixelGeometry(const StereoRig& rig, const Attitude& attitude) {
    const Eigen::Isometry3d pose = rig.camera_to_level(Eye::left, attitude);
    origin = pose.translation();
    rotation = pose.linear();
    column_step = rotation.col(0);
    cx = rig.cx();
    cy = rig.cy();
    focal = rig.focal_px();
  }
  Eigen::Vector3d row_direction(int v) const {
    return rotation * Eigen::Vector3d(-cx, v - cy, focal);
  }
};

// std::hypot rounded to float, without its cost on nearly every pixel: sqrt(x^2 + y^2) lies
// within a few double ulps of the exact value, as does hypot, so where every value within
// 1e-15 (relative) of it rounds to the same float, hypot's does too. Near a float rounding
// boundary, or where the squares might lose precision, hypot decides.
float ground_distance(double x, double y) {
  const double squared = x * x + y * y;
  if (!(squared > 1e-200 && squared < 1e200))
    return static_cast<float>(std::hypot(x, y));
  const double estimate = std::sqrt(squared);
  const auto rounded = static_cast<float>(estimate);
  if (static_cast<float>(estimate * (1.0 - 1e-15)) == rounded &&
      static_cast<float>(estimate * (1.0 + 1e-15)) == rounded)
    return rounded;
  return static_cast<float>(std::hypot(x, y));
}

} // namespace

template <class Meter>
TerrainPoints reconstruct_terrain(ImageView<const float> disparity, const StereoRig& rig,
                                  const Attitude& attitude, Meter& meter,
                                  std::pmr::memory_resource* memory) {
  if (disparity.width() != rig.width() || disparity.height() != rig.height() ||
      disparity.channels() != 1)
    throw std::invalid_argument(fmt::format(
        "reconstruct_terrain: a {}x{} disparity map (channels {}) does not fit the "
        "{}x{} rig",
        disparity.width(), disparity.height(), disparity.channels(), rig.width(), rig.height()));
  const int width = disparity.width();
  const int height = disparity.height();
  TerrainPoints terrain = unknown_terrain(width, height, memory);
  const PixelGeometry geometry(rig, attitude);
  const double baseline = rig.baseline_m();
  for (int v = 0; v < height; ++v) {
    const Eigen::Vector3d row_direction = geometry.row_direction(v);
    const float* d_row = disparity.row(v);
    float* x_row = terrain.forward.row(v);
    float* y_row = terrain.left.row(v);
    float* z_row = terrain.elevation.row(v);
    float* r_row = terrain.range.row(v);
    std::uint64_t converted = 0;
    for (int u = 0; u < width; ++u) {
      const float d = d_row[u];
      if (!(d > 0.0F) || !std::isfinite(d)) // NaN fails the first test
        continue;
      const Eigen::Vector3d point =
          geometry.origin + (baseline / d) * (row_direction + u * geometry.column_step);
      x_row[u] = static_cast<float>(point.x());
      y_row[u] = static_cast<float>(point.y());
      z_row[u] = static_cast<float>(point.z());
      r_row[u] = ground_distance(point.x(), point.y());
      ++converted;
    }
    detail::report(meter, Work::range_pixel, converted);
    detail::report(meter, Work::elevation_pixel, converted);
    terrain.known_pixels += converted;
  }
  return terrain;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template TerrainPoints reconstruct_terrain<M>(ImageView<const float>, const StereoRig&,          \
                                                const Attitude&, M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
