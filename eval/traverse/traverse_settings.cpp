// A traverse's settings checked, its outcomes named and its figures derived.
#include "marsokhod/eval/traverse/traverse.hpp"
#include "marsokhod/world/lighting/lighting.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace marsokhod::eval {

void validate(const TraverseSettings& s) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!(s.rocks >= 0.0 && s.rocks <= 0.5))
    throw std::invalid_argument(fmt::format("traverse: rocks = {} must be within 0..0.5", s.rocks));
  if (!(s.slope_deg >= 0.0 && s.slope_deg <= 15.0))
    throw std::invalid_argument(
        fmt::format("traverse: slope = {} deg must be within 0..15", s.slope_deg));
  if (!(s.goal_m >= 5.0 && s.goal_m <= 180.0))
    throw std::invalid_argument(
        fmt::format("traverse: goal = {} m must be within 5..180", s.goal_m));
  if (!positive(s.goal_tolerance_m) || !positive(s.read_every_m) || !positive(s.drive_speed_m_s) ||
      !positive(s.turn_rate_deg_s))
    throw std::invalid_argument(
        "traverse: tolerances, reading interval and speeds must be positive");
  if (!(s.emergency_tilt_deg > 0.0 && s.emergency_tilt_deg <= s.tilt_limit_deg &&
        s.tilt_limit_deg < 90.0))
    throw std::invalid_argument(fmt::format(
        "traverse: the emergency tilt {} deg must be positive and at most the limit {} deg (< 90)",
        s.emergency_tilt_deg, s.tilt_limit_deg));
  if (!(s.drive_m >= 0.0 && s.drive_m <= 20.0))
    throw std::invalid_argument(
        fmt::format("traverse: drive = {} m must be within 0..20 (0: the whole path)", s.drive_m));
  if (s.hazard_memory_cycles < 0 || s.hazard_memory_cycles > 10)
    throw std::invalid_argument(fmt::format(
        "traverse: hazard memory = {} cycles must be within 0..10", s.hazard_memory_cycles));
  if (!(s.slip >= 0.0 && s.slip <= 0.5))
    throw std::invalid_argument(fmt::format("traverse: slip = {} must be within 0..0.5", s.slip));
  if (s.max_cycles < 0)
    throw std::invalid_argument("traverse: max_cycles must not be negative");
  imaging::validate(s.chassis);
  world::parse_light_preset(s.light);
  if (!s.faults_file.empty() && s.platform == "native")
    throw std::invalid_argument(
        "traverse: faults strike the emulated computer: give an emulated platform with them");
  if (s.platform != "native" && s.platform != "pc-card" && s.platform != "onboard")
    throw std::invalid_argument(
        fmt::format("traverse: platform '{}' is not one of native, pc-card, onboard", s.platform));
}

std::string_view to_string(TraverseOutcome outcome) {
  switch (outcome) {
  case TraverseOutcome::success:
    return "success";
  case TraverseOutcome::hand_over:
    return "hand_over";
  case TraverseOutcome::unsafe:
    return "unsafe";
  case TraverseOutcome::timeout:
    return "timeout";
  }
  return "invalid";
}

double TraverseResult::odometry_error_m() const {
  return std::hypot(estimate.x - end.x, estimate.y - end.y);
}

double TraverseResult::path_efficiency() const {
  if (outcome != TraverseOutcome::success || distance_m <= 0.0)
    return 0.0;
  const double shortest = settings.goal_m - settings.goal_tolerance_m;
  return shortest / std::max(distance_m, shortest);
}

} // namespace marsokhod::eval
