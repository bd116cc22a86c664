// The hook through which a layer above (the overswitch) watches and steers an emulated cycle.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/links/link_network.hpp"
#include "marsokhod/emulator/links/shared_output.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav_program/channels/link_guard.hpp"

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace marsokhod::nav_program {

/// What a supervisor may see and do in a running cycle; the cycle implements it.
class CycleControl {
public:
  virtual ~CycleControl() = default;

  virtual emulator::Kernel& kernel() = 0;
  virtual const emulator::PlatformSpec& platform() const = 0;
  virtual emulator::LinkNetwork& links() = 0;
  /// std::out_of_range for a node the platform does not have.
  virtual emulator::Node& node(const std::string& name) = 0;
  /// The output of a node's device link, which the program's processes share; nullptr for a
  /// node without one.
  virtual emulator::SharedOutput* device_output(const std::string& node) = 0;
  /// `sink` receives the name of the node whose heartbeat byte reached a device link.
  virtual void on_heartbeat(std::function<void(const std::string& node)> sink) = 0;
  /// `sink` receives each link trouble a process reported over its device link: the node, its
  /// link and what went wrong.
  virtual void on_link_trouble(
      std::function<void(const std::string& node, int link, LinkTrouble trouble)> sink) = 0;
  /// The bytes a spare taking `node`'s place must be booted with: the program's code on it and
  /// the mission state record; 0 for a node that runs none of the program.
  virtual std::size_t code_bytes(const std::string& node) const = 0;
  /// The node that runs `process` now.
  virtual const std::string& node_of(const std::string& process) const = 0;

  /// Starts the cycle again from its first process, at once: kills the program's processes on
  /// every node, resets the device links of the nodes that run it and both ends of the links its
  /// channels used, and starts them with every process of a node named in `moved` placed on its
  /// replacement (`moved` empty: on the same nodes). The replacement must be running and hold the
  /// code (booted); channels go on the wires joining the new nodes.
  virtual void restart(const std::map<std::string, std::string>& moved) = 0;
  /// Halts `node` at once, as HaltOnError does on an error the hardware flags (the EDAC's
  /// uncorrectable error): its processes stop and its links go silent; the halt is reported
  /// with the cycle's others. Only from an event.
  virtual void halt(const std::string& node, const std::string& what, const std::string& cause) = 0;
  /// Ends the cycle unfinished (a safe stop): kills the program's processes and stops the run.
  virtual void abandon(const std::string& why) = 0;
  /// The program's last process has ended (the cycle is done; a restart makes no sense).
  virtual bool program_finished() const = 0;
};

/// Watches a cycle (CycleSetup::supervisor): told when it can act and how the program goes.
class CycleSupervisor {
public:
  virtual ~CycleSupervisor() = default;
  /// The network is built, the program about to start; the control lives for the whole run.
  virtual void attach(CycleControl& control) = 0;
  /// How the program guards its messages on links (asked once, before the program starts).
  virtual LinkGuard link_guard() const { return {}; }
  /// Whether the program checks the terrain it keeps after range: range sends a word sum of
  /// each row with it, and a process rebuilding a row whose sum no longer checks stops with a
  /// run-time error (asked as the program starts).
  virtual bool check_terrain() const { return false; }
  /// A process of the program had its input and starts its stage (after a restart, again).
  virtual void stage_started(const std::string& /*process*/, emulator::Tick /*at*/) {}
  /// The program's last process has ended. The run goes on while anything is left to happen
  /// (the last bytes on the links, and whatever the supervisor keeps going: it should wind its
  /// own processes and events down, at once or once it has seen what it still waits for).
  virtual void program_finished() {}
  /// The run is over and its network about to go: nothing of it may be touched after this.
  virtual void detach() {}
};

/// An upload a device received (telemetry, the wheel commands): when, from which node.
struct DeviceUpload {
  emulator::Tick time = 0;
  std::string node;
  std::size_t bytes = 0;
};

} // namespace marsokhod::nav_program
