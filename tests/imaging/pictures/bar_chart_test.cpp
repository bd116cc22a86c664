// The bar chart: the size asked for, each bar as tall as its value against the others, a gap
// for a missing value, bad charts refused.

#include "marsokhod/imaging/pictures/bar_chart.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <stdexcept>

namespace marsokhod::imaging {
namespace {

constexpr int kPaper[3] = {127, 127, 127}; // the first series' colour
constexpr int kModel[3] = {31, 119, 180};  // the second's

bool is(const Image<std::uint8_t>& rgb, int x, int y, const int (&c)[3]) {
  return rgb(x, y, 0) == c[0] && rgb(x, y, 1) == c[1] && rgb(x, y, 2) == c[2];
}

// Height in pixels of the tallest run of a colour in column x, counted from the bottom up.
int bar_height(const Image<std::uint8_t>& rgb, int x, const int (&c)[3]) {
  int h = 0;
  for (int y = 0; y < rgb.height(); ++y)
    h += is(rgb, x, y, c) ? 1 : 0;
  return h;
}

// The columns a colour fills, as [first, last], searched in [x0, x1).
std::pair<int, int> columns(const Image<std::uint8_t>& rgb, int x0, int x1, const int (&c)[3]) {
  int first = -1;
  int last = -1;
  for (int x = x0; x < x1; ++x)
    if (bar_height(rgb, x, c) > 20) {
      first = first < 0 ? x : first;
      last = x;
    }
  return {first, last};
}

BarChart paper_and_model() {
  return BarChart{.title = "paper and model",
                  .y_label = "s",
                  .series = {"paper", "model"},
                  .groups = {{"stereo", {8.0, 8.0}}, {"onboard", {78.0, 19.5}}}};
}

TEST(BarChart, HasTheSizeAskedForAndThreeChannels) {
  const Image<std::uint8_t> picture = draw_bar_chart(paper_and_model());
  EXPECT_EQ(picture.width(), 720);
  EXPECT_EQ(picture.height(), 420);
  EXPECT_EQ(picture.channels(), 3);
}

// Heights are proportional to the values from a common base: 78 is four times 19.5, and the
// two equal values of the first group are equally tall.
TEST(BarChart, DrawsEachBarAsTallAsItsValueInItsGroupsSlot) {
  const Image<std::uint8_t> picture = draw_bar_chart(paper_and_model());
  const int middle = picture.width() / 2;
  const auto [p0, p1] = columns(picture, 0, middle, kPaper);
  const auto [m0, m1] = columns(picture, 0, middle, kModel);
  ASSERT_GE(p0, 0);
  ASSERT_GE(m0, 0);
  EXPECT_LT(p1, m0) << "the paper's bar comes first";
  EXPECT_EQ(bar_height(picture, (p0 + p1) / 2, kPaper), bar_height(picture, (m0 + m1) / 2, kModel));
  const auto [q0, q1] = columns(picture, middle, picture.width(), kPaper);
  const auto [n0, n1] = columns(picture, middle, picture.width(), kModel);
  ASSERT_GE(q0, 0);
  ASSERT_GE(n0, 0);
  const double tall = bar_height(picture, (q0 + q1) / 2, kPaper);
  const double short_one = bar_height(picture, (n0 + n1) / 2, kModel);
  EXPECT_NEAR(tall / short_one, 4.0, 0.15);
  EXPECT_NEAR(tall / bar_height(picture, (p0 + p1) / 2, kPaper), 78.0 / 8.0, 0.6);
}

TEST(BarChart, LeavesAGapWhereAValueIsMissing) {
  BarChart chart = paper_and_model();
  chart.groups[1].values[1] = std::nullopt;
  const Image<std::uint8_t> picture = draw_bar_chart(chart);
  EXPECT_EQ(columns(picture, picture.width() / 2, picture.width(), kModel).first, -1);
  EXPECT_GE(columns(picture, picture.width() / 2, picture.width(), kPaper).first, 0);
}

TEST(BarChart, RefusesValuesThatDoNotMatchTheSeriesOrAreNegativeOrNotFinite) {
  BarChart short_group = paper_and_model();
  short_group.groups[0].values = {8.0};
  EXPECT_THROW(draw_bar_chart(short_group), std::invalid_argument);
  BarChart negative = paper_and_model();
  negative.groups[0].values[0] = -1.0;
  EXPECT_THROW(draw_bar_chart(negative), std::invalid_argument);
  BarChart infinite = paper_and_model();
  infinite.groups[1].values[0] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(draw_bar_chart(infinite), std::invalid_argument);
  BarChart many = paper_and_model();
  many.series = {"a", "b", "c", "d", "e", "f", "g", "h", "i"};
  for (BarChart::Group& g : many.groups)
    g.values.resize(9, 1.0);
  EXPECT_THROW(draw_bar_chart(many), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::imaging
