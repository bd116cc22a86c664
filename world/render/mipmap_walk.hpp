// A ray's walk down the maximum mipmap's blocks (private to max_mipmap.cpp).
#pragma once

#include "terrain/bilinear_cell.hpp"

#include "marsokhod/world/render/max_mipmap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace marsokhod::world::mipmap_walk {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Below this many cells per metre of travel a ray counts as parallel to that grid axis.
inline constexpr double kParallel = 1e-12;

// One grid axis of a ray in grid units (cells from the grid origin, per metre of t), with what
// the walk needs to find block faces without branching on the direction.
struct AxisRay {
  double g;      // position at t = 0
  double dg;     // cells per metre
  double inv;    // metres per cell (0 when parallel to the axis)
  double offset; // t of the face at 0: -g * inv (+inf when parallel, so faces are never met)
  int ahead;     // 1 when moving up the axis: the exit face of block b is b + 1, else b
  int step;      // +1 or -1: the next block along the ray

  AxisRay(double origin, double direction, double grid_origin, double per_m)
      : g((origin - grid_origin) * per_m), dg(direction * per_m) {
    const bool parallel = std::abs(dg) <= kParallel;
    inv = parallel ? 0.0 : 1.0 / dg;
    offset = parallel ? kInfinity : -g * inv;
    ahead = dg > 0.0 ? 1 : 0;
    step = ahead ? 1 : -1;
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
  // Child (at `level`) of parent block b that holds the ray at t, where t_exit is the t where
  // the ray leaves the parent; updates t_exit to where it leaves the child. The ray is in the
  // second child it meets once t has passed the face between the two.
  template <bool Parallel>
  int child(double t, int b, double& t_exit, int level, int blocks) const {
    const int middle = b * 2 + 1;
    if (Parallel && inv == 0.0) // the ray stays at g
      return std::clamp(static_cast<int>(g) >> level, middle - 1, std::min(middle, blocks - 1));
    const double t_middle = static_cast<double>(middle << level) * inv + offset;
    const bool past = t >= t_middle;
    t_exit = past ? t_exit : t_middle;
    return std::min(middle - (past ? 1 - ahead : ahead), blocks - 1);
  }
};

// The walk down the quadtree for one ray, specialised on whether the ray descends, since that
// decides where over a block the ray is lowest (at its exit or at its entry), and on whether it
// runs parallel to a grid axis, which only the choice of a child block has to care about.
//
// With Gentle the caller knows the ray meets nothing before t_end over blocks whose slope bound
// is at most `gentle`, and the walk skips those without comparing heights.
template <bool Descending, bool Parallel, bool Gentle = false>
std::optional<double> walk(const MaxMipmap& mipmap, const AxisRay& x, const AxisRay& y, double z0,
                           double dz, double t, double t_end, int level, double gentle = 0.0) {
  // The walk holds the block (bx, by) of the current level that contains the ray at t, and the
  // t where the ray leaves it across each axis. Skipping a block only steps these integers and
  // recomputes the exit of the axis it crossed, and a child is chosen by comparing t with the
  // t of the face between the two children, so the position is converted to a block only once,
  // at the start. Every step moves forward along the ray, so the walk ends even where rounding
  // puts t exactly on a face.
  const MaxMipmap::LevelView* here = mipmap.level_views() + level;
  const MaxMipmap::LevelView* top = mipmap.level_views() + (mipmap.levels() - 1);
  int bx = std::clamp(static_cast<int>(x.at(t)), 0, mipmap.blocks_x(0) - 1) >> level;
  int by = std::clamp(static_cast<int>(y.at(t)), 0, mipmap.blocks_y(0) - 1) >> level;
  double tx = x.exit(bx, level);
  double ty = y.exit(by, level);
  const imaging::Image<float>& nodes = mipmap.height_field().nodes();
  for (;;) {
    double t_out = std::min(tx, ty);
    const double low = z0 + dz * (Descending ? std::min(t_out, t_end) : t);
    if (level > 0) {
      const std::size_t index = static_cast<std::size_t>(by) * here->width + bx;
      if (low <= here->max[index] && !(Gentle && here->slope && here->slope[index] <= gentle)) {
        --level;
        --here;
        bx = x.child<Parallel>(t, bx, tx, level, here->width);
        by = y.child<Parallel>(t, by, ty, level, here->height);
        continue;
      }
    } else {
      // A cell's maximum is its highest corner, the very value level 0 stores: taken from the
      // corners, which a crossing needs anyway, it costs no cache line of its own. Level 0 has
      // no slope bounds, so the gentle skip never applies here.
      const float* near = nodes.row(by) + bx;
      const float* far = nodes.row(by + 1) + bx;
      const float highest = std::max(std::max(near[0], near[1]), std::max(far[0], far[1]));
      if (low <= highest) {
        const BilinearCell cell{near[0], near[1], far[0], far[1]};
        if (auto hit = cell.first_crossing(x.at(t) - bx, y.at(t) - by, z0 + dz * t, x.dg, y.dg, dz,
                                           std::min(t_out, t_end) - t))
          return t + *hit;
      }
    }
    // Skip the block. When the step enters another parent block and the ray passes above that
    // parent too, skip the parent as well, and so on up: the ray strides again once it clears
    // the ground, and a parent that does not let it pass costs one comparison, not a detour. A
    // rising ray tests its parent after every step, since it may have risen above it since the
    // last test; a falling one only gets lower over the same parent.
    for (;;) {
      if (t_out >= t_end)
        return std::nullopt;
      t = std::max(t, t_out);
      const bool cross_x = tx <= ty;
      const bool cross_y = ty <= tx;
      const int next_x = bx + (cross_x ? x.step : 0);
      const int next_y = by + (cross_y ? y.step : 0);
      if (static_cast<unsigned>(next_x) >= static_cast<unsigned>(here->width) ||
          static_cast<unsigned>(next_y) >= static_cast<unsigned>(here->height))
        return std::nullopt; // left the grid (rounding at its border)
      // Both are >= 0, so they share a parent exactly when they differ in the lowest bit only.
      const bool new_parent = ((next_x ^ bx) | (next_y ^ by)) > 1;
      bx = next_x;
      by = next_y;
      if ((new_parent || !Descending) && here != top) {
        const int up_x = bx >> 1;
        const int up_y = by >> 1;
        const double up_tx = x.exit(up_x, level + 1);
        const double up_ty = y.exit(up_y, level + 1);
        const double up_out = std::min(up_tx, up_ty);
        const double up_low = z0 + dz * (Descending ? std::min(up_out, t_end) : t);
        const MaxMipmap::LevelView* up = here + 1;
        const std::size_t up_index = static_cast<std::size_t>(up_y) * up->width + up_x;
        if (up_low > up->max[up_index] || (Gentle && up->slope && up->slope[up_index] <= gentle)) {
          ++level;
          here = up;
          bx = up_x;
          by = up_y;
          tx = up_tx;
          ty = up_ty;
          t_out = up_out;
          continue;
        }
      }
      // tx and ty are always the exits of (bx, by), so both are recomputed rather than the
      // crossed one only: which axis a ray crosses next is too irregular to branch on.
      tx = x.exit(bx, level);
      ty = y.exit(by, level);
      break;
    }
  }
}

} // namespace marsokhod::world::mipmap_walk
