// The Marsokhod navigation program as OCCAM processes on an emulated transputer network.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/emulator/trace/trace_sink.hpp"
#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/cycle/motion_scheme.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav/work/work.hpp"
#include "marsokhod/nav_program/costs/work_costs.hpp"
#include "marsokhod/nav_program/placement/memory_plan.hpp"
#include "marsokhod/nav_program/placement/placement.hpp"
#include "marsokhod/nav_program/run/cycle_supervisor.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::nav_program {

/// The processes, channels and device uses of the navigation program, in the order the
/// program starts them; what a placement file is checked against.
const ProgramShape& navigation_program_shape();

/// The program's default placement on `platform` (default_placement_file), checked against
/// navigation_program_shape(). Throws PlacementError.
Placement load_program_placement(const emulator::PlatformSpec& platform);

/// What the program keeps from one cycle to the next (docs/faults.md, "State across cycles"):
/// the motion scheme's status, the rover's pose by dead reckoning from the wheel commands, and
/// the uploads sent so far. Every module running the program holds a copy in its memory; a
/// spare gets the survivor's with its boot stream, so that a restarted cycle goes on from it.
struct MissionState {
  nav::MotionStatus motion;
  double x_m = 0.0;
  double y_m = 0.0;
  double heading_deg = 0.0; ///< counter-clockwise from the first cycle's forward axis
  std::uint32_t uploads = 0;
  friend bool operator==(const MissionState&, const MissionState&) = default;
};

/// The mission state as the modules hold it: an occam record of INT32 state, REAL32 turned,
/// INT32 turn sign, REAL32 x, y and heading, INT32 uploads and INT32 check (an XOR of the
/// others, so that a copy struck by an upset is refused rather than driven on).
inline constexpr std::size_t kMissionRecordBytes = 32;

/// What one cycle is run on: the pair (the reference left image and the right one, of the
/// rig's size), the rig, the options of `marsokhod nav`, and the mission state the last cycle
/// left.
struct CycleInput {
  imaging::ImageView<const std::uint8_t> left;
  imaging::ImageView<const std::uint8_t> right;
  const imaging::StereoRig* rig = nullptr;
  nav::NavigationOptions options;
  MissionState mission;
};

/// Where the cycle runs: a platform, which process runs on which node, and what-if changes.
struct CycleSetup {
  const emulator::PlatformSpec* platform = nullptr;
  const Placement* placement = nullptr;
  /// Replaces every node's external memory (what-if runs, `emulate --external-kb`).
  std::optional<std::size_t> external_bytes;
  /// Receives the run's trace when set.
  emulator::TraceSink* trace = nullptr;
  /// The cycles of the program's occam over the cost table's (kOccamStyleFactor, fitted).
  double occam_style = kOccamStyleFactor;
  /// Watches and steers the run (the overswitch); it then ends when the program's last
  /// process does, when the supervisor abandons it, or at `time_limit`.
  CycleSupervisor* supervisor = nullptr;
  std::optional<emulator::Tick> time_limit;
};

/// The steps of the paper's cycle a process belongs to: stereo reconstruction (acquisition to
/// the seeable disparity), the terrain (range, elevation and prohibited zones), path planning
/// (the safest path and its drive commands), execution (the motion scheme and telemetry).
enum class StageGroup : std::uint8_t { stereo, terrain, planning, execution };

/// One stage of the cycle: from the moment its process had its input to the moment it had
/// handed on its output.
struct StageFigures {
  std::string name;
  StageGroup group = StageGroup::stereo;
  emulator::Tick start = 0;
  emulator::Tick end = 0;
};

/// One process: where it ran, the CPU time it held and its memory high-water mark.
struct ProcessFigures {
  std::string name;
  std::string node;
  emulator::Tick cpu = 0;
  std::size_t peak_bytes = 0;
};

/// One node: how busy its CPU was over the cycle and its memory high-water mark.
struct NodeFigures {
  std::string name;
  bool powered = true;
  emulator::Tick busy = 0;
  std::size_t peak_bytes = 0;
  std::size_t memory_bytes = 0; ///< on-chip plus external
};

