// False-colour pictures of scalar fields, with a legend of colour bar and tick labels.

#include "marsokhod/imaging/pictures/colormap.hpp"

#include "pictures/bitmap_font.hpp"
#include "pictures/colour_scale.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace marsokhod::imaging {
namespace {

using detail::Rgb;

constexpr Rgb kPaper{255, 255, 255};
constexpr Rgb kLegendInk{0, 0, 0};
constexpr Rgb kUnknown{0, 0, 0};
constexpr double kLowPercentile = 0.01;
constexpr double kHighPercentile = 0.99;

struct Range {
  double lo = 0.0;
  double hi = 1.0;
};

// Where each part of the legend panel goes, in panel coordinates.
struct LegendLayout {
  int scale = 1;
  int margin = 0;
  int line_height = 0;
  int width = 0;
  int min_height = 0;
  int bar_x = 0;
  int bar_top = 0;
  int bar_width = 0;
  int bottom_reserve = 0; // below the bar: label overhang, unknown swatch, margin
  int label_x = 0;
  bool unknown_swatch = false;
  detail::Ticks ticks;
};

void put(ImageView<std::uint8_t> rgb, int x, int y, Rgb colour) {
  for (int c = 0; c < 3; ++c)
    rgb(x, y, c) = colour[static_cast<std::size_t>(c)];
}

void fill_rect(ImageView<std::uint8_t> rgb, int x, int y, int w, int h, Rgb colour) {
  for (int yy = std::max(y, 0); yy < std::min(y + h, rgb.height()); ++yy)
    for (int xx = std::max(x, 0); xx < std::min(x + w, rgb.width()); ++xx)
      put(rgb, xx, yy, colour);
}

bool has_non_finite(ImageView<const float> field) {
  for (int y = 0; y < field.height(); ++y)
    for (int x = 0; x < field.width(); ++x)
      if (!std::isfinite(field(x, y)))
        return true;
  return false;
}

double percentile(std::vector<float>& values, double p) {
  const auto rank =
      static_cast<std::size_t>(std::llround(p * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

Range automatic_range(ImageView<const float> field) {
  std::vector<float> values;
  for (int y = 0; y < field.height(); ++y)
    for (int x = 0; x < field.width(); ++x)
      if (std::isfinite(field(x, y)))
        values.push_back(field(x, y));
  if (values.empty())
    return {};
  Range range{percentile(values, kLowPercentile), percentile(values, kHighPercentile)};
  if (range.hi <= range.lo) // a flat field: centre it on the scale
    range = {range.lo - 0.5, range.lo + 0.5};
  return range;
}

Range choose_range(ImageView<const float> field, const ColormapOptions& options) {
  Range range;
  if (!options.min_value || !options.max_value)
    range = automatic_range(field);
  if (options.min_value)
    range.lo = *options.min_value;
  if (options.max_value)
    range.hi = *options.max_value;
  if (!std::isfinite(range.lo) || !std::isfinite(range.hi) || !(range.lo < range.hi))
    throw std::invalid_argument(
        fmt::format("false_colour: the minimum {} must be finite and below the maximum {}",
                    range.lo, range.hi));
  return range;
}

double position_on_scale(double value, const Range& range) {
  return (value - range.lo) / (range.hi - range.lo);
}

void paint_field(ImageView<std::uint8_t> rgb, ImageView<const float> field, const Range& range) {
  for (int y = 0; y < field.height(); ++y)
    for (int x = 0; x < field.width(); ++x) {
      const float value = field(x, y);
      put(rgb, x, y,
          std::isfinite(value) ? detail::viridis(position_on_scale(value, range)) : kUnknown);
    }
}

std::string unit_caption(const std::string& unit) {
  return unit.empty() ? "" : "[" + unit + "]";
}

LegendLayout plan_legend(ImageView<const float> field, const ColormapOptions& options,
                         const Range& range) {
  LegendLayout layout;
  layout.scale = std::clamp(1 + field.height() / 240, 1, 4);
  const int s = layout.scale;
  layout.margin = 6 * s;
  layout.line_height = (detail::kGlyphHeight + 2) * s;
  layout.ticks = detail::legend_ticks(range.lo, range.hi);
  layout.unknown_swatch = has_non_finite(field);

  const int text_lines = (options.title.empty() ? 0 : 1) + (options.unit.empty() ? 0 : 1);
  const int label_overhang = detail::kCapHeight * s / 2 + s;
  layout.bar_x = layout.margin + 1; // one pixel for the outline
  layout.bar_width = 10 * s;
  layout.bar_top = layout.margin + text_lines * layout.line_height + label_overhang;
  layout.label_x = layout.bar_x + layout.bar_width + 1 + 3 * s + 2 * s;
  layout.bottom_reserve =
      label_overhang + layout.margin + (layout.unknown_swatch ? layout.line_height + 2 * s : 0);

  int content = layout.label_x - layout.margin;
  int widest_label = 0;
  for (const std::string& label : layout.ticks.labels)
    widest_label = std::max(widest_label, detail::text_width(label, s));
  content += widest_label;
  content = std::max({content, detail::text_width(options.title, s),
                      detail::text_width(unit_caption(options.unit), s),
                      layout.label_x - layout.margin + detail::text_width("unknown", s)});
  layout.width = content + 2 * layout.margin;
  const int min_bar = 5 * layout.line_height;
  layout.min_height = layout.bar_top + min_bar + layout.bottom_reserve;
  return layout;
}

void draw_legend(ImageView<std::uint8_t> panel, const LegendLayout& layout,
                 const ColormapOptions& options, const Range& range) {
  const int s = layout.scale;
  int text_y = layout.margin;
  if (!options.title.empty()) {
    detail::draw_text(panel, layout.margin, text_y, options.title, s, kLegendInk);
    text_y += layout.line_height;
  }
  if (!options.unit.empty())
    detail::draw_text(panel, layout.margin, text_y, unit_caption(options.unit), s, kLegendInk);

  const int bar_height = panel.height() - layout.bar_top - layout.bottom_reserve;
  fill_rect(panel, layout.bar_x - 1, layout.bar_top - 1, layout.bar_width + 2, bar_height + 2,
            kLegendInk);
  for (int row = 0; row < bar_height; ++row) {
    const double t = 1.0 - static_cast<double>(row) / std::max(bar_height - 1, 1);
    fill_rect(panel, layout.bar_x, layout.bar_top + row, layout.bar_width, 1, detail::viridis(t));
  }
  for (std::size_t i = 0; i < layout.ticks.values.size(); ++i) {
    const double t = position_on_scale(layout.ticks.values[i], range);
    const int y = layout.bar_top + static_cast<int>(std::lround((1.0 - t) * (bar_height - 1)));
    fill_rect(panel, layout.bar_x + layout.bar_width + 1, y - s / 2, 3 * s, std::max(1, s / 2 * 2),
              kLegendInk);
    detail::draw_text(panel, layout.label_x, y - detail::kCapHeight * s / 2, layout.ticks.labels[i],
                      s, kLegendInk);
  }
  if (layout.unknown_swatch) {
    const int y = layout.bar_top + bar_height + detail::kCapHeight * s / 2 + s + 2 * s;
    fill_rect(panel, layout.bar_x, y, layout.bar_width, detail::kCapHeight * s, kUnknown);
    detail::draw_text(panel, layout.label_x, y, "unknown", s, kLegendInk);
  }
}

} // namespace

Image<std::uint8_t> false_colour(ImageView<const float> field, const ColormapOptions& options) {
  if (field.channels() != 1)
    throw std::invalid_argument("false_colour: the field must have exactly one channel");
  const Range range = choose_range(field, options);
  if (!options.legend) {
    Image<std::uint8_t> picture(field.width(), field.height(), 3);
    paint_field(picture.view(), field, range);
    return picture;
  }
  const LegendLayout layout = plan_legend(field, options, range);
  const int height = std::max(field.height(), layout.min_height);
  Image<std::uint8_t> picture(field.width() + layout.width, height, 3, kPaper[0]);
  paint_field(picture.view(), field, range);
  draw_legend(picture.view().sub(field.width(), 0, layout.width, height), layout, options, range);
  return picture;
}

} // namespace marsokhod::imaging
