// Which pixels of a row the right camera sees the ground of (private to the navigation cycle).
#pragma once

// Which pixels of a row the right camera can see the level ground of (private; navigate()'s
// seeable disparity, docs/navigation.md).

#include "marsokhod/imaging/rig/camera.hpp"

#include <cstdint>
#include <memory_resource>
#include <vector>

namespace marsokhod::nav::detail {

/// StereoRig::ground_disparity for one attitude, with the camera's pose worked out once rather
/// than at every call: the same arithmetic, so the same values.
class LevelGround {
public:
  LevelGround(const imaging::StereoRig& rig, const imaging::Attitude& attitude);
  double disparity(double u, double v) const;

private:
  Eigen::Isometry3d pose_;
  double cx_;
  double cy_;
  double focal_;
  double baseline_;
};

/// x / span for every column 0..width - 1: the same for every row.
std::pmr::vector<double> column_fractions(int width, double span,
                                          std::pmr::memory_resource* memory);

/// Copies disparity[x] to out[x] (which holds +inf) where seen[x] is not 0 and the level
/// ground's disparity
///   ground_d = first_d + rise * fractions[x]
/// is neither zero or less nor more than the column (ground_d <= 0 || x < ground_d fails).
void keep_seeable(const std::uint8_t* seen, const double* fractions, double first_d, double rise,
                  int width, const float* disparity, float* out);

/// How many of a row's first columns keep_seeable() drops as lying beyond the right image's
/// edge (x < ground_d with ground_d > 0), at most `width`. At or above the horizon (ground_d <= 0)
/// none: that is sky, not ground outside the right image.
int columns_past_edge(const double* fractions, double first_d, double rise, int width);

} // namespace marsokhod::nav::detail
