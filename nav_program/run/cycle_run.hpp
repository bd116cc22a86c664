// CycleRun: the program started on a network, restarted or abandoned on a supervisor's word
// (private to the layer).
#pragma once

#include "processes/cycle_state.hpp"
#include "run/cycle_network.hpp"

#include "marsokhod/nav_program/placement/memory_plan.hpp"
#include "marsokhod/nav_program/run/cycle_supervisor.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace marsokhod::nav_program::detail {

/// One emulated cycle in progress: the network, the program's current run (its state, its
/// placement) and the runs it replaced.
class CycleRun final : public CycleControl {
public:
  /// `trace` (may be null) is set on the kernel before the nodes are made, so that each
  /// declares its tracks.
  CycleRun(const CycleInput& input, const CycleSetup& setup, const emulator::PlatformSpec& platform,
           const MemoryPlan& plan, emulator::TraceSink* trace);
  CycleRun(const CycleRun&) = delete;
  CycleRun& operator=(const CycleRun&) = delete;

  /// Loads the code and starts the processes; false after a memory fault doing so.
  bool start();
  CycleNetwork& network() { return net_; }
  CycleState& state() { return *states_.back(); }
  const Placement& placement() const { return placement_; }
  int restarts() const { return restarts_; }
  const std::vector<ModuleHalt>& halts() const { return halts_; }
  bool finished() const { return finished_; }
  const std::optional<std::string>& abandoned() const { return abandoned_; }

  // CycleControl
  emulator::Kernel& kernel() override { return net_.kernel; }
  const emulator::PlatformSpec& platform() const override { return *platform_; }
  emulator::LinkNetwork& links() override { return *net_.links; }
  emulator::Node& node(const std::string& name) override { return net_.node(name); }
  emulator::SharedOutput* device_output(const std::string& node) override;
  void on_heartbeat(std::function<void(const std::string& node)> sink) override;
  void on_link_trouble(
      std::function<void(const std::string& node, int link, LinkTrouble trouble)> sink) override;
  std::size_t code_bytes(const std::string& node) const override;
  const std::string& node_of(const std::string& process) const override;
  void restart(const std::map<std::string, std::string>& moved) override;
  void halt(const std::string& node, const std::string& what, const std::string& cause) override;
  void abandon(const std::string& why) override;
  bool program_finished() const override { return finished_; }
  /// When the program's last process ended; 0 if it has not.
  emulator::Tick finished_at() const { return finished_at_; }

private:
  void new_state();
  void place_channels();
  void spawn_processes();
  void kill_program();
  void reset_device_link(const std::string& node);
  /// Both ends of every link the program's channels are placed on.
  void reset_channel_links();
  void report_trouble(emulator::LinkPort& port, LinkTrouble trouble);
  void process_ended();
  void halt_on_error(emulator::Node& node, CycleState& cycle, ModuleHalt halt);
  /// Places a copy of the mission state record in `node`'s memory; false after a memory fault.
  bool hold_mission(emulator::Node& node, std::span<const std::byte> record);
  void take_mission_from_survivor(const std::string& failed, const std::string& spare);

  const CycleInput* input_;
  const CycleSetup* setup_;
  const emulator::PlatformSpec* platform_;
  const MemoryPlan* plan_;
  Placement placement_;
  /// The node of the plan each node now running the program stands for.
  std::map<std::string, std::string> roles_;
  std::vector<std::unique_ptr<CycleState>> states_;
  int restarts_ = 0;
  bool finished_ = false;
  bool killing_ = false;
  emulator::Tick finished_at_ = 0;
  std::vector<ModuleHalt> halts_;
  std::map<std::string, emulator::Address> mission_blocks_;
  std::optional<std::string> abandoned_;
  CycleNetwork net_; // last: its nodes, and the processes on them, go first
};

} // namespace marsokhod::nav_program::detail
