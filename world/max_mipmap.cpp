#include "marsokhod/world/max_mipmap.hpp"

#include "bilinear_cell.hpp"

#include <algorithm>
#include <cmath>

namespace marsokhod::world {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Below this many cells per metre of travel a ray counts as parallel to that grid axis.
constexpr double kParallel = 1e-12;

// One grid axis of a ray in grid units (cells from the grid origin, per metre of t), with what
// the walk needs to find block faces without branching on the direction.
struct AxisRay {
  double g;      // position at t = 0
  double dg;     // cells per metre
  double inv;    // metres per cell (0 when parallel to the axis)
  double offset; // t of the face at 0: -g * inv (+inf when parallel, so faces are never met)
  int ahead;     // 1 when moving up the axis: the exit face of block b is b + 1, else b

  AxisRay(double origin, double direction, double grid_origin, double per_m)
      : g((origin - grid_origin) * per_m), dg(direction * per_m) {
    const bool parallel = std::abs(dg) <= kParallel;
    inv = parallel ? 0.0 : 1.0 / dg;
    offset = parallel ? kInfinity : -g * inv;
    ahead = dg > 0.0 ? 1 : 0;
  }
  double at(double t) const { return g + t * dg; }
  // t where the ray leaves block b of 2^level cells.
  double exit(int b, int level) const {
    return static_cast<double>((b + ahead) << level) * inv + offset;
  }
  // Narrows [t0, t1] to the part of the ray over [0, extent]; false if none is.
  bool clip(double extent, double& t0, double& t1) const {
    if (inv == 0.0)
      return g >= 0.0 && g <= extent;
    // The same expression as exit(), so the walk meets the grid border exactly at t1.
    const double a = 0.0 * inv + offset;
    const double b = extent * inv + offset;
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
    return t0 <= t1;
  }
  // Block of 2^level cells holding the ray at t, among the two children of parent block b.
  int child(double t, int parent, int level, int blocks) const {
    const int first = parent * 2;
    return std::clamp(static_cast<int>(at(t)) >> level, first, std::min(first + 1, blocks - 1));
  }
  int step() const { return ahead ? 1 : -1; }
};

// On a bilinear cell dh/dx varies linearly across the cell, so its extremes lie on the two
// edges along x, and likewise for y; the gradient is at most the root of the sum of the two
// squared extremes. Over the whole (continuous) surface the largest cell bound is a Lipschitz
// constant, since any straight ground segment is a chain of pieces inside cells.
double bilinear_lipschitz(const HeightField& height) {
  // Single precision keeps the loop vectorised; the bound is then widened by far more than its
  // rounding error.
  constexpr double kRoundingAllowance = 1.0 + 1e-5;
  const nav::Image<float>& nodes = height.nodes();
  float steepest_squared = 0.0F;
  for (int j = 0; j + 1 < height.ny(); ++j) {
    const float* near = nodes.row(j);
    const float* far = nodes.row(j + 1);
    for (int i = 0; i + 1 < height.nx(); ++i) {
      const float along_x =
          std::max(std::abs(near[i + 1] - near[i]), std::abs(far[i + 1] - far[i]));
      const float along_y =
          std::max(std::abs(far[i] - near[i]), std::abs(far[i + 1] - near[i + 1]));
      steepest_squared = std::max(steepest_squared, along_x * along_x + along_y * along_y);
    }
  }
  return std::sqrt(static_cast<double>(steepest_squared)) * kRoundingAllowance / height.cell_m();
}

} // namespace

MaxMipmap::MaxMipmap(const HeightField& height) : height_(&height) {
  if (height.nx() < 2 || height.ny() < 2)
    return;
  Level cells{height.nx() - 1, height.ny() - 1, {}};
  cells.max.resize(static_cast<std::size_t>(cells.width) * cells.height);
  for (int j = 0; j < cells.height; ++j)
    for (int i = 0; i < cells.width; ++i)
      cells.max[static_cast<std::size_t>(j) * cells.width + i] = std::max(
          {height.at(i, j), height.at(i + 1, j), height.at(i, j + 1), height.at(i + 1, j + 1)});
  levels_.push_back(std::move(cells));
  steepest_gradient_ = bilinear_lipschitz(height);
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    const Level& below = levels_.back();
    Level above{(below.width + 1) / 2, (below.height + 1) / 2, {}};
    above.max.assign(static_cast<std::size_t>(above.width) * above.height,
                     -std::numeric_limits<float>::infinity());
    for (int j = 0; j < below.height; ++j)
      for (int i = 0; i < below.width; ++i) {
        float& parent = above.max[static_cast<std::size_t>(j / 2) * above.width + i / 2];
        parent = std::max(parent, below.max[static_cast<std::size_t>(j) * below.width + i]);
      }
    levels_.push_back(std::move(above));
  }
  for (const Level& level : levels_)
    views_.push_back(LevelView{level.max.data(), level.width, level.height});
}