/// One direction of a link that carried something.
struct LinkFigures {
  std::string from; ///< "module0.link0"
  std::string to;
  std::uint64_t bytes = 0;
  emulator::Tick busy = 0;
};

/// A node's memory ran out: who asked, for what and how much.
struct MemoryFaultFigures {
  std::string node;
  std::string process;
  std::size_t requested_bytes = 0;
  std::string what; ///< "disparity, 128 rows x 128 px x 4 B"
  std::size_t free_bytes = 0;
  std::size_t largest_free_block = 0;
  emulator::Tick time = 0; ///< when the request failed
};

/// "memory fault on module1: process zones wanted 65536 B for terrain forward, ...; N B were
/// free, the largest free block N B".
std::string describe(const MemoryFaultFigures& fault);

/// A module halted on an error, as a T805 with HaltOnError set does (only under a supervisor):
/// a memory fault, a run-time error of a process (a range check, a channel protocol broken by
/// corrupted data), or an uncorrectable memory error its EDAC flagged.
struct ModuleHalt {
  std::string node;
  std::string process; ///< empty when no process raised it (the EDAC)
  std::string what;    ///< the buffer or kernel the process was at, or the word
  std::string cause;   ///< "memory fault: ...", "run-time error: ...", "EDAC: ..."
  emulator::Tick time = 0;
};

/// Everything one emulated cycle produced and measured.
struct CycleEmulation {
  /// From the cycle's start to the last process's end (or to the fault, the safe stop or the
  /// time limit).
  emulator::Tick emulated = 0;
  double occam_style = 0.0; ///< CycleSetup::occam_style, as run
  std::vector<StageFigures> stages;
  std::vector<ProcessFigures> processes;
  std::vector<NodeFigures> nodes;
  std::vector<LinkFigures> links;
  MemoryPlan plan;
  std::optional<MemoryFaultFigures> memory_fault;
  /// Under a supervisor an error does not end the run: the module halts, as a T805 with
  /// HaltOnError set does, and its watchdog takes over. Each such halt, in order.
  std::vector<ModuleHalt> halts;
  /// The cycle's products, read out of the nodes' memories as a debugger would (not charged);
  /// absent after a memory fault.
  std::optional<nav::NavigationResult> result;
  /// Work the nav kernels reported inside the emulation.
  nav::CountingMeter work;
  /// The work done again because a node could not keep its result: the terrain rows the zones
  /// and the path work out again from the disparity. Not in `work`, which equals the native
  /// cycle's.
  nav::CountingMeter recomputed_work;
  /// What reached the host or ground link: the path and the drive commands, then the wheel
  /// commands the motion scheme gave, each upload as the device received it.
  std::vector<std::vector<std::byte>> telemetry;
  /// When each upload reached its device, and from which node.
  std::vector<DeviceUpload> uploads;
  /// Times a supervisor started the program again (after a failover).
  int restarts = 0;
  /// The program's last process ended (false when abandoned, cut by the time limit, or faulted).
  bool finished = false;
  /// The mission state the cycle leaves for the next one (after the finished run).
  std::optional<MissionState> mission_after;
  /// Why a supervisor abandoned the cycle, if it did.
  std::optional<std::string> abandoned;
  std::uint64_t context_switches = 0;
};

/// Runs one navigation cycle on the emulated network: image acquisition from the frame store
/// (or the host) over a link, features and pyramid, matching layer by layer, range and
/// elevation, prohibited zones, safest path, drive commands, the motion scheme at high
/// priority and telemetry, each an OCCAM process on the node its placement names, their buffers
/// from that node's memory. A memory fault ends the run cleanly (memory_fault set). The
/// products are from the run that finished (after any restart); absent if none did. Throws
/// std::invalid_argument for images that do not fit the rig or bad options; the placement must
/// come from load_placement for this platform and navigation_program_shape().
CycleEmulation emulate_navigation_cycle(const CycleInput& input, const CycleSetup& setup);

} // namespace marsokhod::nav_program
