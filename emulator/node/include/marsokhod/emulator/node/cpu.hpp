// A simulated CPU: scheduling constants, two ready queues and the process it runs.
#pragma once

#include "marsokhod/emulator/kernel/process.hpp"
#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/emulator/trace/trace_sink.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace marsokhod::emulator {

class Kernel;
class Node;

/// Scheduling constants of one processor (values come from the platform file).
struct CpuTiming {
  /// Low-priority timeslice period (T805: 5120 cycles of the 5 MHz input clock = 1.024 ms).
  Tick timeslice = 1'024 * kMicrosecond;
  /// A low-priority process is descheduled at the first compute-chunk boundary after this
  /// many timeslice ticks since it got the CPU (T805: 2).
  int slices_before_deschedule = 2;
  /// Delay before a high-priority process made ready by an event or by a low-priority process
  /// interrupts a running low-priority one (T805 event latency, typically 19 cycles).
  Tick preemption_latency = 0;
};

/// One processor's scheduler: two FIFO ready queues (high, low) and the process holding the
/// CPU. The kernel drives it; a Node (T805 model) owns one.
class Cpu {
public:
  Cpu(Kernel& kernel, std::string name, CpuTiming timing = {});
  Cpu(const Cpu&) = delete;
  Cpu& operator=(const Cpu&) = delete;
  ~Cpu();

  Kernel& kernel() const { return *kernel_; }
  const std::string& name() const { return name_; }
  const CpuTiming& timing() const { return timing_; }
  /// The process holding the CPU, or nullptr when idle.
  Process* running() const { return running_; }
  bool idle() const { return running_ == nullptr; }
  std::size_t ready_count() const { return ready_count_; }
  /// Live (not finished) processes on this CPU.
  std::size_t live_count() const { return live_count_; }
  /// Total simulated time a process held the CPU; idle time is now() minus this.
  Tick busy_time() const;
  /// The T805 node model that owns this CPU, if any.
  Node* node() const { return node_; }
  void set_node(Node* node) { node_ = node; }
  /// Trace row of this CPU ("cpu" in group name()), valid when the kernel has a sink.
  TrackId trace_track() const { return track_; }

private:
  friend class Kernel;
  struct Queue {
    Process* head = nullptr;
    Process* tail = nullptr;
  };
  void push_back(Process& p);
  void push_front(Process& p);
  Process* pop();
  bool has_ready(Priority p) const { return queues_[static_cast<int>(p)].head != nullptr; }
  void remove(Process& p);

  Kernel* kernel_;
  std::string name_;
  CpuTiming timing_;
  Queue queues_[2];
  std::size_t ready_count_ = 0;
  std::size_t live_count_ = 0;
  Process* running_ = nullptr;
  std::uint64_t dispatch_event_ = 0; // pending dispatch, 0 = none
  bool preempt_requested_ = false;   // a high process is ready; the running low one yields
  Tick next_tick_ = 0;               // first timeslice tick after the last grant
  Tick slice_end_ = 0;               // slice end of a low process granted before next_tick_
  Tick busy_since_ = 0;
  Tick busy_total_ = 0;
  TrackId track_ = 0;
  Node* node_ = nullptr;
};

// The ready queues are on every process switch: inline.

inline void Cpu::push_back(Process& p) {
  Queue& q = queues_[static_cast<int>(p.priority())];
  p.next_ready_ = nullptr;
  if (q.tail == nullptr)
    q.head = &p;
  else
    q.tail->next_ready_ = &p;
  q.tail = &p;
  ++ready_count_;
}

inline void Cpu::push_front(Process& p) {
  Queue& q = queues_[static_cast<int>(p.priority())];
  p.next_ready_ = q.head;
  q.head = &p;
  if (q.tail == nullptr)
    q.tail = &p;
  ++ready_count_;
}

inline Process* Cpu::pop() {
  for (Queue& q : queues_) {
    Process* p = q.head;
    if (p == nullptr)
      continue;
    // p->next_ready_ keeps its stale value: it is read only while p is queued, and every
    // push sets it.
    q.head = p->next_ready_;
    if (q.head == nullptr)
      q.tail = nullptr;
    --ready_count_;
    return p;
  }
  return nullptr;
}

} // namespace marsokhod::emulator
