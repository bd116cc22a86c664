// Reading campaign files, each error naming its file, line and key.

#include "marsokhod/overswitch/campaign/campaign_file.hpp"

#include "marsokhod/io/formats/toml_file.hpp"
#include "marsokhod/io/formats/toml_table.hpp"
#include "marsokhod/overswitch/campaign/upset_rates.hpp"

#include <fmt/format.h>

#include <map>
#include <optional>
#include <set>

namespace marsokhod::overswitch {
namespace {

io::TomlTable campaign_table(const toml::table& table, const CampaignSpec& spec) {
  return io::TomlTable(table, spec.source, "", io::throw_keyed<CampaignError>);
}

// A campaign file words an unknown key "is not a key of [campaign]" and a range
// "V is not between L and H" (the campaign command's tests pin both).
void reject_unknown_keys(const io::TomlTable& table, std::string_view name) {
  table.reject_unknown_keys(fmt::format("is not a key of {}", name));
}

std::int64_t integer(io::TomlTable& table, std::string_view key, std::int64_t low,
                     std::int64_t high, std::int64_t fallback) {
  const std::int64_t value = table.optional_integer(key).value_or(fallback);
  if (value < low || value > high)
    table.fail(key, fmt::format("{} is not between {} and {}", value, low, high));
  return value;
}

std::optional<double> real(io::TomlTable& table, std::string_view key, double low, double high) {
  const std::optional<double> value = table.optional_number(key);
  if (value && !(*value >= low && *value <= high))
    table.fail(key, fmt::format("{} is not between {} and {}", *value, low, high));
  return value;
}

std::string text(io::TomlTable& table, std::string_view key, std::string fallback) {
  return table.optional_string(key).value_or(std::move(fallback));
}

const toml::table& table_named(io::TomlTable& top, std::string_view key, bool required) {
  static const toml::table empty;
  if (const toml::table* table = top.optional_table(key))
    return *table;
  if (required)
    top.fail(key, fmt::format("the file needs a [{}] table", key));
  return empty;
}

void read_header(io::TomlTable& campaign, CampaignSpec& spec) {
  spec.name = text(campaign, "name", "");
  spec.description = text(campaign, "description", "");
  spec.platform = text(campaign, "platform", "");
  if (spec.platform.empty())
    campaign.fail("platform", "name the platform (\"onboard\") or its file");
  spec.seed = static_cast<std::uint64_t>(
      integer(campaign, "seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
  reject_unknown_keys(campaign, "[campaign]");
}

void read_scenarios(io::TomlTable& scenarios, CampaignSpec& spec) {
  const toml::array* seeds = scenarios.optional_array("world_seeds");
  if (seeds == nullptr || seeds->empty())
    scenarios.fail("world_seeds", "list the world seeds the runs are drawn over, e.g. [2, 3, 4]");
  for (const toml::node& seed : *seeds) {
    const std::optional<std::int64_t> value = seed.value_exact<std::int64_t>();
    if (!value || *value < 0)
      scenarios.fail("world_seeds", "every world seed must be an integer of 0 or more");
    spec.world_seeds.push_back(static_cast<std::uint64_t>(*value));
  }
  spec.light = text(scenarios, "light", spec.light);
  static const std::set<std::string> kLights{"high-sun", "overexposed", "dark-wet", "low-sun"};
  if (!kLights.contains(spec.light))
    scenarios.fail(
        "light",
        fmt::format("'{}' is no light (high-sun, overexposed, dark-wet, low-sun)", spec.light));
  spec.rock_cover = real(scenarios, "rock_cover", 0.0, 0.5).value_or(spec.rock_cover);
  reject_unknown_keys(scenarios, "[scenarios]");
}

/// Where an upset or a stuck bit is drawn: over the allocated memory (the default) or all of it,
/// or in the buffers whose name contains a text.
void read_memory_target(io::TomlTable& fault, FaultMix& mix) {
  const std::string over = text(fault, "over", "allocated");
  if (over == "memory")
    mix.memory.over = MemoryTarget::Over::memory;
  else if (over != "allocated")
    fault.fail("over", fmt::format("'{}' is neither \"allocated\" nor \"memory\"", over));
  const std::optional<std::string> buffer = fault.optional_string("buffer");
  if (buffer && buffer->empty())
    fault.fail("buffer", "name the buffer, or leave the key out");
  mix.memory.buffer = buffer.value_or("");
  if (mix.kind == Fault::Kind::stuck)
    mix.memory.stuck_value = integer(fault, "value", 0, 1, 1) == 1;
}

/// Which links, which wire, and how long a link fault lasts.
void read_link_target(io::TomlTable& fault, FaultMix& mix) {
  if (const toml::array* links = fault.optional_array("links")) {
    mix.links.clear();
    for (const toml::node& link : *links) {
      const std::optional<std::int64_t> index = link.value_exact<std::int64_t>();
      if (!index || *index < 0 || *index > 3)
        fault.fail("links", "every link is a number from 0 to 3");
      mix.links.push_back(static_cast<int>(*index));
    }
    if (mix.links.empty())
      fault.fail("links", "list at least one link, e.g. [0]");
  }
  const bool one_wire = mix.kind != Fault::Kind::link_down;
  const std::string dir = text(fault, "dir", one_wire ? "out" : "both");
  if (dir == "out")
    mix.direction = LinkDirection::out;
  else if (dir == "in")
    mix.direction = LinkDirection::in;
  else if (dir == "both" && !one_wire)
    mix.direction = LinkDirection::both;
  else
    fault.fail("dir", fmt::format("'{}' is no wire of this fault ({})", dir,
                                  one_wire ? "out, in" : "out, in, both"));
  const std::optional<double> shortest = real(fault, "down_for_min_s", 1e-6, 3600.0);
  const std::optional<double> longest = real(fault, "down_for_max_s", 1e-6, 3600.0);
  if ((shortest || longest) && mix.kind != Fault::Kind::link_down)
    fault.fail(shortest ? "down_for_min_s" : "down_for_max_s", "only a link down lasts a while");
  if (shortest.has_value() != longest.has_value())
    fault.fail(shortest ? "down_for_max_s" : "down_for_min_s",
               "give both down_for_min_s and down_for_max_s, or neither (for good)");
  if (shortest && *longest < *shortest)
    fault.fail("down_for_max_s", "must be at least down_for_min_s");
  if (shortest)
    mix.down_for_s = std::pair(*shortest, *longest);
  if (mix.kind == Fault::Kind::link_bit)
    mix.byte_within =
        static_cast<std::uint64_t>(integer(fault, "byte_within", 1, 1'000'000'000, 1000));
}

FaultMix read_fault(io::TomlTable& fault) {
  FaultMix mix;
  mix.line = fault.line();
  const std::string kind = text(fault, "kind", "");
  const std::optional<Fault::Kind> found = parse_fault_kind(kind);
  if (!found)
    fault.fail("kind",
               fmt::format("'{}' is no fault kind of a campaign ({})", kind, fault_kind_names()));
  mix.kind = *found;
  if (is_memory_fault(mix.kind))
    read_memory_target(fault, mix);
  if (is_link_fault(mix.kind))
    read_link_target(fault, mix);
  mix.weight = real(fault, "weight", 1e-9, 1e9).value_or(1.0);
  if (const toml::array* modules = fault.optional_array("modules"))
    for (const toml::node& module : *modules) {
      const std::optional<std::string> name = module.value_exact<std::string>();
      if (!name || name->empty())
        fault.fail("modules", "every module must be a node's name in quotes");
      mix.modules.push_back(*name);
    }
  mix.from_share = real(fault, "from_share", 0.0, 1.0).value_or(0.0);
  mix.to_share = real(fault, "to_share", 0.0, 1.0).value_or(1.0);
  if (mix.to_share <= mix.from_share)
    fault.fail("to_share", "must be more than from_share: the strike's share of the cycle");
  reject_unknown_keys(fault, "a [[fault]]");
  return mix;
}

void read_protection(io::TomlTable& protection, CampaignSpec& spec) {
  Protection& p = spec.protection;
  p.edac = protection.boolean("edac", false);
  if (const std::optional<double> scrub = real(protection, "scrub_period_s", 0.01, 86400.0)) {
    if (!p.edac)
      protection.fail("scrub_period_s", "scrubbing rewrites memory through the EDAC: set edac");
    p.scrub_period = static_cast<emulator::Tick>(*scrub * static_cast<double>(emulator::kSecond));
  }
  p.link_checksums = protection.boolean("link_checksums", false);
  p.terrain_check = protection.boolean("terrain_check", false);
  reject_unknown_keys(protection, "[protection]");
}

void read_upsets(io::TomlTable& upsets, CampaignSpec& spec) {
  const std::optional<std::string> preset = upsets.optional_string("preset");
  const std::optional<double> rate = real(upsets, "rate_per_bit_day", 1e-15, 1e-3);
  if (preset && rate)
    upsets.fail("rate_per_bit_day", "give a preset or a rate, not both");
  if (rate) {
    spec.upset_rate = UpsetRate{"custom", *rate, "the campaign file"};
  } else if (preset) {
    spec.upset_rate = upset_preset(*preset);
    if (!spec.upset_rate)
      upsets.fail("preset", fmt::format("'{}' is no preset ({})", *preset, upset_preset_names()));
  } else {
    upsets.fail("preset", "name a preset or give rate_per_bit_day");
  }
  reject_unknown_keys(upsets, "[upsets]");
}

// A rate strikes every bit alike: the per-year figure holds only for upsets drawn that way.
void check_rate_mix(const CampaignSpec& spec) {
  for (const FaultMix& mix : spec.faults) {
    if (mix.kind != Fault::Kind::upset)
      throw CampaignError(spec.source, mix.line, "kind",
                          "with [upsets] every [[fault]] is an upset (kind = \"seu\"): the rate "
                          "scales the outcome of one upset");
    if (mix.memory.over != MemoryTarget::Over::memory || !mix.memory.buffer.empty())
      throw CampaignError(spec.source, mix.line, "over",
                          "with [upsets] an upset is drawn over every bit of memory (over = "
                          "\"memory\", no buffer), as the rate strikes them");
  }
}

void read_stop(io::TomlTable& stop, CampaignSpec& spec) {
  spec.runs = static_cast<std::uint64_t>(
      integer(stop, "runs", 1, static_cast<std::int64_t>(kMaxCampaignRuns), 1000));
  spec.ci_width = real(stop, "ci_width", 1e-6, 1.0);
  reject_unknown_keys(stop, "[stop]");
}

} // namespace

CampaignSpec load_campaign(const std::filesystem::path& file) {
  const toml::table document = io::parse_toml_file(file, "campaign file");
  CampaignSpec spec;
  spec.source = file.string();
  io::TomlTable top = campaign_table(document, spec);
  io::TomlTable campaign = campaign_table(table_named(top, "campaign", true), spec);
  read_header(campaign, spec);
  io::TomlTable scenarios = campaign_table(table_named(top, "scenarios", true), spec);
  read_scenarios(scenarios, spec);
  const toml::array* faults = top.optional_array("fault");
  if (faults == nullptr || faults->empty())
    top.fail("fault", "the file needs at least one [[fault]] table");
  for (const toml::node& node : *faults) {
    if (!node.is_table())
      top.fail("fault", "every [[fault]] must be a table");
    io::TomlTable fault = campaign_table(*node.as_table(), spec);
    spec.faults.push_back(read_fault(fault));
  }
  io::TomlTable protection = campaign_table(table_named(top, "protection", false), spec);
  read_protection(protection, spec);
  if (top.optional_table("upsets") != nullptr) {
    io::TomlTable upsets = campaign_table(table_named(top, "upsets", true), spec);
    read_upsets(upsets, spec);
    check_rate_mix(spec);
  }
  io::TomlTable stop = campaign_table(table_named(top, "stop", false), spec);
  read_stop(stop, spec);
  reject_unknown_keys(top, "a campaign file");
  return spec;
}

} // namespace marsokhod::overswitch
