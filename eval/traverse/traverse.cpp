// The traverse loop: render, navigate, drive on the true ground, and the motion scheme between.
#include "marsokhod/eval/traverse/traverse.hpp"

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/eval/terrain/terrain_evaluation.hpp"
#include "marsokhod/eval/traverse/cycle_zones.hpp"
#include "marsokhod/eval/traverse/ground_drive.hpp"
#include "marsokhod/eval/traverse/odometry.hpp"
#include "marsokhod/eval/traverse/traverse_map.hpp"
#include "marsokhod/nav/cycle/hazard_memory.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/world/lighting/lit_surface.hpp"
#include "marsokhod/world/render/renderer.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace marsokhod::eval {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
// Ground beyond the course at either end: the view reaches past the goal.
constexpr double kSiteMarginM = 10.0;
// North-south side of the site: the course's strip (the 100 m x 30 m site); the
// navigation sees sky past its edges and plans nothing there.
constexpr double kSiteWidthM = 30.0;

double wrap_deg(double deg) {
  return std::remainder(deg, 360.0);
}

// The rover at the west end of the course, facing east toward the goal.
world::RoverPose start_of(const TraverseSettings& s) {
  return {-0.5 * s.goal_m, 0.0, 0.0};
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

// The emulated computer a cycle runs on, when not native; with faults, the campaign file's.
struct EmulatedComputer {
  std::optional<TraverseFaults> faults;
  emulator::PlatformSpec platform;
  nav_program::Placement placement;

  explicit EmulatedComputer(const TraverseSettings& s)
      : faults(faults_of(s)),
        platform(faults ? faults->platform() : emulator::load_named_platform(s.platform)),
        placement(faults ? faults->placement() : nav_program::load_program_placement(platform)) {}

  static std::optional<TraverseFaults> faults_of(const TraverseSettings& s) {
    if (s.faults_file.empty())
      return std::nullopt;
    std::optional<TraverseFaults> faults(std::in_place, s.faults_file, s.seed);
    if (faults->platform_name() != s.platform)
      throw std::invalid_argument(
          fmt::format("traverse: the campaign file {} runs on '{}', not on '{}'", s.faults_file,
                      faults->platform_name(), s.platform));
    return faults;
  }
};

std::optional<EmulatedComputer> computer_for(const TraverseSettings& s) {
  if (s.platform == "native")
    return std::nullopt;
  return std::optional<EmulatedComputer>(std::in_place, s);
}

// The destination range: the scheme's, drawn in when the goal is nearer than its far end.
std::pair<double, double> target_range(const nav::MotionAction& action, double goal_left_m) {
  if (goal_left_m >= action.plan_max_m)
    return {action.plan_min_m, action.plan_max_m};
  const double far = std::max(goal_left_m + 0.5, 3.0);
  return {std::max(far - 1.0, 2.5), far};
}

// The first `length_m` metres of the commands' driving (all of it when length_m is 0).
std::vector<nav::DriveCommand> first_metres(std::span<const nav::DriveCommand> commands,
                                            double length_m) {
  std::vector<nav::DriveCommand> kept;
  double left = length_m > 0.0 ? length_m : std::numeric_limits<double>::infinity();
  for (const nav::DriveCommand& command : commands) {
    if (left <= 0.0)
      break;
    kept.push_back({command.turn_deg, std::min(command.distance_m, left)});
    left -= command.distance_m;
  }
  return kept;
}

class Loop {
public:
  Loop(const TraverseSettings& s, const world::Terrain& terrain, const CycleView& view)
      : s_(s), course_(s, terrain), computer_(computer_for(s)), view_(view),
        odometry_(start_of(s), s.slip, s.seed), hazards_(std::max(1, s.hazard_memory_cycles)),
        recall_radius_m_(unseen_start_radius(course_.rig, s.chassis) +
                         imaging::footprint_reach_m(s.chassis)) {
    result_.settings = s;
    result_.start = start_of(s);
    result_.goal = Eigen::Vector2d(0.5 * s.goal_m, 0.0);
    pose_ = result_.start;
    limits_ = {s.emergency_tilt_deg, s.tilt_limit_deg, s.read_every_m, result_.goal,
               s.goal_tolerance_m};
  }

  TraverseResult run(const TraverseProgress& progress) {
    nav::MotionAction action = nav::initial_motion_action(s_.motion);
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
  // What the rover steers by: the goal as seen from where the odometry says it is.
  Eigen::Vector2d goal_from_estimate() const {
    const world::RoverPose& e = odometry_.estimate();
    return result_.goal - Eigen::Vector2d(e.x, e.y);
  }

  TraverseResult finish(TraverseOutcome outcome) {
    result_.outcome = outcome;
    result_.end = pose_;
    result_.goal_left_m = goal_left();
    result_.estimate = odometry_.estimate();
    return std::move(result_);
  }

  // Drives on the true ground and books it.
  GroundDrive drive(std::span<const nav::DriveCommand> commands, TraverseCycle& cycle) {
    // The wheels turn through each commanded length; the ground gives `factor` of it.
    const double factor = odometry_.next_drive_factor();
    std::vector<nav::DriveCommand> on_ground(commands.begin(), commands.end());
    for (nav::DriveCommand& command : on_ground)
      command.distance_m *= factor;
    const GroundDrive drive =
        drive_on_ground(course_.terrain, pose_, on_ground, s_.chassis, limits_);
    odometry_.book(pose_, drive.end, factor);
    pose_ = drive.end;
    cycle.slip = 1.0 - factor;
    cycle.driven_m += drive.driven_m;
    cycle.track.insert(cycle.track.end(), drive.track.begin(), drive.track.end());
    result_.distance_m += drive.driven_m;
    result_.driving_seconds +=
        drive.driven_m / factor / s_.drive_speed_m_s + drive.turned_deg / s_.turn_rate_deg_s;
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
    options.zones.step_baseline_m = s_.step_baseline_m;
    options.footprint.unseen_cell_m = s_.unseen_cell_m;
    const world::RoverPose& believed = odometry_.estimate();
    const imaging::PlanarPose at{believed.x, believed.y, believed.heading_deg / kDegreesPerRadian};
    if (s_.hazard_memory_cycles > 0) {
      recalled_ = hazards_.recall(at, recall_radius_m_);
      options.footprint.remembered = recalled_;
    }
    const Eigen::Vector2d to_goal = goal_from_estimate();
    const auto [near, far] = target_range(action, to_goal.norm());
    options.planner.target_min_m = near;
    options.planner.target_max_m = far;
    options.planner.heading_deg =
        wrap_deg(std::atan2(to_goal.y(), to_goal.x()) * kDegreesPerRadian -
                 odometry_.estimate().heading_deg);
    const auto started = std::chrono::steady_clock::now();
    nav::NavigationResult nav = computer_
                                    ? emulate(pair, options, cycle)
                                    : nav::navigate(pair.left, pair.right, course_.rig, options);
    cycle.host_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (s_.hazard_memory_cycles > 0)
      hazards_.remember(nav.terrain, nav.zones, at);
    result_.host_seconds += cycle.host_seconds;
    if (view_)
      view_(cycle.index, pair.left, nav);
    return nav;
  }

  nav_program::CycleEmulation unsupervised(const nav_program::CycleInput& input) const {
    nav_program::CycleSetup setup;
    setup.platform = &computer_->platform;
    setup.placement = &computer_->placement;
    return nav_program::emulate_navigation_cycle(input, setup);
  }

  // The cycle under the overswitch, the course's fault striking when this is its cycle.
  nav_program::CycleEmulation struck(const TraverseFaults& faults,
                                     const nav_program::CycleInput& input, TraverseCycle& cycle) {
    std::optional<TraverseFault> met;
    nav_program::CycleEmulation run = faults.run(input, cycle.index, met);
    if (met) {
      cycle.events.push_back(fmt::format("fault: {}: {}, {} failover{}, {:.1f} s lost", met->fault,
                                         met->outcome, met->failovers,
                                         met->failovers == 1 ? "" : "s", met->time_lost_s));
      result_.faults.push_back(*met);
    }
    return run;
  }

  // The cycle on the emulated computer; its emulated time is mission time.
  nav::NavigationResult emulate(const world::StereoImages& pair,
                                const nav::NavigationOptions& options, TraverseCycle& cycle) {
    nav_program::CycleInput input{pair.left, pair.right, &course_.rig, options, {}};
    const nav_program::CycleEmulation run =
        computer_->faults ? struck(*computer_->faults, input, cycle) : unsupervised(input);
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
    const nav::MotionStep next = nav::next_motion_step(status_, event, s_.motion);
    status_ = next.status;
    return next;
  }

  // One cycle: the action's turn, then plan (and drive) or hand over.
  std::optional<TraverseOutcome> run_cycle(nav::MotionAction& action, TraverseCycle& cycle) {
    cycle.start = pose_;
    cycle.estimate = odometry_.estimate();
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
    book_zones(placement, nav, kTraverseMapCellM, cycle);
    action = step({nav.found() ? nav::MotionEventKind::path_found : nav::MotionEventKind::no_path})
                 .action;
    if (action.then != nav::MotionAction::Then::drive)
      return std::nullopt;
    const GroundDrive driven = drive(first_metres(nav.drive.commands, s_.drive_m), cycle);
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
  Odometry odometry_;
  nav::HazardMemory hazards_;
  double recall_radius_m_;
  std::vector<nav::GroundPoint> recalled_; ///< the points the cycle's options point at
  world::RoverPose pose_;
  GroundDriveLimits limits_;
  nav::MotionStatus status_;
};

} // namespace

world::TerrainSettings traverse_site(const TraverseSettings& s) {
  validate(s);
  world::TerrainSettings site;
  site.seed = s.seed;
  site.rock_cover = s.rocks;
  site.regional_slope_deg = s.slope_deg;
  site.size_m = s.goal_m + 2.0 * kSiteMarginM;
  site.width_m = kSiteWidthM;
  site.clear_centre = Eigen::Vector2d(start_of(s).x, start_of(s).y);
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
