// The line chart: the size asked for, the curve where its points are, the missing values in
// red at the bottom, bad values refused.

#include "marsokhod/imaging/pictures/line_chart.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace marsokhod::imaging {
namespace {

// Pixels of one colour in a region.
int count(const Image<std::uint8_t>& rgb, int x0, int x1, int y0, int y1, int r, int g, int b) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      n += rgb(x, y, 0) == r && rgb(x, y, 1) == g && rgb(x, y, 2) == b ? 1 : 0;
  return n;
}

LineChart falling_curve() {
  return LineChart{.title = "time against memory",
                   .x_label = "kb",
                   .y_label = "s",
                   .points = {{256, 16.0}, {512, 10.0}, {1024, 7.0}},
                   .missing = {32},
                   .marks = {{256, "as shipped"}}};
}

TEST(LineChart, HasTheSizeAskedForAndThreeChannels) {
  const Image<std::uint8_t> picture = draw_line_chart(falling_curve());
  EXPECT_EQ(picture.width(), 720);
  EXPECT_EQ(picture.height(), 420);
  EXPECT_EQ(picture.channels(), 3);
}

// The highest curve pixel (smallest row) of column x, or -1.
int top_of_curve(const Image<std::uint8_t>& rgb, int x) {
  for (int y = 0; y < rgb.height(); ++y)
    if (rgb(x, y, 0) == 31 && rgb(x, y, 1) == 119 && rgb(x, y, 2) == 180)
      return y;
  return -1;
}

TEST(LineChart, DrawsTheCurveFromHighOnTheLeftToLowOnTheRightAndTheMissingInRed) {
  const Image<std::uint8_t> picture = draw_line_chart(falling_curve());
  const int w = picture.width();
  const int h = picture.height();
  int first = -1;
  int last = -1;
  for (int x = 0; x < w; ++x)
    if (top_of_curve(picture, x) >= 0) {
      first = first < 0 ? x : first;
      last = x;
    }
  ASSERT_GE(first, 0) << "no curve drawn";
  // 16 s at the left end, 7 s at the right: the curve falls to the right, and the missing 32,
  // the smallest x, lies left of it all.
  EXPECT_LT(top_of_curve(picture, first), top_of_curve(picture, last));
  EXPECT_GT(count(picture, 0, first, h / 2, h, 214, 39, 40), 0);
  EXPECT_EQ(count(picture, first, w, 0, h, 214, 39, 40), 0);
}

TEST(LineChart, RefusesAnXThatIsNotPositiveOrAYThatIsNotFinite) {
  LineChart chart = falling_curve();
  chart.points.push_back({0.0, 1.0});
  EXPECT_THROW(draw_line_chart(chart), std::invalid_argument);
  chart = falling_curve();
  chart.points.push_back({10.0, std::numeric_limits<double>::quiet_NaN()});
  EXPECT_THROW(draw_line_chart(chart), std::invalid_argument);
  chart = falling_curve();
  chart.missing.push_back(-4.0);
  EXPECT_THROW(draw_line_chart(chart), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::imaging
