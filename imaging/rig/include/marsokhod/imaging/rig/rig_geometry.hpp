// What the rig sees of level ground: horizon row, ground distance, obstacle parallax.
#pragma once

#include "marsokhod/imaging/rig/camera.hpp"

namespace marsokhod::imaging {

/// Row (fractional) where the horizon crosses the left image's centre column; it may lie
/// outside the image. NaN if the centre column never meets the horizon (camera rolled 90 deg).
double horizon_row(const StereoRig& rig, const Attitude& attitude = {});

/// Distance ahead of the rover centre (level x) of the ground seen at row v of the left image's
/// centre column; +inf where the row looks at or above the horizon.
double ground_distance_at_row(const StereoRig& rig, double v, const Attitude& attitude = {});

/// Parallax figures of an obstacle standing on level ground straight ahead of the rover, as the
/// paper quotes them for a 30 cm stone at 14 m (section 2). Disparities are f * B / depth of
/// the ideal rig; rows are in the left image.
struct ObstacleParallax {
  double distance_m = 0.0;          ///< ground distance of the obstacle from the rover centre
  double height_m = 0.0;            ///< obstacle height
  double top_row = 0.0;             ///< left image row of the obstacle's top
  double bottom_row = 0.0;          ///< left image row of its foot
  double top_disparity_px = 0.0;    ///< disparity of the top
  double bottom_disparity_px = 0.0; ///< disparity of the foot (equals the ground's at its row)
  /// The obstacle's own disparity relief: tiny, top and foot are at nearly the same depth.
  double top_minus_bottom_px = 0.0;
  /// Ground seen in the same row as the top, behind the obstacle (+inf if that row looks at or
  /// above the horizon) and its disparity (0 then).
  double ground_behind_distance_m = 0.0;
  double ground_behind_disparity_px = 0.0;
  /// What a detector comparing a row with the ground plane sees at the obstacle's top.
  double top_minus_ground_px = 0.0;
};

/// The figures for an obstacle of height_m at distance_m ahead of the rover centre, rover level.
/// Throws std::invalid_argument unless distance_m > 0 and height_m >= 0 and the obstacle is in
/// front of the cameras.
ObstacleParallax obstacle_parallax(const StereoRig& rig, double distance_m, double height_m);

} // namespace marsokhod::imaging
