// Casting a camera's pixel-centre rays row by row, each walk started where it may safely be.

#include "render/pixel_rays.hpp"

#include <cmath>
#include <limits>
#include <optional>

namespace marsokhod::world {
namespace {

constexpr double kNoHit = std::numeric_limits<double>::infinity();
// The proven start is shortened by this fraction so that rounding in the two casts can never
// step over a surface that touches the bound.
constexpr double kStartMargin = 1e-6;

// What the ray `lower` (same origin, unit directions), which meets nothing before t_lower (its
// first hit, or where it leaves the grid if it has none), proves about the ray `upper`: it meets
// nothing before t_start wherever the surface is no steeper than `gentle`: everywhere when the
// whole surface is, else over blocks with a slope bound that low when the gap between the rays is
// short. t_start = 0 when nothing is proven.
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
using ProvenStart = PixelRayCaster::ProvenStart;

// upper_ground and lower_ground: the lengths of the rays' ground components.
ProvenStart proven_start(const Eigen::Vector3d& upper, double upper_ground,
                         const Eigen::Vector3d& lower, double lower_ground, double t_lower,
                         double lipschitz, double cell_m) {
  if (!std::isfinite(t_lower) || lower_ground <= 0.0 || upper_ground <= 0.0)
    return {};
  const double k = upper_ground / lower_ground;
  const double rise = upper.z() - k * lower.z();
  const double apart = (upper.head<2>() - k * lower.head<2>()).norm();
  if (rise < 0.0)
    return {};
  const double t_start = t_lower / k * (1.0 - kStartMargin);
  if (rise >= lipschitz * apart)
    return {t_start, kNoHit, true, true};
  return {t_start, rise / apart, false, t_start * apart <= cell_m};
}

} // namespace

PixelRayCaster::PixelRayCaster(const CameraView& camera, const MaxMipmap& mipmap, int first_level)
    : camera_(&camera), mipmap_(&mipmap), first_level_(first_level), v_(camera.height()) {
  const auto width = static_cast<std::size_t>(camera.width());
  directions_.resize(width);
  directions_below_.resize(width);
  hits_.assign(width, kNoHit);
  hits_below_.assign(width, kNoHit);
  clear_.resize(width);
  clear_below_.resize(width);
  ground_.resize(width);
  ground_below_.resize(width);
  starts_.resize(width);
}

int PixelRayCaster::next_row() {
  const bool has_below = v_ < camera_->height();
  --v_;
  directions_.swap(directions_below_);
  hits_.swap(hits_below_);
  clear_.swap(clear_below_);
  ground_.swap(ground_below_);
  const double lipschitz = mipmap_->steepest_gradient();
  const double cell_m = mipmap_->height_field().cell_m();
  const Eigen::Vector3d& origin = camera_->centre();
  // The directions and proven starts first, for the whole row: they do not depend on one
  // another, so their square roots and divisions overlap instead of waiting between walks.
  for (int u = 0; u < camera_->width(); ++u) {
    directions_[u] = camera_->ray(u, v_);
    ground_[u] = directions_[u].head<2>().norm();
    starts_[u] = has_below ? proven_start(directions_[u], ground_[u], directions_below_[u],
                                          ground_below_[u], clear_below_[u], lipschitz, cell_m)
                           : ProvenStart{};
  }
  for (int u = 0; u < camera_->width(); ++u) {
    const Eigen::Vector3d& direction = directions_[u];
    const ProvenStart& start = starts_[u];
    std::optional<double> hit;
    if (start.t_start > 0.0 && start.everywhere)
      hit = mipmap_->first_hit_beyond(origin, direction, start.t_start);
    else if (start.t_start > 0.0 && start.short_gap)
      hit = mipmap_->first_hit_beyond_gentle(origin, direction, start.t_start, start.gentle,
                                             first_level_);
    else
      hit = mipmap_->first_hit(origin, direction, kNoHit, first_level_);
    hits_[u] = hit ? *hit : kNoHit;
    clear_[u] = hit ? *hit : mipmap_->grid_exit(origin, directions_[u]);
  }
  return v_;
}

} // namespace marsokhod::world
