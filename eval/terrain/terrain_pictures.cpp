// Drawing the comparison picture: verdict colours per pixel and the two paths.
#include "marsokhod/eval/terrain/terrain_pictures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace marsokhod::eval {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

constexpr Rgb kOpen{0, 0, 0};
constexpr Rgb kFalseUnknown{60, 110, 255};
constexpr Rgb kFalseHazard{255, 140, 0};
constexpr Rgb kFalseMargin{240, 220, 40};
constexpr Rgb kObstacleCaught{255, 255, 255};
constexpr Rgb kObstacleMissed{230, 20, 20};
constexpr Rgb kUnscoredOpen{50, 50, 50};
constexpr Rgb kUnscoredProhibited{120, 120, 120};
constexpr Rgb kNotSeen{20, 20, 60};
constexpr Rgb kPathGreen{40, 230, 60};
constexpr Rgb kTruthPathCyan{0, 220, 230};
constexpr Rgb kTruthMargin{160, 160, 160};
constexpr Rgb kFootprint{255, 0, 255};
constexpr Rgb kHitCross{255, 30, 30};

void put(imaging::Image<std::uint8_t>& picture, int x, int y, const Rgb& colour) {
  for (int c = 0; c < 3; ++c)
    picture(x, y, c) = colour[static_cast<std::size_t>(c)];
}

Rgb verdict(const TerrainComparison& site, int x, int y) {
  if (site.truth.valid(x, y) == 0)
    return kNotSeen;
  const nav::Zone zone = site.zones.at(x, y);
  const bool prohibited = zone != nav::Zone::traversable;
  if (site.truth.obstacles(x, y) != 0)
    return prohibited ? kObstacleCaught : kObstacleMissed;
  if (!site.truth_zones.traversable(x, y))
    return prohibited ? kUnscoredProhibited : kUnscoredOpen;
  if (!prohibited)
    return kOpen;
  if (zone == nav::Zone::unknown)
    return kFalseUnknown;
  if (zone == nav::Zone::margin)
    return kFalseMargin;
  return kFalseHazard;
}

Rgb truth_colour(const TerrainComparison& site, int x, int y) {
  const nav::Zone zone = site.truth_zones.at(x, y);
  if (zone == nav::Zone::traversable)
    return kOpen;
  if (zone == nav::Zone::margin)
    return kTruthMargin;
  if (zone == nav::Zone::unknown)
    return kNotSeen;
  return kObstacleCaught;
}

void draw_path(imaging::Image<std::uint8_t>& picture, const nav::PathPlan& plan, int offset,
               const Rgb& colour) {
  if (!plan.found)
    return;
  for (const nav::PixelPoint& p : plan.pixels)
    put(picture, p.x + offset, p.y, colour);
}

void put_inside(imaging::Image<std::uint8_t>& picture, int x, int y, int panel_width,
                const Rgb& colour) {
  if (x < 0 || y < 0 || x >= panel_width || y >= picture.height())
    return;
  for (int offset : {0, panel_width})
    put(picture, x + offset, y, colour);
}

std::optional<Eigen::Vector2d> pixel_of(const TerrainComparison& site,
                                        const Eigen::Vector3d& point) {
  return site.rig.project(imaging::Eye::left, point, site.attitude);
}

void draw_segment(imaging::Image<std::uint8_t>& picture, const Eigen::Vector2d& a,
                  const Eigen::Vector2d& b, int panel_width) {
  const double length = (b - a).lpNorm<Eigen::Infinity>();
  // A corner far outside the view would make the segment huge; the picture only needs its
  // visible part, which a bounded number of steps still reaches.
  const int steps = static_cast<int>(std::min(4096.0, std::ceil(length))) + 1;
  for (int i = 0; i <= steps; ++i) {
    const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(i) / steps);
    put_inside(picture, static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())),
               panel_width, kFootprint);
  }
}

void draw_unsafe_hit(imaging::Image<std::uint8_t>& picture, const TerrainComparison& site,
                     int panel_width) {
  if (!site.unsafe_hit)
    return;
  const FootprintHit& hit = *site.unsafe_hit;
  for (std::size_t c = 0; c < hit.corners.size(); ++c) {
    const auto a = pixel_of(site, hit.corners[c]);
    const auto b = pixel_of(site, hit.corners[(c + 1) % hit.corners.size()]);
    if (a && b)
      draw_segment(picture, *a, *b, panel_width);
  }
  const auto centre = pixel_of(site, Eigen::Vector3d(hit.x_m, hit.y_m, hit.z_m));
  if (!centre)
    return;
  const int cx = static_cast<int>(std::lround(centre->x()));
  const int cy = static_cast<int>(std::lround(centre->y()));
  for (int d = -3; d <= 3; ++d) {
    put_inside(picture, cx + d, cy, panel_width, kHitCross);
    put_inside(picture, cx, cy + d, panel_width, kHitCross);
  }
}

} // namespace

imaging::Image<std::uint8_t> terrain_comparison_picture(const TerrainComparison& site) {
  const int width = site.left.width();
  const int height = site.left.height();
  imaging::Image<std::uint8_t> picture(3 * width, height, 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint8_t grey = site.left(x, y);
      put(picture, x, y, {grey, grey, grey});
      put(picture, x + width, y, verdict(site, x, y));
      put(picture, x + 2 * width, y, truth_colour(site, x, y));
    }
  draw_path(picture, site.plan, 0, kPathGreen);
  draw_path(picture, site.plan, width, kPathGreen);
  draw_path(picture, site.truth_plan, 2 * width, kTruthPathCyan);
  draw_unsafe_hit(picture, site, width);
  return picture;
}

} // namespace marsokhod::eval
