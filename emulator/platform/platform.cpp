// Reading a platform file: nodes, devices and the wiring between them.

#include "marsokhod/emulator/platform/platform.hpp"

#include "platform/platform_processor.hpp"
#include "platform/platform_table_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <map>

namespace marsokhod::emulator {
namespace {

using detail::TableReader;

// The T805 address space above #80001000 (T805.md, "Clock and memory").
constexpr std::int64_t kMaxExternalKb = 0x7FFFF000LL / 1024;

std::string describe(const std::string& file, int line, const std::string& key,
                     const std::string& problem) {
  std::string where = line > 0 ? fmt::format("{}:{}", file, line) : file;
  if (key.empty())
    return fmt::format("{}: {}", where, problem);
  return fmt::format("{}: '{}': {}", where, key, problem);
}

/// Visits every table of an array of tables, failing on anything else in it.
template <typename Visit>
void for_each_table(TableReader& top, std::string_view key, Visit visit) {
  const toml::array* array = top.optional_array(key);
  if (array == nullptr)
    return;
  for (const toml::node& element : *array) {
    if (!element.is_table())
      top.fail(key, fmt::format("must be written as [[{}]] tables", key));
    visit(*element.as_table());
  }
}

std::string read_name(TableReader& reader) {
  const std::string name = reader.string("name");
  if (name.empty() || name.find_first_of(". \t") != std::string::npos)
    reader.fail("name", fmt::format("'{}' must be non-empty, without dots or spaces", name));
  return name;
}

NodeSpec read_node(TableReader& node, const detail::ProcessorSpec& processor) {
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
      static_cast<std::int32_t>(node.optional_integer("wait_states").value_or(0));
  if (spec.cpu.costs.wait_states < 0 || spec.cpu.costs.wait_states > 64)
    node.fail("wait_states", "must be between 0 and 64");
  const std::int64_t external_kb = node.integer_at_least("external_kb", 1);
  if (external_kb > kMaxExternalKb)
    node.fail("external_kb", fmt::format("exceeds the T805 address space ({} KB)", kMaxExternalKb));
  spec.memory =
      MemoryConfig{processor.cpu.on_chip_bytes, static_cast<std::size_t>(external_kb) * 1024,
                   processor.reserved_on_chip_bytes};
  spec.powered = node.boolean("powered", true);
  spec.links = processor.links;
  node.reject_unknown_keys();
  return spec;
}

DeviceKind read_device_kind(TableReader& device) {
  const std::string kind = device.string("kind");
  if (kind == "frame_store")
    return DeviceKind::frame_store;
  if (kind == "host")
    return DeviceKind::host;
  device.fail("kind", fmt::format("'{}' is not a device kind (frame_store, host)", kind));
}

DeviceSpec read_device(TableReader& device) {
  DeviceSpec spec;
  spec.line = static_cast<int>(device.table().source().begin.line);
  spec.name = read_name(device);
  spec.kind = read_device_kind(device);
  spec.links = static_cast<int>(device.integer_at_least("links", 1));
  spec.powered = device.boolean("powered", true);
  if (spec.kind == DeviceKind::frame_store) {
    spec.cameras = static_cast<int>(device.integer_at_least("cameras", 1));
    spec.image_width = static_cast<int>(device.integer_at_least("image_width", 1));
    spec.image_height = static_cast<int>(device.integer_at_least("image_height", 1));
    spec.bits_per_pixel = static_cast<int>(device.integer_at_least("bits_per_pixel", 1));
    if (spec.bits_per_pixel != 8 && spec.bits_per_pixel != 16)
      device.fail("bits_per_pixel", "must be 8 or 16");
  }
  device.reject_unknown_keys();
  return spec;
}

class WireReader {
public:
  WireReader(const PlatformSpec& platform, const detail::ProcessorSpec& processor)
      : platform_(platform), processor_(processor) {}

  WireSpec read(TableReader& wire, int default_speed) {
    WireSpec spec;
    spec.line = static_cast<int>(wire.table().source().begin.line);
    spec.a = endpoint(wire, "a");
    spec.b = endpoint(wire, "b");
    spec.speed_mbps = static_cast<int>(wire.optional_integer("speed_mbps").value_or(default_speed));
    check_speed(wire, "speed_mbps", spec.speed_mbps);
    spec.broken = wire.boolean("broken", false);
    wire.reject_unknown_keys();
    return spec;
  }

