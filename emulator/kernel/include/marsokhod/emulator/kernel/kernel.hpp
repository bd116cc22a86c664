// The discrete-event kernel: simulated time, the event queue, and processes on fibers.
//
// How to use it (link engines, memory arenas, devices, the occam layer):
//
// * Time is `Tick`, integer picoseconds (time.hpp). `kernel.now()` is the current time.
// * Schedule an event: derive from `EventHandler` and call
//     EventId id = kernel.schedule_at(when, event_priority::link, handler, tag);
//   or pass a `std::function<void()>` instead of handler+tag (allocates if the capture is
//   large; prefer the handler form on hot paths). Events at the same time run by ascending
//   `EventPriority`, then in scheduling order, so results never depend on host timing.
//   `kernel.cancel(id)` removes a pending event. Events run on the kernel's own stack and
//   must never block; they may wake processes and schedule further events.
//   Events marked `EventKind::background` (periodic samplers) do not keep run() alive.
// * A process (Kernel::spawn) is C++ code on its own fiber, bound to one `Cpu`. Inside a
//   process:
//     kernel.consume(duration)   charges CPU time (a compute chunk; may be preempted or
//                                timesliced; other CPUs and events progress meanwhile)
//     kernel.block(WaitInfo{WaitKind::link_output, &my_wait_target})
//                                suspends the current process until someone calls
//                                kernel.wake(process); the WaitInfo feeds deadlock reports
//     kernel.block_until(t, info)  as block(), but also wakes at time t; returns true when
//                                it was the deadline that woke it
//   From anywhere (an event, another process): kernel.wake(process) makes a blocked process
//   ready on its CPU; waking a process that is not blocked does nothing. Remember
//   `kernel.current()` before blocking to know whom to wake later.
// * Killing a process (kernel.kill, kernel.kill_all(cpu) at power-off, ~Kernel) unwinds its
//   stack by throwing a forced-unwind exception inside it: destructors run. Process bodies
//   must not swallow it (no `catch (...)` without rethrow).
// * Trace records: `if (TraceSink* sink = kernel.trace()) sink->instant(track, now, ...)`;
//   declare a track once with sink->track("node0", "link0 out"). The kernel itself writes a
//   slice per process run on each CPU's "cpu" track.
// * run() / run_until(t) / run_for(d) drive the simulation; they stop with a
//   DeadlockReport when every live process is blocked and no event is pending.
#pragma once

#include "marsokhod/emulator/kernel/deadlock_report.hpp"
#include "marsokhod/emulator/kernel/process.hpp"
#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/node/cpu.hpp"
#include "marsokhod/emulator/trace/trace_sink.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::emulator {

/// Order among events at the same instant: lower first (gem5-style explicit priorities).
using EventPriority = std::int32_t;

namespace event_priority {
inline constexpr EventPriority power = -1000; ///< power changes settle first
inline constexpr EventPriority link = -100;   ///< link engines, devices
inline constexpr EventPriority timer = -10;   ///< timer expiries, ALT deadlines
inline constexpr EventPriority normal = 0;    ///< ends of compute chunks, most events
inline constexpr EventPriority dispatch = 10; ///< an idle CPU picks its next process
inline constexpr EventPriority sample = 1000; ///< counters sampled after the instant settled
} // namespace event_priority

/// Receives scheduled events; `tag` is whatever the scheduler passed (an index, a pointer).
class EventHandler {
public:
  virtual ~EventHandler() = default;
  virtual void on_event(std::uint64_t tag) = 0;
};

/// Names a pending event for cancel(); 0 is "no event".
using EventId = std::uint64_t;

/// Background events do not keep the simulation alive.
enum class EventKind : std::uint8_t { foreground, background };

/// Why run() returned.
enum class StopReason : std::uint8_t {
  finished,   ///< no live process and no pending event
  deadlock,   ///< live processes, all blocked, no event pending
  time_limit, ///< run_until / run_for reached its time
  stopped,    ///< stop() was called
};

const char* to_string(StopReason reason);

/// Outcome of a run() call.
struct RunResult {
  StopReason reason = StopReason::finished;
  Tick time = 0;
  std::optional<DeadlockReport> deadlock;
};

/// Kernel-wide settings.
struct KernelOptions {
  /// Default host stack per process (rounded up to pages; one guard page is added).
  std::size_t stack_bytes = 32 * 1024;
};

/// The simulation: time, events, CPUs and their processes. Single-threaded.
class Kernel {
public:
  explicit Kernel(KernelOptions options = {});
  Kernel(const Kernel&) = delete;
  Kernel& operator=(const Kernel&) = delete;
  /// Kills every live process (their destructors run), then frees everything.
  ~Kernel();

  Tick now() const { return now_; }

  // --- events -------------------------------------------------------------------------
  EventId schedule_at(Tick at, EventPriority priority, EventHandler& handler, std::uint64_t tag = 0,
                      EventKind kind = EventKind::foreground);
  EventId schedule_at(Tick at, EventPriority priority, std::function<void()> action,
                      EventKind kind = EventKind::foreground);
  EventId schedule_after(Tick delay, EventPriority priority, EventHandler& handler,
                         std::uint64_t tag = 0, EventKind kind = EventKind::foreground) {
    return schedule_at(now_ + delay, priority, handler, tag, kind);
  }
  EventId schedule_after(Tick delay, EventPriority priority, std::function<void()> action,
                         EventKind kind = EventKind::foreground) {
    return schedule_at(now_ + delay, priority, std::move(action), kind);
  }
  /// Removes a pending event; returns false if it already ran or was cancelled.
  bool cancel(EventId id);
  /// For an event handler with a chain of steps of its own (a link's packets): moves the clock
  /// to `at` when no other event is due before it or at it and the run's limit allows, so that
  /// the handler takes its next step at once, exactly when the queue would have run it, without
  /// a trip through the queue. Returns false, changing nothing, otherwise (and inside a process).
  bool advance_to_next_step(Tick at);
  /// The first time advance_to_next_step() refuses: the next other event's, or just past the
  /// run's limit; now() when it refuses any step.
  Tick inline_step_bound() const;
  /// Pending foreground events.
  std::size_t pending_events() const;

