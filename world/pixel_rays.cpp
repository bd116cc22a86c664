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

// What the ray `lower` (same origin, unit directions) first meeting the surface at t_lower
// proves about the ray `upper`: it meets nothing before t_start wherever the surface is no
// steeper than `gentle`: everywhere when the whole surface is, else over blocks with a slope
// bound that low when the gap between the rays is short. t_start = 0 when nothing is proven.
//
// Compare the two rays at equal ground distance from the origin: p = upper(t) and
// q = lower(k t) with k = |upper_xy| / |lower_xy|. Their ground points are
// t |upper_xy - k lower_xy| apart and p lies t (upper_z - k lower_z) higher. Where the surface
// is L-Lipschitz along the ground segment from q to p,
//   p_z - h(p) >= q_z - h(q) + t ((upper_z - k lower_z) - L |upper_xy - k lower_xy|).
// For k t < t_lower the lower ray is above the surface (q_z > h(q)); when the bracket is not
// negative, so is the upper ray: it meets nothing before t_lower / k. That holds with the
// Lipschitz constant of the whole surface (MaxMipmap::steepest_gradient) for every t, and with
// a block's own bound (MaxMipmap::steepest_gradient_near) wherever p lies over that block and
// the segment is no longer than a cell. Both ground points lie within the triangle of the
// origin's ground point and the two rays' ground tracks, inside the (convex) grid wherever the
// upper ray could meet the surface.
struct ProvenStart {
  double t_start = 0.0;
  double gentle = 0.0;
  bool everywhere = false; // gentle is at least the whole surface's Lipschitz constant
  bool short_gap = false;  // the two rays' ground points stay within a cell of each other
};

ProvenStart proven_start(const Eigen::Vector3d& upper, const Eigen::Vector3d& lower, double t_lower,
                         double lipschitz, double cell_m) {
  if (!std::isfinite(t_lower))
    return {};
  const double upper_ground = upper.head<2>().norm();
  const double lower_ground = lower.head<2>().norm();
  if (lower_ground <= 0.0 || upper_ground <= 0.0)
    return {};
  const double k = upper_ground / lower_ground;
  const double rise = upper.z() - k * lower.z();
  const double apart = (upper.head<2>() - k * lower.head<2>()).norm();
  if (rise < 0.0)
    return {};
  const double t_start = t_lower / k * (1.0 - kStartMargin);
  return {t_start, apart > 0.0 ? rise / apart : kNoHit, rise >= lipschitz * apart,
          t_start * apart <= cell_m};
}

} // namespace

std::vector<double> cast_pixel_rays(const CameraView& camera, const MaxMipmap& mipmap,
                                    int first_level) {
  const int width = camera.width();
  const int height = camera.height();
  std::vector<double> hits(static_cast<std::size_t>(width) * height, kNoHit);
  std::vector<Eigen::Vector3d> below(static_cast<std::size_t>(width));
  const double lipschitz = mipmap.steepest_gradient();
  const double cell_m = mipmap.height_field().cell_m();
  const Eigen::Vector3d& origin = camera.centre();
  // Bottom row first: each ray then has the one below it, which usually ends just short of it.
  for (int v = height - 1; v >= 0; --v) {
    double* row = hits.data() + static_cast<std::size_t>(v) * width;
    const double* row_below = v + 1 < height ? row + width : nullptr;
    for (int u = 0; u < width; ++u) {
      const Eigen::Vector3d direction = camera.ray(u, v);
      const ProvenStart start =
          row_below ? proven_start(direction, below[u], row_below[u], lipschitz, cell_m)
                    : ProvenStart{};
      std::optional<double> hit;
      if (start.t_start > 0.0 && start.everywhere)
        hit = mipmap.first_hit_beyond(origin, direction, start.t_start);
      else if (start.t_start > 0.0 && start.short_gap)
        hit = mipmap.first_hit_beyond_gentle(origin, direction, start.t_start, start.gentle,
                                             first_level);
      else
        hit = mipmap.first_hit(origin, direction, kNoHit, first_level);
      row[u] = hit ? *hit : kNoHit;
      below[u] = direction;
    }
  }
  return hits;
}

} // namespace marsokhod::world
