// The process API: spawning, CPU time, blocking and waking, yielding, killing.

#include "fibers/kernel_switch.hpp"

#include "marsokhod/emulator/kernel/kernel.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <stdexcept>

namespace marsokhod::emulator {

namespace {

[[noreturn, gnu::noinline, gnu::cold]] void no_current_process(const char* operation) {
  throw std::logic_error(std::string(operation) + " called outside a simulated process");
}

inline Process& require_current(Process* current, const char* operation) {
  if (current == nullptr) [[unlikely]]
    no_current_process(operation);
  return *current;
}

} // namespace

// --- the public process API ---------------------------------------------------------------

Process& Kernel::spawn(Cpu& cpu, std::string name, std::function<void()> body,
                       SpawnOptions options) {
  const std::uint64_t id = impl_->next_process_id++;
  Process& p = *impl_->processes.create(cpu, std::move(name), id, options.priority);
  p.body_ = std::move(body);
  p.exit_hook_ = options.exit_hook;
  try {
    impl_->start_fiber(p,
                       options.stack_bytes != 0 ? options.stack_bytes : impl_->options.stack_bytes);
  } catch (...) {
    impl_->processes.destroy(&p);
    throw;
  }
  impl_->processes.add(&p);
  ++live_;
  ++cpu.live_count_;
  cpu.push_back(p);
  if (cpu.running_ == nullptr)
    impl_->request_dispatch(cpu, now_);
  else if (p.priority_ == Priority::high && cpu.running_->priority_ == Priority::low)
    impl_->preempt(cpu, *cpu.running_);
  return p;
}

void Kernel::consume_slowly(Tick duration) {
  Process& p = require_current(current_, "Kernel::consume");
  refresh_horizon();
  Cpu& cpu = *p.cpu_;
  if (cpu.preempt_requested_) {
    // Interrupted, not timesliced: it resumes before the other low-priority processes.
    p.state_ = ProcessState::ready;
    cpu.push_front(p);
    Process* next = impl_->leave_cpu(p);
    impl_->switch_to(impl_->context_of(next), impl_->context_of(&p));
  } else if (now_ >= p.slice_end_ && cpu.has_ready(Priority::low)) {
    p.state_ = ProcessState::ready;
    cpu.push_back(p);
    Process* next = impl_->leave_cpu(p);
    impl_->switch_to(impl_->context_of(next), impl_->context_of(&p));
  }
  if (duration <= 0)
    return;
  if (now_ + duration < horizon_) {
    now_ += duration;
    return;
  }
  p.compute_left_ = duration;
  while (p.compute_left_ > 0) {
    p.compute_end_ = now_ + p.compute_left_;
    p.compute_event_ = schedule_at(p.compute_end_, event_priority::normal, impl_->compute_done,
                                   detail::tag_of(&p));
    current_ = nullptr;
    fast_until_ = kNoFastPath;
    ++switches_;
    impl_->switch_to(impl_->main, p.context_->fiber);
  }
}

void Kernel::block(WaitInfo why) {
  Process& p = require_current(current_, "Kernel::block");
  if (impl_->unwinding > 0) {
    std::fputs("marsokhod: a process blocked while being killed\n", stderr);
    std::terminate();
  }
  p.state_ = ProcessState::blocked;
  p.wait_ = why;
  p.blocked_since_ = now_;
  Process* next = impl_->leave_cpu(p);
  impl_->switch_to(impl_->context_of(next), p.context_->fiber);
  p.wait_ = WaitInfo{};
}

bool Kernel::block_until(Tick deadline, WaitInfo why) {
  Process& p = require_current(current_, "Kernel::block_until");
  p.timed_out_ = false;
  p.timeout_event_ =
      schedule_at(deadline, event_priority::timer, impl_->deadline, detail::tag_of(&p));
  block(why);
  return p.timed_out_;
}

void Kernel::wake_slowly(Process& p) {
  if (p.timeout_event_ != 0)
    cancel(std::exchange(p.timeout_event_, 0));
  p.state_ = ProcessState::ready;
  Cpu& cpu = *p.cpu_;
  cpu.push_back(p);
  if (cpu.running_ == nullptr) {
    impl_->request_dispatch(cpu, now_);
    return;
  }
  if (p.priority_ == Priority::high && cpu.running_->priority_ == Priority::low)
    impl_->preempt(cpu, *cpu.running_);
}

void Kernel::yield() {
  Process& p = require_current(current_, "Kernel::yield");
  Cpu& cpu = *p.cpu_;
  if (!cpu.has_ready(p.priority_) && !cpu.preempt_requested_)
    return;
  p.state_ = ProcessState::ready;
  if (cpu.preempt_requested_)
    cpu.push_front(p);
  else
    cpu.push_back(p);
  Process* next = impl_->leave_cpu(p);
  impl_->switch_to(impl_->context_of(next), p.context_->fiber);
}

void Kernel::kill(Process& p) {
  if (&p == current_)
    throw std::logic_error("a process cannot kill itself: " + p.name());
  if (p.state_ == ProcessState::finished)
    return;
  Cpu& cpu = *p.cpu_;
  if (p.state_ == ProcessState::ready)
    cpu.remove(p);
  for (std::uint64_t* event : {&p.compute_event_, &p.timeout_event_})
    if (*event != 0)
      cancel(std::exchange(*event, 0));
  if (cpu.running_ == &p) {
    impl_->release(cpu);
    if (cpu.ready_count_ > 0)
      impl_->request_dispatch(cpu, now_);
  }
  p.state_ = ProcessState::finished;
  --live_;
  --cpu.live_count_;
  Process* saved = std::exchange(current_, &p);
  refresh_fast_until();
  ++impl_->unwinding;
  {
    // Destroying a suspended fiber throws forced_unwind inside it: its destructors run.
    boost::context::fiber doomed = std::move(p.context_->fiber);
  }
  --impl_->unwinding;
  current_ = saved;
  refresh_fast_until();
  impl_->processes.remove_and_delete(&p);
}

void Kernel::kill_all(Cpu& cpu) {
  // Newest first, so that PAR branches unwind before the parent whose stack they refer to.
  std::vector<Process*> victims;
  for (Process* p = impl_->processes.newest(); p != nullptr; p = Impl::Registry::older(p)) {
    if (p->cpu_ != &cpu || p->state_ == ProcessState::finished)
      continue;
    if (p == current_)
      throw std::logic_error("kill_all called by a process of the CPU " + cpu.name());
    victims.push_back(p);
  }
  for (Process* p : victims)
    kill(*p);
}

} // namespace marsokhod::emulator
