// Filling the ground truth pixel by pixel from the left rays' hits (private to the renderer).
#pragma once

#include "marsokhod/world/render/camera_view.hpp"
#include "marsokhod/world/render/ground_truth.hpp"
#include "marsokhod/world/render/max_mipmap.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <Eigen/Geometry>

#include <optional>

namespace marsokhod::world {

/// Fills a GroundTruth pixel by pixel from the points the left camera's centre rays hit.
/// Given the right view's ray lengths (right_depth, +inf for sky), it decides occlusion from
/// them where they are unambiguous and casts a ray from the right camera only elsewhere.
class GroundTruthRecorder {
public:
  GroundTruthRecorder(GroundTruth& truth, const Terrain& terrain, const MaxMipmap& mipmap,
                      const CameraView& right, const Eigen::Isometry3d& level_to_world,
                      double occlusion_tolerance_m,
                      const imaging::Image<float>* right_depth = nullptr);

  /// Left pixel (u, v) saw the terrain at this world point.
  void record(int u, int v, const Eigen::Vector3d& hit_world);

private:
  enum class Sight { seen, hidden, unsure };

  bool hidden_from_right(const Eigen::Vector3d& hit_world, const Eigen::Vector2d& pixel) const;
  Sight judge_by_right_depth(const Eigen::Vector2d& pixel, double distance) const;
  bool on_obstacle(const Eigen::Vector3d& hit_world) const;

  GroundTruth* truth_;
  const Terrain* terrain_;
  const MaxMipmap* mipmap_;
  const CameraView* right_;
  Eigen::Isometry3d world_to_level_;
  double tolerance_m_;
  const imaging::Image<float>* right_depth_;
  std::optional<Eigen::Vector2d> obstacle_scale_; // obstacle-map nodes per height-field node
};

} // namespace marsokhod::world
