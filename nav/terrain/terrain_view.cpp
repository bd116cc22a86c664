// The level ground's disparity per pixel, and which pixels the right camera can see.

#include "terrain/terrain_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

constexpr float kHidden = std::numeric_limits<float>::infinity();

double ground_disparity(const double* fractions, double first_d, double rise, int x) {
  return first_d + rise * fractions[x];
}

void keep_tested(const std::uint8_t* seen, const double* fractions, double first_d, double rise,
                 int begin, int end, const float* disparity, float* out) {
  for (int x = begin; x < end; ++x) {
    const double ground_d = ground_disparity(fractions, first_d, rise, x);
    if (seen[x] != 0 && !(ground_d <= 0.0 || x < ground_d))
      out[x] = disparity[x];
  }
}

void keep_textured(const std::uint8_t* seen, int begin, int end, const float* disparity,
                   float* out) {
  for (int x = begin; x < end; ++x)
    out[x] = seen[x] != 0 ? disparity[x] : kHidden;
}

// The first column at or after `limit` (a positive finite value), at most `width`.
int first_column_from(double limit, int width) {
  if (limit >= width)
    return width;
  return static_cast<int>(std::ceil(limit));
}

} // namespace

LevelGround::LevelGround(const imaging::StereoRig& rig, const imaging::Attitude& attitude)
    : pose_(rig.camera_to_level(imaging::Eye::left, attitude)), cx_(rig.cx()), cy_(rig.cy()),
      focal_(rig.focal_px()), baseline_(rig.baseline_m()) {}

double LevelGround::disparity(double u, double v) const {
  const Eigen::Vector3d direction = pose_.linear() * Eigen::Vector3d(u - cx_, v - cy_, focal_);
  const double height = pose_.translation().z();
  if (height <= 0.0 || direction.z() >= 0.0)
    return 0.0;
  const double t = height / -direction.z();
  return baseline_ / t;
}

std::pmr::vector<double> column_fractions(int width, double span,
                                          std::pmr::memory_resource* memory) {
  std::pmr::vector<double> fractions(static_cast<std::size_t>(std::max(width, 0)), memory);
  for (int x = 0; x < width; ++x)
    fractions[static_cast<std::size_t>(x)] = x / span;
  return fractions;
}

// Every rounding step of ground_d is monotonic in x (x / span, the product by rise, the sum),
// so along the row ground_d never leaves the range of its two end values: columns left of the
// smaller one see past the right image's edge, columns right of the larger one inside it, and
// only the columns between, some |rise| of them, need the test itself. A row that is neither
// wholly below nor wholly above the horizon is tested throughout.
void keep_seeable(const std::uint8_t* seen, const double* fractions, double first_d, double rise,
                  int width, const float* disparity, float* out) {
  if (width <= 0)
    return;
  const double at_first = ground_disparity(fractions, first_d, rise, 0);
  const double at_last = ground_disparity(fractions, first_d, rise, width - 1);
  if (!std::isfinite(at_first) || !std::isfinite(at_last))
    return keep_tested(seen, fractions, first_d, rise, 0, width, disparity, out);
  const double lowest = std::min(at_first, at_last);
  const double highest = std::max(at_first, at_last);
  if (highest <= 0.0)
    return;
  if (lowest <= 0.0)
    return keep_tested(seen, fractions, first_d, rise, 0, width, disparity, out);
  const int past_edge = first_column_from(lowest, width);
  const int in_view = std::max(past_edge, first_column_from(highest, width));
  keep_tested(seen, fractions, first_d, rise, past_edge, in_view, disparity, out);
  keep_textured(seen, in_view, width, disparity, out);
}

int columns_past_edge(const double* fractions, double first_d, double rise, int width) {
  // Along a row ground_d changes by far less than a pixel a column (a row spans a few pixels
  // of disparity), so the columns past the edge are the ones before the first that is not.
  int x = 0;
  while (x < width) {
    const double ground_d = ground_disparity(fractions, first_d, rise, x);
    if (ground_d <= 0.0 || x >= ground_d)
      break;
    ++x;
  }
  return x;
}

} // namespace marsokhod::nav::detail
