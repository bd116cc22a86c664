// The rig description's keys and the values that make physical sense for each.

#include "rig/rig_fields.hpp"

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>

namespace marsokhod::imaging::detail {
namespace {

// The matcher searches along rows, so the right camera may only be slightly off parallel.
constexpr double kMaxMisalignmentArcsec = 3600.0;
// The optical axis is never vertical: the horizon row divides by the cosine of the pitch.
constexpr double kMaxPitchDeg = 89.0;
constexpr int kMinImageSide = 16;
// Lengths and the lens span six or fewer orders of magnitude around the paper's rig, so that
// every derived figure (focal length in pixels f / s * w, disparities f * B / z, ground
// distances H / tan(angle), ground disparities B * depression / H) is a finite double for
// every combination of legal values; docs/formats.md, "Rig files", gives each bound's reason.
constexpr double kMinMastHeightM = 0.01;
constexpr double kMaxMastHeightM = 100.0;
constexpr double kMaxMastForwardM = 100.0;
constexpr double kMinFocalMm = 0.1;
constexpr double kMaxFocalMm = 10000.0;
constexpr double kMinSensorMm = 0.1;
constexpr double kMaxSensorMm = 1000.0;
constexpr double kMinBaselineM = 0.001;
constexpr double kMaxBaselineM = 100.0;
// The stone must lie at least this far in front of the left camera's image plane, so that its
// disparity f * B / depth stays finite.
constexpr double kMinStoneDepthM = 0.001;

template <double RigParameters::*member>
RigField real_field(std::string_view key, double low, double high) {
  return {"rig",
          key,
          false,
          low,
          high,
          [](const RigParameters& p) { return p.*member; },
          [](RigParameters& p, double value) { p.*member = value; }};
}

template <int RigParameters::*member>
RigField size_field(std::string_view key) {
  return {"rig",
          key,
          true,
          kMinImageSide,
          kMaxImageSide,
          [](const RigParameters& p) { return static_cast<double>(p.*member); },
          [](RigParameters& p, double value) { p.*member = static_cast<int>(value); }};
}

template <double Misalignment::*member>
RigField misalignment_field(std::string_view key) {
  return {"rig.right_misalignment",
          key,
          false,
          -kMaxMisalignmentArcsec,
          kMaxMisalignmentArcsec,
          [](const RigParameters& p) { return p.right_misalignment.*member; },
          [](RigParameters& p, double value) { p.right_misalignment.*member = value; }};
}

using P = RigParameters;
using M = Misalignment;

const std::array kFields = {
    real_field<&P::mast_height_m>("mast_height_m", kMinMastHeightM, kMaxMastHeightM),
    real_field<&P::mast_forward_m>("mast_forward_m", -kMaxMastForwardM, kMaxMastForwardM),
    real_field<&P::pitch_down_deg>("pitch_down_deg", -kMaxPitchDeg, kMaxPitchDeg),
    real_field<&P::focal_mm>("focal_mm", kMinFocalMm, kMaxFocalMm),
    real_field<&P::sensor_mm>("sensor_mm", kMinSensorMm, kMaxSensorMm),
    real_field<&P::baseline_m>("baseline_m", kMinBaselineM, kMaxBaselineM),
    size_field<&P::width_px>("width_px"),
    size_field<&P::height_px>("height_px"),
    misalignment_field<&M::pan_arcsec>("pan_arcsec"),
    misalignment_field<&M::tilt_arcsec>("tilt_arcsec"),
    misalignment_field<&M::roll_arcsec>("roll_arcsec"),
};

} // namespace

std::span<const RigField> rig_fields() {
  return kFields;
}

std::optional<std::string> rig_value_problem(const RigField& field, double value) {
  if (!std::isfinite(value))
    return fmt::format("must be a finite number, not {}", value);
  if (value >= field.low && value <= field.high)
    return std::nullopt;
  return fmt::format("{} is out of range: it must be {}", value,
                     io::range_text(field.low, field.high));
}

std::optional<std::string> rig_geometry_problem(const RigParameters& p) {
  // The left camera's optical axis in the level frame is (cos a, 0, -sin a) for a pitch a
  // down; a point is in front of the camera when its offset from the optical centre has a
  // positive component along it. The stone's foot and top are the points that matter.
  const double pitch = p.pitch_down_deg * std::numbers::pi / 180.0;
  const double forward = kReferenceStoneDistanceM - p.mast_forward_m;
  for (const double height : {0.0, kReferenceStoneHeightM}) {
    const double depth = std::cos(pitch) * forward - std::sin(pitch) * (height - p.mast_height_m);
    if (depth < kMinStoneDepthM)
      return fmt::format(
          "the cameras do not see the ground ahead at this pitch and mast position: the "
          "paper's {:.0f} cm stone {:.0f} m ahead of the rover centre would be {} the left "
          "camera (rig.pitch_down_deg = {}, rig.mast_height_m = {}, rig.mast_forward_m = {})",
          100.0 * kReferenceStoneHeightM, kReferenceStoneDistanceM,
          depth > 0.0 ? "almost in the plane of" : "behind", p.pitch_down_deg, p.mast_height_m,
          p.mast_forward_m);
  }
  return std::nullopt;
}

} // namespace marsokhod::imaging::detail
