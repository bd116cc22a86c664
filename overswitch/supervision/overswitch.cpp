// The overswitch's watchdogs and its failover: power off, take a spare, boot it, or stop.

#include "marsokhod/overswitch/supervision/overswitch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace marsokhod::overswitch {

const char* to_string(OverswitchEvent::Kind kind) {
  switch (kind) {
  case OverswitchEvent::Kind::watchdog_expired:
    return "watchdog expired";
  case OverswitchEvent::Kind::powered_off:
    return "powered off";
  case OverswitchEvent::Kind::boot_started:
    return "boot started";
  case OverswitchEvent::Kind::booted:
    return "booted";
  case OverswitchEvent::Kind::boot_failed:
    return "boot failed";
  case OverswitchEvent::Kind::safe_stop:
    return "safe stop";
  case OverswitchEvent::Kind::link_trouble:
    return "link trouble";
  case OverswitchEvent::Kind::restarted:
    return "cycle restarted";
  case OverswitchEvent::Kind::declared_failed:
    return "declared failed";
  }
  return "?";
}

Overswitch::Overswitch(emulator::Kernel& kernel, const emulator::OverswitchSpec& spec,
                       std::vector<emulator::Node*> modules, BootFunction boot)
    : kernel_(&kernel), spec_(spec), boot_(std::move(boot)) {
  if (modules.size() != spec.modules.size())
    throw std::invalid_argument(fmt::format("the overswitch switches {} modules, given {}",
                                            spec.modules.size(), modules.size()));
  for (std::size_t i = 0; i < modules.size(); ++i) {
    if (modules[i] == nullptr || modules[i]->name() != spec.modules[i])
      throw std::invalid_argument(
          fmt::format("the overswitch's module {} must be {}", i, spec.modules[i]));
    modules_.push_back({modules[i], State::off, 0});
  }
}

void Overswitch::stop() {
  stopped_ = true;
  for (Module& m : modules_)
    disarm(m);
}

void Overswitch::start() {
  for (Module& m : modules_) {
    if (!m.node->powered())
      continue;
    m.state = State::running;
    arm(m, spec_.watchdog_timeout);
  }
}

Overswitch::Module& Overswitch::module_of(const emulator::Node& node) {
  const auto found = std::find_if(modules_.begin(), modules_.end(),
                                  [&node](const Module& m) { return m.node == &node; });
  if (found == modules_.end())
    throw std::logic_error(node.name() + " is not switched by the overswitch");
  return *found;
}

// A watchdog keeps the run alive: with every module hung, its expiry is what happens next.
void Overswitch::arm(Module& m, emulator::Tick after) {
  disarm(m);
  if (stopped_)
    return;
  m.deadline =
      kernel_->schedule_after(after, emulator::event_priority::timer, [this, &m] { expire(m); });
}

void Overswitch::disarm(Module& m) {
  if (m.deadline != 0)
    kernel_->cancel(m.deadline);
  m.deadline = 0;
}

void Overswitch::kick(const emulator::Node& node) {
  Module& m = module_of(node);
  if (m.state == State::running && !safe_stopped_)
    arm(m, spec_.watchdog_timeout);
}

std::vector<emulator::Node*> Overswitch::running() const {
  std::vector<emulator::Node*> nodes;
  for (const Module& m : modules_)
    if (m.state == State::running)
      nodes.push_back(m.node);
  return nodes;
}

void Overswitch::log(OverswitchEvent::Kind kind, const Module& m, std::string detail) {
  events_.push_back({kernel_->now(), kind, m.node->name(), std::move(detail)});
  if (emulator::TraceSink* sink = kernel_->trace())
    sink->instant(sink->track("overswitch", "events"), kernel_->now(),
                  fmt::format("{}: {}", to_string(kind), m.node->name()), events_.back().detail);
}

void Overswitch::expire(Module& m) {
  m.deadline = 0;
  if (m.state == State::booting) {
    boot_timed_out(m, m.failover);
    return;
  }
  log(OverswitchEvent::Kind::watchdog_expired, m,
      fmt::format("no heartbeat for {} us", emulator::to_microseconds(spec_.watchdog_timeout)));
  fail(m, "watchdog");
  take_spare(Failover{m.node->name(), {}, {}, kernel_->now(), 0, false});
}

