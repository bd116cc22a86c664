// Driving the commands on the true ground, reading the inclinometer as the chassis would.
#include "marsokhod/eval/traverse/ground_drive.hpp"

#include "marsokhod/eval/terrain/footprint_judge.hpp"
#include "marsokhod/nav/path/drive_poses.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace marsokhod::eval {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;
// A reading over the threshold stops the rover when it is this much over the drive's first.
constexpr double kTiltRiseDeg = 0.5;

world::RoverPose to_world(const world::RoverPlacement& start, const imaging::PlanarPose& local) {
  const Eigen::Vector3d p = start.level_to_world * Eigen::Vector3d(local.x, local.y, 0.0);
  return {p.x(), p.y(), start.pose.heading_deg + local.heading_rad * kDegrees};
}

} // namespace

double tilt_deg(double pitch_deg, double roll_deg) {
  const double c = std::cos(pitch_deg / kDegrees) * std::cos(roll_deg / kDegrees);
  return std::acos(std::clamp(c, -1.0, 1.0)) * kDegrees;
}

GroundDrive drive_on_ground(const world::Terrain& terrain, const world::RoverPose& start,
                            std::span<const nav::DriveCommand> commands,
                            const imaging::Chassis& chassis, const GroundDriveLimits& limits) {
  const world::RoverPlacement placement = world::place_rover(terrain.height, start, chassis);
  GroundDrive drive;
  drive.end = start;
  double next_reading = 0.0;
  // The tilt the rover starts from: standing over the threshold already (after an emergency
  // stop) is what the scheme's turn answers, not a new emergency.
  std::optional<double> start_tilt;
  double last_heading = 0.0;
  for (const nav::DrivePose& local : nav::drive_poses(commands)) {
    const world::RoverPose pose = to_world(placement, local.pose);
    drive.turned_deg += std::abs(local.pose.heading_rad - last_heading) * kDegrees;
    last_heading = local.pose.heading_rad;
    drive.end = pose;
    drive.driven_m = local.along_m;
    // Nodes beyond the site count as obstacles, so leaving the site is met here too.
    if (const auto hit = footprint_hit_at(terrain, placement, local, chassis)) {
      drive.unsafe = fmt::format("the footprint covers a true obstacle ({})", describe(*hit));
      drive.unsafe_at = Eigen::Vector2d(pose.x, pose.y);
      drive.track.emplace_back(pose.x, pose.y);
      return drive;
    }
    if (!local.turning && local.along_m + 1e-9 < next_reading)
      continue;
    next_reading = local.along_m + limits.read_every_m;
    drive.track.emplace_back(pose.x, pose.y);
    const imaging::Attitude attitude = world::place_rover(terrain.height, pose, chassis).attitude;
    const double tilt = tilt_deg(attitude.pitch_deg, attitude.roll_deg);
    if (tilt > limits.tilt_limit_deg) {
      drive.unsafe =
          fmt::format("tilt {:.1f} deg over the chassis limit {:.1f} deg (pitch "
                      "{:.1f}, roll {:.1f})",
                      tilt, limits.tilt_limit_deg, attitude.pitch_deg, attitude.roll_deg);
      drive.unsafe_at = Eigen::Vector2d(pose.x, pose.y);
      return drive;
    }
    if (!start_tilt)
      start_tilt = tilt;
    if (tilt > limits.emergency_tilt_deg && tilt > *start_tilt + kTiltRiseDeg) {
      drive.emergency_stop = true;
      drive.tilt_deg = tilt;
      drive.risen_side = attitude.roll_deg >= 0.0 ? nav::Side::left : nav::Side::right;
      return drive;
    }
    if (limits.goal &&
        (Eigen::Vector2d(pose.x, pose.y) - *limits.goal).norm() <= limits.goal_tolerance_m) {
      drive.at_goal = true;
      return drive;
    }
  }
  const Eigen::Vector2d end(drive.end.x, drive.end.y);
  if (drive.track.empty() || (drive.track.back() - end).norm() > 1e-9)
    drive.track.push_back(end);
  return drive;
}

} // namespace marsokhod::eval
