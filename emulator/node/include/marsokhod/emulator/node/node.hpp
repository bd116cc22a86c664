// A T805 node: CPU cost model, two priorities, timers, memory and link ports.
#pragma once

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/memory/memory_arena.hpp"
#include "marsokhod/emulator/memory/memory_upsets.hpp"
#include "marsokhod/emulator/node/cost_table.hpp"
#include "marsokhod/emulator/node/cpu.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace marsokhod::emulator {

class Link;
class LinkPort;

/// How to start a process on a node.
struct NodeSpawnOptions {
  Priority priority = Priority::low;
  /// Host stack bytes (0: the kernel's default).
  std::size_t stack_bytes = 0;
  /// Emulated workspace charged to the node's memory for the process's lifetime (0: none).
  std::size_t workspace_bytes = 0;
  ExitHook* exit_hook = nullptr;
};

/// One T805 transputer: a CPU with two priorities and the data-book cost model, on-chip and
/// external memory, four link ports, and a power switch.
class Node {
public:
  static constexpr int kLinks = 4;

  Node(Kernel& kernel, const NodeSpec& spec);
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;
  ~Node();

  const std::string& name() const { return spec_.name; }
  const NodeSpec& spec() const { return spec_; }
  const CpuSpec& cpu_spec() const { return spec_.cpu; }
  Kernel& kernel() const { return *kernel_; }
  /// Unique among all nodes created by this program (never 0, never reused, unlike an
  /// address): a key for values derived from the node's spec and cached elsewhere.
  std::uint64_t serial() const { return serial_; }
  Cpu& cpu() { return *cpu_; }
  MemoryArena& memory() { return *memory_; }
  /// Upsets and stuck bits in the node's memory, and its EDAC.
  MemoryUpsets& upsets() { return *upsets_; }

  /// The node of the process executing now; std::logic_error outside a process on a node.
  static Node& current() {
    const Kernel* kernel = Kernel::active();
    const Process* p = kernel != nullptr ? kernel->current() : nullptr;
    if (p == nullptr || p->cpu().node() == nullptr)
      no_current_node();
    return *p->cpu().node();
  }

  // --- CPU model --------------------------------------------------------------------------
  Tick cycles(std::uint64_t n) const { return static_cast<Tick>(n) * spec_.cpu.cycle; }
  std::uint64_t cycles_of(const InstructionMix& mix) const { return spec_.cpu.costs.cycles(mix); }
  /// Charges the current process (which must run on this node) for the mix: one compute chunk.
  void compute(const InstructionMix& mix);
  void compute_cycles(std::uint64_t n) { consume(cycles(n)); }
  /// Charges the current process `time` of computing. A stuck memory cell undoes whatever the
  /// computing wrote to it, so it is forced back first.
  void consume(Tick time) {
    if (upsets_->has_stuck())
      upsets_->reassert_stuck();
    kernel_->consume(time);
  }
  /// Charges `times` executions of one instruction with `units_each` (words, bits).
  void execute(Instruction instruction, std::uint64_t times = 1, std::uint64_t units_each = 0) {
    const InstructionCost& cost = spec_.cpu.costs[instruction];
    compute_cycles(times * static_cast<std::uint64_t>(cost.base) +
                   times * units_each * static_cast<std::uint64_t>(cost.per_unit));
  }
  /// Timer period of a priority (1 us high, 64 us low on a T805).
  Tick timer_period(Priority priority) const;

  // --- processes --------------------------------------------------------------------------
  Process& spawn(std::string name, std::function<void()> body, NodeSpawnOptions options = {});

  // --- links ------------------------------------------------------------------------------
  /// Connects link `index` (0..3) of this node to end `end` of `link`.
  void attach_link(int index, Link& link, int end);
  /// The port of link `index`, nullptr when unconnected.
  LinkPort* link(int index) const;

  // --- power ------------------------------------------------------------------------------
  bool powered() const { return powered_; }
  /// Powered, and neither hung nor off: its processes run and its links answer.
  bool running() const { return powered_ && !hung_; }
  /// Kills every process (their destructors run) and stops the link engines. Not from a
  /// process of this node.
  void power_off();
  /// Restarts the link engines; processes must be started again (as after a reset). Clears a
  /// hang.
  void power_on();
  /// A hung module: the CPU stops for good (its processes never run again) and its links stop
  /// acknowledging, but it stays powered until power_off(). Not from a process of this node.
  void hang();
  bool hung() const { return hung_; }

private:
  [[noreturn]] static void no_current_node();

  struct Attachment {
    Link* link = nullptr;
    int end = 0;
  };

  Kernel* kernel_;
  std::uint64_t serial_;
  NodeSpec spec_;
  std::unique_ptr<Cpu> cpu_;
  std::unique_ptr<MemoryArena> memory_;
  std::unique_ptr<MemoryUpsets> upsets_;
  std::array<Attachment, kLinks> links_{};
  bool powered_ = true;
  bool hung_ = false;
  TrackId events_track_ = 0;
};

} // namespace marsokhod::emulator
