// Tests: false colour pictures, their legends, the tick choice and the bitmap font.

#include "marsokhod/imaging/pictures/colormap.hpp"

// White-box checks of the legend's parts, which the public function does not expose.
#include "pictures/bitmap_font.hpp"
#include "pictures/colour_scale.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace marsokhod::imaging {
namespace {

using Rgb = std::array<int, 3>;

// Published viridis values (matplotlib's table, entries 0, 128 and 255, times 255, rounded).
constexpr Rgb kViridisLow = {68, 1, 84};
constexpr Rgb kViridisMiddle = {33, 145, 140};
constexpr Rgb kViridisHigh = {253, 231, 37};
constexpr Rgb kBlack = {0, 0, 0};

Rgb pixel(const Image<std::uint8_t>& image, int x, int y) {
  return {image(x, y, 0), image(x, y, 1), image(x, y, 2)};
}

Image<float> row_of(std::initializer_list<float> values) {
  Image<float> field(static_cast<int>(values.size()), 1);
  std::copy(values.begin(), values.end(), field.data());
  return field;
}

ColormapOptions range(float lo, float hi) {
  ColormapOptions options;
  options.min_value = lo;
  options.max_value = hi;
  options.legend = false;
  return options;
}

TEST(FalseColour, EndsAndMiddleOfTheRangeGetViridisColours) {
  const Image<float> field = row_of({0.0F, 5.0F, 10.0F});
  const Image<std::uint8_t> picture = false_colour(field, range(0.0F, 10.0F));
  ASSERT_EQ(picture.width(), 3);
  ASSERT_EQ(picture.channels(), 3);
  EXPECT_EQ(pixel(picture, 0, 0), kViridisLow);
  EXPECT_EQ(pixel(picture, 1, 0), kViridisMiddle);
  EXPECT_EQ(pixel(picture, 2, 0), kViridisHigh);
}

TEST(FalseColour, ValuesOutsideTheRangeAreClampedToItsEnds) {
  const Image<std::uint8_t> picture = false_colour(row_of({-100.0F, 1e30F}), range(0.0F, 1.0F));
  EXPECT_EQ(pixel(picture, 0, 0), kViridisLow);
  EXPECT_EQ(pixel(picture, 1, 0), kViridisHigh);
}

TEST(FalseColour, NonFiniteValuesAreBlack) {
  const float inf = std::numeric_limits<float>::infinity();
  const Image<std::uint8_t> picture =
      false_colour(row_of({inf, -inf, std::numeric_limits<float>::quiet_NaN()}), range(0.0F, 1.0F));
  for (int x = 0; x < 3; ++x)
    EXPECT_EQ(pixel(picture, x, 0), kBlack) << x;
}

TEST(FalseColour, LightnessRisesMonotonicallyAlongTheScale) {
  // Perceptual order: each step up the scale is at least as light (Rec. 601 luma) as the last.
  double previous = -1.0;
  for (int i = 0; i <= 100; ++i) {
    const detail::Rgb c = detail::viridis(i / 100.0);
    const double luma = 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2];
    EXPECT_GE(luma, previous - 0.5) << "at " << i / 100.0;
    previous = luma;
  }
}

TEST(FalseColour, AutomaticRangeIgnoresOutliersBeyondThePercentiles) {
  // Values 0..99 plus one wild 1e9: the 1st..99th percentiles are 1 and 99.
  Image<float> field(101, 1);
  for (int x = 0; x < 100; ++x)
    field(x, 0) = static_cast<float>(x);
  field(100, 0) = 1e9F;
  ColormapOptions options;
  options.legend = false;
  const Image<std::uint8_t> picture = false_colour(field, options);
  EXPECT_EQ(pixel(picture, 1, 0), kViridisLow);
  EXPECT_EQ(pixel(picture, 50, 0), kViridisMiddle); // (50 - 1) / (99 - 1) = 0.5
  EXPECT_EQ(pixel(picture, 99, 0), kViridisHigh);
}

TEST(FalseColour, FlatFieldSitsInTheMiddleOfTheScale) {
  ColormapOptions options;
  options.legend = false;
  const Image<std::uint8_t> picture = false_colour(Image<float>(2, 2, 1, 3.0F), options);
  EXPECT_EQ(pixel(picture, 1, 1), kViridisMiddle);
}

TEST(FalseColour, RejectsAnEmptyRangeAndMultiChannelFields) {
  EXPECT_THROW((void)false_colour(row_of({1.0F}), range(2.0F, 2.0F)), std::invalid_argument);
  EXPECT_THROW((void)false_colour(row_of({1.0F}), range(3.0F, 2.0F)), std::invalid_argument);
  EXPECT_THROW((void)false_colour(Image<float>(1, 1, 3), range(0.0F, 1.0F)), std::invalid_argument);
}

