// Reading a placement file: its tables and keys, and each process's node.

#include "marsokhod/nav_program/placement/placement.hpp"

#include "placement/placement_checks.hpp"

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/formats/toml_file.hpp"
#include "marsokhod/io/formats/toml_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <initializer_list>
#include <map>
#include <optional>
#include <system_error>
#include <utility>

namespace marsokhod::nav_program {
namespace {

namespace fs = std::filesystem;

int line_of(const toml::source_region& region) {
  return static_cast<int>(region.begin.line);
}

/// One table of a placement file; errors name the key by its place in the file
/// ('process[2].node'), so the table needs no name of its own.
io::TomlTable placement_table(const toml::table& table, const std::string& file,
                              std::string prefix) {
  return io::TomlTable(table, file, "", io::throw_keyed<PlacementError>, std::move(prefix));
}

/// Refuses any key outside `known` before a key is read, so that a misspelt `nod` is named as
/// such, not as a missing `node`; the message lists the keys the table takes (or says
/// `instead`).
void reject_keys_outside(io::TomlTable& table, std::initializer_list<std::string_view> known,
                         std::string_view instead = {}) {
  table.expect_keys(known);
  table.reject_unknown_keys(
      instead.empty() ? fmt::format("unknown key (this table takes {})", fmt::join(known, ", "))
                      : fmt::format("unknown key ({})", instead));
}

/// A string that must be there; `missing` says what it is for.
std::string required_string(io::TomlTable& table, std::string_view key, std::string_view missing) {
  std::optional<std::string> value = table.optional_string(key);
  if (!value)
    table.fail(key, fmt::format("missing: {}", missing));
  return *std::move(value);
}

toml::table parse(const std::string& file) {
  try {
    return io::parse_toml_file(file, "placement file");
  } catch (const io::InputError& error) {
    // A syntax error has a line; a file that could not be read at all (missing, a FIFO, too
    // large) has none.
    throw PlacementError(error.file().empty() ? file : error.file(), error.line(), "",
                         error.problem());
  }
}

/// "powered nodes: module0, module1", the choices a process can be placed on.
std::string powered_nodes(const emulator::PlatformSpec& platform) {
  std::vector<std::string> names;
  for (const emulator::NodeSpec& node : platform.nodes)
    if (node.powered)
      names.push_back(node.name);
  if (names.empty())
    return fmt::format("platform '{}' has no powered node", platform.name);
  return fmt::format("powered nodes: {}", fmt::join(names, ", "));
}

/// Reads [[process]] tables one by one, each checked as far as it can be alone: a process of
/// the program, not placed before, on a powered node of the platform.
class PlaceReader {
public:
  PlaceReader(const emulator::PlatformSpec& platform, const ProgramShape& shape)
      : platform_(platform), shape_(shape) {}

