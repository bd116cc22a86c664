// Reading a platform file: nodes, devices and the wiring between them.

#include "marsokhod/emulator/platform/platform.hpp"

#include "platform/platform_overswitch.hpp"
#include "platform/platform_processor.hpp"
#include "platform/platform_toml.hpp"

#include "marsokhod/emulator/platform/platform_limits.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <utility>

namespace marsokhod::emulator {
namespace {

using detail::platform_table;
using io::TomlTable;
namespace limits = platform_limits;

/// Visits every table of an array of tables, failing on anything else in it and on more than
/// `most` tables.
template <typename Visit>
void for_each_table(TomlTable& top, std::string_view key, std::size_t most, Visit visit) {
  const toml::array* array = top.optional_array(key);
  if (array == nullptr)
    return;
  std::size_t count = 0;
  for (const toml::node& element : *array) {
    if (!element.is_table())
      top.fail(key, fmt::format("must be written as [[{}]] tables", key));
    if (++count > most)
      throw PlatformError(top.file(), static_cast<int>(element.source().begin.line),
                          std::string(key),
                          fmt::format("a platform has at most {} [[{}]] tables", most, key));
    visit(*element.as_table());
  }
}

bool is_name_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}

std::string read_name(TomlTable& reader) {
  const std::string name = reader.string("name");
  if (name.empty() || name.size() > limits::kMaxNameLength ||
      !std::all_of(name.begin(), name.end(), is_name_character))
    reader.fail("name", fmt::format("'{}' must be 1 to {} letters, digits, '_' or '-'", name,
                                    limits::kMaxNameLength));
  return name;
}

NodeSpec read_node(TomlTable& node, const detail::ProcessorSpec& processor) {
  NodeSpec spec;
  spec.line = static_cast<int>(node.table().source().begin.line);
  spec.name = read_name(node);
  spec.speed_grade = node.string("speed_grade");
  const auto grade = processor.speed_grades.find(spec.speed_grade);
  if (grade == processor.speed_grades.end())
    node.fail("speed_grade", fmt::format("'{}' is not a speed grade of the {} processor file",
                                         spec.speed_grade, processor.type));
  spec.cpu = processor.cpu;
  spec.cpu.cycle = grade->second;
  spec.cpu.costs.wait_states =
      node.optional_integer_in("wait_states", 0, limits::kMaxWaitStates, 0, "cycles");
  const std::int64_t external_kb =
      node.integer_in("external_kb", std::int64_t{1}, limits::kMaxExternalKb,
                      "KB, the T805 address space above #80001000");
  spec.memory =
      MemoryConfig{processor.cpu.on_chip_bytes, static_cast<std::size_t>(external_kb) * 1024,
                   processor.reserved_on_chip_bytes};
  spec.powered = node.boolean("powered", true);
  spec.links = processor.links;
  node.reject_unknown_keys();
  return spec;
}

DeviceKind read_device_kind(TomlTable& device) {
  const std::string kind = device.string("kind");
  if (kind == "frame_store")
    return DeviceKind::frame_store;
  if (kind == "host")
    return DeviceKind::host;
  device.fail("kind", fmt::format("'{}' is not a device kind (frame_store, host)", kind));
}

DeviceSpec read_device(TomlTable& device) {
  DeviceSpec spec;
  spec.line = static_cast<int>(device.table().source().begin.line);
  spec.name = read_name(device);
  spec.kind = read_device_kind(device);
  spec.links = device.integer_in("links", 1, limits::kMaxDeviceLinks);
  spec.powered = device.boolean("powered", true);
  if (spec.kind == DeviceKind::frame_store) {
    spec.cameras = device.integer_in("cameras", 1, limits::kMaxCameras,
                                     "cameras, chosen by a one-byte request");
    spec.image_width = device.integer_in("image_width", 1, limits::kMaxImageSide, "pixels");
    spec.image_height = device.integer_in("image_height", 1, limits::kMaxImageSide, "pixels");
    spec.bits_per_pixel = device.integer_in("bits_per_pixel", 1, 16);
    if (spec.bits_per_pixel != 8 && spec.bits_per_pixel != 16)
      device.fail("bits_per_pixel", "must be 8 or 16");
  }
  device.reject_unknown_keys();
  return spec;
}

/// A link speed of the platform file: an integer the processor offers.
int read_speed(TomlTable& reader, std::string_view key, const detail::ProcessorSpec& processor,
               std::optional<int> fallback) {
  const int speed =
      fallback ? reader.optional_integer_in(key, limits::kMinLinkMbps, limits::kMaxLinkMbps,
                                            *fallback, "Mbit/s")
               : reader.integer_in(key, limits::kMinLinkMbps, limits::kMaxLinkMbps, "Mbit/s");
  const auto& speeds = processor.link_speeds_mbps;
  if (std::find(speeds.begin(), speeds.end(), speed) == speeds.end())
    reader.fail(key, fmt::format("{} Mbit/s is not a link speed of the {} ({} Mbit/s)", speed,
                                 processor.type, fmt::join(speeds, ", ")));
  return speed;
}

/// The canonical link number of "linkN": N decimal, without sign or leading zero.
std::optional<int> link_number(std::string_view text) {
  constexpr std::string_view kLink = "link";
  if (!text.starts_with(kLink))
    return std::nullopt;
  const std::string_view digits = text.substr(kLink.size());
  if (digits.empty() || (digits.size() > 1 && digits.front() == '0') ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  return io::parse_integer<int>(digits);
}

/// Reads the [[wire]] tables: each end parsed once into (owner, link number), so that a link
/// end is wired at most once however it is written.
class WireReader {
public:
  WireReader(const PlatformSpec& platform, const detail::ProcessorSpec& processor)
      : processor_(processor) {
    for (const NodeSpec& node : platform.nodes)
      owners_.emplace(node.name, Owner{node.links, false});
    for (const DeviceSpec& device : platform.devices)
      owners_.emplace(device.name, Owner{device.links, true});
  }

  WireSpec read(TomlTable& wire, int default_speed) {
    WireSpec spec;
    spec.line = static_cast<int>(wire.table().source().begin.line);
    spec.a = endpoint(wire, "a");
    spec.b = endpoint(wire, "b");
    spec.speed_mbps = read_speed(wire, "speed_mbps", processor_, default_speed);
    spec.broken = wire.boolean("broken", false);
    wire.reject_unknown_keys();
    return spec;
  }

private:
  struct Owner {
    int links;
    bool device;
  };

  LinkEndpoint endpoint(TomlTable& wire, std::string_view key) {
    const std::string text = wire.string(key);
    const auto dot = text.find('.');
    const std::optional<int> link = dot == std::string::npos
                                        ? std::nullopt
                                        : link_number(std::string_view(text).substr(dot + 1));
    if (dot == 0 || !link)
      wire.fail(key, fmt::format("'{}' must be written NAME.linkN, N a link number without sign "
                                 "or leading zeros (module0.link0)",
                                 text));
    LinkEndpoint point{text.substr(0, dot), *link, false};
    const auto owner = owners_.find(point.owner);
    if (owner == owners_.end())
      wire.fail(key, fmt::format("'{}' is no node or device of this platform", point.owner));
    point.device = owner->second.device;
    const int links = owner->second.links;
    if (point.link >= links)
      wire.fail(key, fmt::format("{} has {} links (link0..link{}); link{} does not exist",
                                 point.owner, links, links - 1, point.link));
    const int line = wire.line_of(key);
    const auto [used, fresh] = wired_.emplace(std::pair(point.owner, point.link), line);
    if (!fresh)
      wire.fail(key, fmt::format("{} is already wired on line {} (a link end takes one wire)",
                                 point.text(), used->second));
    return point;
  }

  const detail::ProcessorSpec& processor_;
  std::map<std::string, Owner, std::less<>> owners_;
  /// Each wired end, parsed, and the line that wired it.
  std::map<std::pair<std::string, int>, int> wired_;
};

void check_unique_names(const PlatformSpec& platform) {
  std::map<std::string, int> seen;
  auto check = [&](const std::string& name, int line) {
    const auto [it, fresh] = seen.emplace(name, line);
    if (!fresh)
      throw PlatformError(platform.source, line, "name",
                          fmt::format("'{}' is already declared on line {}", name, it->second));
  };
  for (const NodeSpec& node : platform.nodes)
    check(node.name, node.line);
  for (const DeviceSpec& device : platform.devices)
    check(device.name, device.line);
}

/// The processor file a platform names; a file that cannot be read at all is reported at the
/// platform's 'processor' key, so that the message shows where the path came from.
detail::ProcessorSpec read_processor(TomlTable& reader, const std::filesystem::path& platform) {
  const std::string named = reader.string("processor");
  if (named.empty())
    reader.fail("processor", "must name the processor file (relative to this file)");
  const std::filesystem::path file = platform.parent_path() / named;
  try {
    return detail::load_processor(file.string());
  } catch (const detail::UnreadableFileError& error) {
    reader.fail("processor", error.what());
  }
}

} // namespace

const char* to_string(DeviceKind kind) {
  return kind == DeviceKind::frame_store ? "frame_store" : "host";
}

std::string LinkEndpoint::text() const {
  return fmt::format("{}.link{}", owner, link);
}

const NodeSpec* PlatformSpec::find_node(const std::string& node_name) const {
  const auto it = std::find_if(nodes.begin(), nodes.end(),
                               [&](const NodeSpec& node) { return node.name == node_name; });
  return it == nodes.end() ? nullptr : &*it;
}

const DeviceSpec* PlatformSpec::find_device(const std::string& device_name) const {
  const auto it = std::find_if(devices.begin(), devices.end(), [&](const DeviceSpec& device) {
    return device.name == device_name;
  });
  return it == devices.end() ? nullptr : &*it;
}

const WireSpec* PlatformSpec::wire_at(const LinkEndpoint& endpoint) const {
  const auto it = std::find_if(wires.begin(), wires.end(), [&](const WireSpec& wire) {
    return wire.a == endpoint || wire.b == endpoint;
  });
  return it == wires.end() ? nullptr : &*it;
}

const WireSpec* PlatformSpec::wire_between(const std::string& x, const std::string& y) const {
  const WireSpec* found = nullptr;
  for (const WireSpec& wire : wires) {
    const bool joins =
        !wire.a.device && !wire.b.device &&
        ((wire.a.owner == x && wire.b.owner == y) || (wire.a.owner == y && wire.b.owner == x));
    if (joins && (found == nullptr || found->broken))
      found = &wire;
  }
  return found;
}

PlatformSpec load_platform(const std::filesystem::path& file) {
  PlatformSpec platform;
  platform.source = file.string();
  const toml::table root = detail::parse_toml_file(platform.source, "platform file");
  TomlTable top = platform_table(root, platform.source, "the platform file");
  const toml::table* header = top.optional_table("platform");
  if (header == nullptr)
    throw PlatformError(platform.source, 1, "platform", "missing [platform] table");
  TomlTable reader = platform_table(*header, platform.source, "[platform]");
  platform.name = reader.string("name");
  platform.description = reader.optional_string("description").value_or("");
  const detail::ProcessorSpec processor = read_processor(reader, file);
  platform.processor_type = processor.type;
  platform.link_speeds_mbps = processor.link_speeds_mbps;
  platform.speed_grades = processor.speed_grades;
  platform.link_timing = processor.link_timing;
  const int default_speed = read_speed(reader, "link_speed_mbps", processor, std::nullopt);
  reader.reject_unknown_keys();

  for_each_table(top, "node", limits::kMaxNodes, [&](const toml::table& table) {
    TomlTable node = platform_table(table, platform.source, "a [[node]]");
    platform.nodes.push_back(read_node(node, processor));
  });
  if (platform.nodes.empty())
    throw PlatformError(platform.source, 1, "node", "a platform needs at least one [[node]]");
  for_each_table(top, "device", limits::kMaxDevices, [&](const toml::table& table) {
    TomlTable device = platform_table(table, platform.source, "a [[device]]");
    platform.devices.push_back(read_device(device));
  });
  check_unique_names(platform);
  WireReader wires(platform, processor);
  // Every wire takes two link ends, each at most once: more wires than that is refused by
  // the ends themselves.
  for_each_table(top, "wire", std::numeric_limits<std::size_t>::max(),
                 [&](const toml::table& table) {
                   TomlTable wire = platform_table(table, platform.source, "a [[wire]]");
                   platform.wires.push_back(wires.read(wire, default_speed));
                 });
  if (const toml::table* table = top.optional_table("overswitch")) {
    TomlTable overswitch = platform_table(*table, platform.source, "[overswitch]");
    platform.overswitch = detail::read_overswitch(overswitch, platform);
  }
  top.reject_unknown_keys();
  return platform;
}

} // namespace marsokhod::emulator