namespace {

// The walk down the quadtree for one ray, specialised on whether the ray descends, since that
// decides where over a block the ray is lowest (at its exit or at its entry).
template <bool Descending>
std::optional<double> walk(const MaxMipmap& mipmap, const AxisRay& x, const AxisRay& y, double z0,
                           double dz, double t, double t_end, int level) {
  // The walk holds the block (bx, by) of the current level that contains the ray at t, and the
  // t where the ray leaves it across each axis. Skipping a block only steps these integers and
  // recomputes the exit of the axis it crossed, so the common path has no float-to-int
  // conversion; the position is converted only when descending into a child. Every step moves
  // forward along the ray, so the walk ends even where rounding puts t exactly on a face.
  const MaxMipmap::LevelView* levels = mipmap.level_views();
  const int top = mipmap.levels() - 1;
  int bx = std::clamp(static_cast<int>(x.at(t)), 0, levels[0].width - 1) >> level;
  int by = std::clamp(static_cast<int>(y.at(t)), 0, levels[0].height - 1) >> level;
  double tx = x.exit(bx, level);
  double ty = y.exit(by, level);
  const nav::Image<float>& nodes = mipmap.height_field().nodes();
  for (;;) {
    const MaxMipmap::LevelView& here = levels[level];
    const double t_out = std::min(tx, ty);
    const double t_stop = std::min(t_out, t_end);
    if (z0 + dz * (Descending ? t_stop : t) <=
        here.max[static_cast<std::size_t>(by) * here.width + bx]) {
      if (level > 0) {
        --level;
        bx = x.child(t, bx, level, levels[level].width);
        by = y.child(t, by, level, levels[level].height);
        tx = x.exit(bx, level);
        ty = y.exit(by, level);
        continue;
      }
      const BilinearCell cell{nodes(bx, by), nodes(bx + 1, by), nodes(bx, by + 1),
                              nodes(bx + 1, by + 1)};
      if (auto hit = cell.first_crossing(x.at(t) - bx, y.at(t) - by, z0 + dz * t, x.dg, y.dg, dz,
                                         t_stop - t))
        return t + *hit;
    }
    if (t_out >= t_end)
      return std::nullopt;
    t = std::max(t, t_out);
    const int parent_x = bx >> 1;
    const int parent_y = by >> 1;
    const bool cross_x = tx <= ty;
    const bool cross_y = ty <= tx;
    if (cross_x)
      bx += x.step();
    if (cross_y)
      by += y.step();
    if (static_cast<unsigned>(bx) >= static_cast<unsigned>(here.width) ||
        static_cast<unsigned>(by) >= static_cast<unsigned>(here.height))
      return std::nullopt; // left the grid (rounding at its border)
    // Entering another parent block: test the parent, which may let the ray skip it whole.
    if (level < top && ((bx >> 1) != parent_x || (by >> 1) != parent_y)) {
      ++level;
      bx >>= 1;
      by >>= 1;
      tx = x.exit(bx, level);
      ty = y.exit(by, level);
      continue;
    }
    if (cross_x)
      tx = x.exit(bx, level);
    if (cross_y)
      ty = y.exit(by, level);
  }
}

} // namespace

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

std::optional<double> MaxMipmap::cast(const Eigen::Vector3d& origin,
                                      const Eigen::Vector3d& direction, double t_start,
                                      double t_max, int level) const {
  if (levels_.empty())
    return std::nullopt;
  const HeightField& field = *height_;
  const double per_m = 1.0 / field.cell_m();
  const AxisRay x(origin.x(), direction.x(), field.origin().x(), per_m);
  const AxisRay y(origin.y(), direction.y(), field.origin().y(), per_m);
  double t = t_start;
  double t_end = t_max;
  if (!x.clip(blocks_x(0), t, t_end) || !y.clip(blocks_y(0), t, t_end))
    return std::nullopt;
  // Above the highest point of the site the ray meets nothing: clip that part away.
  const double highest = max_height(levels() - 1, 0, 0);
  if (direction.z() > 0.0)
    t_end = std::min(t_end, (highest - origin.z()) / direction.z());
  else if (direction.z() < 0.0)
    t = std::max(t, (highest - origin.z()) / direction.z());
  if (t > t_end)
    return std::nullopt;
  if (direction.z() < 0.0)
    return walk<true>(*this, x, y, origin.z(), direction.z(), t, t_end, level);
  return walk<false>(*this, x, y, origin.z(), direction.z(), t, t_end, level);
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
