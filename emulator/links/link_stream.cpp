// The link throughput experiment: byte streams between two nodes over one wire.

#include "marsokhod/emulator/links/link_stream.hpp"

#include "marsokhod/emulator/kernel/kernel.hpp"
#include "marsokhod/emulator/links/link_network.hpp"
#include "marsokhod/emulator/node/node.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <memory_resource>
#include <stdexcept>
#include <vector>

namespace marsokhod::emulator {
namespace {

/// The byte at position `i` of direction `direction`: varied enough to catch a lost,
/// duplicated or reordered byte.
std::byte pattern_byte(std::uint64_t i, int direction) {
  const std::uint64_t mixed = (i * 0x9E3779B97F4A7C15ULL) >> 56;
  return std::byte(
      static_cast<unsigned char>(mixed ^ (i >> 8) ^ static_cast<unsigned>(direction * 0x5A)));
}

const WireSpec& pick_wire(const PlatformSpec& platform) {
  for (const WireSpec& wire : platform.wires) {
    if (wire.a.device || wire.b.device || wire.broken || wire.a.owner == wire.b.owner)
      continue;
    if (platform.find_node(wire.a.owner)->powered && platform.find_node(wire.b.owner)->powered)
      return wire;
  }
  throw std::invalid_argument(
      fmt::format("{}: no working wire joins two powered nodes", platform.source));
}

/// One direction's sender and receiver processes and what they saw.
struct Direction {
  LinkPort* from = nullptr;
  LinkPort* to = nullptr;
  Tick send_cost = 0;
  Tick receive_cost = 0;
  Tick arrived = 0;
  bool intact = true;
};

// The message buffers live in the nodes' own memory, as on the real machine: the trace's
// memory counters show them, and a message larger than a node's memory is a memory fault.
void spawn_direction(Kernel& kernel, Node& sender, Node& receiver, Direction& d, int index,
                     const LinkStreamOptions& options) {
  const std::string tag = index == 0 ? "" : "_back";
  sender.spawn(
      "stream_out" + tag,
      [&kernel, &d, &sender, index, options] {
        std::pmr::vector<std::byte> message(options.message_bytes, &sender.memory());
        for (std::uint64_t sent = 0; sent < options.bytes;) {
          const auto size = static_cast<std::size_t>(
              std::min<std::uint64_t>(message.size(), options.bytes - sent));
          for (std::size_t i = 0; i < size; ++i)
            message[i] = pattern_byte(sent + i, index);
          kernel.consume(d.send_cost);
          d.from->output(std::span(message.data(), size));
          sent += size;
        }
      },
      NodeSpawnOptions{Priority::high});
  receiver.spawn(
      "stream_in" + tag,
      [&kernel, &d, &receiver, index, options] {
        std::pmr::vector<std::byte> message(options.message_bytes, &receiver.memory());
        for (std::uint64_t got = 0; got < options.bytes;) {
          const auto size = static_cast<std::size_t>(
              std::min<std::uint64_t>(message.size(), options.bytes - got));
          kernel.consume(d.receive_cost);
          d.to->input(std::span(message.data(), size));
          for (std::size_t i = 0; i < size; ++i)
            d.intact = d.intact && message[i] == pattern_byte(got + i, index);
          got += size;
        }
        d.arrived = kernel.now();
      },
      NodeSpawnOptions{Priority::high});
}

} // namespace

LinkStreamResult run_link_stream(const PlatformSpec& platform, const LinkStreamOptions& options) {
  if (options.bytes == 0 || options.message_bytes == 0)
    throw std::invalid_argument("the stream needs at least one byte and one-byte messages");
  const WireSpec& wire = pick_wire(platform);
  const NodeSpec& node_a = *platform.find_node(wire.a.owner);
  const NodeSpec& node_b = *platform.find_node(wire.b.owner);

  Kernel kernel;
  kernel.set_trace(options.trace);
  LinkNetwork network(kernel, platform, options.mbps);
  // Every node of the platform, so that the trace shows the unpowered ones as such. Declared
  // after the network: the nodes (and any process still on them) go first.
  std::vector<std::unique_ptr<Node>> nodes;
  for (const NodeSpec& spec : platform.nodes) {
    nodes.push_back(std::make_unique<Node>(kernel, spec));
    network.attach(*nodes.back());
  }
  const auto node_named = [&nodes](const std::string& name) -> Node& {
    return **std::find_if(nodes.begin(), nodes.end(),
                          [&name](const auto& node) { return node->name() == name; });
  };
  LinkPort& port_a = network.require_port(wire.a.owner, wire.a.link);
  LinkPort& port_b = network.require_port(wire.b.owner, wire.b.link);

  const auto cost = [](const NodeSpec& node, Instruction instruction) {
    return node.cpu.costs[instruction].base * node.cpu.cycle;
  };
  std::vector<Direction> directions;
  directions.push_back(
      Direction{&port_a, &port_b, cost(node_a, Instruction::out), cost(node_b, Instruction::in)});
  if (options.both_ways)
    directions.push_back(
        Direction{&port_b, &port_a, cost(node_b, Instruction::out), cost(node_a, Instruction::in)});
  Node& a = node_named(node_a.name);
  Node& b = node_named(node_b.name);
  spawn_direction(kernel, a, b, directions[0], 0, options);
  if (options.both_ways)
    spawn_direction(kernel, b, a, directions[1], 1, options);

  const RunResult run = kernel.run();
  LinkStreamResult result;
  result.from = port_a.name();
  result.to = port_b.name();
  result.mbps = options.mbps.value_or(wire.speed_mbps);
  result.bytes_moved = options.bytes * directions.size();
  result.intact = run.reason == StopReason::finished;
  for (const Direction& d : directions) {
    result.elapsed = std::max(result.elapsed, d.arrived);
    result.intact = result.intact && d.intact;
  }
  result.bytes_per_second = static_cast<double>(result.bytes_moved) / to_seconds(result.elapsed);
  result.context_switches = kernel.context_switches();
  return result;
}

} // namespace marsokhod::emulator
