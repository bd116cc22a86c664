// Reading a placement file: its tables and keys, and each process's node.

#include "marsokhod/occam_port/navigation/placement.hpp"

#include "navigation/placement_checks.hpp"

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/formats/toml_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <initializer_list>
#include <map>
#include <optional>
#include <system_error>
#include <utility>

namespace marsokhod::occam_port {
namespace {

namespace fs = std::filesystem;

// The shape of emulator::PlatformError's messages, so that both read alike.
std::string describe(const std::string& file, int line, const std::string& key,
                     const std::string& problem) {
  const std::string where = line > 0 ? fmt::format("{}:{}", file, line) : file;
  if (key.empty())
    return fmt::format("{}: {}", where, problem);
  return fmt::format("{}: '{}': {}", where, key, problem);
}

int line_of(const toml::source_region& region) {
  return static_cast<int>(region.begin.line);
}

/// One table of a placement file: typed reads failing with the file, the line and the key's full
/// name ("process[2].node"). Unknown keys are errors, not comments: a misspelt `nod` would
/// otherwise read as a process without a node, or worse, be ignored.
class TableReader {
public:
  TableReader(const toml::table& table, const std::string& file, std::string prefix)
      : table_(table), file_(file), prefix_(std::move(prefix)) {}

  /// Fails on the first key outside `known`, listing them (or saying `instead`).
  void reject_unknown_keys(std::initializer_list<std::string_view> known,
                           std::string_view instead = {}) const {
    for (const auto& [key, node] : table_)
      if (std::find(known.begin(), known.end(), key.str()) == known.end())
        throw PlacementError(file_, line_of(key.source()), full_name(key.str()),
                             instead.empty() ? fmt::format("unknown key (this table takes {})",
                                                           fmt::join(known, ", "))
                                             : fmt::format("unknown key ({})", instead));
  }

  /// A string, or nullopt when the key is absent; any other type is an error.
  std::optional<std::string> optional_string(std::string_view key) const {
    const toml::node* node = table_.get(key);
    if (node == nullptr)
      return std::nullopt;
    const auto value = node->value_exact<std::string>();
    if (!value)
      fail(key, fmt::format("must be a string, not {}", io::toml_type_name(node->type())));
    return *value;
  }

  /// A string that must be there; `missing` says what it is for.
  std::string string(std::string_view key, std::string_view missing) const {
    std::optional<std::string> value = optional_string(key);
    if (!value)
      fail(key, fmt::format("missing: {}", missing));
    return *std::move(value);
  }

  /// The line of the key's value, or of the table when it lacks the key.
  int line_of_key(std::string_view key) const {
    const toml::node* node = table_.get(key);
    return line_of(node != nullptr ? node->source() : table_.source());
  }
  int line() const { return line_of(table_.source()); }
  std::string full_name(std::string_view key) const {
    return prefix_.empty() ? std::string(key) : fmt::format("{}.{}", prefix_, key);
  }
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const {
    throw PlacementError(file_, line_of_key(key), full_name(key), problem);
  }

private:
  const toml::table& table_;
  const std::string& file_;
  std::string prefix_;
};

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

  ProcessPlace read(const TableReader& entry) {
    entry.reject_unknown_keys({"name", "node"});
    const std::string processes = fmt::format("{}", fmt::join(shape_.processes, ", "));
    ProcessPlace place;
    place.process =
        entry.string("name", fmt::format("each [[process]] names a process ({})", processes));
    if (place.process.empty())
      entry.fail("name",
                 fmt::format("must name a process of the program ({}), not be empty", processes));
    if (std::find(shape_.processes.begin(), shape_.processes.end(), place.process) ==
        shape_.processes.end())
      entry.fail("name", fmt::format("'{}' is not a process of the program (known processes: {})",
                                     place.process, processes));
    const std::string choices = powered_nodes(platform_);
    place.node = entry.string(
        "node", fmt::format("each [[process]] says which node runs its process ({})", choices));
    place.line = entry.line_of_key("node");
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

std::vector<ProcessPlace> read_places(const toml::table& root, const std::string& file,
                                      const emulator::PlatformSpec& platform,
                                      const ProgramShape& shape) {
  std::vector<ProcessPlace> places;
  const toml::node* list = root.get("process");
  if (list == nullptr)
    return places;
  if (!list->is_array())
    throw PlacementError(file, line_of(list->source()), "process",
                         fmt::format("must be written as [[process]] tables, not {}",
                                     io::toml_type_name(list->type())));
  PlaceReader reader(platform, shape);
  for (const toml::node& element : *list->as_array()) {
    const std::string prefix = fmt::format("process[{}]", places.size());
    if (!element.is_table())
      throw PlacementError(file, line_of(element.source()), prefix,
                           fmt::format("must be a table written [[process]], not {}",
                                       io::toml_type_name(element.type())));
    places.push_back(reader.read(TableReader(*element.as_table(), file, prefix)));
  }
  return places;
}

} // namespace

PlacementError::PlacementError(std::string file, int line, std::string key,
                               const std::string& problem)
    : std::runtime_error(describe(file, line, key, problem)), file_(std::move(file)), line_(line),
      key_(std::move(key)) {}

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
  const TableReader top(root, placement.source, "");
  top.reject_unknown_keys({"placement", "process"},
                          "a placement file holds only [placement] and [[process]] tables");

  const toml::node* header = root.get("placement");
  if (header == nullptr)
    throw PlacementError(placement.source, 0, "placement",
                         fmt::format("missing [placement] table: it names the platform the "
                                     "placement is for (platform = \"{}\")",
                                     platform.name));
  if (!header->is_table())
    top.fail("placement",
             fmt::format("must be a table, not {}", io::toml_type_name(header->type())));
  const TableReader reader(*header->as_table(), placement.source, "placement");
  reader.reject_unknown_keys({"platform", "description"});
  placement.platform = reader.string(
      "platform", fmt::format("name the platform this placement is for (\"{}\")", platform.name));
  if (placement.platform.empty())
    reader.fail("platform", fmt::format("must name the platform this placement is for (\"{}\"), "
                                        "not be empty",
                                        platform.name));
  if (placement.platform != platform.name)
    reader.fail("platform", fmt::format("this placement is for platform '{}' but the platform "
                                        "is '{}' ({})",
                                        placement.platform, platform.name, platform.source));
  placement.description = reader.optional_string("description").value_or("");

  placement.places = read_places(root, placement.source, platform, shape);
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

} // namespace marsokhod::occam_port
