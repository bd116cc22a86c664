// The traverse loop: render, navigate, drive on the true ground, and the motion scheme between.
#include "marsokhod/eval/traverse/traverse.hpp"

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/eval/terrain/terrain_evaluation.hpp"
#include "marsokhod/eval/traverse/ground_drive.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/world/lighting/lit_surface.hpp"
#include "marsokhod/world/render/renderer.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace marsokhod::eval {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
// Ground beyond the course on every side: the view reaches past the goal and the escapes turn.
constexpr double kSiteMarginM = 10.0;

double wrap_deg(double deg) {
  return std::remainder(deg, 360.0);
}

int cycle_limit(const TraverseSettings& s) {
  return s.max_cycles > 0 ? s.max_cycles : static_cast<int>(std::ceil(0.4 * s.goal_m)) + 20;
}

imaging::RigParameters rig_of(const TraverseSettings& s) {
  imaging::RigParameters rig;
  rig.width_px = rig.height_px = s.image_px;
  return rig;
}

// The course's ground, the light on it and the camera that sees it.
struct Course {
  imaging::StereoRig rig;
  const world::Terrain& terrain;
  world::LitSurface surface;
  world::Renderer renderer;

  Course(const TraverseSettings& s, const world::Terrain& ground)
      : rig(rig_of(s)), terrain(ground),
        surface(terrain, world::lighting_preset(world::parse_light_preset(s.light))),
        renderer(terrain) {}
};

// The emulated computer a cycle runs on, when not native.
struct EmulatedComputer {
  emulator::PlatformSpec platform;
  nav_program::Placement placement;

  explicit EmulatedComputer(const std::string& name)
      : platform(emulator::load_named_platform(name)),
        placement(nav_program::load_program_placement(platform)) {}
};

std::optional<EmulatedComputer> computer_for(const TraverseSettings& s) {
  if (s.platform == "native")
    return std::nullopt;
  return EmulatedComputer(s.platform);
}

// The destination range: the scheme's, drawn in when the goal is nearer than its far end.
std::pair<double, double> target_range(const nav::MotionAction& action, double goal_left_m) {
  if (goal_left_m >= action.plan_max_m)
    return {action.plan_min_m, action.plan_max_m};
  const double far = std::max(goal_left_m + 0.5, 3.0);
  return {std::max(far - 1.0, 2.5), far};
}

class Loop {
public:
  Loop(const TraverseSettings& s, const world::Terrain& terrain, const CycleView& view)
      : s_(s), course_(s, terrain), computer_(computer_for(s)), view_(view) {
    result_.settings = s;
    result_.start = {-0.5 * s.goal_m, 0.0, 0.0};
    result_.goal = Eigen::Vector2d(0.5 * s.goal_m, 0.0);
    pose_ = result_.start;
    limits_ = {s.emergency_tilt_deg, s.tilt_limit_deg, s.read_every_m, result_.goal,
               s.goal_tolerance_m};
  }

  TraverseResult run(const TraverseProgress& progress) {
    nav::MotionAction action = nav::initial_motion_action();
    const int limit = cycle_limit(s_);
    while (static_cast<int>(result_.cycles.size()) < limit) {
      if (goal_left() <= s_.goal_tolerance_m)
        return finish(TraverseOutcome::success);
      TraverseCycle cycle;
      cycle.index = static_cast<int>(result_.cycles.size());
      const std::optional<TraverseOutcome> end = run_cycle(action, cycle);
      result_.cycles.push_back(std::move(cycle));
      if (progress)
        progress(result_.cycles.back(), result_);
      if (end)
        return finish(*end);
    }
    return finish(goal_left() <= s_.goal_tolerance_m ? TraverseOutcome::success
                                                     : TraverseOutcome::timeout);
  }

private:
  double goal_left() const { return (Eigen::Vector2d(pose_.x, pose_.y) - result_.goal).norm(); }

  TraverseResult finish(TraverseOutcome outcome) {
    result_.outcome = outcome;
    result_.end = pose_;
    result_.goal_left_m = goal_left();
    return std::move(result_);
  }

