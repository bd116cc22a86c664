// Overswitch: the hardware block that decides which two of the four modules are powered.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::overswitch {

/// A platform without an [overswitch] table where one is needed: no module could fail over.
class NoOverswitchError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Throws NoOverswitchError, naming `named_in` (the file or option that chose the platform),
/// when `platform` has no [overswitch] table.
void require_overswitch(const emulator::PlatformSpec& platform, const std::string& named_in);

/// One thing the overswitch did, in the order it did them.
struct OverswitchEvent {
  enum class Kind : std::uint8_t {
    watchdog_expired, ///< a powered module was not kicked for the watchdog's timeout
    powered_off,      ///< the overswitch cut a module's power
    boot_started,     ///< a spare was powered and its boot stream began
    booted,           ///< the spare runs: the pair is whole again
    boot_failed,      ///< the spare did not run within the boot allowance
    safe_stop,        ///< no pair can be formed: the rover stands still, remote control takes over
    link_trouble,     ///< a module reported a link: an output not acknowledged, a bad checksum
    restarted,        ///< the cycle was started again on the same pair (after a link trouble)
    declared_failed,  ///< a module was failed on what its partner reported of their link
  };
  emulator::Tick time = 0;
  Kind kind = Kind::watchdog_expired;
  std::string module;
  std::string detail;
};

const char* to_string(OverswitchEvent::Kind kind);

/// One failover: the module declared failed, the spare taken, and when the spare ran.
struct Failover {
  std::string failed;
  std::string spare; ///< empty when there was no spare or nothing left to boot it from
  std::string booted_from;
  emulator::Tick detected = 0;
  emulator::Tick booted = 0; ///< 0 until the spare runs
  bool ok = false;
};

/// Brings a powered spare up from a running module: starts the boot and later calls `done`
/// with true once the spare runs the program, or never (the overswitch's allowance then fails
/// the boot). Called from an event, not from a process.
using BootFunction =
    std::function<void(emulator::Node& spare, emulator::Node& from, std::function<void()> done)>;

/// The 2-of-4 logic (seed paper: "only two out of four transputer modules are powered at a
/// time. Which two, it is determined by the actual state of the overswitch logic"): a
/// watchdog per powered module, which the module's heartbeat process kicks; a watchdog that
/// runs out powers its module off for good and powers the first spare (the order of the
/// platform's [overswitch] modules), booted from the running partner; with no spare, or no
/// running module to boot one from, a safe stop.
class Overswitch {
public:
  Overswitch(emulator::Kernel& kernel, const emulator::OverswitchSpec& spec,
             std::vector<emulator::Node*> modules, BootFunction boot);
  Overswitch(const Overswitch&) = delete;
  Overswitch& operator=(const Overswitch&) = delete;
  /// The kernel's events die with it: an overswitch outliving its run must not touch them.
  ~Overswitch() = default;

  /// Arms the watchdogs of the modules powered now; call once, before the run.
  void start();
  /// A heartbeat from `module`; ignored unless the module is running (a booting spare's first
  /// kicks come after it runs).
  void kick(const emulator::Node& module);
  /// Disarms every watchdog: the run is over (before its kernel goes).
  void stop();
  /// Fails a running module on what its partner reported (a link between them that keeps
  /// failing): powered off for good and replaced by a spare, as on a watchdog's expiry.
  void declare_failed(const emulator::Node& module, const std::string& why);
  /// Adds an event of the supervisor's to the overswitch's log (a link trouble, a restart).
  void note(OverswitchEvent::Kind kind, const std::string& module, std::string detail);

  /// The running modules, in the overswitch's order.
  std::vector<emulator::Node*> running() const;
  bool safe_stopped() const { return safe_stopped_; }
  const std::vector<OverswitchEvent>& events() const { return events_; }
  const std::vector<Failover>& failovers() const { return failovers_; }

  /// Called once the pair is whole again after a failover (the spare runs).
  void on_booted(std::function<void(const Failover&)> action) { on_booted_ = std::move(action); }
  /// Called when the overswitch gives up: no pair can be formed.
  void on_safe_stop(std::function<void()> action) { on_safe_stop_ = std::move(action); }

private:
  enum class State : std::uint8_t { off, running, booting, failed };
  struct Module {
    emulator::Node* node = nullptr;
    State state = State::off;
    emulator::EventId deadline = 0;
    std::size_t failover = 0; ///< while booting: the failover it serves
  };

  Module& module_of(const emulator::Node& node);
  void arm(Module& m, emulator::Tick after);
  void disarm(Module& m);
  void expire(Module& m);
  void fail(Module& m, const std::string& why);
  void take_spare(Failover failover);
  void booted(Module& spare, std::size_t failover);
  void boot_timed_out(Module& spare, std::size_t failover);
  void safe_stop(const std::string& why);
  void log(OverswitchEvent::Kind kind, const Module& m, std::string detail);

  emulator::Kernel* kernel_;
  emulator::OverswitchSpec spec_;
  std::vector<Module> modules_;
  BootFunction boot_;
  bool safe_stopped_ = false;
  bool stopped_ = false; ///< stop(): kicks arm nothing any more
  std::vector<OverswitchEvent> events_;
  std::vector<Failover> failovers_;
  std::function<void(const Failover&)> on_booted_;
  std::function<void()> on_safe_stop_;
};

} // namespace marsokhod::overswitch
