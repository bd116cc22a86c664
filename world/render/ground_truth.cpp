// Ground truth: the per-pixel recorder (hit, occlusion, obstacle) and the pixel-count summary.

#include "marsokhod/world/render/ground_truth.hpp"

#include "render/ground_truth_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace marsokhod::world {
namespace {

constexpr float kUnknown = std::numeric_limits<float>::infinity();
constexpr std::uint8_t kSet = 255;
// Share of the distance within which the right view's ray lengths around a point's projection
// count as agreeing with it (plus half the occlusion tolerance), and by which they must all fall
// short of it to count as hiding it. Looser values disagreed with the exact ray on a few pixels
// of the default site (tests/world/hybrid_occlusion_test.cpp).
constexpr double kDepthAgreement = 0.0;
constexpr double kDepthGap = 0.5;

long count_set(const imaging::Image<std::uint8_t>& mask) {
  return static_cast<long>(std::count_if(
      mask.data(), mask.data() + mask.size(), [](std::uint8_t value) { return value != 0; }));
}

} // namespace

GroundTruth GroundTruth::unknown(int width, int height) {
  GroundTruth truth;
  truth.range = imaging::Image<float>(width, height, 1, kUnknown);
  truth.disparity = imaging::Image<float>(width, height, 1, kUnknown);
  truth.vertical_parallax = imaging::Image<float>(width, height, 1, kUnknown);
  truth.elevation = imaging::Image<float>(width, height, 1, kUnknown);
  truth.visible = imaging::Image<std::uint8_t>(width, height);
  truth.occluded = imaging::Image<std::uint8_t>(width, height);
  truth.valid = imaging::Image<std::uint8_t>(width, height);
  truth.obstacles = imaging::Image<std::uint8_t>(width, height);
  return truth;
}

GroundTruthStats summarize(const GroundTruth& truth) {
  GroundTruthStats stats;
  stats.pixels = static_cast<long>(truth.visible.size());
  stats.visible = count_set(truth.visible);
  stats.occluded = count_set(truth.occluded);
  stats.valid = count_set(truth.valid);
  stats.obstacles = count_set(truth.obstacles);
  return stats;
}

GroundTruthRecorder::GroundTruthRecorder(GroundTruth& truth, const Terrain& terrain,
                                         const MaxMipmap& mipmap, const CameraView& right,
                                         const Eigen::Isometry3d& level_to_world,
                                         double occlusion_tolerance_m,
                                         const imaging::Image<float>* right_depth)
    : truth_(&truth), terrain_(&terrain), mipmap_(&mipmap), right_(&right),
      world_to_level_(level_to_world.inverse()), tolerance_m_(occlusion_tolerance_m),
      right_depth_(right_depth) {
  // The obstacle map covers the height field's area; it may be sampled more coarsely.
  const imaging::Image<std::uint8_t>& map = terrain.obstacles;
  const HeightField& height = terrain.height;
  if (!map.empty() && height.nx() >= 2 && height.ny() >= 2)
    obstacle_scale_.emplace(static_cast<double>(map.width() - 1) / (height.nx() - 1),
                            static_cast<double>(map.height() - 1) / (height.ny() - 1));
}

void GroundTruthRecorder::record(int u, int v, const Eigen::Vector3d& hit_world) {
  const Eigen::Vector3d level = world_to_level_ * hit_world;
  truth_->range(u, v) =
      static_cast<float>(std::sqrt(level.x() * level.x() + level.y() * level.y()));
  truth_->elevation(u, v) = static_cast<float>(level.z());
  truth_->visible(u, v) = kSet;
  if (on_obstacle(hit_world))
    truth_->obstacles(u, v) = kSet;

  const auto right_pixel = right_->project(hit_world);
  if (right_pixel) {
    truth_->disparity(u, v) = static_cast<float>(u - right_pixel->x());
    truth_->vertical_parallax(u, v) = static_cast<float>(v - right_pixel->y());
  }
  const bool occluded =
      !right_pixel || !right_->on_image(*right_pixel) || hidden_from_right(hit_world, *right_pixel);
  truth_->occluded(u, v) = occluded ? kSet : 0;
  truth_->valid(u, v) = occluded ? 0 : kSet;
}

GroundTruthRecorder::Sight GroundTruthRecorder::judge_by_right_depth(const Eigen::Vector2d& pixel,
                                                                     double distance) const {
  if (!right_depth_)
    return Sight::unsure;
  const imaging::Image<float>& depth = *right_depth_;
  if (!(pixel.x() >= 0.0 && pixel.y() >= 0.0))
    return Sight::unsure;
  // Truncation is floor here, the coordinates being >= 0.
  const int u = static_cast<int>(pixel.x());
  const int v = static_cast<int>(pixel.y());
  if (u + 1 >= depth.width() || v + 1 >= depth.height())
    return Sight::unsure;
  // The right rays through the four pixel centres around the point's projection.
  const float around[4] = {depth(u, v), depth(u + 1, v), depth(u, v + 1), depth(u + 1, v + 1)};
  const auto [nearest, farthest] = std::minmax_element(std::begin(around), std::end(around));
  if (!std::isfinite(*farthest))
    return Sight::unsure; // sky next to it: a silhouette
  // All four stop well short of the point: it lies behind what they met.
  if (*farthest < distance - kDepthGap * distance - tolerance_m_)
    return Sight::hidden;
  // All four meet the surface close to the point and to one another: no depth edge there.
  const double margin = kDepthAgreement * distance + 0.5 * tolerance_m_;
  if (*nearest >= distance - margin && *farthest <= distance + margin)
    return Sight::seen;
  return Sight::unsure;
}

bool GroundTruthRecorder::hidden_from_right(const Eigen::Vector3d& hit_world,
                                            const Eigen::Vector2d& pixel) const {
  const Eigen::Vector3d towards = hit_world - right_->centre();
  const double distance = towards.norm();
  if (distance <= tolerance_m_)
    return false;
  const Sight sight = judge_by_right_depth(pixel, distance);
  if (sight != Sight::unsure)
    return sight == Sight::hidden;
  // The sight line walked from the point back towards the camera: the same segment, but the
  // walk starts beside the point in the finest level and, rising, soon climbs above every
  // block (or above the highest point of the site) instead of descending to it from the top.
  return mipmap_->first_hit_beyond(hit_world, -towards / distance, tolerance_m_, distance)
      .has_value();
}

bool GroundTruthRecorder::on_obstacle(const Eigen::Vector3d& hit_world) const {
  const imaging::Image<std::uint8_t>& map = terrain_->obstacles;
  if (!obstacle_scale_)
    return false;
  const HeightField& height = terrain_->height;
  const double gx = (hit_world.x() - height.origin().x()) / height.cell_m();
  const double gy = (hit_world.y() - height.origin().y()) / height.cell_m();
  // Truncation stands in for floor: the two differ only below 0, which the clamp maps to 0.
  const int i = static_cast<int>(gx * obstacle_scale_->x() + 0.5);
  const int j = static_cast<int>(gy * obstacle_scale_->y() + 0.5);
  return map(std::clamp(i, 0, map.width() - 1), std::clamp(j, 0, map.height() - 1)) != 0;
}

} // namespace marsokhod::world