TEST(FalseColourLegend, AddsAPanelWithBarEndsAndInk) {
  Image<float> field(200, 150);
  for (int y = 0; y < 150; ++y)
    for (int x = 0; x < 200; ++x)
      field(x, y) = static_cast<float>(x) / 10.0F;
  field(0, 0) = std::numeric_limits<float>::infinity();
  ColormapOptions options;
  options.min_value = 0.0F;
  options.max_value = 20.0F;
  options.unit = "px";
  options.title = "disparity";
  const Image<std::uint8_t> picture = false_colour(field, options);
  ASSERT_GT(picture.width(), 200);
  ASSERT_GE(picture.height(), 150);
  EXPECT_EQ(pixel(picture, 100, 10), kViridisMiddle); // the field itself is untouched
  int high = 0, low = 0, ink = 0, paper = 0;
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 200; x < picture.width(); ++x) {
      const Rgb c = pixel(picture, x, y);
      high += c == kViridisHigh;
      low += c == kViridisLow;
      ink += c == kBlack;
      paper += c == Rgb{255, 255, 255};
    }
  EXPECT_GT(high, 0) << "the bar's top colour is missing";
  EXPECT_GT(low, 0) << "the bar's bottom colour is missing";
  EXPECT_GT(ink, 100) << "no text or outline";
  EXPECT_GT(paper, ink) << "the panel should be mostly background";
}

TEST(FalseColourLegend, IsDeterministic) {
  Image<float> field(40, 30);
  for (std::size_t i = 0; i < field.size(); ++i)
    field.data()[i] = std::sin(static_cast<float>(i) * 0.1F);
  ColormapOptions options;
  options.title = "elevation";
  options.unit = "m";
  EXPECT_TRUE(false_colour(field, options) == false_colour(field, options));
}

TEST(LegendTicks, PicksThreeToFiveRoundValues) {
  using Labels = std::vector<std::string>;
  EXPECT_EQ(detail::legend_ticks(0.0, 14.0).labels, (Labels{"0", "5", "10"}));
  EXPECT_EQ(detail::legend_ticks(0.0, 64.0).labels, (Labels{"0", "20", "40", "60"}));
  EXPECT_EQ(detail::legend_ticks(-1.0, 1.0).labels, (Labels{"-1.0", "-0.5", "0.0", "0.5", "1.0"}));
}

TEST(LegendTicks, FallsBackToQuarterStepsWhenWholeStepsDoNotFit) {
  // Steps of 2 give 6 ticks in 1..12.9 and steps of 5 only 2; 2.5 gives 5.
  using Labels = std::vector<std::string>;
  EXPECT_EQ(detail::legend_ticks(1.0, 12.9).labels, (Labels{"2.5", "5.0", "7.5", "10.0", "12.5"}));
  // Likewise 0.02 steps give 6 ticks in 0.02..0.13 and 0.05 steps only 2.
  EXPECT_EQ(detail::legend_ticks(0.02, 0.13).labels,
            (Labels{"0.025", "0.050", "0.075", "0.100", "0.125"}));
}

TEST(LegendTicks, LargeValuesUseScientificNotation) {
  const detail::Ticks ticks = detail::legend_ticks(0.0, 4e6);
  ASSERT_GE(ticks.labels.size(), 3U);
  EXPECT_EQ(ticks.labels[1], "1e+06");
}

TEST(BitmapFont, CoversDigitsSignsAndLetters) {
  for (char c :
       std::string("0123456789.-+ abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ[]()/%:"))
    EXPECT_TRUE(detail::has_glyph(c)) << c;
  EXPECT_FALSE(detail::has_glyph('~'));
  EXPECT_EQ(&detail::glyph_for('~'), &detail::glyph_for('?'));
  EXPECT_EQ(detail::text_width("px", 2), (2 * 6 - 1) * 2);
}

TEST(BitmapFont, GlyphsAreDistinct) {
  const std::string characters = "0123456789.-+abcdefghijklmnopqrstuvwxyz";
  for (std::size_t i = 0; i < characters.size(); ++i)
    for (std::size_t j = i + 1; j < characters.size(); ++j)
      EXPECT_NE(detail::glyph_for(characters[i]), detail::glyph_for(characters[j]))
          << characters[i] << " and " << characters[j] << " look the same";
}

} // namespace
} // namespace marsokhod::imaging
