// The pinhole stereo rig: parameter checks, camera poses, rays, projection, disparity.

#include "marsokhod/imaging/rig/camera.hpp"

#include "rig/rig_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace marsokhod::imaging {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}
double arcsec_radians(double arcsec) {
  return radians(arcsec / 3600.0);
}

void validate(const RigParameters& parameters) {
  for (const detail::RigField& field : detail::rig_fields()) {
    const double value = field.get(parameters);
    if (auto problem = detail::rig_value_problem(field, value))
      throw RigError(fmt::format("rig parameter '{}.{}': {}", field.table, field.key, *problem));
  }
  if (auto problem = detail::rig_geometry_problem(parameters))
    throw RigError(fmt::format("rig: {}", *problem));
}

// Columns are the camera's x (right), y (down) and z (optical axis) in the body frame
// (x forward, y left, z up): the optical axis points forward and pitch_down below the
// body's horizontal plane.
Eigen::Matrix3d ideal_camera_axes(double pitch_down_rad) {
  const double s = std::sin(pitch_down_rad);
  const double c = std::cos(pitch_down_rad);
  Eigen::Matrix3d axes;
  axes.col(0) = Eigen::Vector3d(0.0, -1.0, 0.0);
  axes.col(1) = Eigen::Vector3d(-s, 0.0, -c);
  axes.col(2) = Eigen::Vector3d(c, 0.0, -s);
  return axes;
}

Eigen::Matrix3d misalignment_rotation(const Misalignment& m) {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  return (AngleAxisd(arcsec_radians(m.pan_arcsec), Vector3d::UnitY()) *
          AngleAxisd(arcsec_radians(m.tilt_arcsec), Vector3d::UnitX()) *
          AngleAxisd(arcsec_radians(m.roll_arcsec), Vector3d::UnitZ()))
      .toRotationMatrix();
}

Eigen::Matrix3d body_to_level(const Attitude& attitude) {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  // Nose up is a negative right-hand turn about y (left).
  return (AngleAxisd(-radians(attitude.pitch_deg), Vector3d::UnitY()) *
          AngleAxisd(radians(attitude.roll_deg), Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d camera_pose_in_body(const RigParameters& p, Eye eye) {
  const double side = eye == Eye::left ? 0.5 : -0.5;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(p.mast_forward_m, side * p.baseline_m, p.mast_height_m);
  pose.linear() = ideal_camera_axes(radians(p.pitch_down_deg));
  if (eye == Eye::right)
    pose.linear() = pose.linear() * misalignment_rotation(p.right_misalignment);
  return pose;
}

} // namespace

StereoRig::StereoRig(const RigParameters& parameters) : parameters_(parameters) {
  validate(parameters_);
  focal_px_ = parameters_.focal_mm / parameters_.sensor_mm * parameters_.width_px;
  left_to_body_ = camera_pose_in_body(parameters_, Eye::left);
  right_to_body_ = camera_pose_in_body(parameters_, Eye::right);
}

const Eigen::Isometry3d& StereoRig::camera_to_body(Eye eye) const {
  return eye == Eye::left ? left_to_body_ : right_to_body_;
}

double StereoRig::vertical_fov_deg() const {
  // Square pixels: the pixel pitch is sensor_mm / width_px in both directions.
  const double half_height_px = 0.5 * parameters_.height_px;
  return 2.0 * std::atan(half_height_px / focal_px_) * 180.0 / std::numbers::pi;
}

Eigen::Isometry3d StereoRig::camera_to_level(Eye eye, const Attitude& attitude) const {
  Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
  body.linear() = body_to_level(attitude);
  return body * camera_to_body(eye);
}

Eigen::Vector3d StereoRig::ray(Eye eye, double u, double v, const Attitude& attitude) const {
  const Eigen::Vector3d direction(u - cx(), v - cy(), focal_px_);
  return camera_to_level(eye, attitude).linear() * direction.normalized();
}

std::optional<Eigen::Vector2d> StereoRig::project(Eye eye, const Eigen::Vector3d& point_level,
                                                  const Attitude& attitude) const {
  const Eigen::Vector3d p = camera_to_level(eye, attitude).inverse(Eigen::Isometry) * point_level;
  if (p.z() <= 0.0)
    return std::nullopt;
  return Eigen::Vector2d(cx() + focal_px_ * p.x() / p.z(), cy() + focal_px_ * p.y() / p.z());
}

double StereoRig::disparity_from_depth(double depth_m) const {
  return focal_px_ * parameters_.baseline_m / depth_m;
}

double StereoRig::depth_from_disparity(double disparity_px) const {
  if (disparity_px <= 0.0)
    return kInfinity;
  return focal_px_ * parameters_.baseline_m / disparity_px;
}

Eigen::Vector3d StereoRig::point_from_disparity(double u, double v, double disparity_px,
                                                const Attitude& attitude) const {
  if (!(disparity_px > 0.0) || !std::isfinite(disparity_px))
    throw std::domain_error(
        fmt::format("point_from_disparity: disparity {} px has no point", disparity_px));
  const double depth = depth_from_disparity(disparity_px);
  const Eigen::Vector3d in_camera((u - cx()) * depth / focal_px_, (v - cy()) * depth / focal_px_,
                                  depth);
  return camera_to_level(Eye::left, attitude) * in_camera;
}

double StereoRig::ground_disparity(double u, double v, const Attitude& attitude) const {
  const Eigen::Isometry3d pose = camera_to_level(Eye::left, attitude);
  // Scaled so its camera z is the focal length: the ground point is centre + t * direction,
  // its depth is t * f and its disparity f * B / (t * f) = B / t.
  const Eigen::Vector3d direction = pose.linear() * Eigen::Vector3d(u - cx(), v - cy(), focal_px_);
  const double height = pose.translation().z();
  if (height <= 0.0 || direction.z() >= 0.0)
    return 0.0;
  const double t = height / -direction.z();
  return parameters_.baseline_m / t;
}

double StereoRig::ground_visible_from_m() const {
  // The bottom edge of the image (half a pixel below the last row's centre) looks
  // pitch_down + half the vertical field of view below the horizon.
  const double depression =
      radians(parameters_.pitch_down_deg) + std::atan(0.5 * parameters_.height_px / focal_px_);
  if (depression <= 0.0)
    return kInfinity;
  const double ahead =
      parameters_.mast_forward_m + parameters_.mast_height_m / std::tan(depression);
  return std::max(0.0, ahead);
}

double ground_range_m(const Eigen::Vector3d& point_level) {
  return std::hypot(point_level.x(), point_level.y());
}

} // namespace marsokhod::imaging
