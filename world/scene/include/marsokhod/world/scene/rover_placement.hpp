// RoverPose and RoverPlacement: the rover set down on the terrain, its pitch and roll.
#pragma once

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/imaging/rig/chassis.hpp"
#include "marsokhod/world/terrain/height_field.hpp"

#include <Eigen/Geometry>

#include <array>

namespace marsokhod::world {

/// Where the rover stands: position and heading on the terrain (heading 0 = east, counter-
/// clockwise positive, degrees).
struct RoverPose {
  double x = 0.0;
  double y = 0.0;
  double heading_deg = 90.0;
};

/// The rover settled on the terrain: ground height under its centre and the pitch and roll its
/// wheels impose (imaging::Attitude conventions), plus the level frame as a world transform.
struct RoverPlacement {
  RoverPose pose;
  double ground_z = 0.0;
  imaging::Attitude attitude;
  /// Level frame (see imaging::StereoRig) -> world frame.
  Eigen::Isometry3d level_to_world = Eigen::Isometry3d::Identity();
};

/// World (x, y) of the six wheel contacts: front left, middle left, rear left, front right,
/// middle right, rear right.
std::array<Eigen::Vector2d, 6> wheel_contacts(const RoverPose& pose,
                                              const imaging::Chassis& chassis);

/// Settles the rover: the plane fitted by least squares to the ground heights under the six
/// wheels gives the forward gradient a = (mean front - mean rear) / wheelbase and the leftward
/// gradient b = (mean left - mean right) / track; pitch = atan(a) and
/// roll = asin(b / sqrt(1 + a^2 + b^2)), which are the angles of a body frame turned from the
/// level frame first by roll about x, then by pitch about y (nose up positive), whose z axis
/// is the fitted plane's normal. Throws std::invalid_argument for a non-positive wheelbase or
/// track, or a pose outside the height field.
RoverPlacement place_rover(const HeightField& height, const RoverPose& pose,
                           const imaging::Chassis& chassis = {});

} // namespace marsokhod::world
