// Ground truth of a rendered pair: range, disparity, elevation and masks per left pixel.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <cstdint>

namespace marsokhod::world {

/// What a perfect stereo system would find, per pixel of the left (reference) image, from the
/// exact intersection of the pixel-centre ray with the terrain. Float fields hold +inf where
/// the ray saw no terrain (Middlebury convention); masks hold 0 or 255.
struct GroundTruth {
  /// Horizontal distance from the rover centre to the seen point, level frame, metres.
  imaging::Image<float> range;
  /// u_left - u_right, where u_right is the seen point's projection in the actual (possibly
  /// misaligned) right camera: the disparity a matcher should find. Finite wherever the ray
  /// hit the terrain, also where the right camera cannot see the point (see valid).
  imaging::Image<float> disparity;
  /// v_left - v_right, non-zero only for a misaligned rig, pixels.
  imaging::Image<float> vertical_parallax;
  /// Height of the seen point above the horizontal plane under the rover (level frame z), m.
  imaging::Image<float> elevation;
  /// 255 where the ray hit the terrain.
  imaging::Image<std::uint8_t> visible;
  /// 255 where the point is visible on the left but hidden from the right camera (terrain in
  /// the way or outside the right image).
  imaging::Image<std::uint8_t> occluded;
  /// 255 where visible and not occluded: the pixels on which a matcher can be scored.
  imaging::Image<std::uint8_t> valid;
  /// 255 where the seen point lies on the terrain's obstacle map.
  imaging::Image<std::uint8_t> obstacles;

  /// Everything unknown: +inf fields and empty masks.
  static GroundTruth unknown(int width, int height);
};

/// Pixel counts of a ground truth, for summaries.
struct GroundTruthStats {
  long pixels = 0;
  long visible = 0;
  long occluded = 0;
  long valid = 0;
  long obstacles = 0;

  double valid_fraction() const { return pixels > 0 ? static_cast<double>(valid) / pixels : 0.0; }
  /// Share of the visible pixels that see an obstacle.
  double obstacle_fraction() const {
    return visible > 0 ? static_cast<double>(obstacles) / visible : 0.0;
  }
};

GroundTruthStats summarize(const GroundTruth& truth);

} // namespace marsokhod::world
