// One navigation cycle: stereo, range and elevation, zones, safest path and drive commands.

#include "marsokhod/nav/cycle/navigation.hpp"

#include "terrain/terrain_view.hpp"
#include "work/work_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace marsokhod::nav {
namespace {

/// Room for rocks nearer than the ground seen in the bottom row.
constexpr double kNearRockAllowance = 1.25;

// The level ground's disparity along each row of a `width`-pixel-wide left image, which is
// affine in x: the line the strip outside the right image is judged against.
class GroundRows {
public:
  struct Line {
    double first_d; // at column 0
    double rise;    // from column 0 to the last
  };

  GroundRows(const imaging::StereoRig& rig, const imaging::Attitude& attitude, int width,
             std::pmr::memory_resource* memory)
      : last_(width - 1.0),
        fractions_(detail::column_fractions(width, std::max(last_, 1.0), memory)),
        ground_(rig, attitude) {}

  const double* fractions() const { return fractions_.data(); }
  Line line(int y) const {
    const double first_d = ground_.disparity(0.0, y);
    return {first_d, ground_.disparity(last_, y) - first_d};
  }

private:
  double last_;
  std::pmr::vector<double> fractions_;
  detail::LevelGround ground_;
};

// Per row, the first columns whose level ground lies outside the right image: the matcher keeps
// them out of its right view (StereoOptions::unseen_columns), where their necessarily wrong
// matches would otherwise compete with the true ones of the right image's first columns.
std::pmr::vector<std::int16_t> columns_past_right_edge(const imaging::StereoRig& rig,
                                                       const NavigationOptions& options,
                                                       std::pmr::memory_resource* memory) {
  std::pmr::vector<std::int16_t> columns(static_cast<std::size_t>(rig.height()), 0, memory);
  const GroundRows ground(rig, options.attitude, rig.width(), memory);
  for (int y = 0; y < rig.height(); ++y) {
    const GroundRows::Line line = ground.line(y);
    columns[static_cast<std::size_t>(y)] = static_cast<std::int16_t>(
        detail::columns_past_edge(ground.fractions(), line.first_d, line.rise, rig.width()));
  }
  return columns;
}

} // namespace

imaging::Image<float> seeable_disparity(imaging::ImageView<const std::uint8_t> left,
                                        const imaging::Image<float>& disparity,
                                        const imaging::StereoRig& rig,
                                        const NavigationOptions& options,
                                        std::pmr::memory_resource* memory) {
  imaging::Image<float> seeable(disparity.width(), disparity.height(), 1,
                                std::numeric_limits<float>::infinity(), memory);
  if (seeable.empty())
    return seeable;
  const imaging::Image<std::uint8_t> textured =
      options.featureless_grey_range > 0
          ? textured_pixels(left, options.featureless_grey_range, memory)
          : imaging::Image<std::uint8_t>(left.width(), left.height(), 1, 255, memory);
  const GroundRows ground(rig, options.attitude, left.width(), memory);
  for (int y = 0; y < left.height(); ++y) {
    const GroundRows::Line line = ground.line(y);
    detail::keep_seeable(textured.row(y), ground.fractions(), line.first_d, line.rise, left.width(),
                         disparity.row(y), seeable.row(y));
  }
  return seeable;
}

void check_images_fit(imaging::ImageView<const std::uint8_t> left,
                      imaging::ImageView<const std::uint8_t> right, const imaging::StereoRig& rig) {
  if (left.width() != right.width() || left.height() != right.height())
    throw std::invalid_argument(fmt::format("the left image is {}x{} but the right is {}x{}",
                                            left.width(), left.height(), right.width(),
                                            right.height()));
  if (left.width() != rig.width() || left.height() != rig.height())
    throw std::invalid_argument(fmt::format("the images are {}x{} but the rig is {}x{}",
                                            left.width(), left.height(), rig.width(),
                                            rig.height()));
}

