// CycleState and ProcessContext: what the navigation program's processes share and carry.
#pragma once

// The state of one emulated cycle as its processes see it (private to the layer):
// the constants compiled into the program (image size, rig, options), the channels, the
// device links, and the host's side: the products read out of the nodes' memories and the
// figures of the run.

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"
#include "marsokhod/nav_program/channels/block_channel.hpp"
#include "marsokhod/nav_program/costs/emulated_meter.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <map>
#include <memory_resource>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::emulator {
class LinkPort;
class SharedOutput;
} // namespace marsokhod::emulator

namespace marsokhod::nav_program {
class CycleSupervisor;
} // namespace marsokhod::nav_program

namespace marsokhod::nav_program::detail {

struct ProcessSpec;

/// The program's channels, one per arrow of its process diagram (channel_list.def).
struct CycleChannels {
#define MARSOKHOD_CHANNEL(name, from, to) BlockChannel name{#name};
#include "channels/channel_list.def"

  /// The channel of a ProgramShape entry; nullptr for an unknown name.
  BlockChannel* named(std::string_view name);
};

struct CycleState {
  int width = 0;
  int height = 0;
  const imaging::StereoRig* rig = nullptr;
  nav::NavigationOptions options;
  /// The memory plan the program was built to: whether the processes after range keep the
  /// terrain's four maps, and the zones' ground grid budget.
  const MemoryPlan* plan = nullptr;
  double occam_style = 1.0; ///< CycleSetup::occam_style
  emulator::Kernel* kernel = nullptr;
  CycleChannels channels;
  /// Each node's link to the devices (frame store, host), if it has one; its output is shared
  /// with the heartbeat.
  std::map<std::string, emulator::SharedOutput*> device_outputs;
  /// Where each node running the program holds its copy of the mission state.
  std::map<std::string, emulator::Address> mission_blocks;
  /// Told of each stage's start, when the cycle is supervised.
  CycleSupervisor* supervisor = nullptr;
  /// The program's processes of this run that have not ended, in the order they started.
  std::vector<emulator::Process*> live;
  /// A process of this run was killed (its node hung or lost power): the run cannot finish.
  bool killed = false;

  // The host's side.
  nav::NavigationResult products;
  std::optional<MissionState> mission_after;
  nav::CountingMeter work;
  nav::CountingMeter recomputed_work;
  std::vector<StageFigures> stages;
  std::optional<MemoryFaultFigures> fault;
  std::optional<std::string> error;
};

/// One running process: its node, its meter, and what it is allocating (for fault messages).
class ProcessContext {
public:
  ProcessContext(CycleState& cycle, emulator::Node& node, const ProcessSpec& spec);

  CycleState& cycle() { return *cycle_; }
  emulator::Node& node() { return *node_; }
  const std::string& name() const { return name_; }
  const ProcessSpec& spec() const { return *spec_; }
  /// The meter the nav kernels report to (through the virtual call: they are compiled once).
  nav::DynamicMeter& meter() { return meter_; }
  const EmulatedMeter& emulated_meter() const { return meter_; }
  /// The meter for work done again (terrain rows worked out again): charged on the node like
  /// the other, counted apart.
  nav::DynamicMeter& recompute_meter() { return recompute_meter_; }
  const EmulatedMeter& emulated_recompute_meter() const { return recompute_meter_; }
  std::pmr::memory_resource* memory() { return &node_->memory(); }
  /// Names the buffer or kernel the next allocations are for (in fault messages, and on the
  /// blocks, for reports of upsets).
  void doing(std::string what);
  const std::string& what() const { return what_; }
  /// The stage starts (its input has arrived) / ends.
  void start_stage();
  void end_stage();
  /// The node's link to the devices and its shared output; std::logic_error without one (the
  /// placement checks it).
  emulator::LinkPort& device_port();
  emulator::SharedOutput& device_output();

private:
  CycleState* cycle_;
  emulator::Node* node_;
  const ProcessSpec* spec_;
  std::string name_;
  EmulatedMeter meter_;
  EmulatedMeter recompute_meter_;
  std::string what_;
  std::optional<emulator::Tick> started_;
};

} // namespace marsokhod::nav_program::detail
