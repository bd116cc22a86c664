// The emulated machine of a cycle: nodes, links, the devices serving the pair, device outputs.

#include "run/cycle_network.hpp"

#include "placement/placement_checks.hpp"

#include <algorithm>
#include <stdexcept>

namespace marsokhod::nav_program::detail {
namespace {

std::vector<std::byte> image_bytes(imaging::ImageView<const std::uint8_t> image) {
  std::vector<std::byte> bytes;
  bytes.reserve(static_cast<std::size_t>(image.width() * image.height()));
  for (int y = 0; y < image.height(); ++y) {
    const auto* row = reinterpret_cast<const std::byte*>(image.row(y));
    bytes.insert(bytes.end(), row, row + image.width());
  }
  return bytes;
}

/// The node wired to `device`'s link `link`, or "".
std::string node_at(const emulator::PlatformSpec& platform, const std::string& device, int link) {
  const emulator::WireSpec* wire = platform.wire_at({device, link, true});
  if (wire == nullptr)
    return {};
  return wire->a.owner == device ? wire->b.owner : wire->a.owner;
}

} // namespace

emulator::Node& CycleNetwork::node(const std::string& name) {
  const auto found = std::find_if(nodes.begin(), nodes.end(),
                                  [&name](const auto& n) { return n->name() == name; });
  if (found == nodes.end())
    throw std::out_of_range("the platform has no node " + name);
  return **found;
}

void build_network(CycleNetwork& net, const emulator::PlatformSpec& platform,
                   const CycleInput& input) {
  net.links = std::make_unique<emulator::LinkNetwork>(net.kernel, platform);
  for (const emulator::NodeSpec& spec : platform.nodes) {
    net.nodes.push_back(std::make_unique<emulator::Node>(net.kernel, spec));
    net.links->attach(*net.nodes.back());
  }
  const std::vector<std::byte> left = image_bytes(input.left);
  const std::vector<std::byte> right = image_bytes(input.right);
  // Both kinds of device serve the program: the frame store holds the pair's images, and the
  // host PC of a card serves them the same way.
  for (const emulator::DeviceSpec& device : platform.devices) {
    emulator::DeviceSpec serving = device;
    serving.kind = emulator::DeviceKind::frame_store;
    serving.cameras = 2;
    serving.image_width = input.left.width();
    serving.image_height = input.left.height();
    serving.bits_per_pixel = 8;
    const std::string name = device.name;
    net.devices.push_back(std::make_unique<emulator::FrameStore>(
        *net.links, serving, [left, right](int camera) { return camera == 0 ? left : right; },
        [&net, &platform, name](int link, std::vector<std::byte> bytes) {
          net.uploads.push_back({net.kernel.now(), node_at(platform, name, link), bytes.size()});
          net.telemetry.push_back(std::move(bytes));
        }));
    net.devices.back()->set_heartbeat_sink([&net, &platform, name](int link) {
      if (net.heartbeat_sink)
        net.heartbeat_sink(node_at(platform, name, link));
    });
    // A report names a link of the module and what went wrong; anything else is no report the
    // program writes and is ignored, as a device ignores a request it does not know.
    net.devices.back()->set_report_sink(
        [&net, &platform, name](int link, std::byte first, std::byte second) {
          const int trouble = std::to_integer<int>(second);
          const int module_link = std::to_integer<int>(first);
          if (!net.trouble_sink || module_link > 3 ||
              (trouble != static_cast<int>(LinkTrouble::timeout) &&
               trouble != static_cast<int>(LinkTrouble::checksum)))
            return;
          net.trouble_sink(node_at(platform, name, link), module_link,
                           static_cast<LinkTrouble>(trouble));
        });
  }
  for (const emulator::NodeSpec& node : platform.nodes) {
    const emulator::WireSpec* wire = device_wire(platform, node.name);
    if (wire == nullptr)
      continue;
    const bool node_is_a = wire->a.owner == node.name;
    const emulator::LinkEndpoint& mine = node_is_a ? wire->a : wire->b;
    const emulator::LinkEndpoint& device = node_is_a ? wire->b : wire->a;
    net.device_outputs[node.name] =
        std::make_unique<emulator::SharedOutput>(net.links->require_port(node.name, mine.link));
    const auto index = static_cast<std::size_t>(
        std::find_if(platform.devices.begin(), platform.devices.end(),
                     [&device](const emulator::DeviceSpec& d) { return d.name == device.owner; }) -
        platform.devices.begin());
    net.device_ends[node.name] = {net.devices.at(index).get(), device.link};
  }
}

} // namespace marsokhod::nav_program::detail
