// The horizon row, the ground distance at a row and an obstacle's parallax for a rig.

#include "marsokhod/imaging/rig/rig_geometry.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace marsokhod::imaging {
namespace {

constexpr double kInfiniteRange = std::numeric_limits<double>::infinity();

struct CameraPoint {
  double u, v, depth;
};

CameraPoint to_left_camera(const StereoRig& rig, const Eigen::Vector3d& point_level) {
  const Eigen::Vector3d p = rig.camera_to_level(Eye::left).inverse(Eigen::Isometry) * point_level;
  if (p.z() <= 0.0)
    throw std::invalid_argument("obstacle_parallax: the obstacle is not in front of the cameras");
  return {rig.cx() + rig.focal_px() * p.x() / p.z(), rig.cy() + rig.focal_px() * p.y() / p.z(),
          p.z()};
}

// Forward distance where the line from the left camera through point_level meets the ground.
double ground_behind(const StereoRig& rig, const Eigen::Vector3d& point_level) {
  const Eigen::Vector3d centre = rig.camera_to_level(Eye::left).translation();
  const double drop = centre.z() - point_level.z();
  if (drop <= 0.0)
    return kInfiniteRange;
  return (centre + (point_level - centre) * (centre.z() / drop)).x();
}

} // namespace

double horizon_row(const StereoRig& rig, const Attitude& attitude) {
  const Eigen::Vector3d up =
      rig.camera_to_level(Eye::left, attitude).linear().transpose() * Eigen::Vector3d::UnitZ();
  // Horizontal rays through column cx satisfy up . (0, v - cy, f) = 0.
  if (std::abs(up.y()) < 1e-12)
    return std::numeric_limits<double>::quiet_NaN();
  return rig.cy() - up.z() * rig.focal_px() / up.y();
}

double ground_distance_at_row(const StereoRig& rig, double v, const Attitude& attitude) {
  const Eigen::Isometry3d pose = rig.camera_to_level(Eye::left, attitude);
  const Eigen::Vector3d direction =
      pose.linear() * Eigen::Vector3d(0.0, v - rig.cy(), rig.focal_px());
  const Eigen::Vector3d centre = pose.translation();
  if (centre.z() <= 0.0 || direction.z() >= 0.0)
    return kInfiniteRange;
  return (centre + direction * (centre.z() / -direction.z())).x();
}

ObstacleParallax obstacle_parallax(const StereoRig& rig, double distance_m, double height_m) {
  if (!(distance_m > 0.0) || !(height_m >= 0.0) || !std::isfinite(distance_m + height_m))
    throw std::invalid_argument("obstacle_parallax: needs distance > 0 and height >= 0");
  const Eigen::Vector3d top(distance_m, 0.0, height_m);
  const CameraPoint top_seen = to_left_camera(rig, top);
  const CameraPoint bottom_seen = to_left_camera(rig, Eigen::Vector3d(distance_m, 0.0, 0.0));

  ObstacleParallax result;
  result.distance_m = distance_m;
  result.height_m = height_m;
  result.top_row = top_seen.v;
  result.bottom_row = bottom_seen.v;
  result.top_disparity_px = rig.disparity_from_depth(top_seen.depth);
  result.bottom_disparity_px = rig.disparity_from_depth(bottom_seen.depth);
  result.top_minus_bottom_px = result.top_disparity_px - result.bottom_disparity_px;
  result.ground_behind_distance_m = ground_behind(rig, top);
  result.ground_behind_disparity_px = rig.ground_disparity(top_seen.u, top_seen.v);
  result.top_minus_ground_px = result.top_disparity_px - result.ground_behind_disparity_px;
  return result;
}

} // namespace marsokhod::imaging
