// The overswitch's modules and timings, checked against the platform's nodes.

#include "platform/platform_overswitch.hpp"

#include "marsokhod/emulator/platform/platform_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace marsokhod::emulator::detail {
namespace {

namespace limits = platform_limits;

std::vector<std::string> module_names(io::TomlTable& table, const PlatformSpec& platform) {
  const toml::array* array = table.optional_array("modules");
  if (array == nullptr || array->empty())
    table.fail("modules", "must list the modules it switches, e.g. [\"module0\", \"module1\"]");
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const toml::node& element : *array) {
    const std::optional<std::string> name = element.value<std::string>();
    if (!name)
      table.fail("modules", "every entry must be a node's name in quotes");
    if (platform.find_node(*name) == nullptr)
      table.fail("modules", fmt::format("'{}' is no node of this platform", *name));
    if (!seen.insert(*name).second)
      table.fail("modules", fmt::format("'{}' is listed twice", *name));
    names.push_back(*name);
  }
  return names;
}

} // namespace

OverswitchSpec read_overswitch(io::TomlTable& table, const PlatformSpec& platform) {
  OverswitchSpec spec;
  spec.line = static_cast<int>(table.table().source().begin.line);
  spec.modules = module_names(table, platform);
  const int modules = static_cast<int>(spec.modules.size());
  spec.powered_at_once =
      table.integer_in<int>("powered_at_once", 1, modules, "the number of modules it switches");
  const auto powered =
      std::count_if(spec.modules.begin(), spec.modules.end(), [&platform](const std::string& name) {
        return platform.find_node(name)->powered;
      });
  if (powered != spec.powered_at_once)
    table.fail("powered_at_once",
               fmt::format("{} of its modules are powered in the platform; it powers {} at once",
                           powered, spec.powered_at_once));
  spec.heartbeat_period =
      table.integer_in<std::int64_t>("heartbeat_period_us", limits::kMinOverswitchUs,
                                     limits::kMaxOverswitchUs) *
      kMicrosecond;
  spec.watchdog_timeout =
      table.integer_in<std::int64_t>("watchdog_timeout_us", limits::kMinOverswitchUs,
                                     limits::kMaxOverswitchUs) *
      kMicrosecond;
  spec.boot_allowance =
      table.integer_in<std::int64_t>("boot_allowance_us", limits::kMinOverswitchUs,
                                     limits::kMaxOverswitchUs) *
      kMicrosecond;
  if (const std::optional<std::int64_t> timeout = table.optional_integer("link_timeout_us")) {
    spec.link_timeout = table.integer_in<std::int64_t>("link_timeout_us", limits::kMinOverswitchUs,
                                                       limits::kMaxOverswitchUs) *
                        kMicrosecond;
  }
  if (spec.watchdog_timeout <= spec.heartbeat_period)
    table.fail("watchdog_timeout_us",
               "must be longer than heartbeat_period_us, or a healthy module would be failed");
  table.reject_unknown_keys();
  return spec;
}

} // namespace marsokhod::emulator::detail
