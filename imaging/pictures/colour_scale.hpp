// Viridis and legend ticks (private to the pictures room's false_colour).
#pragma once

// Internal: the colour scale and tick choice behind false_colour's pictures and legends.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace marsokhod::imaging::detail {

using Rgb = std::array<std::uint8_t, 3>;

/// Viridis (van der Walt and Smith, 2015, CC0) at t in 0..1, clamped: dark blue to yellow,
/// ordered in lightness so that it reads the same in grey and to colour-blind eyes.
Rgb viridis(double t);

/// Evenly spaced round values (steps of 1, 2, 2.5 or 5 times a power of ten) inside lo..hi
/// with their printed labels: three to five of them.
struct Ticks {
  std::vector<double> values;
  std::vector<std::string> labels;
};
Ticks legend_ticks(double lo, double hi);

} // namespace marsokhod::imaging::detail
