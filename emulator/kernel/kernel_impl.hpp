// The kernel's private state: fibers, the process registry and its internal events.
#pragma once

#include "fibers/fiber.hpp"
#include "fibers/stack_pool.hpp"
#include "kernel/event_queue.hpp"
#include "kernel/process_registry.hpp"

#include "marsokhod/emulator/kernel/kernel.hpp"

#include <cstdint>
#include <exception>
#include <memory>
#include <vector>

namespace marsokhod::emulator {

namespace detail {
/// Event tags that carry a pointer (the Process or Cpu an internal event concerns).
inline std::uint64_t tag_of(const void* object) {
  return reinterpret_cast<std::uintptr_t>(object);
}
template <typename T>
T* from_tag(std::uint64_t tag) {
  return reinterpret_cast<T*>(static_cast<std::uintptr_t>(tag));
}
} // namespace detail

/// The kernel's private state: the event queue, fibers, process and CPU registries.
struct Kernel::Impl {
  /// Fires the kernel's own events; `tag` is the Process* or Cpu* concerned.
  struct ComputeDone : EventHandler {
    Kernel* kernel = nullptr;
    void on_event(std::uint64_t tag) override;
  };
  struct Deadline : EventHandler {
    Kernel* kernel = nullptr;
    void on_event(std::uint64_t tag) override;
  };
  struct Dispatch : EventHandler {
    Kernel* kernel = nullptr;
    void on_event(std::uint64_t tag) override;
  };

  explicit Impl(Kernel& kernel, KernelOptions opts);

  Kernel* owner;
  KernelOptions options;
  detail::EventQueue events;
  detail::StackPool stacks;
  ComputeDone compute_done;
  Deadline deadline;
  Dispatch dispatch;
  Tick limit = kNever;
  /// The kernel loop's own context while a process runs.
  boost::context::fiber main;
  /// Where the context switched away from is stored by the context switched to.
  boost::context::fiber* save_slot = nullptr;
  boost::context::fiber discarded;
  /// A process whose fiber ended; deleted by the next context to run.
  Process* zombie = nullptr;
  int unwinding = 0; // kills in progress (a dying PAR kills its branches)
  std::exception_ptr failure;
  std::uint64_t next_process_id = 1;
  using Registry = detail::ProcessRegistry;
  Registry processes;
  std::vector<Cpu*> cpus;
  std::vector<std::unique_ptr<Cpu>> owned_cpus;
  /// Parked fibers of one stack size.
  struct Parked {
    std::size_t stack_bytes = 0;
    std::vector<std::unique_ptr<detail::Context>> fibers;
  };
  /// Parked fibers by stack size (a program uses a few sizes, so a list); declared after
  /// `stacks`, so destroyed (unwound) first.
  std::vector<Parked> idle;
  std::vector<std::unique_ptr<detail::Context>>& parked(std::size_t stack_bytes) {
    for (Parked& entry : idle)
      if (entry.stack_bytes == stack_bytes)
        return entry.fibers;
    return idle.emplace_back(Parked{stack_bytes, {}}).fibers;
  }
  static constexpr std::size_t kMaxIdlePerSize = 256;

  void switch_to(boost::context::fiber& target, boost::context::fiber& save);
  void after_switch();
  void start_fiber(Process& p, std::size_t stack_bytes);
  void run_body(Process& p);
  /// The fiber's life: run its process, park, run the next one given to it.
  boost::context::fiber fiber_main(detail::Context& context);
  boost::context::fiber& context_of(Process* p) { return p ? p->context_->fiber : main; }
  /// Gives the CPU of `p` (which stops running) to its next ready process or to the loop.
  Process* leave_cpu(Process& p);
  /// Makes `next` the process holding `cpu`, with its timeslice.
  void assign(Cpu& cpu, Process& next);
  /// As assign(), for a CPU that was idle: its busy time and trace slice start.
  void grant(Cpu& cpu, Process& next);
  void release(Cpu& cpu);
  void request_dispatch(Cpu& cpu, Tick at);
  void preempt(Cpu& cpu, Process& low);
  void finish(Process& p);
  void destroy(Process& p);
};

} // namespace marsokhod::emulator
