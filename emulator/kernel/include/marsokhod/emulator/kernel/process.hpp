// A simulated process: its state, priority, what it waits for, and its fiber.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace marsokhod::emulator {

class Cpu;
class Kernel;
class Process;

/// Transputer process priority: high runs until it blocks; low is timesliced.
enum class Priority : std::uint8_t { high = 0, low = 1 };

/// Life cycle of a simulated process.
enum class ProcessState : std::uint8_t {
  ready,    ///< queued on its CPU
  running,  ///< holds its CPU (executing host code, or consuming simulated time)
  blocked,  ///< waiting for wake() (channel, timer, ALT, PAR join, link)
  finished, ///< body returned or was killed
};

/// What a blocked process waits for; the deadlock report prints it.
enum class WaitKind : std::uint8_t {
  none,
  channel_input,
  channel_output,
  timer,
  alt,
  par_join,
  link_input,
  link_output,
  other,
};

const char* to_string(WaitKind kind);

/// Anything a process can wait on; asked for a description only when a report is written,
/// so blocking costs no string work.
class WaitTarget {
public:
  virtual ~WaitTarget() = default;
  /// e.g. "channel prefix->delta", "ALT {channel a, AFTER 12.000000 us}".
  virtual std::string describe() const = 0;
};

/// The reason a process blocks.
struct WaitInfo {
  WaitKind kind = WaitKind::none;
  const WaitTarget* target = nullptr;
};

/// Told when a process ends (PAR joins use it). Runs in the kernel, must not block.
class ExitHook {
public:
  virtual ~ExitHook() = default;
  virtual void on_exit(Process& process) = 0;
};

/// How to create a process.
struct SpawnOptions {
  Priority priority = Priority::low;
  /// Host stack size in bytes, rounded up to whole pages; 0 = the kernel's default. One guard
  /// page below it turns an overflow into a fault instead of silent corruption.
  std::size_t stack_bytes = 0;
  ExitHook* exit_hook = nullptr;
};

namespace detail {
struct Context;
class ProcessRegistry;
} // namespace detail

/// A simulated process: a host fiber that runs on one CPU. Created by Kernel::spawn, owned by
/// the kernel, destroyed after it finishes; a Process& is valid until its body returns.
class Process {
public:
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;
  ~Process();

  const std::string& name() const { return name_; }
  Cpu& cpu() const { return *cpu_; }
  Priority priority() const { return priority_; }
  ProcessState state() const { return state_; }
  const WaitInfo& wait() const { return wait_; }
  /// Simulated time at which it last blocked.
  Tick blocked_since() const { return blocked_since_; }
  /// Unique within the kernel, in order of creation.
  std::uint64_t id() const { return id_; }

private:
  friend class Kernel;
  friend class Cpu;
  friend class detail::ProcessRegistry;
  Process(Cpu& cpu, std::string&& name, std::uint64_t id, Priority priority);

  // What every switch and wake-up touches comes first, to share cache lines.
  Cpu* cpu_;
  std::unique_ptr<detail::Context> context_;
  Process* next_ready_ = nullptr;   // intrusive ready queue of the CPU
  Tick slice_end_ = kNever;         // low priority: descheduled at a chunk boundary from then on
  std::uint64_t timeout_event_ = 0; // pending deadline of block_until, 0 = none
  WaitInfo wait_{};
  Tick blocked_since_ = 0;
  Priority priority_;
  ProcessState state_ = ProcessState::ready;
  bool timed_out_ = false;
  std::uint64_t id_;
  std::string name_;
  ExitHook* exit_hook_ = nullptr;
  std::function<void()> body_;
  Process* older_ = nullptr; // the kernel's list of processes, in creation order
  Process* newer_ = nullptr;
  Tick compute_left_ = 0;           // remaining consume() time after a preemption
  std::uint64_t compute_event_ = 0; // pending end of consume(), 0 = none
  Tick compute_end_ = 0;
};

} // namespace marsokhod::emulator
