#pragma once

#include "marsokhod/world/terrain.hpp"

#include <Eigen/Core>

#include <limits>
#include <optional>
#include <vector>

namespace marsokhod::world {

/// Quadtree of maximum heights over a HeightField's bilinear cells (Tevs, Ihrke and Seidel 2008,
/// "Maximum mipmaps for fast, accurate and scalable dynamic height field rendering"): level 0
/// holds the highest corner of every cell, which bounds the bilinear patch, and each level above
/// holds the maximum of 2 x 2 blocks below. A ray skips every block it passes above, so a cast
/// visits a few dozen blocks instead of every cell along its way. Build it once per terrain;
/// it keeps a reference to the height field, which must outlive it.
class MaxMipmap {
public:
  explicit MaxMipmap(const HeightField& height);
  // Level views point into the levels' buffers: a move keeps them, a copy would not.
  MaxMipmap(const MaxMipmap&) = delete;
  MaxMipmap& operator=(const MaxMipmap&) = delete;
  MaxMipmap(MaxMipmap&&) = default;
  MaxMipmap& operator=(MaxMipmap&&) = default;

  const HeightField& height_field() const { return *height_; }
  /// Number of levels, from the cells (0) to the single block covering the whole grid.
  int levels() const { return static_cast<int>(levels_.size()); }
  int blocks_x(int level) const { return levels_[level].width; }
  int blocks_y(int level) const { return levels_[level].height; }
  /// Highest surface point inside block (bx, by) of a level (2^level x 2^level cells).
  float max_height(int level, int bx, int by) const {
    const Level& l = levels_[level];
    return l.max[static_cast<std::size_t>(by) * l.width + bx];
  }

  /// One level's maxima, row-major, as a ray walk reads them.
  struct LevelView {
    const float* max;
    int width;
    int height;
  };
  /// The levels, finest first (levels() of them).
  const LevelView* level_views() const { return views_.data(); }

  /// Distance t >= 0 along the ray origin + t * direction (world frame, unit direction) to its
  /// first intersection with the bilinear surface, if one exists with t <= t_max. Rays that
  /// leave the grid or pass above everything return nothing.
  std::optional<double> first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                  double t_max = std::numeric_limits<double>::infinity(),
                                  int first_level = -1) const;
  /// First intersection at t >= t_start for a caller that knows the ray meets nothing before
  /// t_start (pixel_rays.cpp proves it for neighbouring camera rays). The walk starts there in
  /// the finest level and climbs as it leaves blocks, so a start near the surface skips the
  /// descent from the top.
  std::optional<double> first_hit_beyond(const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& direction, double t_start,
                                         double t_max = std::numeric_limits<double>::infinity()) const;
  /// Lipschitz constant of the bilinear surface (metres of height per metre of ground): no two
  /// surface points differ in height by more than this times their ground distance.
  double steepest_gradient() const { return steepest_gradient_; }
  /// The coarsest level whose block around the origin lies wholly below it: rays cast from
  /// there may start their walk at that level (first_level) instead of the top, which gives the
  /// same answers with less work. Compute it once per camera.
  int start_level(const Eigen::Vector3d& origin) const;

private:
  std::optional<double> cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                             double t_start, double t_max, int level) const;

  struct Level {
    int width = 0;
    int height = 0;
    std::vector<float> max;
  };

  const HeightField* height_;
  std::vector<Level> levels_;
  std::vector<LevelView> views_; // into levels_, which never changes after construction
  double steepest_gradient_ = 0.0;
};

} // namespace marsokhod::world
