// One camera of the rig placed in the world for a rover placement, ready for casting rays.
#pragma once

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <Eigen/Geometry>

#include <optional>

namespace marsokhod::world {

/// One camera of the rig placed in the world: optical centre and orientation in the world
/// frame for a rover placement, with the rig's pinhole model (pixel centres at integer (u, v),
/// principal point at the image centre, camera x right, y down, z forward). Computed once per
/// frame so that casting a ray costs a matrix-vector product instead of a rig pose per pixel.
class CameraView {
public:
  CameraView(const imaging::StereoRig& rig, imaging::Eye eye, const RoverPlacement& placement);

  const Eigen::Vector3d& centre() const { return centre_; }
  int width() const { return width_; }
  int height() const { return height_; }

  /// Unit world-frame direction of the ray through pixel (u, v).
  Eigen::Vector3d ray(double u, double v) const {
    return (rotation_ * Eigen::Vector3d((u - cx_) * inv_focal_, (v - cy_) * inv_focal_, 1.0))
        .normalized();
  }
  /// Pixel where a world point projects, or nothing when it lies behind the camera.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world_point) const;
  /// True when (u, v) lies on the image, pixel edges included.
  bool on_image(const Eigen::Vector2d& pixel) const;

private:
  Eigen::Vector3d centre_;
  Eigen::Matrix3d rotation_; // camera frame -> world frame
  double focal_ = 1.0;
  double inv_focal_ = 1.0;
  double cx_ = 0.0;
  double cy_ = 0.0;
  int width_ = 0;
  int height_ = 0;
};

} // namespace marsokhod::world
