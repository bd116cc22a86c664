// Test support for the world tests: hand-made scenes and a hand-written pinhole camera.
#pragma once
// Hand-made scenes and a hand-written pinhole camera for the renderer tests. The camera model is
// written out from the rig's documented conventions (level frame x forward, y left, z up;
// camera x right, y down, z along the optical axis, pitched down by a; left camera at +B/2,
// right camera at -B/2, both mast_forward ahead of and mast_height above the rover centre),
// not taken from the code under test.

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <numbers>

namespace marsokhod::test {

/// A square height field of zeros centred on the origin.
inline world::HeightField flat_field(double half_size_m, double cell_m) {
  const int n = static_cast<int>(std::lround(2.0 * half_size_m / cell_m)) + 1;
  return world::HeightField(n, n, cell_m, Eigen::Vector2d(-half_size_m, -half_size_m));
}

/// Raises every node with x in [x0, x1] and y in [y0, y1] to height_m: a box whose flat top is
/// exactly that rectangle and whose sides slope down over one cell.
inline void raise_box(world::HeightField& field, double x0, double x1, double y0, double y1,
                      double height_m) {
  const double eps = 1e-9;
  for (int j = 0; j < field.ny(); ++j)
    for (int i = 0; i < field.nx(); ++i) {
      const Eigen::Vector2d p = field.origin() + Eigen::Vector2d(i, j) * field.cell_m();
      if (p.x() >= x0 - eps && p.x() <= x1 + eps && p.y() >= y0 - eps && p.y() <= y1 + eps)
        field.at(i, j) = static_cast<float>(height_m);
    }
}

/// A terrain around a given height field: albedo from a function of (x, y), obstacles from the
/// default locomotion limits.
inline world::Terrain terrain_from(world::HeightField field,
                                   const std::function<float(double, double)>& albedo) {
  world::Terrain terrain;
  terrain.settings.size_m = (field.nx() - 1) * field.cell_m();
  terrain.settings.cell_m = field.cell_m();
  terrain.height = std::move(field);
  const world::HeightField& h = terrain.height;
  terrain.albedo = imaging::Image<float>(h.nx(), h.ny());
  for (int j = 0; j < h.ny(); ++j)
    for (int i = 0; i < h.nx(); ++i)
      terrain.albedo(i, j) =
          albedo(h.origin().x() + i * h.cell_m(), h.origin().y() + j * h.cell_m());
  terrain.obstacles = world::obstacle_map(terrain.height, world::LocomotionLimits{});
  return terrain;
}

/// Smooth albedo pattern with wavelengths of 0.4..1.3 m: matchable at every range the test
/// cameras see, without aliasing at one ray per pixel.
inline float smooth_albedo(double x, double y) {
  return static_cast<float>(0.45 + 0.12 * std::sin(2.0 * std::numbers::pi * x / 0.9) +
                            0.10 * std::sin(2.0 * std::numbers::pi * (0.6 * x + y) / 1.3) +
                            0.08 * std::cos(2.0 * std::numbers::pi * (x - 0.8 * y) / 0.4));
}

/// The rover at the origin, heading east, on level ground: the level frame is the world frame.
inline world::RoverPlacement level_placement() {
  world::RoverPlacement placement;
  placement.pose = world::RoverPose{0.0, 0.0, 0.0};
  return placement;
}

/// A pinhole camera of the rig on a level rover, in the level frame.
struct HandCamera {
  Eigen::Vector3d centre;
  Eigen::Vector3d x_axis, y_axis, z_axis;
  double f, cx, cy;

  HandCamera(const imaging::RigParameters& p, imaging::Eye eye) {
    const double side = eye == imaging::Eye::left ? 0.5 : -0.5;
    centre = Eigen::Vector3d(p.mast_forward_m, side * p.baseline_m, p.mast_height_m);
    const double a = p.pitch_down_deg * std::numbers::pi / 180.0;
    x_axis = Eigen::Vector3d(0.0, -1.0, 0.0);
    y_axis = Eigen::Vector3d(-std::sin(a), 0.0, -std::cos(a));
    z_axis = Eigen::Vector3d(std::cos(a), 0.0, -std::sin(a));
    f = p.focal_mm / p.sensor_mm * p.width_px;
    cx = 0.5 * (p.width_px - 1);
    cy = 0.5 * (p.height_px - 1);
  }

  Eigen::Vector2d project(const Eigen::Vector3d& point) const {
    const Eigen::Vector3d d = point - centre;
    const double z = d.dot(z_axis);
    return {cx + f * d.dot(x_axis) / z, cy + f * d.dot(y_axis) / z};
  }
  /// Direction (not unit) of the ray through pixel (u, v).
  Eigen::Vector3d ray(double u, double v) const {
    return x_axis * ((u - cx) / f) + y_axis * ((v - cy) / f) + z_axis;
  }
  /// Where the ray through (u, v) meets the plane z = 0 (the ray must point down).
  Eigen::Vector3d ground_point(double u, double v) const {
    const Eigen::Vector3d d = ray(u, v);
    return centre + d * (centre.z() / -d.z());
  }
};

} // namespace marsokhod::test
