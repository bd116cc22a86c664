// TerrainRowMaker: the level points of one row from its disparities (private to the terrain room).
#pragma once

// One row of level-frame points at a time, as reconstruct_terrain and RecomputedTerrain make
// them (private to the terrain room).

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"

#include <Eigen/Geometry>

#include <cstdint>

namespace marsokhod::nav::detail {

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

  PixelGeometry(const imaging::StereoRig& rig, const imaging::Attitude& attitude) {
    const Eigen::Isometry3d pose = rig.camera_to_level(imaging::Eye::left, attitude);
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

/// Converts rows of disparities into level points.
class TerrainRowMaker {
public:
  TerrainRowMaker(const imaging::StereoRig& rig, const imaging::Attitude& attitude)
      : geometry_(rig, attitude), baseline_(rig.baseline_m()) {}
  /// Writes the points of row v whose disparity is positive and finite into rows[0..3]
  /// (forward, left, elevation, range), leaving the others as they are; returns how many.
  std::uint64_t make(int v, const float* disparity, int width, float* const (&rows)[4]) const;

private:
  PixelGeometry geometry_;
  double baseline_;
};

/// Throws std::invalid_argument, naming `who`, when the disparity does not fit the rig.
void check_disparity_fits(imaging::ImageView<const float> disparity, const imaging::StereoRig& rig,
                          const char* who);

} // namespace marsokhod::nav::detail