void Overswitch::declare_failed(const emulator::Node& module, const std::string& why) {
  Module& m = module_of(module);
  if (m.state != State::running || safe_stopped_)
    return;
  log(OverswitchEvent::Kind::declared_failed, m, why);
  fail(m, "declared failed");
  take_spare(Failover{m.node->name(), {}, {}, kernel_->now(), 0, false});
}

void Overswitch::note(OverswitchEvent::Kind kind, const std::string& module, std::string detail) {
  events_.push_back({kernel_->now(), kind, module, std::move(detail)});
  if (emulator::TraceSink* sink = kernel_->trace())
    sink->instant(sink->track("overswitch", "events"), kernel_->now(),
                  fmt::format("{}: {}", to_string(kind), module), events_.back().detail);
}

// A failed module stays off: the overswitch never powers it again.
void Overswitch::fail(Module& m, const std::string& why) {
  disarm(m);
  m.state = State::failed;
  m.node->power_off();
  log(OverswitchEvent::Kind::powered_off, m, why);
}

// The first module never powered, booted from the first running one.
void Overswitch::take_spare(Failover failover) {
  if (safe_stopped_)
    return;
  const auto spare = std::find_if(
      modules_.begin(), modules_.end(), [](const Module& m) { return m.state == State::off; });
  const auto from = std::find_if(modules_.begin(), modules_.end(),
                                 [](const Module& m) { return m.state == State::running; });
  failovers_.push_back(failover);
  if (spare == modules_.end())
    return safe_stop(fmt::format("{} failed and no spare is left", failover.failed));
  if (from == modules_.end())
    return safe_stop(fmt::format("{} failed and no running module is left to boot a spare from",
                                 failover.failed));
  const std::size_t index = failovers_.size() - 1;
  failovers_[index].spare = spare->node->name();
  failovers_[index].booted_from = from->node->name();
  spare->state = State::booting;
  spare->failover = index;
  spare->node->power_on();
  log(OverswitchEvent::Kind::boot_started, *spare, "from " + from->node->name());
  arm(*spare, spec_.boot_allowance);
  Module& booting = *spare;
  boot_(*booting.node, *from->node, [this, &booting, index] {
    if (booting.state == State::booting)
      booted(booting, index);
  });
}

void Overswitch::booted(Module& spare, std::size_t failover) {
  spare.state = State::running;
  arm(spare, spec_.watchdog_timeout);
  failovers_[failover].booted = kernel_->now();
  failovers_[failover].ok = true;
  log(OverswitchEvent::Kind::booted, spare,
      fmt::format("{} us after {} was found failed",
                  emulator::to_microseconds(kernel_->now() - failovers_[failover].detected),
                  failovers_[failover].failed));
  if (on_booted_)
    on_booted_(failovers_[failover]);
}

void Overswitch::boot_timed_out(Module& spare, std::size_t failover) {
  log(OverswitchEvent::Kind::boot_failed, spare,
      fmt::format("not running {} us after its power-on",
                  emulator::to_microseconds(spec_.boot_allowance)));
  fail(spare, "boot failed");
  Failover again = failovers_[failover];
  again.failed = spare.node->name();
  again.spare.clear();
  again.booted_from.clear();
  again.detected = kernel_->now();
  take_spare(again);
}

void Overswitch::safe_stop(const std::string& why) {
  safe_stopped_ = true;
  for (Module& m : modules_)
    disarm(m);
  events_.push_back({kernel_->now(), OverswitchEvent::Kind::safe_stop, "", why});
  if (emulator::TraceSink* sink = kernel_->trace())
    sink->instant(sink->track("overswitch", "events"), kernel_->now(), "safe stop", why);
  if (on_safe_stop_)
    on_safe_stop_();
}

void require_overswitch(const emulator::PlatformSpec& platform, const std::string& named_in) {
  if (platform.overswitch)
    return;
  throw NoOverswitchError(fmt::format("{}: platform {} has no [overswitch] table, so no module can "
                                      "fail over (the onboard platform has one)",
                                      named_in, platform.name));
}

} // namespace marsokhod::overswitch