  // --- running ------------------------------------------------------------------------
  /// Runs until nothing can happen any more (finished or deadlock) or stop().
  RunResult run() { return run_until(kNever); }
  /// Runs events up to and including time `limit`; now() is then `limit` unless it stopped
  /// earlier for another reason.
  RunResult run_until(Tick limit);
  RunResult run_for(Tick duration) { return run_until(now_ + duration); }
  /// Asks run() to return after the current event or process switch.
  void stop() { stop_requested_ = true; }

  // --- CPUs and processes ---------------------------------------------------------------
  /// Creates a CPU owned by the kernel (a Node may instead own its Cpu and register it).
  Cpu& add_cpu(std::string name, CpuTiming timing = {});
  /// Starts a process on `cpu`; it becomes ready at now().
  Process& spawn(Cpu& cpu, std::string name, std::function<void()> body, SpawnOptions options = {});
  /// The kernel whose run() is executing on this thread (processes only run inside run()),
  /// or nullptr; lets the occam layer find the current process without passing the kernel.
  static Kernel* active() { return active_; }
  /// The process whose code is executing, or nullptr inside an event.
  Process* current() const { return current_; }
  /// Charges `duration` of CPU time to the current process (a compute-chunk boundary).
  void consume(Tick duration) {
    if (!consume_quickly(duration))
      consume_slowly(duration);
  }
  /// consume()'s fast path alone: true if the chunk was charged; false if consume() is due,
  /// with nothing changed.
  bool consume_quickly(Tick duration) {
    // Nothing can happen before the chunk ends (no event, no deadline, no preemption or
    // timeslice due), so the clock just moves on; this is exactly what the event queue would
    // do, without its cost.
    if (duration >= 0 && now_ + duration < fast_until_) {
      now_ += duration;
      return true;
    }
    return false;
  }
  /// Suspends the current process until wake(). (`why` by value: two registers, where a
  /// reference would reload a just-written temporary through memory.)
  void block(WaitInfo why);
  /// As block(), but also woken at `deadline`; true if the deadline woke it.
  bool block_until(Tick deadline, WaitInfo why);
  /// Makes a blocked process ready; does nothing if it is not blocked.
  void wake(Process& process) {
    if (process.state_ != ProcessState::blocked)
      return;
    // Fast path, the usual end of a channel communication: a low-priority process with no
    // deadline, woken while its CPU is busy, only joins the back of its ready queue.
    Cpu& cpu = *process.cpu_;
    if (process.timeout_event_ == 0 && process.priority_ == Priority::low &&
        cpu.running_ != nullptr) {
      process.state_ = ProcessState::ready;
      cpu.push_back(process);
      return;
    }
    wake_slowly(process);
  }
  /// Puts the current process behind the other ready processes of its priority.
  void yield();
  /// Ends a process that is not the current one; its stack unwinds, destructors run.
  void kill(Process& process);
  /// Ends every process of a CPU (power-off). Must not be called from one of them.
  void kill_all(Cpu& cpu);
  /// Live processes, all CPUs.
  std::size_t live_processes() const { return live_; }

  // --- observation ---------------------------------------------------------------------
  TraceSink* trace() const { return trace_; }
  /// Sets the sink (not owned); call before spawning so CPU tracks are declared.
  void set_trace(TraceSink* sink);
  /// The report of the current state as if it were a deadlock (for diagnostics).
  DeadlockReport blocked_report() const;
  /// Process context switches so far (direct and via the kernel loop).
  std::uint64_t context_switches() const { return switches_; }

  void register_cpu(Cpu& cpu);
  void unregister_cpu(Cpu& cpu);

private:
  struct Impl;
  class ActiveScope;
  friend struct Impl;
  friend class Cpu;

  void consume_slowly(Tick duration);
  void wake_slowly(Process& process);
  void refresh_horizon();
  /// Recomputes fast_until_; due whenever current_, horizon_, the current process's slice end
  /// or its CPU's preemption request change.
  void refresh_fast_until() {
    const Process* p = current_;
    fast_until_ = p != nullptr && !p->cpu_->preempt_requested_ ? std::min(horizon_, p->slice_end_)
                                                               : kNoFastPath;
  }

  static constexpr Tick kNoFastPath = std::numeric_limits<Tick>::min();

  static inline thread_local Kernel* active_ = nullptr;
  Tick now_ = 0;
  /// A lower bound of min(next event time, run limit + 1): chunks ending before it need no
  /// look at the event queue.
  Tick horizon_ = 0;
  /// min(horizon_, the current process's slice end), or kNoFastPath when no process runs or a
  /// preemption is pending: a chunk that ends before it only moves the clock. One comparison
  /// for what would otherwise be four; refresh_fast_until() keeps it true.
  Tick fast_until_ = kNoFastPath;
  Process* current_ = nullptr;
  TraceSink* trace_ = nullptr;
  std::size_t live_ = 0;
  std::uint64_t switches_ = 0;
  bool stop_requested_ = false;
  std::unique_ptr<Impl> impl_;
};

} // namespace marsokhod::emulator
