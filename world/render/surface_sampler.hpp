// The radiance a camera ray samples from the lit surface (private to the renderer).
#pragma once

#include "marsokhod/world/terrain/terrain.hpp"

#include <Eigen/Core>

namespace marsokhod::world {

/// Exposed radiance of the terrain as one camera ray samples it. The lit surface carries a
/// procedural texture finer than the terrain grid; where a pixel's footprint on the ground is
/// wider than that texture's pitch, a real sensor averages it away, and a single ray per pixel
/// would instead alias it into noise that differs between the two cameras. So the texture's
/// contrast is scaled by pitch / footprint (the standard deviation of an average over the
/// footprint), the level-of-detail rule of texture filtering; the grid-scale radiance is kept.
class SurfaceSampler {
public:
  /// pixel_angle: angle one ray stands for (1 / focal_px, divided by the supersampling).
  SurfaceSampler(const LitSurface& surface, const HeightField& height, double pixel_angle,
                 bool filter_texture);

  /// Grey level (before noise) of the surface point a ray met after `distance` metres:
  /// grey_with(point, texture_weight(point, direction, distance)).
  double grey(const Eigen::Vector3d& point, const Eigen::Vector3d& direction,
              double distance) const {
    return grey_with(point, texture_weight(point, direction, distance));
  }
  /// The two halves of grey(), for a caller who computes the weights of many rays first, so
  /// that their square roots and divisions overlap: the share of the sub-grid texture's
  /// contrast the ray's footprint keeps (1 or more: all of it)...
  double texture_weight(const Eigen::Vector3d& point, const Eigen::Vector3d& direction,
                        double distance) const;
  /// ... and the grey level with that share.
  double grey_with(const Eigen::Vector3d& point, double weight) const;

private:
  double grid_radiance(double x, double y) const;

  const LitSurface* surface_;
  const HeightField* height_;
  double pixel_angle_;
  bool filter_;
  double exposure_;
  double texture_pitch_m_;
};

} // namespace marsokhod::world