  ProcessPlace read(io::TomlTable& entry) {
    reject_keys_outside(entry, {"name", "node"});
    const std::string processes = fmt::format("{}", fmt::join(shape_.processes, ", "));
    ProcessPlace place;
    place.process = required_string(
        entry, "name", fmt::format("each [[process]] names a process ({})", processes));
    if (place.process.empty())
      entry.fail("name",
                 fmt::format("must name a process of the program ({}), not be empty", processes));
    if (std::find(shape_.processes.begin(), shape_.processes.end(), place.process) ==
        shape_.processes.end())
      entry.fail("name", fmt::format("'{}' is not a process of the program (known processes: {})",
                                     place.process, processes));
    const std::string choices = powered_nodes(platform_);
    place.node = required_string(
        entry, "node",
        fmt::format("each [[process]] says which node runs its process ({})", choices));
    place.line = entry.line_of("node");
    if (const auto first = placed_.find(place.process); first != placed_.end())
      entry.fail("name", fmt::format("'{}' is already placed on line {} (on {}); a process runs "
                                     "on one node",
                                     place.process, first->second.line, first->second.node));
    if (place.node.empty())
      entry.fail("node", fmt::format("must name a node of platform '{}', not be empty ({})",
                                     platform_.name, choices));
    const emulator::NodeSpec* node = platform_.find_node(place.node);
    if (node == nullptr && platform_.find_device(place.node) != nullptr)
      entry.fail("node", fmt::format("'{}' is a device of platform '{}', not a node: devices "
                                     "cannot run processes ({})",
                                     place.node, platform_.name, choices));
    if (node == nullptr)
      entry.fail("node", fmt::format("'{}' is not a node of platform '{}' ({})", place.node,
                                     platform_.name, choices));
    if (!node->powered)
      entry.fail("node", fmt::format("'{}' is not powered on platform '{}': a cold node runs "
                                     "nothing ({})",
                                     place.node, platform_.name, choices));
    placed_.emplace(place.process, place);
    return place;
  }

private:
  const emulator::PlatformSpec& platform_;
  const ProgramShape& shape_;
  std::map<std::string, ProcessPlace, std::less<>> placed_;
};

std::vector<ProcessPlace> read_places(const io::TomlTable& top,
                                      const emulator::PlatformSpec& platform,
                                      const ProgramShape& shape) {
  std::vector<ProcessPlace> places;
  const toml::node* list = top.table().get("process");
  if (list == nullptr)
    return places;
  if (!list->is_array())
    top.fail("process", fmt::format("must be written as [[process]] tables, not {}",
                                    io::toml_type_name(list->type())));
  PlaceReader reader(platform, shape);
  for (const toml::node& element : *list->as_array()) {
    const std::string prefix = fmt::format("process[{}]", places.size());
    if (!element.is_table())
      throw PlacementError(top.file(), line_of(element.source()), prefix,
                           fmt::format("must be a table written [[process]], not {}",
                                       io::toml_type_name(element.type())));
    io::TomlTable entry = placement_table(*element.as_table(), top.file(), prefix);
    places.push_back(reader.read(entry));
  }
  return places;
}

} // namespace

const std::string& Placement::node_of(std::string_view process) const {
  const auto it = std::find_if(places.begin(), places.end(),
                               [&](const ProcessPlace& place) { return place.process == process; });
  if (it == places.end())
    throw std::out_of_range(fmt::format("process '{}' is not placed by {}", process, source));
  return it->node;
}

Placement load_placement(const fs::path& file, const emulator::PlatformSpec& platform,
                         const ProgramShape& shape) {
  detail::check_shape(shape);
  Placement placement;
  placement.source = file.string();
  const toml::table root = parse(placement.source);
  io::TomlTable top = placement_table(root, placement.source, "");
  reject_keys_outside(top, {"placement", "process"},
                      "a placement file holds only [placement] and [[process]] tables");

  const toml::table* header = top.optional_table("placement");
  if (header == nullptr)
    throw PlacementError(placement.source, 0, "placement",
                         fmt::format("missing [placement] table: it names the platform the "
                                     "placement is for (platform = \"{}\")",
                                     platform.name));
  io::TomlTable reader = placement_table(*header, placement.source, "placement");
  reject_keys_outside(reader, {"platform", "description"});
  placement.platform = required_string(
      reader, "platform",
      fmt::format("name the platform this placement is for (\"{}\")", platform.name));
  if (placement.platform.empty())
    reader.fail("platform", fmt::format("must name the platform this placement is for (\"{}\"), "
                                        "not be empty",
                                        platform.name));
  if (placement.platform != platform.name)
    reader.fail("platform", fmt::format("this placement is for platform '{}' but the platform "
                                        "is '{}' ({})",
                                        placement.platform, platform.name, platform.source));
  placement.description = reader.optional_string("description").value_or("");

  placement.places = read_places(top, platform, shape);
  detail::check_program_fits(placement, reader.line(), platform, shape);
  return placement;
}

fs::path default_placement_file(const emulator::PlatformSpec& platform) {
  const fs::path file =
      fs::path(platform.source).parent_path() / "placements" / (platform.name + ".toml");
  std::error_code error;
  if (!fs::exists(file, error))
    throw PlacementError(file.string(), 0, "",
                         fmt::format("no placement file for platform '{}' ({}){}{}: the default "
                                     "placement of a platform is placements/<name>.toml beside "
                                     "its platform file",
                                     platform.name, platform.source, error ? ": " : "",
                                     error ? error.message() : ""));
  return file;
}

} // namespace marsokhod::nav_program
