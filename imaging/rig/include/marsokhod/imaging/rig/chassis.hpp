// The rover's chassis: where its wheels stand and the ground its footprint covers.
#pragma once

#include <Eigen/Core>

#include <array>

namespace marsokhod::imaging {

/// The Marsokhod chassis as this project states it (docs/navigation.md, "The rover's
/// footprint"): six wheels on three axles, the middle axle at the centre. The paper gives the
/// layout, not the dimensions; these are stated values, the same for the world's placement of
/// the rover, the navigation's margin and the judges of paths.
struct Chassis {
  double wheelbase_m = 1.5; ///< first to last axle
  double track_m = 1.0;     ///< left to right wheel centres
  double wheel_diameter_m = 0.35;
  double wheel_width_m = 0.20;

  /// Front of the front wheels to the back of the rear wheels.
  double length_m() const { return wheelbase_m + wheel_diameter_m; }
  /// Outer face of the left wheels to the outer face of the right wheels.
  double width_m() const { return track_m + wheel_width_m; }
};

/// Throws std::invalid_argument naming the first dimension that is not finite and positive.
void validate(const Chassis& chassis);

/// Where the rover's centre stands on the ground and which way it faces (radians,
/// counter-clockwise from the frame's x axis).
struct PlanarPose {
  double x = 0.0;
  double y = 0.0;
  double heading_rad = 0.0;
};

/// The footprint's corners at a pose: front left, rear left, rear right, front right.
std::array<Eigen::Vector2d, 4> footprint_corners(const Chassis& chassis, const PlanarPose& pose);

/// True when the ground point (x, y) lies under the footprint (the rectangle length_m by
/// width_m centred on the pose, edges included).
bool under_footprint(const Chassis& chassis, const PlanarPose& pose, double x, double y);

/// Half the diagonal of the footprint: the farthest any of it reaches from the centre, which
/// is what turning on the spot sweeps.
double footprint_reach_m(const Chassis& chassis);

} // namespace marsokhod::imaging