  void check_speed(TableReader& reader, std::string_view key, std::int64_t speed) const {
    const auto& speeds = processor_.link_speeds_mbps;
    if (std::find(speeds.begin(), speeds.end(), speed) == speeds.end())
      reader.fail(key, fmt::format("{} Mbit/s is not a link speed of the {} ({} Mbit/s)", speed,
                                   processor_.type, fmt::join(speeds, ", ")));
  }

private:
  LinkEndpoint endpoint(TableReader& wire, std::string_view key) {
    const std::string text = wire.string(key);
    const auto dot = text.rfind(".link");
    if (dot == std::string::npos || dot == 0)
      wire.fail(key, fmt::format("'{}' must be written NAME.linkN", text));
    int link = -1;
    const char* digits = text.data() + dot + 5;
    const char* end = text.data() + text.size();
    const auto [parsed_end, error] = std::from_chars(digits, end, link);
    if (digits == end || parsed_end != end || error != std::errc{} || link < 0)
      wire.fail(key, fmt::format("'{}' must be written NAME.linkN", text));
    LinkEndpoint point{text.substr(0, dot), link, false};
    int links = 0;
    if (const NodeSpec* node = platform_.find_node(point.owner)) {
      links = node->links;
    } else if (const DeviceSpec* device = platform_.find_device(point.owner)) {
      links = device->links;
      point.device = true;
    } else {
      wire.fail(key, fmt::format("'{}' is no node or device of this platform", point.owner));
    }
    if (link >= links)
      wire.fail(key, fmt::format("{} has {} links (link0..link{}); link{} does not exist",
                                 point.owner, links, links - 1, link));
    const auto [used, fresh] = used_.emplace(text, wire.line_of(key));
    if (!fresh)
      wire.fail(key, fmt::format("{} is already wired on line {}", text, used->second));
    return point;
  }

  const PlatformSpec& platform_;
  const detail::ProcessorSpec& processor_;
  std::map<std::string, int> used_;
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

} // namespace

PlatformError::PlatformError(std::string file, int line, std::string key,
                             const std::string& problem)
    : std::runtime_error(describe(file, line, key, problem)), file_(std::move(file)), line_(line),
      key_(std::move(key)) {}

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

PlatformSpec load_platform(const std::filesystem::path& file) {
  PlatformSpec platform;
  platform.source = file.string();
  const toml::table root = detail::parse_toml_file(platform.source);
  TableReader top(root, platform.source, "the platform file");
  const toml::table* header = top.optional_table("platform");
  if (header == nullptr)
    throw PlatformError(platform.source, 1, "platform", "missing [platform] table");
  TableReader reader(*header, platform.source, "[platform]");
  platform.name = reader.string("name");
  platform.description = reader.optional_string("description").value_or("");
  const std::filesystem::path processor_file = file.parent_path() / reader.string("processor");
  const detail::ProcessorSpec processor = detail::load_processor(processor_file.string());
  platform.processor_type = processor.type;
  platform.link_speeds_mbps = processor.link_speeds_mbps;
  platform.link_timing = processor.link_timing;

  WireReader wires(platform, processor);
  const auto default_speed = reader.integer("link_speed_mbps");
  wires.check_speed(reader, "link_speed_mbps", default_speed);
  reader.reject_unknown_keys();

  for_each_table(top, "node", [&](const toml::table& table) {
    TableReader node(table, platform.source, "a [[node]]");
    platform.nodes.push_back(read_node(node, processor));
  });
  if (platform.nodes.empty())
    throw PlatformError(platform.source, 1, "node", "a platform needs at least one [[node]]");
  for_each_table(top, "device", [&](const toml::table& table) {
    TableReader device(table, platform.source, "a [[device]]");
    platform.devices.push_back(read_device(device));
  });
  check_unique_names(platform);
  for_each_table(top, "wire", [&](const toml::table& table) {
    TableReader wire(table, platform.source, "a [[wire]]");
    platform.wires.push_back(wires.read(wire, static_cast<int>(default_speed)));
  });
  top.reject_unknown_keys();
  return platform;
}

} // namespace marsokhod::emulator
