// The maximum mipmap: building its levels and casting rays through them to the terrain.

#include "marsokhod/world/render/max_mipmap.hpp"

#include "render/mipmap_walk.hpp"
#include "terrain/slope_levels.hpp"

#include <algorithm>
#include <cmath>

namespace marsokhod::world {
namespace {

using mipmap_walk::AxisRay;
using mipmap_walk::walk;

constexpr double kNoLimit = std::numeric_limits<double>::infinity();
// A ray end this far below the site's highest point is below it whatever the rounding, metres.
constexpr double kClipMargin = 1e-6;

} // namespace

// The maximum of each 2 x 2 block of the level below (fewer at an odd border).
MaxMipmap::Level MaxMipmap::coarser(const Level& below) {
  Level above{(below.width + 1) / 2, (below.height + 1) / 2, {}, {}};
  above.max.resize(static_cast<std::size_t>(above.width) * above.height);
  const int pairs = below.width / 2; // blocks with two children along x
  for (int j = 0; j < above.height; ++j) {
    const float* near = below.max.data() + static_cast<std::size_t>(2 * j) * below.width;
    const float* far = 2 * j + 1 < below.height ? near + below.width : near;
    float* out = above.max.data() + static_cast<std::size_t>(j) * above.width;
    for (int i = 0; i < pairs; ++i)
      out[i] =
          std::max(std::max(near[2 * i], near[2 * i + 1]), std::max(far[2 * i], far[2 * i + 1]));
    if (pairs < above.width)
      out[pairs] = std::max(near[2 * pairs], far[2 * pairs]);
  }
  return above;
}

MaxMipmap::MaxMipmap(const HeightField& height) : height_(&height) {
  if (height.nx() < 2 || height.ny() < 2)
    return;
  Level cells{height.nx() - 1, height.ny() - 1, {}, {}};
  cells.max.resize(static_cast<std::size_t>(cells.width) * cells.height);
  for (int j = 0; j < cells.height; ++j) {
    const float* near = height.nodes().row(j);
    const float* far = height.nodes().row(j + 1);
    float* out = cells.max.data() + static_cast<std::size_t>(j) * cells.width;
    for (int i = 0; i < cells.width; ++i)
      out[i] = std::max(std::max(near[i], near[i + 1]), std::max(far[i], far[i + 1]));
  }
  levels_.push_back(std::move(cells));
  while (levels_.back().width > 1 || levels_.back().height > 1)
    levels_.push_back(coarser(levels_.back()));
  SlopeLevels slopes = slope_levels(height, kSlopeLevel);
  steepest_gradient_ = slopes.steepest;
  if (levels() == kSlopeLevel + static_cast<int>(slopes.levels.size()))
    for (std::size_t k = 0; k < slopes.levels.size(); ++k)
      levels_[kSlopeLevel + k].slope = std::move(slopes.levels[k]);
  highest_ = levels_.back().max[0];
  per_m_ = 1.0 / height.cell_m();
  for (const Level& level : levels_)
    views_.push_back(LevelView{level.max.data(), level.slope.empty() ? nullptr : level.slope.data(),
                               level.width, level.height});
}

std::optional<double> MaxMipmap::first_hit(const Eigen::Vector3d& origin,
                                           const Eigen::Vector3d& direction, double t_max,
                                           int first_level) const {
  const int level = first_level < 0 ? levels() - 1 : std::min(first_level, levels() - 1);
  return cast(origin, direction, 0.0, t_max, level);
}

std::optional<double> MaxMipmap::first_hit_beyond(const Eigen::Vector3d& origin,
                                                  const Eigen::Vector3d& direction, double t_start,
                                                  double t_max) const {
  return cast(origin, direction, std::max(0.0, t_start), t_max, 0);
}

std::optional<double> MaxMipmap::first_hit_beyond_gentle(const Eigen::Vector3d& origin,
                                                         const Eigen::Vector3d& direction,
                                                         double t_start, double gentle,
                                                         int first_level) const {
  const int level = first_level < 0 ? levels() - 1 : std::min(first_level, levels() - 1);
  return cast(origin, direction, 0.0, kNoLimit, level, t_start, gentle);
}

std::optional<double> MaxMipmap::cast(const Eigen::Vector3d& origin,
                                      const Eigen::Vector3d& direction, double t_start,
                                      double t_max, int level, double t_gentle,
                                      double gentle) const {
  if (levels_.empty())
    return std::nullopt;
  const HeightField& field = *height_;
  const AxisRay x(origin.x(), direction.x(), field.origin().x(), per_m_);
  const AxisRay y(origin.y(), direction.y(), field.origin().y(), per_m_);
  double t = t_start;
  double t_end = t_max;
  if (!x.clip(blocks_x(0), t, t_end) || !y.clip(blocks_y(0), t, t_end))
    return std::nullopt;
  // Above the highest point of the site the ray meets nothing: clip that part away. Where the
  // ray is well below it at that end already the clip would change nothing, and the division
  // is saved.
  const double z0 = origin.z();
  const double dz = direction.z();
  if (dz > 0.0 && z0 + dz * t_end > highest_ - kClipMargin)
    t_end = std::min(t_end, (highest_ - z0) / dz);
  else if (dz < 0.0 && z0 + dz * t > highest_ - kClipMargin)
    t = std::max(t, (highest_ - z0) / dz);
  if (t > t_end)
    return std::nullopt;
  const bool parallel = x.inv == 0.0 || y.inv == 0.0;
  if (t_gentle > t && dz < 0.0) {
    // Up to t_gentle gentle blocks are skipped unseen; from there the walk starts afresh in the
    // finest level, as first_hit_beyond would.
    const double t_split = std::min(t_gentle, t_end);
    if (auto hit = parallel
                       ? walk<true, true, true>(*this, x, y, z0, dz, t, t_split, level, gentle)
                       : walk<true, false, true>(*this, x, y, z0, dz, t, t_split, level, gentle))
      return hit;
    if (t_split >= t_end)
      return std::nullopt;
    t = t_split;
    level = 0;
  }
  if (dz < 0.0)
    return parallel ? walk<true, true>(*this, x, y, z0, dz, t, t_end, level)
                    : walk<true, false>(*this, x, y, z0, dz, t, t_end, level);
  return parallel ? walk<false, true>(*this, x, y, z0, dz, t, t_end, level)
                  : walk<false, false>(*this, x, y, z0, dz, t, t_end, level);
}

double MaxMipmap::grid_exit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) const {
  if (levels_.empty())
    return 0.0;
  const HeightField& field = *height_;
  const AxisRay x(origin.x(), direction.x(), field.origin().x(), per_m_);
  const AxisRay y(origin.y(), direction.y(), field.origin().y(), per_m_);
  double t = 0.0;
  double t_end = kNoLimit;
  if (!x.clip(blocks_x(0), t, t_end) || !y.clip(blocks_y(0), t, t_end))
    return 0.0;
  return t_end;
}

int MaxMipmap::start_level(const Eigen::Vector3d& origin) const {
  const HeightField& h = *height_;
  const double gx = (origin.x() - h.origin().x()) / h.cell_m();
  const double gy = (origin.y() - h.origin().y()) / h.cell_m();
  if (levels_.empty() || gx < 0.0 || gy < 0.0 || gx >= levels_[0].width || gy >= levels_[0].height)
    return levels() - 1;
  const int ix = static_cast<int>(gx);
  const int iy = static_cast<int>(gy);
  int level = 0;
  while (level + 1 < levels() &&
         max_height(level + 1, ix >> (level + 1), iy >> (level + 1)) < origin.z())
    ++level;
  return level;
}

} // namespace marsokhod::world