  // Drives on the true ground and books it.
  GroundDrive drive(std::span<const nav::DriveCommand> commands, TraverseCycle& cycle) {
    const GroundDrive drive =
        drive_on_ground(course_.terrain, pose_, commands, s_.chassis, limits_);
    pose_ = drive.end;
    cycle.driven_m += drive.driven_m;
    cycle.track.insert(cycle.track.end(), drive.track.begin(), drive.track.end());
    result_.distance_m += drive.driven_m;
    result_.driving_seconds +=
        drive.driven_m / s_.drive_speed_m_s + drive.turned_deg / s_.turn_rate_deg_s;
    if (drive.unsafe) {
      result_.unsafe_events.push_back({drive.unsafe_at.x(), drive.unsafe_at.y(), *drive.unsafe});
      cycle.events.push_back("unsafe: " + *drive.unsafe);
    }
    if (drive.emergency_stop) {
      ++result_.emergency_stops;
      cycle.emergency_stop = true;
      cycle.events.push_back(fmt::format("emergency stop: tilt {:.1f} deg, {} side up",
                                         drive.tilt_deg,
                                         drive.risen_side == nav::Side::left ? "left" : "right"));
    }
    return drive;
  }

  // The outcome when a drive ends the traverse.
  static std::optional<TraverseOutcome> end_of(const GroundDrive& drive) {
    if (drive.unsafe)
      return TraverseOutcome::unsafe;
    if (drive.at_goal)
      return TraverseOutcome::success;
    return std::nullopt;
  }

  nav::NavigationResult navigate(const world::RoverPlacement& placement,
                                 const nav::MotionAction& action, TraverseCycle& cycle) {
    world::RenderOptions render;
    render.noise_seed = s_.seed * 100003u + static_cast<std::uint64_t>(cycle.index);
    const world::StereoImages pair =
        course_.renderer.render(course_.rig, placement, course_.surface, render);
    nav::NavigationOptions options;
    options.attitude = placement.attitude;
    const auto [near, far] = target_range(action, goal_left());
    options.planner.target_min_m = near;
    options.planner.target_max_m = far;
    const Eigen::Vector2d to_goal = result_.goal - Eigen::Vector2d(pose_.x, pose_.y);
    options.planner.heading_deg =
        wrap_deg(std::atan2(to_goal.y(), to_goal.x()) * kDegreesPerRadian - pose_.heading_deg);
    const auto started = std::chrono::steady_clock::now();
    nav::NavigationResult nav = computer_
                                    ? emulate(pair, options, cycle)
                                    : nav::navigate(pair.left, pair.right, course_.rig, options);
    cycle.host_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    result_.host_seconds += cycle.host_seconds;
    if (view_)
      view_(cycle.index, pair.left, nav);
    return nav;
  }

  // The cycle on the emulated computer; its emulated time is mission time.
  nav::NavigationResult emulate(const world::StereoImages& pair,
                                const nav::NavigationOptions& options, TraverseCycle& cycle) {
    nav_program::CycleInput input{pair.left, pair.right, &course_.rig, options, {}};
    nav_program::CycleSetup setup;
    setup.platform = &computer_->platform;
    setup.placement = &computer_->placement;
    const nav_program::CycleEmulation run = nav_program::emulate_navigation_cycle(input, setup);
    cycle.compute_seconds = emulator::to_seconds(run.emulated);
    result_.compute_seconds += cycle.compute_seconds;
    if (run.result)
      return *run.result;
    nav::NavigationResult none;
    none.plan.found = false;
    none.plan.reason =
        run.memory_fault ? "the emulated cycle stopped: " + nav_program::describe(*run.memory_fault)
                         : "the emulated cycle gave no result";
    return none;
  }

