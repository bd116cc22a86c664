// The vertical parallax map's shifts, and right images resampled to remove them.

#include "marsokhod/nav/calibration/vertical_parallax.hpp"

#include "work/work_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace marsokhod::nav {

double VerticalParallaxMap::shift_at(double x, double y) const {
  const double u = x - 0.5 * (width - 1);
  const double v = y - 0.5 * (height - 1);
  const auto& c = coefficients;
  return c[0] + c[1] * u + c[2] * v + c[3] * u * u + c[4] * u * v + c[5] * v * v;
}

double VerticalParallaxMap::largest_shift() const {
  // A quadratic's extremes over a rectangle lie on its border or at one interior point; a
  // 33 x 33 grid including the border bounds it closely enough for a plausibility check.
  constexpr int kSteps = 32;
  double largest = 0.0;
  for (int i = 0; i <= kSteps; ++i)
    for (int j = 0; j <= kSteps; ++j) {
      const double x = (width - 1) * static_cast<double>(i) / kSteps;
      const double y = (height - 1) * static_cast<double>(j) / kSteps;
      largest = std::max(largest, std::fabs(shift_at(x, y)));
    }
  return largest;
}

bool VerticalParallaxMap::is_identity() const {
  return std::all_of(
      coefficients.begin(), coefficients.end(), [](double c) { return c == 0.0; });
}

std::string calibration_map_problem(const VerticalParallaxMap& map) {
  const auto side_ok = [](int side) {
    return side >= kMinCalibrationSide && side <= imaging::kMaxImageSide;
  };
  if (!side_ok(map.width) || !side_ok(map.height))
    return fmt::format("the map is for {}x{} images; a calibration needs {}..{} pixels a side",
                       map.width, map.height, kMinCalibrationSide, imaging::kMaxImageSide);
  for (const double c : map.coefficients)
    if (!(std::fabs(c) <= kMaxCalibrationCoefficient))
      return fmt::format("a coefficient of {} is beyond the +-{} a calibration may hold", c,
                         kMaxCalibrationCoefficient);
  const double largest = map.largest_shift();
  if (!(largest <= kMaxVerticalShift))
    return fmt::format("the map shifts rows by up to {:.1f}, more than the {} rows a calibration "
                       "may correct",
                       largest, kMaxVerticalShift);
  return {};
}

void check_map_size(const VerticalParallaxMap& map, int width, int height,
                    const std::string& source) {
  if (map.width == width && map.height == height)
    return;
  throw CalibrationError(fmt::format("{}: the calibration is for {}x{} images but the images are "
                                     "{}x{}",
                                     source, map.width, map.height, width, height));
}

namespace {

// Interpolation weights in 1/4096: integer arithmetic on byte images, as the T805 would do it,
// with rounding error far below one grey level.
constexpr int kWeightBits = 12;
constexpr int kWeightOne = 1 << kWeightBits;

using Taps = std::array<int, 4>; // weights of rows upper - 1, upper, upper + 1, upper + 2

// Keys' cubic convolution (a = -1/2): exact for quadratics, and at half a row it passes
// detail that linear interpolation averages away.
Taps cubic_taps(int fraction) {
  const double t = static_cast<double>(fraction) / kWeightOne;
  const double t2 = t * t;
  const double t3 = t2 * t;
  const std::array<double, 4> w = {-0.5 * t3 + t2 - 0.5 * t, 1.5 * t3 - 2.5 * t2 + 1.0,
                                   -1.5 * t3 + 2.0 * t2 + 0.5 * t, 0.5 * t3 - 0.5 * t2};
  Taps taps{};
  int sum = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    taps[i] = static_cast<int>(std::lround(w[i] * kWeightOne));
    sum += taps[i];
  }
  taps[1] += kWeightOne - sum; // the weights sum to one exactly: flat areas stay flat
  return taps;
}

// The source row of every pixel of row y in 1/kWeightOne rows, clamped to the image. Along a
// row the quadratic is c + u (b + a u), evaluated with the row's own constants.
void source_rows(const VerticalParallaxMap& map, int y, int last_row,
                 std::pmr::vector<std::int32_t>& rows) {
  const auto& c = map.coefficients;
  const double v = y - 0.5 * (map.height - 1);
  const double constant = y + c[0] + c[2] * v + c[5] * v * v;
  const double slope = c[1] + c[4] * v;
  const double centre = 0.5 * (map.width - 1);
  const double limit = last_row;
  for (std::size_t x = 0; x < rows.size(); ++x) {
    const double u = static_cast<double>(x) - centre;
    const double source = std::clamp(constant + u * (slope + u * c[3]), 0.0, limit);
    rows[x] = static_cast<std::int32_t>(source * kWeightOne + 0.5);
  }
}

void linear_row(imaging::ImageView<const std::uint8_t> right, std::span<const std::int32_t> rows,
                std::uint8_t* out) {
  const int last_row = right.height() - 1;
  for (std::size_t x = 0; x < rows.size(); ++x) {
    const int upper = rows[x] >> kWeightBits;
    const int weight = rows[x] & (kWeightOne - 1);
    const int lower = std::min(upper + 1, last_row);
    const int column = static_cast<int>(x);
    const int sum = right(column, upper) * (kWeightOne - weight) + right(column, lower) * weight;
    out[x] = static_cast<std::uint8_t>((sum + kWeightOne / 2) >> kWeightBits);
  }
}

void cubic_row(imaging::ImageView<const std::uint8_t> right, std::span<const std::int32_t> rows,
               std::uint8_t* out) {
  const int last_row = right.height() - 1;
  for (std::size_t x = 0; x < rows.size(); ++x) {
    const int upper = rows[x] >> kWeightBits;
    const Taps taps = cubic_taps(rows[x] & (kWeightOne - 1));
    int sum = kWeightOne / 2;
    for (int i = 0; i < 4; ++i)
      sum += taps[static_cast<std::size_t>(i)] *
             right(static_cast<int>(x), std::clamp(upper - 1 + i, 0, last_row));
    out[x] = static_cast<std::uint8_t>(std::clamp(sum >> kWeightBits, 0, 255));
  }
}

} // namespace

template <class Meter>
imaging::Image<std::uint8_t>
remove_vertical_parallax(imaging::ImageView<const std::uint8_t> right,
                         const VerticalParallaxMap& map, VerticalInterpolation interpolation,
                         Meter& meter, std::pmr::memory_resource* memory) {
  check_map_size(map, right.width(), right.height(), "vertical parallax map");
  const int width = right.width();
  const int last_row = right.height() - 1;
  imaging::Image<std::uint8_t> aligned(width, right.height(), 1, 0, memory);
  std::pmr::vector<std::int32_t> rows(static_cast<std::size_t>(width), 0, memory);
  for (int y = 0; y <= last_row; ++y) {
    source_rows(map, y, last_row, rows);
    if (interpolation == VerticalInterpolation::cubic)
      cubic_row(right, rows, aligned.row(y));
    else
      linear_row(right, rows, aligned.row(y));
    detail::report(meter, Work::pyramid_pixel, static_cast<std::uint64_t>(width));
  }
  return aligned;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template imaging::Image<std::uint8_t> remove_vertical_parallax<M>(                               \
      imaging::ImageView<const std::uint8_t>, const VerticalParallaxMap&, VerticalInterpolation,   \
      M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
