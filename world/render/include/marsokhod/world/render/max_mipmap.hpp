// The maximum mipmap: a quadtree of height maxima for fast ray casting on the terrain.
#pragma once

#include "marsokhod/world/terrain/terrain.hpp"

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

  /// One level's maxima, row-major, as a ray walk reads them, and from level kSlopeLevel up
  /// the local slope bounds of its blocks (steepest_gradient_near; null below).
  struct LevelView {
    const float* max;
    const float* slope;
    int width;
    int height;
  };
  /// The finest level that has local slope bounds.
  static constexpr int kSlopeLevel = 3;
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
  std::optional<double>
  first_hit_beyond(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_start,
                   double t_max = std::numeric_limits<double>::infinity()) const;
  /// First intersection for a caller that knows the ray meets nothing before t_start wherever
  /// the surface is no steeper than `gentle` (steepest_gradient_near of the blocks it passes;
  /// pixel_rays.cpp proves it for neighbouring camera rays). Before t_start the walk skips such
  /// blocks unseen and tests the others as first_hit does from first_level; from t_start on it
  /// goes on as first_hit_beyond.
  std::optional<double> first_hit_beyond_gentle(const Eigen::Vector3d& origin,
                                                const Eigen::Vector3d& direction, double t_start,
                                                double gentle, int first_level = -1) const;
  /// Where the ray leaves the grid (t along it; 0 if it never is over the grid). A ray that met
  /// nothing before then meets nothing at all: first_hit's "nothing" means this far clear.
  double grid_exit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) const;
  /// Lipschitz constant of the bilinear surface (metres of height per metre of ground): no two
  /// surface points differ in height by more than this times their ground distance.
  double steepest_gradient() const { return steepest_gradient_; }
  /// Lipschitz constant of the surface over block (bx, by) of a level >= kSlopeLevel widened by
  /// one cell on every side: it bounds the height difference between the ends of any ground
  /// segment no longer than a cell that starts over the block.
  float steepest_gradient_near(int level, int bx, int by) const {
    const Level& l = levels_[level];
    return l.slope[static_cast<std::size_t>(by) * l.width + bx];
  }
  /// The coarsest level whose block around the origin lies wholly below it: rays cast from
  /// there may start their walk at that level (first_level) instead of the top, which gives the
  /// same answers with less work. Compute it once per camera.
  int start_level(const Eigen::Vector3d& origin) const;

private:
  // Walks the ray over [t_start, t_max] from `level`; before t_gentle it may skip blocks whose
  // slope bound is at most `gentle` (see first_hit_beyond_gentle).
  std::optional<double> cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                             double t_start, double t_max, int level, double t_gentle = 0.0,
                             double gentle = 0.0) const;

  struct Level {
    int width = 0;
    int height = 0;
    std::vector<float> max;
    std::vector<float> slope; // empty below kSlopeLevel
  };

  static Level coarser(const Level& below);

  const HeightField* height_;
  std::vector<Level> levels_;
  std::vector<LevelView> views_; // into levels_, which never changes after construction
  double steepest_gradient_ = 0.0;
  double highest_ = 0.0; // of the whole site
  double per_m_ = 1.0;   // cells per metre
};

} // namespace marsokhod::world
