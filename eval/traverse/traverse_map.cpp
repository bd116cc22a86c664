// Drawing the traverse map: hillshade, obstacles, plans, track and events.
#include "marsokhod/eval/traverse/traverse_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace marsokhod::eval {
namespace {

using Rgb = std::array<std::uint8_t, 3>;
constexpr Rgb kObstacle{220, 40, 40};
constexpr Rgb kPlan{60, 120, 255};
constexpr Rgb kTrack{255, 220, 0};
constexpr Rgb kStop{255, 0, 255};
constexpr Rgb kStart{0, 230, 0};
constexpr Rgb kGoal{255, 255, 255};
constexpr Rgb kProhibited{255, 140, 0};
constexpr Rgb kTurn{0, 220, 220};
constexpr Rgb kFault{170, 60, 255};
// What the cycles' zones made of a map pixel.
enum Judged : std::uint8_t { kUnjudged = 0, kSeen = 1, kProhibitedCell = 2 };
// Ground shown around the course, its plans and its tracks.
constexpr double kMapMarginM = 5.0;

// Map pixel <-> world: column from the west edge, row from the north edge.
struct MapFrame {
  double west = 0.0;
  double north = 0.0;
  int width = 0;
  int height = 0;
  Eigen::Vector2d pixel(const Eigen::Vector2d& world) const {
    return {(world.x() - west) / kTraverseMapCellM, (north - world.y()) / kTraverseMapCellM};
  }
  Eigen::Vector2d world(int x, int y) const {
    return {west + (x + 0.5) * kTraverseMapCellM, north - (y + 0.5) * kTraverseMapCellM};
  }
};

void plot(imaging::Image<std::uint8_t>& map, int x, int y, const Rgb& colour) {
  if (x < 0 || y < 0 || x >= map.width() || y >= map.height())
    return;
  for (int c = 0; c < 3; ++c)
    map(x, y, c) = colour[static_cast<std::size_t>(c)];
}

void segment(imaging::Image<std::uint8_t>& map, const MapFrame& f, const Eigen::Vector2d& a,
             const Eigen::Vector2d& b, const Rgb& colour) {
  const Eigen::Vector2d pa = f.pixel(a);
  const Eigen::Vector2d pb = f.pixel(b);
  const int steps = static_cast<int>(std::min(8192.0, std::ceil((pb - pa).norm()))) + 1;
  for (int i = 0; i <= steps; ++i) {
    const Eigen::Vector2d p = pa + (pb - pa) * (static_cast<double>(i) / steps);
    plot(map, static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())), colour);
  }
}

void polyline(imaging::Image<std::uint8_t>& map, const MapFrame& f,
              const std::vector<Eigen::Vector2d>& points, const Rgb& colour) {
  for (std::size_t i = 1; i < points.size(); ++i)
    segment(map, f, points[i - 1], points[i], colour);
}

void square(imaging::Image<std::uint8_t>& map, const MapFrame& f, const Eigen::Vector2d& at,
            int half, const Rgb& colour) {
  const Eigen::Vector2d p = f.pixel(at);
  const int cx = static_cast<int>(std::lround(p.x()));
  const int cy = static_cast<int>(std::lround(p.y()));
  for (int dy = -half; dy <= half; ++dy)
    for (int dx = -half; dx <= half; ++dx)
      plot(map, cx + dx, cy + dy, colour);
}

void circle(imaging::Image<std::uint8_t>& map, const MapFrame& f, const Eigen::Vector2d& centre,
            double radius_m, const Rgb& colour) {
  constexpr int kSteps = 180;
  for (int i = 0; i < kSteps; ++i) {
    const double a0 = 2.0 * M_PI * i / kSteps;
    const double a1 = 2.0 * M_PI * (i + 1) / kSteps;
    segment(map, f, centre + radius_m * Eigen::Vector2d(std::cos(a0), std::sin(a0)),
            centre + radius_m * Eigen::Vector2d(std::cos(a1), std::sin(a1)), colour);
  }
}

// Every cycle's zones on the map's pixels; a prohibition outranks a free sighting.
imaging::Image<std::uint8_t> judged_pixels(const MapFrame& f, const TraverseResult& result) {
  imaging::Image<std::uint8_t> judged(f.width, f.height, 1, kUnjudged);
  const auto mark = [&](const std::vector<Eigen::Vector2d>& points, Judged what) {
    for (const Eigen::Vector2d& p : points) {
      const Eigen::Vector2d px = f.pixel(p);
      const auto x = static_cast<int>(std::floor(px.x()));
      const auto y = static_cast<int>(std::floor(px.y()));
      if (x >= 0 && y >= 0 && x < f.width && y < f.height && judged(x, y) < what)
        judged(x, y) = what;
    }
  };
  for (const TraverseCycle& cycle : result.cycles) {
    mark(cycle.seen, kSeen);
    mark(cycle.prohibited, kProhibitedCell);
  }
  return judged;
}

// Ground a cycle saw free: the hillshade tinted blue.
Rgb seen_tint(std::uint8_t grey) {
  return {static_cast<std::uint8_t>(grey * 0.6), static_cast<std::uint8_t>(grey * 0.75 + 20),
          static_cast<std::uint8_t>(std::min(255.0, grey * 0.6 + 100.0))};
}

