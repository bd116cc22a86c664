// The rig description's keys and the values that make physical sense for each.

#include "rig/rig_fields.hpp"

#include "marsokhod/imaging/image/image.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>

namespace marsokhod::imaging::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The matcher searches along rows, so the right camera may only be slightly off parallel.
constexpr double kMaxMisalignmentArcsec = 3600.0;
constexpr double kMaxPitchDeg = 89.0;
constexpr int kMinImageSide = 16;

template <double RigParameters::*member>
RigField real_field(std::string_view key, double low, double high, bool low_excluded) {
  return {"rig",
          key,
          false,
          low,
          high,
          low_excluded,
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
          false,
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
          false,
          [](const RigParameters& p) { return p.right_misalignment.*member; },
          [](RigParameters& p, double value) { p.right_misalignment.*member = value; }};
}

using P = RigParameters;
using M = Misalignment;

const std::array kFields = {
    real_field<&P::mast_height_m>("mast_height_m", 0.0, kInfinity, true),
    real_field<&P::mast_forward_m>("mast_forward_m", -kInfinity, kInfinity, false),
    real_field<&P::pitch_down_deg>("pitch_down_deg", -kMaxPitchDeg, kMaxPitchDeg, false),
    real_field<&P::focal_mm>("focal_mm", 0.0, kInfinity, true),
    real_field<&P::sensor_mm>("sensor_mm", 0.0, kInfinity, true),
    real_field<&P::baseline_m>("baseline_m", 0.0, kInfinity, true),
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
    return "must be a finite number";
  const bool too_low = field.low_excluded ? value <= field.low : value < field.low;
  if (!too_low && value <= field.high)
    return std::nullopt;
  if (field.low_excluded && field.low == 0.0 && field.high == kInfinity)
    return fmt::format("must be positive (got {})", value);
  return fmt::format("must be between {} and {} (got {})", field.low, field.high, value);
}

} // namespace marsokhod::imaging::detail
