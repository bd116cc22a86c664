// Process contexts: fibers, direct switches between processes, giving and taking CPUs, the
// kernel's own events (end of a compute chunk, deadline, dispatch), the process registry.

#include "fibers/kernel_switch.hpp"

#include "marsokhod/emulator/kernel/kernel.hpp"

#include <exception>
#include <utility>

namespace marsokhod::emulator {

void Kernel::Impl::start_fiber(Process& p, std::size_t stack_bytes) {
  auto& spare = parked(stack_bytes);
  if (!spare.empty()) {
    p.context_ = std::move(spare.back());
    spare.pop_back();
    p.context_->process = &p;
    return;
  }
  p.context_ = std::make_unique<detail::Context>();
  detail::Context* context = p.context_.get();
  context->process = &p;
  context->stack_bytes = stack_bytes;
  context->fiber = boost::context::fiber(
      std::allocator_arg, detail::PooledStack(stacks, stack_bytes),
      [this, context](boost::context::fiber&& caller) -> boost::context::fiber {
        // Killed before it ever ran: the fcontext backend unwinds such a fiber without
        // entering it, the ucontext backend (sanitizer builds) enters it; return at once.
        if (context->process->state_ == ProcessState::finished)
          return std::move(caller);
        *save_slot = std::move(caller);
        after_switch();
        return fiber_main(*context);
      });
}

void Kernel::Impl::run_body(Process& p) {
  try {
    p.body_();
  } catch (const detail::ForcedUnwind&) {
    throw;
  } catch (...) {
    if (!failure)
      failure = std::current_exception();
    owner->stop_requested_ = true;
  }
}

boost::context::fiber Kernel::Impl::fiber_main(detail::Context& context) {
  for (;;) {
    Process& p = *context.process;
    run_body(p);
    finish(p);
    Process* next = owner->current_;
    zombie = &p;
    auto& spare = parked(context.stack_bytes);
    if (spare.size() >= kMaxIdlePerSize) {
      // Enough spare fibers: this one ends and its stack goes back to the pool.
      save_slot = &discarded;
      return std::move(context_of(next));
    }
    context.process = nullptr;
    spare.push_back(std::move(p.context_));
    switch_to(context_of(next), context.fiber);
  }
}

void Kernel::Impl::request_dispatch(Cpu& cpu, Tick at) {
  if (cpu.dispatch_event_ == 0) {
    cpu.dispatch_event_ =
        owner->schedule_at(at, event_priority::dispatch, dispatch, detail::tag_of(&cpu));
  }
}

void Kernel::Impl::finish(Process& p) {
  p.state_ = ProcessState::finished;
  p.body_ = nullptr;
  --owner->live_;
  --p.cpu_->live_count_;
  // The hook runs while p still holds the CPU, so a parent it wakes is picked below directly.
  if (p.exit_hook_ != nullptr)
    p.exit_hook_->on_exit(p);
  leave_cpu(p);
}

void Kernel::Impl::preempt(Cpu& cpu, Process& low) {
  if (owner->current_ == &low) {
    // The low-priority process itself readied a high-priority one. It yields at its next
    // kernel call (consume, block, yield, end); no simulated time passes before that, and
    // the operation that readied the high process completes first, as an instruction would.
    cpu.preempt_requested_ = true;
    owner->refresh_fast_until();
    return;
  }
  low.state_ = ProcessState::ready;
  cpu.push_front(low);
  // Otherwise it is inside consume(): stop its compute chunk, keep the remainder.
  if (low.compute_event_ != 0) {
    owner->cancel(low.compute_event_);
    low.compute_event_ = 0;
    low.compute_left_ = low.compute_end_ - owner->now_;
  }
  release(cpu);
  request_dispatch(cpu, owner->now_ + cpu.timing_.preemption_latency);
}

void Kernel::Impl::ComputeDone::on_event(std::uint64_t tag) {
  Process& p = *detail::from_tag<Process>(tag);
  p.compute_event_ = 0;
  p.compute_left_ = 0;
  kernel->current_ = &p;
  kernel->refresh_fast_until();
  ++kernel->switches_;
  kernel->impl_->switch_to(p.context_->fiber, kernel->impl_->main);
}

void Kernel::Impl::Deadline::on_event(std::uint64_t tag) {
  Process& p = *detail::from_tag<Process>(tag);
  p.timeout_event_ = 0;
  p.timed_out_ = true;
  kernel->wake(p);
}

void Kernel::Impl::Dispatch::on_event(std::uint64_t tag) {
  Cpu& cpu = *detail::from_tag<Cpu>(tag);
  cpu.dispatch_event_ = 0;
  if (cpu.running_ != nullptr)
    return;
  Process* next = cpu.pop();
  if (next == nullptr)
    return;
  Impl& impl = *kernel->impl_;
  impl.grant(cpu, *next);
  kernel->current_ = next;
  kernel->refresh_fast_until();
  ++kernel->switches_;
  impl.switch_to(next->context_->fiber, impl.main);
}

} // namespace marsokhod::emulator
