// Sampling the turns and straight legs of drive commands into poses.
#include "marsokhod/nav/path/drive_poses.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

int steps_for(double amount, double step) {
  return std::max(1, static_cast<int>(std::ceil(std::abs(amount) / step)));
}

} // namespace

std::pmr::vector<DrivePose> drive_poses(std::span<const DriveCommand> commands,
                                        const DriveSweepOptions& options,
                                        std::pmr::memory_resource* memory) {
  if (!(options.step_m > 0.0) || !(options.turn_step_deg > 0.0) || !std::isfinite(options.step_m) ||
      !std::isfinite(options.turn_step_deg))
    throw std::invalid_argument("drive_poses: steps must be finite and positive");
  constexpr double kRadian = std::numbers::pi / 180.0;
  std::pmr::vector<DrivePose> poses(1, DrivePose{}, memory);
  imaging::PlanarPose at;
  double along = 0.0;
  for (std::size_t c = 0; c < commands.size(); ++c) {
    const DriveCommand& command = commands[c];
    if (!std::isfinite(command.turn_deg) || !std::isfinite(command.distance_m))
      throw std::invalid_argument("drive_poses: a command is not finite");
    const int index = static_cast<int>(c);
    const double turn = command.turn_deg * kRadian;
    const double start_heading = at.heading_rad;
    if (turn != 0.0) {
      const int n = steps_for(command.turn_deg, options.turn_step_deg);
      for (int i = 1; i <= n; ++i) {
        at.heading_rad = start_heading + turn * i / n;
        poses.push_back({at, along, index, true});
      }
    }
    const double ox = at.x;
    const double oy = at.y;
    const int n = steps_for(command.distance_m, options.step_m);
    for (int i = 1; i <= n; ++i) {
      const double d = command.distance_m * i / n;
      at.x = ox + d * std::cos(at.heading_rad);
      at.y = oy + d * std::sin(at.heading_rad);
      poses.push_back({at, along + std::abs(d), index, false});
    }
    along += std::abs(command.distance_m);
  }
  return poses;
}

} // namespace marsokhod::nav
