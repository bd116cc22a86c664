// The viridis colour scale and the legends' tick choice (private to false_colour).

#include "pictures/colour_scale.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace marsokhod::imaging::detail {
namespace {

// Every sixteenth entry of the published 256-entry viridis table, as 8-bit sRGB.
constexpr Rgb kViridisAnchors[] = {
    {68, 1, 84},    {72, 24, 106},  {71, 45, 123},  {66, 64, 134},  {59, 82, 139},  {51, 99, 141},
    {44, 114, 142}, {38, 130, 142}, {33, 145, 140}, {31, 159, 136}, {39, 173, 129}, {61, 188, 116},
    {92, 200, 99},  {129, 211, 77}, {170, 220, 50}, {213, 226, 26}, {253, 231, 37},
};
constexpr std::size_t kMinTicks = 3;
constexpr double kMaxTicks = 5;
constexpr int kSegments = static_cast<int>(std::size(kViridisAnchors)) - 1;

std::string format_tick(double value, int decimals, bool scientific) {
  if (value == 0.0)
    value = 0.0; // turns -0 into 0
  if (scientific)
    return fmt::format("{:.3g}", value);
  return fmt::format("{:.{}f}", value, decimals);
}

// The fewest decimals that print every multiple of step exactly.
int decimals_of(double step) {
  for (int decimals = 0; decimals < 12; ++decimals) {
    const double scaled = step * std::pow(10.0, decimals);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * scaled)
      return decimals;
  }
  return 12;
}

// Empty when the step would give more than a legend can show.
Ticks ticks_with_step(double lo, double hi, double step, int decimals) {
  const double first = std::ceil(lo / step - 1e-9);
  const double last = std::floor(hi / step + 1e-9);
  const bool scientific = std::max(std::abs(lo), std::abs(hi)) >= 1e6 || step < 1e-4;
  Ticks ticks;
  if (!(last - first < kMaxTicks))
    return ticks;
  for (int i = 0; first + i <= last; ++i) {
    ticks.values.push_back((first + i) * step);
    ticks.labels.push_back(format_tick((first + i) * step, decimals, scientific));
  }
  return ticks;
}

} // namespace

Rgb viridis(double t) {
  const double position = std::clamp(t, 0.0, 1.0) * kSegments;
  const int segment = std::min(static_cast<int>(position), kSegments - 1);
  const double fraction = position - segment;
  const Rgb& a = kViridisAnchors[segment];
  const Rgb& b = kViridisAnchors[segment + 1];
  Rgb colour{};
  for (std::size_t c = 0; c < 3; ++c)
    colour[c] = static_cast<std::uint8_t>(std::lround(a[c] + (b[c] - a[c]) * fraction));
  return colour;
}

Ticks legend_ticks(double lo, double hi) {
  const double span = hi - lo;
  if (!(span > 0.0) || !std::isfinite(span))
    return {{lo}, {format_tick(lo, 2, true)}};
  const double base = std::pow(10.0, std::floor(std::log10(span / 5.0)));
  // Steps of 1, 2 and 5 read best; 2.5 only when they give too many or too few ticks.
  for (const double factor : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 2.5, 25.0}) {
    const double step = base * factor;
    Ticks ticks = ticks_with_step(lo, hi, step, decimals_of(step));
    if (ticks.values.size() >= kMinTicks)
      return ticks;
  }
  // No round step fits: label the ends and the middle exactly.
  const int decimals = std::max(0, 2 - static_cast<int>(std::floor(std::log10(span))));
  const bool scientific = std::max(std::abs(lo), std::abs(hi)) >= 1e6 || span < 1e-4;
  Ticks ticks;
  for (const double value : {lo, (lo + hi) / 2, hi}) {
    ticks.values.push_back(value);
    ticks.labels.push_back(format_tick(value, decimals, scientific));
  }
  return ticks;
}

} // namespace marsokhod::imaging::detail
