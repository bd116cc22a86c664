// One rig camera placed in the world: its pose, projection and image bounds.

#include "marsokhod/world/render/camera_view.hpp"

namespace marsokhod::world {

CameraView::CameraView(const imaging::StereoRig& rig, imaging::Eye eye,
                       const RoverPlacement& placement)
    : focal_(rig.focal_px()), inv_focal_(1.0 / rig.focal_px()), cx_(rig.cx()), cy_(rig.cy()),
      width_(rig.width()), height_(rig.height()) {
  const Eigen::Isometry3d camera_to_world =
      placement.level_to_world * rig.camera_to_level(eye, placement.attitude);
  centre_ = camera_to_world.translation();
  rotation_ = camera_to_world.linear();
}

std::optional<Eigen::Vector2d> CameraView::project(const Eigen::Vector3d& world_point) const {
  const Eigen::Vector3d p = rotation_.transpose() * (world_point - centre_);
  if (p.z() <= 0.0)
    return std::nullopt;
  return Eigen::Vector2d(cx_ + focal_ * p.x() / p.z(), cy_ + focal_ * p.y() / p.z());
}

bool CameraView::on_image(const Eigen::Vector2d& pixel) const {
  return pixel.x() >= -0.5 && pixel.y() >= -0.5 && pixel.x() <= width_ - 0.5 &&
         pixel.y() <= height_ - 0.5;
}

} // namespace marsokhod::world
