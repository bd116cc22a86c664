// The navigation program's processes from image acquisition to telemetry, the stereo half aside.

#include "processes/mission_record.hpp"
#include "processes/node_terrain.hpp"
#include "processes/process_bodies.hpp"

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/emulator/links/link_frame_store.hpp"
#include "marsokhod/emulator/links/shared_output.hpp"
#include "marsokhod/nav/cycle/motion_scheme.hpp"

#include <fmt/format.h>

#include <array>
#include <cstring>
#include <stdexcept>

namespace marsokhod::nav_program::detail {
namespace {

/// The plan's fixed part, as the path process hands it to drive and drive to telemetry.
struct PlanHeader {
  std::int32_t found = 0;
  nav::PixelPoint start;
  nav::PixelPoint target;
  double cost = 0.0;
  double score = 0.0;
};

// Header and payload in one turn at the shared device output, so that no heartbeat byte
// comes between them.
void upload(ProcessContext& c, std::span<const std::byte> payload) {
  std::array<std::byte, 5> header{emulator::FrameStore::kUploadRequest};
  for (std::size_t i = 0; i < 4; ++i)
    header[1 + i] = std::byte(static_cast<unsigned char>(payload.size() >> (8 * i)));
  emulator::Node& node = c.node();
  c.device_output().output({header, payload},
                           [&node] { node.execute(emulator::Instruction::out); });
}

/// The mission state as this process's module holds it (read, not charged: a few words).
MissionState held_mission(ProcessContext& c) {
  const auto& blocks = c.cycle().mission_blocks;
  const auto block = blocks.find(c.node().name());
  if (block == blocks.end())
    throw std::logic_error("node " + c.node().name() + " holds no mission state");
  const std::byte* record = c.node().memory().pointer(block->second);
  return decode_mission(
      std::span<const std::byte, kMissionRecordBytes>(record, kMissionRecordBytes));
}

/// The planner's options for the motion scheme's state: a short path (escape range) after an
/// emergency, the normal range otherwise (paper, section 3).
nav::PlannerOptions planner_for(ProcessContext& c) {
  nav::PlannerOptions options = c.cycle().options.planner;
  if (held_mission(c).motion.state != nav::MotionState::escape_planning)
    return options;
  const nav::MotionConfig scheme;
  options.target_min_m = scheme.escape_min_m;
  options.target_max_m = scheme.escape_max_m;
  return options;
}

} // namespace

// ---- the processes ----

void acquire(ProcessContext& c) {
  CycleState& s = c.cycle();
  c.start_stage();
  emulator::LinkPort& port = c.device_port();
  for (int camera = 0; camera < 2; ++camera) {
    c.doing(image_what(camera == 0 ? "left image" : "right image", s.width, s.height, 1));
    U8Image image(s.width, s.height, 1, 0, c.memory());
    const std::byte request{static_cast<unsigned char>(camera)};
    c.node().execute(emulator::Instruction::out);
    c.device_output().output(std::span(&request, 1));
    c.node().execute(emulator::Instruction::in);
    port.input(std::as_writable_bytes(std::span(image.data(), image.size())));
    send_image<std::uint8_t>(s.channels.images, image.view());
  }
}

void range(ProcessContext& c) {
  CycleState& s = c.cycle();
  {
    const std::string reason = receive_text(s.channels.disparity, c.memory());
    const FloatImage seeable = receive_floats(c, s.channels.disparity, "seeable disparity");
    c.start_stage();
    const U8Image valid = receive_bytes(c, s.channels.disparity, "validity", s.width, s.height);
    await_hand_over(s.channels.disparity);
    send_text(s.channels.terrain, reason);
    make_and_send_terrain(c, seeable, s.channels.terrain);
    send_image<std::uint8_t>(s.channels.terrain, valid.view());
  }
  close_hand_over(s.channels.terrain);
}

namespace {

// The zones of the terrain; the validity they take goes before the hand-over to path.
nav::ZoneMap zone_map(ProcessContext& c, const nav::TerrainRows& terrain) {
  CycleState& s = c.cycle();
  const U8Image valid = receive_bytes(c, s.channels.terrain, "validity", s.width, s.height);
  await_hand_over(s.channels.terrain);
  const std::size_t grid_bytes = s.plan->zone_grid_bytes;
  c.doing(grid_bytes > 0 ? fmt::format("prohibited zones: a strip of the ground grid "
                                       "(at most {} B) and the zone map",
                                       grid_bytes)
                         : std::string("prohibited zones: ground grid and zone map"));
  return nav::find_zones(terrain, valid, s.options.zones, c.meter(), c.memory(),
                         nav::ZoneStrips{0, grid_bytes, &c.recompute_meter()});
}

} // namespace

void zones(ProcessContext& c) {
  CycleState& s = c.cycle();
  {
    const std::string reason = receive_text(s.channels.terrain, c.memory());
    const NodeTerrain terrain(c, s.channels.terrain);
    c.start_stage();
    const nav::ZoneMap zones = zone_map(c, terrain.rows());
    s.products.zones = zones;
    send_text(s.channels.zones, reason);
    terrain.send(s.channels.zones);
    send_image<std::uint8_t>(s.channels.zones, zones.zone.view());
    send_value(s.channels.zones, zones.counts);
  }
  close_hand_over(s.channels.zones);
}

void path(ProcessContext& c) {
  CycleState& s = c.cycle();
  const std::string reason = receive_text(s.channels.zones, c.memory());
  const NodeTerrain terrain(c, s.channels.zones);
  c.start_stage();
  nav::ZoneMap zones{U8Image(c.memory()), {}};
  zones.zone = receive_bytes(c, s.channels.zones, "zone map", s.width, s.height);
  zones.counts = receive_value<decltype(zones.counts)>(s.channels.zones);
  await_hand_over(s.channels.zones);
  c.doing("safest path: row sweep costs and steps");
  nav::PathPlan plan = nav::plan_cycle_path(terrain.rows(), zones, planner_for(c), s.options.drive,
                                            s.options.footprint, c.meter(), c.memory());
  nav::explain_stereo_failure(reason, plan);
  std::pmr::vector<nav::GroundPoint> ground(c.memory());
  if (plan.found) {
    c.doing(fmt::format("ground path, {} points x 16 B", plan.pixels.size()));
    ground = nav::ground_path(terrain.rows(), plan.pixels, c.memory());
  }
  s.products.plan = plan;
  send_value(s.channels.path,
             PlanHeader{plan.found ? 1 : 0, plan.start, plan.target, plan.cost, plan.score});
  send_text(s.channels.path, plan.reason);
  send_list<nav::PixelPoint>(s.channels.path, plan.pixels);
  send_list<nav::GroundPoint>(s.channels.path, ground);
}

void drive(ProcessContext& c) {
  CycleState& s = c.cycle();
  const auto header = receive_value<PlanHeader>(s.channels.path);
  c.start_stage();
  const std::string reason = receive_text(s.channels.path, c.memory());
  c.doing("path pixels");
  const auto pixels = receive_list<nav::PixelPoint>(s.channels.path, c.memory());
  c.doing("ground path");
  const auto ground = receive_list<nav::GroundPoint>(s.channels.path, c.memory());
  nav::DrivePlan plan{std::pmr::vector<nav::GroundPoint>(c.memory()),
                      std::pmr::vector<nav::GroundPoint>(c.memory()),
                      0.0,
                      std::pmr::vector<double>(c.memory()),
                      0.0,
                      std::pmr::vector<nav::DriveCommand>(c.memory())};
  if (header.found != 0) {
    c.doing("drive plan: polyline and commands");
    plan = nav::plan_drive(ground, s.options.drive, c.memory());
  }
  s.products.drive = plan;
  send_value(s.channels.commands, header.found);
  send_list<nav::DriveCommand>(s.channels.commands, plan.commands);
  send_value(s.channels.plan_out, header);
  send_list<nav::PixelPoint>(s.channels.plan_out, pixels);
  send_list<nav::DriveCommand>(s.channels.plan_out, plan.commands);
}

// The paper's motion scheme at high priority: it takes the cycle's answer and tells the
// wheels what to do, before any low-priority work on its node goes on.
void motion(ProcessContext& c) {
  CycleState& s = c.cycle();
  const auto found = receive_value<std::int32_t>(s.channels.commands);
  c.start_stage();
  c.doing("drive commands");
  const auto commands = receive_list<nav::DriveCommand>(s.channels.commands, c.memory());
  const MissionState before = held_mission(c);
  const nav::MotionStep step = nav::next_motion_step(
      before.motion, nav::MotionEvent{found != 0 ? nav::MotionEventKind::path_found
                                                 : nav::MotionEventKind::no_path,
                                      nav::Side::left});
  std::pmr::vector<nav::DriveCommand> wheels(c.memory());
  if (step.action.turn_deg != 0.0)
    wheels.push_back({step.action.turn_deg, 0.0});
  if (step.action.then == nav::MotionAction::Then::drive)
    wheels.insert(wheels.end(), commands.begin(), commands.end());
  s.mission_after = mission_after(before, step.status, wheels);
  send_value(s.channels.wheels, static_cast<std::int32_t>(step.status.state));
  send_list<nav::DriveCommand>(s.channels.wheels, wheels);
}

void telemetry(ProcessContext& c) {
  CycleState& s = c.cycle();
  const auto header = receive_value<PlanHeader>(s.channels.plan_out);
  c.start_stage();
  c.doing("telemetry: path pixels");
  const auto pixels = receive_list<nav::PixelPoint>(s.channels.plan_out, c.memory());
  c.doing("telemetry: drive commands");
  const auto commands = receive_list<nav::DriveCommand>(s.channels.plan_out, c.memory());
  upload(c, bytes_of(header));
  upload(c, std::as_bytes(std::span(pixels)));
  upload(c, std::as_bytes(std::span(commands)));
  const auto state = receive_value<std::int32_t>(s.channels.wheels);
  c.doing("telemetry: wheel commands");
  const auto wheels = receive_list<nav::DriveCommand>(s.channels.wheels, c.memory());
  upload(c, bytes_of(state));
  upload(c, std::as_bytes(std::span(wheels)));
}

void await_hand_over(BlockChannel& channel) {
  if (receive_value<std::int32_t>(channel) != kHandOverClosed)
    throw std::logic_error(
        fmt::format("{}: a hand-over did not end where its receiver expected", channel.name()));
}

} // namespace marsokhod::nav_program::detail
