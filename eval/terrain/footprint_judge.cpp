// Sweeping the chassis footprint over the true obstacle map along the executed commands.
#include "marsokhod/eval/terrain/footprint_judge.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace marsokhod::eval {
namespace {

struct WorldFrame {
  Eigen::Isometry3d level_to_world;
  double heading_rad;
};

imaging::PlanarPose to_world(const WorldFrame& frame, const imaging::PlanarPose& level) {
  const Eigen::Vector3d p = frame.level_to_world * Eigen::Vector3d(level.x, level.y, 0.0);
  return {p.x(), p.y(), frame.heading_rad + level.heading_rad};
}

Eigen::Vector3d on_ground(const world::Terrain& terrain, const Eigen::Vector2d& point) {
  return {point.x(), point.y(), terrain.height.height(point.x(), point.y())};
}

// The first obstacle node (world position) under the footprint at a world pose.
std::optional<Eigen::Vector2d> obstacle_under(const world::Terrain& terrain,
                                              const imaging::Chassis& chassis,
                                              const imaging::PlanarPose& pose) {
  const world::HeightField& height = terrain.height;
  const double reach = imaging::footprint_reach_m(chassis);
  const Eigen::Vector2d low =
      (Eigen::Vector2d(pose.x, pose.y).array() - reach - height.origin().array()) / height.cell_m();
  const Eigen::Vector2d high =
      (Eigen::Vector2d(pose.x, pose.y).array() + reach - height.origin().array()) / height.cell_m();
  const int i0 = static_cast<int>(std::floor(low.x()));
  const int j0 = static_cast<int>(std::floor(low.y()));
  const int i1 = static_cast<int>(std::ceil(high.x()));
  const int j1 = static_cast<int>(std::ceil(high.y()));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const Eigen::Vector2d node = height.origin() + height.cell_m() * Eigen::Vector2d(i, j);
      if (!imaging::under_footprint(chassis, pose, node.x(), node.y()))
        continue;
      const bool outside = i < 0 || j < 0 || i >= height.nx() || j >= height.ny();
      if (outside || terrain.obstacles(i, j) != 0)
        return node;
    }
  return std::nullopt;
}

} // namespace

std::optional<FootprintHit> footprint_hit_at(const world::Terrain& terrain,
                                             const world::RoverPlacement& placement,
                                             const nav::DrivePose& pose,
                                             const imaging::Chassis& chassis) {
  const WorldFrame frame{placement.level_to_world,
                         placement.pose.heading_deg * std::numbers::pi / 180.0};
  const std::optional<Eigen::Vector2d> node =
      obstacle_under(terrain, chassis, to_world(frame, pose.pose));
  if (!node)
    return std::nullopt;
  const Eigen::Isometry3d world_to_level = placement.level_to_world.inverse();
  const Eigen::Vector3d level = world_to_level * on_ground(terrain, *node);
  FootprintHit hit{level.x(), level.y(), level.z(), std::hypot(level.x(), level.y()), pose, {}, {}};
  const auto corners = imaging::footprint_corners(chassis, to_world(frame, pose.pose));
  for (std::size_t c = 0; c < corners.size(); ++c)
    hit.corners[c] = world_to_level * on_ground(terrain, corners[c]);
  return hit;
}

FootprintVerdict judge_footprint(const world::Terrain& terrain,
                                 const world::RoverPlacement& placement,
                                 std::span<const nav::DriveCommand> commands,
                                 const imaging::Chassis& chassis) {
  for (const nav::DrivePose& pose : nav::drive_poses(commands))
    if (auto hit = footprint_hit_at(terrain, placement, pose, chassis))
      return {std::move(hit)};
  return {};
}

std::string describe(const FootprintHit& hit) {
  return fmt::format("obstacle {:.2f} m away ({:.2f} ahead, {:.2f} {}), {:.2f} m into the drive, "
                     "leg {} {}",
                     hit.range_m, hit.x_m, std::abs(hit.y_m), hit.y_m >= 0.0 ? "left" : "right",
                     hit.pose.along_m, hit.pose.command + 1,
                     hit.pose.turning ? "turning" : "driving") +
         (hit.seen_as.empty() ? std::string() : "; the navigation: " + hit.seen_as);
}

} // namespace marsokhod::eval
