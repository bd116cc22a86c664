// The hot path of a process switch, inline so that blocking, the choice of the next process
// and the fiber jump happen in one frame: fewer calls between two fibers means fewer returns
// whose prediction the stack switch spoils.
#pragma once

#include "kernel/kernel_impl.hpp"

#include <algorithm>
#include <utility>

namespace marsokhod::emulator {

inline void Kernel::Impl::switch_to(boost::context::fiber& target, boost::context::fiber& save) {
  save_slot = &save;
  // Whoever switches back to us says where its own context belongs.
  detail::switch_fiber(target, save_slot);
  after_switch();
}

inline void Kernel::Impl::after_switch() {
  if (zombie != nullptr)
    processes.remove_and_delete(std::exchange(zombie, nullptr));
}

inline void Kernel::Impl::assign(Cpu& cpu, Process& next) {
  cpu.running_ = &next;
  next.state_ = ProcessState::running;
  if (next.priority_ == Priority::high) {
    next.slice_end_ = kNever;
    return;
  }
  // The timeslice clock ticks at multiples of the period; a low-priority process is
  // descheduled at a chunk boundary once it has seen `slices_before_deschedule` ticks since
  // it got the CPU. The CPU keeps the next tick and the slice end that goes with it, so that
  // a switch costs neither a division nor a multiplication (without timeslicing both are
  // kNever).
  if (owner->now_ >= cpu.next_tick_) [[unlikely]] {
    const CpuTiming& timing = cpu.timing_;
    cpu.next_tick_ = (owner->now_ / timing.timeslice + 1) * timing.timeslice;
    cpu.slice_end_ = cpu.next_tick_ + (timing.slices_before_deschedule - 1) * timing.timeslice;
  }
  next.slice_end_ = cpu.slice_end_;
}

inline void Kernel::Impl::grant(Cpu& cpu, Process& next) {
  assign(cpu, next);
  cpu.busy_since_ = owner->now_;
  if (owner->trace_ != nullptr)
    owner->trace_->begin_slice(cpu.track_, owner->now_, next.name_);
}

inline void Kernel::Impl::release(Cpu& cpu) {
  if (cpu.running_ == nullptr)
    return;
  cpu.busy_total_ += owner->now_ - cpu.busy_since_;
  cpu.running_ = nullptr;
  if (owner->trace_ != nullptr)
    owner->trace_->end_slice(cpu.track_, owner->now_);
}

// Hands the CPU of the current process to the next ready one; returns it (nullptr: idle).
inline Process* Kernel::Impl::leave_cpu(Process& p) {
  Cpu& cpu = *p.cpu_;
  cpu.preempt_requested_ = false;
  Process* next = cpu.pop();
  owner->current_ = next;
  ++owner->switches_;
  if (next == nullptr || cpu.running_ == nullptr) {
    release(cpu);
    if (next != nullptr)
      grant(cpu, *next);
    owner->refresh_fast_until();
    return next;
  }
  // The CPU passes straight from one process to the next and stays busy: its busy time
  // (busy_total_ plus the time since busy_since_) is the same without touching either.
  if (owner->trace_ != nullptr) {
    owner->trace_->end_slice(cpu.track_, owner->now_);
    owner->trace_->begin_slice(cpu.track_, owner->now_, next->name_);
  }
  assign(cpu, *next);
  // Its CPU has just dropped any preemption request, so the fast path is open to it.
  owner->fast_until_ = std::min(owner->horizon_, next->slice_end_);
  return next;
}

} // namespace marsokhod::emulator