int rover_max_disparity(const imaging::StereoRig& rig, const imaging::Attitude& attitude) {
  double nearest = 0.0;
  const double bottom = rig.height() - 1.0;
  for (const double u : {0.0, rig.cx(), rig.width() - 1.0})
    nearest = std::max(nearest, rig.ground_disparity(u, bottom, attitude));
  const int wanted = static_cast<int>(std::ceil(kNearRockAllowance * nearest));
  return std::clamp(wanted, 1, rig.width() - 1);
}

StereoOptions rover_stereo_options(const imaging::StereoRig& rig, const NavigationOptions& options,
                                   std::pmr::vector<std::int16_t>& unseen) {
  StereoOptions stereo = options.stereo;
  if (stereo.max_disparity == 0)
    stereo.max_disparity = rover_max_disparity(rig, options.attitude);
  if (stereo.unseen_columns.empty()) {
    unseen = columns_past_right_edge(rig, options, unseen.get_allocator().resource());
    stereo.unseen_columns = unseen;
  }
  return stereo;
}

void explain_stereo_failure(const std::string& stereo_reason, PathPlan& plan) {
  if (stereo_reason.empty())
    return;
  plan.found = false;
  plan.reason = "stereo: " + stereo_reason;
}

template <class Meter>
NavigationResult navigate_disparity(imaging::ImageView<const float> disparity,
                                    imaging::ImageView<const std::uint8_t> reliable,
                                    const imaging::StereoRig& rig, const NavigationOptions& options,
                                    Meter& meter, std::pmr::memory_resource* memory) {
  validate(options.zones);
  validate(options.planner);
  validate(options.drive);
  validate(options.footprint);
  NavigationResult result{StereoResult{imaging::Image<float>(memory),
                                       imaging::Image<std::uint8_t>(memory),
                                       0,
                                       std::pmr::vector<StereoLayerStats>(memory),
                                       {}},
                          reconstruct_terrain(disparity, rig, options.attitude, meter, memory),
                          {},
                          {},
                          {}};
  result.zones = find_zones(result.terrain, reliable, options.zones, meter, memory);
  result.plan = plan_cycle_path(result.terrain, result.zones, options.planner, options.drive,
                                options.footprint, meter, memory);
  if (result.plan.found)
    result.drive = plan_drive(result.terrain, result.plan.pixels, options.drive, memory);
  return result;
}

template <class Meter>
NavigationResult navigate(imaging::ImageView<const std::uint8_t> left,
                          imaging::ImageView<const std::uint8_t> right,
                          const imaging::StereoRig& rig, const NavigationOptions& options,
                          Meter& meter, std::pmr::memory_resource* memory) {
  check_images_fit(left, right, rig);
  // Kept alive here: the options only point at it.
  std::pmr::vector<std::int16_t> unseen(memory);
  const StereoOptions stereo_options = rover_stereo_options(rig, options, unseen);
  StereoResult stereo = match_stereo(left, right, stereo_options, meter, memory);
  const imaging::Image<float> seeable =
      seeable_disparity(left, stereo.disparity, rig, options, memory);
  NavigationResult result = navigate_disparity(seeable, stereo.valid, rig, options, meter, memory);
  explain_stereo_failure(stereo.reason, result.plan);
  result.stereo = std::move(stereo);
  return result;
}

#define MARSOKHOD_INSTANTIATE(M)                                                                   \
  template NavigationResult navigate<M>(                                                           \
      imaging::ImageView<const std::uint8_t>, imaging::ImageView<const std::uint8_t>,              \
      const imaging::StereoRig&, const NavigationOptions&, M&, std::pmr::memory_resource*);        \
  template NavigationResult navigate_disparity<M>(                                                 \
      imaging::ImageView<const float>, imaging::ImageView<const std::uint8_t>,                     \
      const imaging::StereoRig&, const NavigationOptions&, M&, std::pmr::memory_resource*);
MARSOKHOD_NAV_FOR_EACH_METER(MARSOKHOD_INSTANTIATE)
#undef MARSOKHOD_INSTANTIATE

} // namespace marsokhod::nav