void hillshade(imaging::Image<std::uint8_t>& map, const MapFrame& f, const world::Terrain& terrain,
               const imaging::Image<std::uint8_t>& judged) {
  const Eigen::Vector3d sun = Eigen::Vector3d(-1.0, 1.0, 1.5).normalized();
  const world::HeightField& h = terrain.height;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const Eigen::Vector2d w = f.world(x, y);
      const double shade = std::clamp(h.normal(w.x(), w.y()).dot(sun), 0.0, 1.0);
      const auto grey = static_cast<std::uint8_t>(std::lround(40.0 + 180.0 * shade));
      const auto node_i =
          static_cast<int>(std::lround((w.x() - h.node_position(0, 0).x()) / h.cell_m()));
      const auto node_j =
          static_cast<int>(std::lround((w.y() - h.node_position(0, 0).y()) / h.cell_m()));
      const bool obstacle = node_i >= 0 && node_j >= 0 && node_i < h.nx() && node_j < h.ny() &&
                            terrain.obstacles(node_i, node_j) != 0;
      if (obstacle)
        plot(map, x, y, kObstacle);
      else if (judged(x, y) == kProhibitedCell)
        plot(map, x, y, kProhibited);
      else
        plot(map, x, y, judged(x, y) == kSeen ? seen_tint(grey) : Rgb{grey, grey, grey});
    }
}

Rgb outcome_colour(TraverseOutcome outcome) {
  if (outcome == TraverseOutcome::success)
    return {0, 200, 0};
  if (outcome == TraverseOutcome::unsafe)
    return {230, 0, 0};
  return {255, 150, 0};
}

// The map's frame: every point of the course, its plans and tracks, kMapMarginM around them,
// within the site.
MapFrame frame_of(const world::Terrain& terrain, const TraverseResult& result) {
  Eigen::Vector2d low(result.start.x, result.start.y);
  Eigen::Vector2d high = low;
  const auto include = [&](const Eigen::Vector2d& p) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  };
  include(result.goal);
  for (const TraverseCycle& cycle : result.cycles) {
    for (const Eigen::Vector2d& p : cycle.planned)
      include(p);
    for (const Eigen::Vector2d& p : cycle.track)
      include(p);
  }
  const Eigen::Vector2d edge =
      0.5 * Eigen::Vector2d(terrain.settings.size_m, world::north_south_m(terrain.settings));
  low = (low - Eigen::Vector2d::Constant(kMapMarginM)).cwiseMax(-edge);
  high = (high + Eigen::Vector2d::Constant(kMapMarginM)).cwiseMin(edge);
  MapFrame f{low.x(), high.y(), 0, 0};
  f.width = std::max(1, static_cast<int>(std::lround((high.x() - low.x()) / kTraverseMapCellM)));
  f.height = std::max(1, static_cast<int>(std::lround((high.y() - low.y()) / kTraverseMapCellM)));
  return f;
}

} // namespace

imaging::Image<std::uint8_t> traverse_map(const world::Terrain& terrain,
                                          const TraverseResult& result) {
  const MapFrame f = frame_of(terrain, result);
  imaging::Image<std::uint8_t> map(f.width, f.height, 3, 0);
  hillshade(map, f, terrain, judged_pixels(f, result));
  for (const TraverseCycle& cycle : result.cycles)
    polyline(map, f, cycle.planned, kPlan);
  for (const TraverseCycle& cycle : result.cycles)
    polyline(map, f, cycle.track, kTrack);
  for (const TraverseCycle& cycle : result.cycles)
    if (cycle.emergency_stop && !cycle.track.empty())
      square(map, f, cycle.track.back(), 4, kStop);
  for (const UnsafeEvent& event : result.unsafe_events) {
    const Eigen::Vector2d at(event.x_m, event.y_m);
    segment(map, f, at + Eigen::Vector2d(-1, -1), at + Eigen::Vector2d(1, 1), kObstacle);
    segment(map, f, at + Eigen::Vector2d(-1, 1), at + Eigen::Vector2d(1, -1), kObstacle);
  }
  for (const TraverseCycle& cycle : result.cycles)
    if (cycle.turned_deg != 0.0)
      circle(map, f, Eigen::Vector2d(cycle.start.x, cycle.start.y), 0.6, kTurn);
  for (const TraverseFault& fault : result.faults) {
    const world::RoverPose& at = result.cycles.at(static_cast<std::size_t>(fault.cycle)).start;
    square(map, f, Eigen::Vector2d(at.x, at.y), 3, kFault);
  }
  square(map, f, Eigen::Vector2d(result.start.x, result.start.y), 5, kStart);
  circle(map, f, result.goal, result.settings.goal_tolerance_m, kGoal);
  const Rgb border = outcome_colour(result.outcome);
  for (int i = 0; i < 6; ++i) {
    for (int x = 0; x < f.width; ++x) {
      plot(map, x, i, border);
      plot(map, x, f.height - 1 - i, border);
    }
    for (int y = 0; y < f.height; ++y) {
      plot(map, i, y, border);
      plot(map, f.width - 1 - i, y, border);
    }
  }
  return map;
}

} // namespace marsokhod::eval
