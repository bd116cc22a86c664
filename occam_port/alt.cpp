// ALT and PRI ALT: the enable, wait and disable sequence and its data-book costs.

#include "marsokhod/occam_port/alt.hpp"

#include "marsokhod/emulator/node/node.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace marsokhod::occam_port {

using emulator::Instruction;
using emulator::Node;
using emulator::Tick;

AltState::AltState(emulator::Kernel& kernel, emulator::Process& process,
                   std::span<const Guard> guards)
    : kernel_(kernel), process_(process), guards_(guards) {}

AltState::~AltState() {
  // Killed while waiting: no channel may keep pointing at this ALT.
  for (std::size_t i = 0; i < enabled_; ++i) {
    const Guard& g = guards_[i];
    if (g.kind == Guard::Kind::channel && g.precondition &&
        std::find(gone_.begin(), gone_.end(), g.channel) == gone_.end())
      g.channel->disable(*this);
  }
}

void AltState::guard_ready() {
  if (ready_)
    return;
  ready_ = true;
  if (waiting_)
    kernel_.wake(process_);
}

std::string AltState::describe() const {
  std::string text = "ALT {";
  for (std::size_t i = 0; i < guards_.size(); ++i) {
    const Guard& g = guards_[i];
    text += i == 0 ? "" : ", ";
    text += g.precondition ? "" : "FALSE & ";
    switch (g.kind) {
    case Guard::Kind::channel:
      text += g.channel->describe();
      break;
    case Guard::Kind::timer:
      text += fmt::format("AFTER {}", g.after);
      break;
    case Guard::Kind::skip:
      text += "SKIP";
      break;
    }
  }
  return text + "}";
}

bool AltState::enable_all() {
  Node& node = Node::current();
  const emulator::CostTable& costs = node.cpu_spec().costs;
  const Tick period = node.timer_period(process_.priority());
  const std::int32_t clock = Timer::clock_at(kernel_.now(), period);
  std::uint64_t cycles = 0;
  for (const Guard& g : guards_) {
    ++enabled_;
    has_timer_ = has_timer_ || (g.kind == Guard::Kind::timer && g.precondition);
  }
  cycles +=
      static_cast<std::uint64_t>(costs[has_timer_ ? Instruction::talt : Instruction::alt].base);
  bool timer_seen = false;
  for (const Guard& g : guards_) {
    switch (g.kind) {
    case Guard::Kind::channel: {
      const bool ready = g.precondition && g.channel->enable(*this);
      ready_ = ready_ || ready;
      cycles += static_cast<std::uint64_t>(
          costs[ready ? Instruction::enbc_ready : Instruction::enbc_not_ready].base);
      break;
    }
    case Guard::Kind::timer:
      if (g.precondition) {
        ready_ = ready_ || is_after(clock, g.after);
        if (!timer_seen || is_after(earliest_, g.after))
          earliest_ = g.after;
        timer_seen = true;
      }
      cycles += static_cast<std::uint64_t>(costs[Instruction::enbt].base);
      break;
    case Guard::Kind::skip:
      ready_ = ready_ || g.precondition;
      cycles += static_cast<std::uint64_t>(costs[Instruction::enbs].base);
      break;
    }
  }
  node.compute_cycles(cycles);
  return ready_;
}

void AltState::wait() {
  Node& node = Node::current();
  if (has_timer_)
    node.execute(ready_ ? Instruction::taltwt_ready : Instruction::taltwt_wait);
  else
    node.execute(ready_ ? Instruction::altwt_ready : Instruction::altwt_wait);
  if (ready_)
    return;
  waiting_ = true;
  const emulator::WaitInfo why{emulator::WaitKind::alt, this};
  if (has_timer_) {
    const Tick period = node.timer_period(process_.priority());
    kernel_.block_until(Timer::time_after(earliest_, kernel_.now(), period), why);
  } else {
    kernel_.block(why);
  }
  waiting_ = false;
}

std::size_t AltState::disable_all() {
  Node& node = Node::current();
  const emulator::CostTable& costs = node.cpu_spec().costs;
  std::uint64_t cycles = static_cast<std::uint64_t>(costs[Instruction::altend].base);
  for (const Guard& g : guards_) {
    const Instruction i = g.kind == Guard::Kind::channel ? Instruction::disc
                          : g.kind == Guard::Kind::timer ? Instruction::dist
                                                         : Instruction::diss;
    cycles += static_cast<std::uint64_t>(costs[i].base);
  }
  // Charge first: an outputter that commits while the disables run is still seen by them.
  node.compute_cycles(cycles);
  const Tick period = node.timer_period(process_.priority());
  const std::int32_t clock = Timer::clock_at(kernel_.now(), period);
  std::size_t selected = guards_.size();
  for (std::size_t i = 0; i < guards_.size(); ++i) {
    const Guard& g = guards_[i];
    bool ready = false;
    switch (g.kind) {
    case Guard::Kind::channel:
      ready = g.precondition && g.channel->disable(*this);
      break;
    case Guard::Kind::timer:
      ready = g.precondition && is_after(clock, g.after);
      break;
    case Guard::Kind::skip:
      ready = g.precondition;
      break;
    }
    if (ready && selected == guards_.size())
      selected = i;
  }
  enabled_ = 0;
  return selected;
}

std::size_t AltState::run() {
  for (;;) {
    enable_all();
    wait();
    const std::size_t selected = disable_all();
    if (selected < guards_.size())
      return selected;
    // Woken but nothing is ready any more (cannot happen with one-to-one channels); retry.
    ready_ = false;
  }
}

std::size_t pri_alt(std::span<const Guard> guards) {
  emulator::Kernel* kernel = emulator::Kernel::active();
  emulator::Process* process = kernel != nullptr ? kernel->current() : nullptr;
  if (process == nullptr)
    throw std::logic_error("ALT used outside a simulated process");
  AltState state(*kernel, *process, guards);
  return state.run();
}

} // namespace marsokhod::occam_port