  static void book_plan(const world::RoverPlacement& placement, const nav::NavigationResult& nav,
                        TraverseCycle& cycle) {
    cycle.found = nav.found();
    cycle.reason = nav.reason();
    if (!nav.found())
      return;
    Eigen::Vector2d previous(0.0, 0.0);
    cycle.planned.emplace_back(placement.pose.x, placement.pose.y);
    for (const nav::GroundPoint& p : nav.drive.polyline) {
      const Eigen::Vector3d world = placement.level_to_world * Eigen::Vector3d(p.x, p.y, 0.0);
      cycle.planned.emplace_back(world.x(), world.y());
      cycle.planned_m += (Eigen::Vector2d(p.x, p.y) - previous).norm();
      previous = Eigen::Vector2d(p.x, p.y);
    }
  }

  nav::MotionStep step(const nav::MotionEvent& event) {
    const nav::MotionStep next = nav::next_motion_step(status_, event);
    status_ = next.status;
    return next;
  }

  // One cycle: the action's turn, then plan (and drive) or hand over.
  std::optional<TraverseOutcome> run_cycle(nav::MotionAction& action, TraverseCycle& cycle) {
    cycle.start = pose_;
    cycle.state = status_.state;
    if (action.turn_deg != 0.0) {
      cycle.turned_deg = action.turn_deg;
      cycle.events.push_back(fmt::format("turn {:+.0f} deg on the spot", action.turn_deg));
      const nav::DriveCommand turn{action.turn_deg, 0.0};
      if (auto end = end_of(drive(std::span(&turn, 1), cycle)))
        return end;
    }
    if (action.then == nav::MotionAction::Then::hand_over) {
      ++result_.hand_overs;
      cycle.events.push_back("hand over: a full turn found no path");
      return TraverseOutcome::hand_over;
    }
    const world::RoverPlacement placement =
        world::place_rover(course_.terrain.height, pose_, s_.chassis);
    const nav::NavigationResult nav = navigate(placement, action, cycle);
    book_plan(placement, nav, cycle);
    action = step({nav.found() ? nav::MotionEventKind::path_found : nav::MotionEventKind::no_path})
                 .action;
    if (action.then != nav::MotionAction::Then::drive)
      return std::nullopt;
    const GroundDrive driven = drive(nav.drive.commands, cycle);
    if (auto end = end_of(driven))
      return end;
    const nav::MotionEvent event =
        driven.emergency_stop
            ? nav::MotionEvent{nav::MotionEventKind::inclination_exceeded, driven.risen_side}
            : nav::MotionEvent{nav::MotionEventKind::path_done};
    action = step(event).action;
    return std::nullopt;
  }

  const TraverseSettings& s_;
  Course course_;
  std::optional<EmulatedComputer> computer_;
  const CycleView& view_;
  TraverseResult result_;
  world::RoverPose pose_;
  GroundDriveLimits limits_;
  nav::MotionStatus status_;
};

} // namespace

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
  if (s.max_cycles < 0)
    throw std::invalid_argument("traverse: max_cycles must not be negative");
  imaging::validate(s.chassis);
  world::parse_light_preset(s.light);
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

double TraverseResult::path_efficiency() const {
  if (outcome != TraverseOutcome::success || distance_m <= 0.0)
    return 0.0;
  const double shortest = settings.goal_m - settings.goal_tolerance_m;
  return shortest / std::max(distance_m, shortest);
}

world::TerrainSettings traverse_site(const TraverseSettings& s) {
  validate(s);
  world::TerrainSettings site;
  site.seed = s.seed;
  site.rock_cover = s.rocks;
  site.regional_slope_deg = s.slope_deg;
  site.size_m = s.goal_m + 2.0 * kSiteMarginM;
  site.clear_centre = Eigen::Vector2d(-0.5 * s.goal_m, 0.0);
  site.clear_radius_m = unseen_start_radius(imaging::StereoRig(rig_of(s)), s.chassis);
  return site;
}

TraverseResult run_traverse(const world::Terrain& terrain, const TraverseSettings& settings,
                            const TraverseProgress& progress, const CycleView& view) {
  validate(settings);
  return Loop(settings, terrain, view).run(progress);
}

TraverseResult run_traverse(const TraverseSettings& settings, const TraverseProgress& progress) {
  const world::Terrain terrain = world::Terrain::generate(traverse_site(settings));
  return run_traverse(terrain, settings, progress);
}

} // namespace marsokhod::eval
