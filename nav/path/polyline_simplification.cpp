// Simplifying a ground polyline to the vertices that the drive commands turn at.

#include "marsokhod/nav/path/drive_commands.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace marsokhod::nav {
namespace {

// Distance from p to the segment a-b (to a itself when the segment has no length).
double distance_to_segment(const GroundPoint& p, const GroundPoint& a, const GroundPoint& b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = 0.0;
  if (length2 > 0.0)
    t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

} // namespace

std::pmr::vector<std::size_t> simplify_polyline(std::span<const GroundPoint> points,
                                                double tolerance_m,
                                                std::pmr::memory_resource* memory) {
  std::pmr::vector<std::size_t> kept(memory);
  if (points.empty())
    return kept;
  std::pmr::vector<bool> keep(points.size(), false, memory);
  keep.front() = keep.back() = true;
  // An explicit stack of index ranges instead of recursion: paths can be as long as the image
  // is tall.
  std::pmr::vector<std::pair<std::size_t, std::size_t>> pending(memory);
  if (points.size() > 2)
    pending.emplace_back(0, points.size() - 1);
  while (!pending.empty()) {
    const auto [first, last] = pending.back();
    pending.pop_back();
    double farthest = -1.0;
    std::size_t split = first;
    for (std::size_t i = first + 1; i < last; ++i) {
      const double d = distance_to_segment(points[i], points[first], points[last]);
      if (d > farthest) {
        farthest = d;
        split = i;
      }
    }
    if (farthest <= tolerance_m)
      continue;
    keep[split] = true;
    if (split - first > 1)
      pending.emplace_back(first, split);
    if (last - split > 1)
      pending.emplace_back(split, last);
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    if (keep[i])
      kept.push_back(i);
  return kept;
}

} // namespace marsokhod::nav
