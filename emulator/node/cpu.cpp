// A simulated CPU: its scheduling constants and its two ready queues.

#include "marsokhod/emulator/node/cpu.hpp"

#include "marsokhod/emulator/kernel/kernel.hpp"

namespace marsokhod::emulator {

Cpu::Cpu(Kernel& kernel, std::string name, CpuTiming timing)
    : kernel_(&kernel), name_(std::move(name)), timing_(timing) {
  if (timing_.timeslice <= 0) {
    // No timeslicing: low-priority processes are granted slices that never end.
    next_tick_ = kNever;
    slice_end_ = kNever;
  }
  kernel.register_cpu(*this);
}

Cpu::~Cpu() {
  kernel_->unregister_cpu(*this);
}

Tick Cpu::busy_time() const {
  return busy_total_ + (running_ != nullptr ? kernel_->now() - busy_since_ : 0);
}

void Cpu::remove(Process& p) {
  Queue& q = queues_[static_cast<int>(p.priority())];
  Process* previous = nullptr;
  for (Process* at = q.head; at != nullptr; previous = at, at = at->next_ready_) {
    if (at != &p)
      continue;
    (previous == nullptr ? q.head : previous->next_ready_) = p.next_ready_;
    if (q.tail == &p)
      q.tail = previous;
    p.next_ready_ = nullptr;
    --ready_count_;
    return;
  }
}

} // namespace marsokhod::emulator
