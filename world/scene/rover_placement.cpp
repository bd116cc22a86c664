// Placing the rover on the terrain: the wheels' contact points give its height, pitch and roll.

#include "marsokhod/world/scene/rover_placement.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace marsokhod::world {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

} // namespace

std::array<Eigen::Vector2d, 6> wheel_contacts(const RoverPose& pose,
                                              const imaging::Chassis& chassis) {
  const double heading = pose.heading_deg * kRadiansPerDegree;
  const Eigen::Vector2d forward(std::cos(heading), std::sin(heading));
  const Eigen::Vector2d left(-forward.y(), forward.x());
  const Eigen::Vector2d centre(pose.x, pose.y);
  const Eigen::Vector2d half_base = 0.5 * chassis.wheelbase_m * forward;
  const Eigen::Vector2d half_track = 0.5 * chassis.track_m * left;
  return {centre + half_base + half_track, centre + half_track, centre - half_base + half_track,
          centre + half_base - half_track, centre - half_track, centre - half_base - half_track};
}

RoverPlacement place_rover(const HeightField& height, const RoverPose& pose,
                           const imaging::Chassis& chassis) {
  if (!(chassis.wheelbase_m > 0.0) || !(chassis.track_m > 0.0))
    throw std::invalid_argument("place_rover: wheelbase and track must be positive");
  if (!height.contains(pose.x, pose.y) || !std::isfinite(pose.heading_deg))
    throw std::invalid_argument("place_rover: the rover centre is outside the terrain");
  const auto wheels = wheel_contacts(pose, chassis);
  std::array<double, 6> z{};
  for (std::size_t w = 0; w < wheels.size(); ++w)
    z[w] = height.height(wheels[w].x(), wheels[w].y());
  // Least-squares plane through the six contacts (wheel order: FL, ML, RL, FR, MR, RR).
  const double forward_gradient = ((z[0] + z[3]) - (z[2] + z[5])) / (2.0 * chassis.wheelbase_m);
  const double left_gradient =
      ((z[0] + z[1] + z[2]) - (z[3] + z[4] + z[5])) / (3.0 * chassis.track_m);

  RoverPlacement placement;
  placement.pose = pose;
  placement.ground_z = height.height(pose.x, pose.y);
  placement.attitude.pitch_deg = std::atan(forward_gradient) / kRadiansPerDegree;
  placement.attitude.roll_deg =
      std::asin(left_gradient / std::sqrt(1.0 + forward_gradient * forward_gradient +
                                          left_gradient * left_gradient)) /
      kRadiansPerDegree;
  placement.level_to_world =
      Eigen::Translation3d(pose.x, pose.y, placement.ground_z) *
      Eigen::AngleAxisd(pose.heading_deg * kRadiansPerDegree, Eigen::Vector3d::UnitZ());
  return placement;
}

} // namespace marsokhod::world
