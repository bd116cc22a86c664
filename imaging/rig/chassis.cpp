// Footprint geometry of the rover chassis at a pose on the ground.
#include "marsokhod/imaging/rig/chassis.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace marsokhod::imaging {
namespace {

void require_positive(const char* name, double value) {
  if (!std::isfinite(value) || value <= 0.0)
    throw std::invalid_argument(
        fmt::format("chassis {} = {}: must be finite and positive", name, value));
}

} // namespace

void validate(const Chassis& chassis) {
  require_positive("wheelbase_m", chassis.wheelbase_m);
  require_positive("track_m", chassis.track_m);
  require_positive("wheel_diameter_m", chassis.wheel_diameter_m);
  require_positive("wheel_width_m", chassis.wheel_width_m);
}

std::array<Eigen::Vector2d, 4> footprint_corners(const Chassis& chassis, const PlanarPose& pose) {
  const Eigen::Vector2d forward(std::cos(pose.heading_rad), std::sin(pose.heading_rad));
  const Eigen::Vector2d left(-forward.y(), forward.x());
  const Eigen::Vector2d centre(pose.x, pose.y);
  const Eigen::Vector2d half_length = 0.5 * chassis.length_m() * forward;
  const Eigen::Vector2d half_width = 0.5 * chassis.width_m() * left;
  return {centre + half_length + half_width, centre - half_length + half_width,
          centre - half_length - half_width, centre + half_length - half_width};
}

bool under_footprint(const Chassis& chassis, const PlanarPose& pose, double x, double y) {
  const double dx = x - pose.x;
  const double dy = y - pose.y;
  const double c = std::cos(pose.heading_rad);
  const double s = std::sin(pose.heading_rad);
  const double along = c * dx + s * dy;
  const double across = -s * dx + c * dy;
  return std::abs(along) <= 0.5 * chassis.length_m() && std::abs(across) <= 0.5 * chassis.width_m();
}

double footprint_reach_m(const Chassis& chassis) {
  return 0.5 * std::hypot(chassis.length_m(), chassis.width_m());
}

} // namespace marsokhod::imaging
