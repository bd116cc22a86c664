// The checks of a placement that need the whole file: every process of the program placed,
// every channel between two nodes on a wire, every device reachable from its process's node.

#include "placement/placement_checks.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace marsokhod::nav_program::detail {
using emulator::PlatformSpec;
using emulator::WireSpec;

const WireSpec* device_wire(const PlatformSpec& platform, const std::string& node) {
  for (const WireSpec& wire : platform.wires) {
    if (wire.broken)
      continue;
    const bool a_is_node = !wire.a.device && wire.a.owner == node;
    const bool b_is_node = !wire.b.device && wire.b.owner == node;
    const emulator::LinkEndpoint& other = a_is_node ? wire.b : wire.a;
    if ((!a_is_node && !b_is_node) || !other.device)
      continue;
    const emulator::DeviceSpec* device = platform.find_device(other.owner);
    if (device != nullptr && device->powered &&
        (device->kind == emulator::DeviceKind::frame_store ||
         device->kind == emulator::DeviceKind::host))
      return &wire;
  }
  return nullptr;
}

void check_shape(const ProgramShape& shape) {
  const std::set<std::string, std::less<>> processes(shape.processes.begin(),
                                                     shape.processes.end());
  if (processes.size() != shape.processes.size())
    throw std::invalid_argument("program shape: a process is listed twice");
  auto known = [&](const std::string& process, const std::string& what) {
    if (!processes.contains(process))
      throw std::invalid_argument(fmt::format(
          "program shape: {} names process '{}', which it does not list", what, process));
  };
  for (const ProgramShape::Channel& channel : shape.channels) {
    known(channel.from, fmt::format("channel '{}'", channel.name));
    known(channel.to, fmt::format("channel '{}'", channel.name));
  }
  for (const ProgramShape::DeviceUse& use : shape.devices)
    known(use.process, fmt::format("the device use '{}'", use.purpose));
}

void check_program_fits(const Placement& placement, int header_line, const PlatformSpec& platform,
                        const ProgramShape& shape) {
  // Every entry names a distinct process of the shape, so each is found here once.
  std::map<std::string, std::size_t, std::less<>> index;
  for (std::size_t i = 0; i < placement.places.size(); ++i)
    index.emplace(placement.places[i].process, i);

  std::vector<std::string> missing;
  for (const std::string& process : shape.processes)
    if (!index.contains(process))
      missing.push_back(process);
  if (!missing.empty())
    throw PlacementError(placement.source, header_line, "process",
                         fmt::format("not placed: {} (every process of the program needs a "
                                     "[[process]] with its name and node)",
                                     fmt::join(missing, ", ")));

  // An occam configuration maps one channel onto each direction of a link.
  std::map<std::pair<std::string, std::string>, const ProgramShape::Channel*> directions;
  for (const ProgramShape::Channel& channel : shape.channels) {
    const std::size_t from = index.at(channel.from);
    const std::size_t to = index.at(channel.to);
    const ProcessPlace& a = placement.places[from];
    const ProcessPlace& b = placement.places[to];
    if (a.node == b.node)
      continue;
    const WireSpec* wire = platform.wire_between(a.node, b.node);
    if (wire != nullptr && !wire->broken) {
      const auto [taken, added] = directions.emplace(std::pair{a.node, b.node}, &channel);
      if (added)
        continue;
      const std::size_t later = std::max(from, to);
      throw PlacementError(
          placement.source, placement.places[later].line, fmt::format("process[{}].node", later),
          fmt::format("channels '{}' and '{}' would both need the link from {} to {} ({}:{}); "
                      "occam places one channel on each direction of a link: place them "
                      "otherwise",
                      taken->second->name, channel.name, a.node, b.node, platform.source,
                      wire->line));
    }
    // Reported where the second of the two is placed: the entry that broke the route.
    const std::size_t later = std::max(from, to);
    const std::string why = wire == nullptr
                                ? fmt::format("no wire joins {} and {}", a.node, b.node)
                                : fmt::format("the wire joining {} and {} ({}:{}) is broken",
                                              a.node, b.node, platform.source, wire->line);
    throw PlacementError(placement.source, placement.places[later].line,
                         fmt::format("process[{}].node", later),
                         fmt::format("channel '{}' from {} (on {}) to {} (on {}) has no route: {}; "
                                     "place both on one node or on two nodes wired to each other",
                                     channel.name, a.process, a.node, b.process, b.node, why));
  }

  for (const ProgramShape::DeviceUse& use : shape.devices) {
    const std::size_t i = index.at(use.process);
    const ProcessPlace& place = placement.places[i];
    if (device_wire(platform, place.node) != nullptr)
      continue;
    std::vector<std::string> able;
    for (const emulator::NodeSpec& node : platform.nodes)
      if (node.powered && device_wire(platform, node.name) != nullptr)
        able.push_back(node.name);
    throw PlacementError(
        placement.source, place.line, fmt::format("process[{}].node", i),
        fmt::format("process '{}' needs {}, but its node {} has no unbroken wire to a powered "
                    "frame_store or host device ({})",
                    use.process, use.purpose, place.node,
                    able.empty()
                        ? std::string("no powered node has one")
                        : fmt::format("powered nodes with one: {}", fmt::join(able, ", "))));
  }
}

} // namespace marsokhod::nav_program::detail
