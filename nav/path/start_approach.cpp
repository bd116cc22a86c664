// The pixels nearest the line from the rover centre to the start of its path.

#include "marsokhod/nav/path/start_approach.hpp"

#include <cmath>
#include <limits>
#include <optional>

namespace marsokhod::nav {
namespace {

struct Segment {
  double forward = 0.0;
  double left = 0.0;
  double squared_length = 0.0;
};

// Distance of a ground point from the segment rover centre -> start, or nothing when the point
// lies behind the centre or at or beyond the start.
std::optional<double> distance_short_of_start(const Segment& segment, double forward, double left) {
  const double along = (forward * segment.forward + left * segment.left) / segment.squared_length;
  if (!(along >= 0.0 && along < 1.0))
    return std::nullopt;
  return std::hypot(forward - along * segment.forward, left - along * segment.left);
}

} // namespace

std::pmr::vector<PixelPoint> start_approach(const TerrainPoints& terrain, PixelPoint start,
                                            double tolerance_m, std::pmr::memory_resource* memory) {
  std::pmr::vector<PixelPoint> pixels(memory);
  if (!terrain.known(start.x, start.y))
    return pixels; // no ground point to drive to
  const double forward = terrain.forward(start.x, start.y);
  const double left = terrain.left(start.x, start.y);
  const Segment line{forward, left, forward * forward + left * left};
  if (!std::isfinite(line.squared_length) || line.squared_length == 0.0)
    return pixels;
  for (int y = start.y + 1; y < terrain.height(); ++y) {
    double nearest = std::numeric_limits<double>::infinity();
    std::optional<int> column; // among equals the leftmost column, a fixed order
    for (int x = 0; x < terrain.width(); ++x) {
      if (!terrain.known(x, y))
        continue;
      const std::optional<double> distance =
          distance_short_of_start(line, terrain.forward(x, y), terrain.left(x, y));
      if (distance && *distance <= tolerance_m && *distance < nearest) {
        nearest = *distance;
        column = x;
      }
    }
    if (column)
      pixels.push_back(PixelPoint{*column, y});
  }
  return pixels;
}

} // namespace marsokhod::nav
