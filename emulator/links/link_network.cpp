// Every link of a platform, built from its wiring.

#include "marsokhod/emulator/links/link_network.hpp"

#include "marsokhod/emulator/node/node.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace marsokhod::emulator {
namespace {

bool powered(const PlatformSpec& platform, const LinkEndpoint& endpoint) {
  if (endpoint.device)
    return platform.find_device(endpoint.owner)->powered;
  return platform.find_node(endpoint.owner)->powered;
}

} // namespace

LinkNetwork::LinkNetwork(Kernel& kernel, const PlatformSpec& platform,
                         std::optional<int> speed_override_mbps) {
  if (speed_override_mbps) {
    const auto& speeds = platform.link_speeds_mbps;
    if (std::find(speeds.begin(), speeds.end(), *speed_override_mbps) == speeds.end())
      throw std::invalid_argument(fmt::format("{} Mbit/s is not a link speed of the {} ({} Mbit/s)",
                                              *speed_override_mbps, platform.processor_type,
                                              fmt::join(speeds, ", ")));
  }
  for (const WireSpec& wire : platform.wires) {
    const int mbps = speed_override_mbps.value_or(wire.speed_mbps);
    auto link = std::make_unique<Link>(kernel, wire.a.text(), wire.b.text(),
                                       LinkTiming::from(platform.link_timing, mbps),
                                       static_cast<std::uint32_t>(links_.size()));
    ports_[{wire.a.owner, wire.a.link}] = &link->port(0);
    ports_[{wire.b.owner, wire.b.link}] = &link->port(1);
    if (!powered(platform, wire.a))
      link->set_powered(0, false);
    if (!powered(platform, wire.b))
      link->set_powered(1, false);
    if (wire.broken)
      link->set_broken(true);
    links_.push_back(std::move(link));
  }
}

LinkPort* LinkNetwork::port(const std::string& owner, int link) {
  const auto found = ports_.find({owner, link});
  return found == ports_.end() ? nullptr : found->second;
}

LinkPort& LinkNetwork::require_port(const std::string& owner, int link) {
  LinkPort* found = port(owner, link);
  if (found == nullptr)
    throw std::invalid_argument(fmt::format("nothing is wired to {}.link{}", owner, link));
  return *found;
}

void LinkNetwork::attach(Node& node) {
  for (auto& [key, port] : ports_)
    if (key.first == node.name())
      node.attach_link(key.second, port->link(), port->end());
}

void LinkNetwork::set_powered(const std::string& owner, bool on) {
  for (auto& [key, port] : ports_)
    if (key.first == owner)
      port->link().set_powered(port->end(), on);
}

void LinkNetwork::set_broken(const std::string& owner, int link, bool broken) {
  require_port(owner, link).link().set_broken(broken);
}

} // namespace marsokhod::emulator
