// The ground a pair saw, as a level grid, and the footprint's sweep over ground it did not see.
#include "marsokhod/nav/path/seen_ground.hpp"

#include "work/work_report.hpp"

#include "marsokhod/nav/path/drive_poses.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace marsokhod::nav {
namespace {

struct Extent {
  double x0 = std::numeric_limits<double>::infinity();
  double y0 = x0;
  double x1 = -x0;
  double y1 = -x0;
  double nearest = x0;
};

// Points farther than this are not binned: no path reaches them, and a far point (disparity
// near zero) would otherwise stretch the grid without bound.
constexpr double kFarthestBinnedM = 30.0;

// Calls visit(forward, left) for every known point of the terrain within kFarthestBinnedM.
template <class Meter, class Visit>
void for_each_known_point(const TerrainRows& terrain, Meter& meter, Visit&& visit) {
  for (int y = 0; y < terrain.height(); ++y) {
    detail::report(meter, Work::footprint_scan, static_cast<std::uint64_t>(terrain.width()));
    const TerrainRows::Row row = terrain.row(y);
    for (int x = 0; x < terrain.width(); ++x)
      if (row.known(x) && std::hypot(row.forward[x], row.left[x]) <= kFarthestBinnedM)
        visit(static_cast<double>(row.forward[x]), static_cast<double>(row.left[x]));
  }
}

template <class Meter>
Extent extent_of(const TerrainRows& terrain, Meter& meter) {
  Extent e;
  for_each_known_point(terrain, meter, [&e](double px, double py) {
    e.x0 = std::min(e.x0, px);
    e.y0 = std::min(e.y0, py);
    e.x1 = std::max(e.x1, px);
    e.y1 = std::max(e.y1, py);
    e.nearest = std::min(e.nearest, std::hypot(px, py));
  });
  return e;
}

} // namespace

template <class Meter>
SeenGround::SeenGround(const TerrainRows& terrain, double cell_m, Meter& meter,
                       std::pmr::memory_resource* memory)
    : cell_m_(cell_m), nearest_m_(std::numeric_limits<double>::infinity()), cells_(memory) {
  if (!(cell_m > 0.0) || !std::isfinite(cell_m))
    throw std::invalid_argument("seen ground: the cell must be a positive length");
  const Extent e = extent_of(terrain, meter);
  if (!(e.x1 >= e.x0))
    return;
  nearest_m_ = e.nearest;
  x0_ = e.x0;
  y0_ = e.y0;
  columns_ = static_cast<long>(std::floor((e.x1 - e.x0) / cell_m)) + 1;
  rows_ = static_cast<long>(std::floor((e.y1 - e.y0) / cell_m)) + 1;
  cells_.assign(static_cast<std::size_t>(columns_ * rows_), 0);
  for_each_known_point(terrain, meter, [this](double px, double py) {
    const auto column = static_cast<long>((px - x0_) / cell_m_);
    const auto line = static_cast<long>((py - y0_) / cell_m_);
    cells_[static_cast<std::size_t>(line * columns_ + column)] = 1;
  });
}

bool SeenGround::cell(long column, long row) const {
  return column >= 0 && row >= 0 && column < columns_ && row < rows_ &&
         cells_[static_cast<std::size_t>(row * columns_ + column)] != 0;
}

bool SeenGround::seen(double x, double y) const {
  if (cells_.empty())
    return false;
  const auto column = static_cast<long>(std::floor((x - x0_) / cell_m_));
  const auto row = static_cast<long>(std::floor((y - y0_) / cell_m_));
  for (long dy = -1; dy <= 1; ++dy)
    for (long dx = -1; dx <= 1; ++dx)
      if (cell(column + dx, row + dy))
        return true;
  return false;
}

template <class Meter>
std::pmr::vector<FootprintConflict>
footprint_unseen(const SeenGround& seen, std::span<const DriveCommand> commands,
                 const imaging::Chassis& chassis, std::size_t limit, Meter& meter,
                 std::pmr::memory_resource* memory) {
  std::pmr::vector<FootprintConflict> unseen(memory);
  const double step = 0.5 * seen.cell_m();
  const double known_within = seen.nearest_m() + seen.cell_m();
  const int along = static_cast<int>(std::ceil(chassis.length_m() / step));
  const int across = static_cast<int>(std::ceil(chassis.width_m() / step));
  for (const DrivePose& pose : drive_poses(commands, {step, kFootprintTurnStepDeg}, memory)) {
    const double c = std::cos(pose.pose.heading_rad);
    const double s = std::sin(pose.pose.heading_rad);
    detail::report(meter, Work::footprint_test,
                   static_cast<std::uint64_t>((along + 1) * (across + 1)));
    for (int i = 0; i <= along; ++i)
      for (int j = 0; j <= across; ++j) {
        const double u = chassis.length_m() * (static_cast<double>(i) / along - 0.5);
        const double v = chassis.width_m() * (static_cast<double>(j) / across - 0.5);
        const double x = pose.pose.x + u * c - v * s;
        const double y = pose.pose.y + u * s + v * c;
        if (std::hypot(x, y) < known_within || seen.seen(x, y))
          continue;
        unseen.push_back(FootprintConflict{GroundPoint{x, y}, pose.command, pose.turning, true});
        if (unseen.size() >= limit)
          return unseen;
      }
  }
  return unseen;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template SeenGround::SeenGround(const TerrainRows&, double, M&, std::pmr::memory_resource*);     \
  template std::pmr::vector<FootprintConflict> footprint_unseen<M>(                                \
      const SeenGround&, std::span<const DriveCommand>, const imaging::Chassis&, std::size_t, M&,  \
      std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
