// The discrete-event kernel: its run loop, events and the public process calls.

#include "marsokhod/emulator/kernel/kernel.hpp"

#include "kernel/kernel_impl.hpp"

#include <algorithm>
#include <stdexcept>

namespace marsokhod::emulator {

const char* to_string(StopReason reason) {
  switch (reason) {
  case StopReason::finished:
    return "finished";
  case StopReason::deadlock:
    return "deadlock";
  case StopReason::time_limit:
    return "time limit";
  case StopReason::stopped:
    return "stopped";
  }
  return "?";
}

Kernel::Impl::Impl(Kernel& kernel, KernelOptions opts) : owner(&kernel), options(opts) {
  compute_done.kernel = &kernel;
  deadline.kernel = &kernel;
  dispatch.kernel = &kernel;
}

Kernel::Kernel(KernelOptions options) : impl_(std::make_unique<Impl>(*this, options)) {}

Kernel::~Kernel() {
  // Newest first, so that PAR children unwind before the parent whose stack they refer to.
  std::vector<Process*> live;
  for (Process* p = impl_->processes.newest(); p != nullptr; p = Impl::Registry::older(p))
    if (p->state() != ProcessState::finished)
      live.push_back(p);
  for (Process* p : live)
    kill(*p);
  impl_->idle.clear();
  impl_->owned_cpus.clear();
}

EventId Kernel::schedule_at(Tick at, EventPriority priority, EventHandler& handler,
                            std::uint64_t tag, EventKind kind) {
  at = std::max(at, now_);
  horizon_ = std::min(horizon_, at);
  fast_until_ = std::min(fast_until_, at);
  return impl_->events.push(at, priority, &handler, tag, nullptr, kind);
}

EventId Kernel::schedule_at(Tick at, EventPriority priority, std::function<void()> action,
                            EventKind kind) {
  at = std::max(at, now_);
  horizon_ = std::min(horizon_, at);
  fast_until_ = std::min(fast_until_, at);
  return impl_->events.push(at, priority, nullptr, 0, std::move(action), kind);
}

bool Kernel::cancel(EventId id) {
  return impl_->events.cancel(id);
}

bool Kernel::advance_to_next_step(Tick at) {
  const Tick after_limit = impl_->limit == kNever ? kNever : impl_->limit + 1;
  if (current_ != nullptr || stop_requested_ || impl_->failure || at < now_ ||
      at >= impl_->events.next_time() || at >= after_limit)
    return false;
  now_ = at;
  refresh_horizon();
  return true;
}

Tick Kernel::inline_step_bound() const {
  if (current_ != nullptr || stop_requested_ || impl_->failure)
    return now_;
  const Tick after_limit = impl_->limit == kNever ? kNever : impl_->limit + 1;
  return std::min(impl_->events.next_time(), after_limit);
}

std::size_t Kernel::pending_events() const {
  return impl_->events.foreground();
}

/// Marks a kernel as the one running on this thread for the scope of run_until().
class Kernel::ActiveScope {
public:
  explicit ActiveScope(Kernel* kernel) : previous_(std::exchange(Kernel::active_, kernel)) {}
  ActiveScope(const ActiveScope&) = delete;
  ActiveScope& operator=(const ActiveScope&) = delete;
  ~ActiveScope() { Kernel::active_ = previous_; }

private:
  Kernel* previous_;
};

void Kernel::refresh_horizon() {
  const Tick after_limit = impl_->limit == kNever ? kNever : impl_->limit + 1;
  horizon_ = std::min(impl_->events.next_time(), after_limit);
  refresh_fast_until();
}

RunResult Kernel::run_until(Tick limit) {
  if (current_ != nullptr)
    throw std::logic_error("Kernel::run called from inside a simulated process");
  ActiveScope active(this);
  impl_->limit = limit;
  refresh_horizon();
  stop_requested_ = false;
  detail::EventQueue::Fired fired;
  for (;;) {
    if (impl_->failure)
      std::rethrow_exception(std::exchange(impl_->failure, nullptr));
    if (stop_requested_)
      return RunResult{StopReason::stopped, now_, std::nullopt};
    if (impl_->events.foreground() == 0) {
      if (live_ > 0)
        return RunResult{StopReason::deadlock, now_, blocked_report()};
      if (limit == kNever || impl_->events.size() == 0)
        return RunResult{StopReason::finished, now_, std::nullopt};
    }
    if (impl_->events.next_time() > limit) {
      now_ = limit;
      return RunResult{StopReason::time_limit, now_, std::nullopt};
    }
    impl_->events.pop(fired);
    now_ = fired.time;
    refresh_horizon();
    if (fired.handler != nullptr)
      fired.handler->on_event(fired.tag);
    else
      fired.action();
  }
}

Cpu& Kernel::add_cpu(std::string name, CpuTiming timing) {
  impl_->owned_cpus.push_back(std::make_unique<Cpu>(*this, std::move(name), timing));
  return *impl_->owned_cpus.back();
}

void Kernel::register_cpu(Cpu& cpu) {
  impl_->cpus.push_back(&cpu);
  if (trace_ != nullptr)
    cpu.track_ = trace_->track(cpu.name(), "cpu");
}

void Kernel::unregister_cpu(Cpu& cpu) {
  kill_all(cpu);
  if (cpu.dispatch_event_ != 0) {
    cancel(cpu.dispatch_event_);
    cpu.dispatch_event_ = 0;
  }
  auto& cpus = impl_->cpus;
  cpus.erase(std::remove(cpus.begin(), cpus.end(), &cpu), cpus.end());
}

void Kernel::set_trace(TraceSink* sink) {
  trace_ = sink;
  if (sink == nullptr)
    return;
  for (Cpu* cpu : impl_->cpus)
    cpu->track_ = sink->track(cpu->name(), "cpu");
}

DeadlockReport Kernel::blocked_report() const {
  DeadlockReport report;
  report.time = now_;
  for (const Cpu* cpu : impl_->cpus) {
    for (const Process* p = impl_->processes.oldest(); p != nullptr; p = Impl::Registry::newer(p)) {
      if (&p->cpu() != cpu || p->state() != ProcessState::blocked)
        continue;
      const std::uint64_t id = p->id();
      const WaitInfo& wait = p->wait();
      report.processes.push_back(BlockedProcess{
          cpu->name(), p->name(), id, wait.kind,
          wait.target != nullptr ? wait.target->describe() : std::string(to_string(wait.kind)),
          p->blocked_since()});
    }
  }
  return report;
}

} // namespace marsokhod::emulator
