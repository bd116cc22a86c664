// Link faults as the supervisor injects them, and what it does with the troubles reported.

#include "marsokhod/emulator/links/link.hpp"
#include "marsokhod/overswitch/faults/split_mix.hpp"
#include "marsokhod/overswitch/supervision/failover_supervisor.hpp"

#include <fmt/format.h>

namespace marsokhod::overswitch {
namespace {

/// "module1.link0" -> "module1".
std::string node_of_port(const emulator::LinkPort& port) {
  return port.name().substr(0, port.name().rfind('.'));
}

std::string wire_name(const std::string& a, const std::string& b) {
  return a < b ? a + "-" + b : b + "-" + a;
}

} // namespace

nav_program::LinkGuard FailoverSupervisor::link_guard() const {
  return {platform_->overswitch->link_timeout, protection_.link_checksums};
}

// The wire the fault cuts: `out` is the one the module's link drives, `in` the one it listens
// to; a lost acknowledge or a flipped bit is on one of them.
void FailoverSupervisor::strike_link(emulator::Node& node, InjectedFault& injected) {
  const Fault& fault = injected.fault;
  emulator::LinkPort* port = node.link(fault.link);
  if (port == nullptr) {
    error_ = fmt::format("fault {}: {} has no link {}", describe(fault), node.name(), fault.link);
    control_->abandon(*error_);
    return;
  }
  emulator::Link& link = port->link();
  const int mine = port->end();
  const int from = fault.direction == LinkDirection::in ? 1 - mine : mine;
  const std::string peer = node_of_port(link.port(1 - mine));
  switch (fault.kind) {
  case Fault::Kind::link_down: {
    const bool both = fault.direction == LinkDirection::both;
    link.set_wire_dead(from, true);
    if (both)
      link.set_wire_dead(1 - from, true);
    injected.effect = fmt::format("{} to {} dead{}", both ? "both wires" : "the wire", peer,
                                  fault.duration ? " for a while" : "");
    if (fault.duration)
      control_->kernel().schedule_after(*fault.duration, emulator::event_priority::power,
                                        [&link, from, both] {
                                          link.set_wire_dead(from, false);
                                          if (both)
                                            link.set_wire_dead(1 - from, false);
                                        });
    return;
  }
  case Fault::Kind::link_bit: {
    const unsigned bit =
        fault.data_bit.value_or(static_cast<unsigned>(SplitMix(fault.draw, 0x11B).below(8)));
    link.flip_data_bit(from, fault.byte, bit);
    injected.effect = fmt::format("bit {} of data byte {} from {} inverted", bit, fault.byte,
                                  node_of_port(link.port(from)));
    return;
  }
  case Fault::Kind::ack_lost:
    link.lose_acknowledge(from);
    injected.effect =
        fmt::format("the next acknowledge from {} lost", node_of_port(link.port(from)));
    return;
  default:
    return;
  }
}

// A trouble on a wire may be a moment's (a lost acknowledge, a flipped bit, a wire down for a
// while): the cycle is restarted on the same pair, its links reset at both ends. A second one on
// the same wire in the run means it stays: the module at the far end is failed, and its spare,
// joined to the reporting module by a wire of its own, takes its share. Traffic cannot go round
// through a third module: the overswitch powers two.
void FailoverSupervisor::link_trouble(const std::string& module, int link,
                                      nav_program::LinkTrouble trouble) {
  emulator::LinkPort* port = control_->node(module).link(link);
  if (port == nullptr)
    return;
  const std::string peer = node_of_port(port->link().port(1 - port->end()));
  troubles_.push_back({control_->kernel().now(), module, link, peer, trouble});
  overswitch_->note(OverswitchEvent::Kind::link_trouble, module,
                    fmt::format("link{} to {}: {}", link, peer, nav_program::to_string(trouble)));
  if (control_->program_finished() || overswitch_->safe_stopped())
    return;
  // A restart needs both ends to start again; a module that has stopped (it hung or lost its
  // power, so its link went silent) cannot, and is failed at once rather than a timeout later.
  emulator::Node& far = control_->node(peer);
  if (!far.running()) {
    overswitch_->declare_failed(far, fmt::format("it stopped: its link to {} is silent", module));
    return;
  }
  if (++wire_troubles_[wire_name(module, peer)] == 1) {
    control_->kernel().schedule_after(0, emulator::event_priority::normal, [this, module, peer] {
      // A module struck in the same instant is left to its watchdog.
      if (!control_->node(module).running() || !control_->node(peer).running())
        return;
      overswitch_->note(OverswitchEvent::Kind::restarted, module,
                        "on the same pair, its links reset");
      control_->restart({});
    });
    return;
  }
  overswitch_->declare_failed(control_->node(peer),
                              fmt::format("its link to {} failed again", module));
}

} // namespace marsokhod::overswitch
