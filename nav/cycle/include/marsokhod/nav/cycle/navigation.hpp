// One navigation cycle: from a stereo pair and the rig to zones, a safe path and drive commands.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/cycle/checked_path.hpp"
#include "marsokhod/nav/path/drive_commands.hpp"
#include "marsokhod/nav/path/path_planner.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"
#include "marsokhod/nav/terrain/elevation.hpp"
#include "marsokhod/nav/work/work.hpp"
#include "marsokhod/nav/zones/zones.hpp"

#include <cstdint>
#include <memory_resource>
#include <string>

namespace marsokhod::nav {

/// Everything one navigation cycle needs besides the images and the rig.
struct NavigationOptions {
  /// Stereo search; max_disparity 0 means "from the rig" (rover_max_disparity).
  StereoOptions stereo = rover_stereo_defaults();
  imaging::Attitude attitude; ///< the rover's measured pitch and roll
  ZoneOptions zones;
  PlannerOptions planner;
  DriveOptions drive;
  FootprintCheckOptions footprint;
  /// Pixels of the left image whose 5 x 5 neighbourhood spans fewer grey levels than this are
  /// featureless (clipped to black or white): whatever disparity they got, nothing was seen
  /// there, so they count as unreliable. Sensor noise alone spans about 4 sigma. 0 turns the
  /// test off.
  int featureless_grey_range = 5;

  static StereoOptions rover_stereo_defaults() {
    StereoOptions options;
    options.max_disparity = 0;
    return options;
  }
};

/// Throws std::invalid_argument when the two images differ in size or do not have the rig's.
void check_images_fit(imaging::ImageView<const std::uint8_t> left,
                      imaging::ImageView<const std::uint8_t> right, const imaging::StereoRig& rig);

/// The largest disparity a rover pair can hold: the nearest ground the rig sees (the bottom
/// row) at the given attitude, plus a quarter for rocks standing in front of it, at most the
/// image width minus one.
int rover_max_disparity(const imaging::StereoRig& rig, const imaging::Attitude& attitude);

/// The stereo options a rover cycle matches with: options.stereo, with the search range from
/// the rig when it is 0 and, unless given, the first columns of each row whose level ground lies
/// outside the right image (StereoOptions::unseen_columns). Those columns are written into
/// `unseen` (from its memory resource), which the options then point at: it must outlive them.
StereoOptions rover_stereo_options(const imaging::StereoRig& rig, const NavigationOptions& options,
                                   std::pmr::vector<std::int16_t>& unseen);

/// What navigate() makes of the matcher's disparity before the terrain: the disparity of what
/// the pair can show at all, textured pixels
/// (NavigationOptions::featureless_grey_range) below the horizon whose ground the right camera
/// sees; +inf elsewhere. Where the level ground's disparity exceeds the column (x - d < 0) the
/// ground, and anything standing on it, lies outside the right image: a match found there can
/// only be a wrong, smaller disparity that the left-right check happened to confirm. Rocks and
/// rising ground just right of that strip are hidden from the right camera too; their wrong
/// matches are left to the left-right check and the columns' ordering test, which see them,
/// rather than to a wider strip, which would also hide the ground beside it. At or above the
/// horizon only the sky, or the top of something taller than the mast, can be seen; the sky must
/// not become terrain.
imaging::Image<float> seeable_disparity(imaging::ImageView<const std::uint8_t> left,
                                        const imaging::Image<float>& disparity,
                                        const imaging::StereoRig& rig,
                                        const NavigationOptions& options,
                                        std::pmr::memory_resource* memory);

/// A stereo matcher that gave up (a non-empty reason) leaves the cycle without a path, for
/// that reason ("stereo: ..."), whatever the planner made of its empty map.
void explain_stereo_failure(const std::string& stereo_reason, PathPlan& plan);

/// 255 where the 5 x 5 neighbourhood of a pixel spans at least `grey_range` grey levels, 0
/// where it is featureless (NavigationOptions::featureless_grey_range).
imaging::Image<std::uint8_t>
textured_pixels(imaging::ImageView<const std::uint8_t> image, int grey_range,
                std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// One navigation cycle's products, each stage's output kept for pictures and evaluation.
struct NavigationResult {
  StereoResult stereo; ///< empty when the cycle started from a given disparity map
  TerrainPoints terrain;
  ZoneMap zones;
  PathPlan plan;
  DrivePlan drive; ///< empty unless plan.found

  bool found() const { return plan.found; }
  const std::string& reason() const { return plan.reason; }
};

/// Stereo reconstruction, range and elevation, prohibited zones, safest path and drive
/// commands for one rectified grey pair of the rig's size. Throws std::invalid_argument for
/// images that do not fit the rig or each other, images too small for the pyramid, and bad
/// options; a pair that yields no path (nothing matched, everything prohibited) is a result
/// with found() false and a reason. Instantiated for NullMeter, CountingMeter, DynamicMeter.
template <class Meter = NullMeter>
NavigationResult
navigate(imaging::ImageView<const std::uint8_t> left, imaging::ImageView<const std::uint8_t> right,
         const imaging::StereoRig& rig, const NavigationOptions& options, Meter& meter = null_meter,
         std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// The same cycle from a disparity map already made (+inf unknown); `reliable` (may be empty)
/// marks the pixels that passed the left-right check.
template <class Meter = NullMeter>
NavigationResult
navigate_disparity(imaging::ImageView<const float> disparity,
                   imaging::ImageView<const std::uint8_t> reliable, const imaging::StereoRig& rig,
                   const NavigationOptions& options, Meter& meter = null_meter,
                   std::pmr::memory_resource* memory = std::pmr::get_default_resource());

} // namespace marsokhod::nav
