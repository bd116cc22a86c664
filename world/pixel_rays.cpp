#include "pixel_rays.hpp"

#include <cmath>
#include <limits>
#include <optional>

namespace marsokhod::world {
namespace {

constexpr double kNoHit = std::numeric_limits<double>::infinity();
// The proven start is shortened by this fraction so that rounding in the two casts can never
// step over a surface that touches the bound.
constexpr double kStartMargin = 1e-6;

// Where the walk of ray `upper` may start, given that the ray `lower` (same origin, unit
// directions) first meets the surface at t_lower.
//
// Compare the two rays at equal ground distance from the origin: p = upper(t) and
// q = lower(k t) with k = |upper_xy| / |lower_xy|. Their ground points are
// t |upper_xy - k lower_xy| apart and p lies t (upper_z - k lower_z) higher. The surface is
// L-Lipschitz (MaxMipmap::steepest_gradient), so
//   p_z - h(p) >= q_z - h(q) + t ((upper_z - k lower_z) - L |upper_xy - k lower_xy|).
// For k t < t_lower the lower ray is above the surface (q_z > h(q)); when the bracket is not
// negative, so is the upper ray: it meets nothing before t_lower / k. Both ground points lie
// within the triangle of the origin's ground point and the two rays' ground tracks, inside the
// (convex) grid wherever the upper ray could meet the surface.
double proven_start(const Eigen::Vector3d& upper, const Eigen::Vector3d& lower, double t_lower,
                    double lipschitz) {
  if (!std::isfinite(t_lower))
    return 0.0;
  const double upper_ground = upper.head<2>().norm();
  const double lower_ground = lower.head<2>().norm();
  if (lower_ground <= 0.0 || upper_ground <= 0.0)
    return 0.0;
  const double k = upper_ground / lower_ground;
  const double rise = upper.z() - k * lower.z();
  const double apart = (upper.head<2>() - k * lower.head<2>()).norm();
  if (rise < lipschitz * apart)
    return 0.0;
  return t_lower / k * (1.0 - kStartMargin);
}

} // namespace

std::vector<double> cast_pixel_rays(const CameraView& camera, const MaxMipmap& mipmap,
                                    int first_level) {
  const int width = camera.width();
  const int height = camera.height();
  std::vector<double> hits(static_cast<std::size_t>(width) * height, kNoHit);
  std::vector<Eigen::Vector3d> below(static_cast<std::size_t>(width));
  const double lipschitz = mipmap.steepest_gradient();
  const Eigen::Vector3d& origin = camera.centre();
  // Bottom row first: each ray then has the one below it, which usually ends just short of it.
  for (int v = height - 1; v >= 0; --v) {
    double* row = hits.data() + static_cast<std::size_t>(v) * width;
    const double* row_below = v + 1 < height ? row + width : nullptr;
    for (int u = 0; u < width; ++u) {
      const Eigen::Vector3d direction = camera.ray(u, v);
      const double start =
          row_below ? proven_start(direction, below[u], row_below[u], lipschitz) : 0.0;
      const std::optional<double> hit =
          start > 0.0 ? mipmap.first_hit_beyond(origin, direction, start)
                      : mipmap.first_hit(origin, direction, kNoHit, first_level);
      row[u] = hit ? *hit : kNoHit;
      below[u] = direction;
    }
  }
  return hits;
}

} // namespace marsokhod::world
