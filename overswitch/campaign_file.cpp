// Reading campaign files, each error naming its file, line and key.

#include "marsokhod/overswitch/campaign_file.hpp"

#include "marsokhod/io/formats/toml_file.hpp"
#include "marsokhod/overswitch/upset_rates.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <set>

namespace marsokhod::overswitch {
namespace {

int line_of(const toml::node& node) {
  return static_cast<int>(node.source().begin.line);
}

/// One table of the file with the keys it has been asked for, so that the others are refused.
class Table {
public:
  Table(const toml::table& table, const CampaignSpec& spec, std::string name)
      : table_(table), spec_(spec), name_(std::move(name)) {}

  [[noreturn]] void fail(std::string_view key, const std::string& problem) const {
    const toml::node* node = table_.get(key);
    throw CampaignError(spec_.source, node != nullptr ? line_of(*node) : line_of(table_),
                        std::string(key), problem);
  }

  const toml::node* get(std::string_view key) {
    known_.insert(std::string(key));
    return table_.get(key);
  }

  template <class T>
  std::optional<T> optional(std::string_view key, std::string_view type) {
    const toml::node* node = get(key);
    if (node == nullptr)
      return std::nullopt;
    const std::optional<T> value = node->value_exact<T>();
    if (!value)
      fail(key, fmt::format("must be {}, not {}", type, io::toml_type_name(node->type())));
    return value;
  }

  bool flag(std::string_view key, bool fallback) {
    return optional<bool>(key, "true or false").value_or(fallback);
  }

  std::string text(std::string_view key, std::string fallback) {
    return optional<std::string>(key, "a string in quotes").value_or(std::move(fallback));
  }

  std::int64_t integer(std::string_view key, std::int64_t low, std::int64_t high,
                       std::int64_t fallback) {
    const std::int64_t value = optional<std::int64_t>(key, "an integer").value_or(fallback);
    if (value < low || value > high)
      fail(key, fmt::format("{} is not between {} and {}", value, low, high));
    return value;
  }

  std::optional<double> real(std::string_view key, double low, double high) {
    const toml::node* node = get(key);
    if (node == nullptr)
      return std::nullopt;
    const std::optional<double> value = node->value<double>();
    if (!value || !node->is_number())
      fail(key, fmt::format("must be a number, not {}", io::toml_type_name(node->type())));
    if (!(std::isfinite(*value) && *value >= low && *value <= high))
      fail(key, fmt::format("{} is not between {} and {}", *value, low, high));
    return value;
  }

  const toml::array* array(std::string_view key) {
    const toml::node* node = get(key);
    if (node == nullptr)
      return nullptr;
    if (!node->is_array())
      fail(key, fmt::format("must be a list, not {}", io::toml_type_name(node->type())));
    return node->as_array();
  }

  void reject_unknown_keys() const {
    for (const auto& [key, node] : table_)
      if (!known_.contains(std::string(key.str())))
        throw CampaignError(spec_.source, line_of(node), std::string(key.str()),
                            fmt::format("is not a key of {}", name_));
  }

  int line() const { return line_of(table_); }

private:
  const toml::table& table_;
  const CampaignSpec& spec_;
  std::string name_;
  std::set<std::string> known_;
};

const toml::table& table_named(Table& top, std::string_view key, bool required) {
  static const toml::table empty;
  const toml::node* node = top.get(key);
  if (node == nullptr) {
    if (required)
      top.fail(key, fmt::format("the file needs a [{}] table", key));
    return empty;
  }
  if (!node->is_table())
    top.fail(key, fmt::format("must be a table, not {}", io::toml_type_name(node->type())));
  return *node->as_table();
}

void read_header(Table& campaign, CampaignSpec& spec) {
  spec.name = campaign.text("name", "");
  spec.description = campaign.text("description", "");
  spec.platform = campaign.text("platform", "");
  if (spec.platform.empty())
    campaign.fail("platform", "name the platform (\"onboard\") or its file");
  spec.seed = static_cast<std::uint64_t>(
      campaign.integer("seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
  campaign.reject_unknown_keys();
}

void read_scenarios(Table& scenarios, CampaignSpec& spec) {
  const toml::array* seeds = scenarios.array("world_seeds");
  if (seeds == nullptr || seeds->empty())
    scenarios.fail("world_seeds", "list the world seeds the runs are drawn over, e.g. [2, 3, 4]");
  for (const toml::node& seed : *seeds) {
    const std::optional<std::int64_t> value = seed.value_exact<std::int64_t>();
    if (!value || *value < 0)
      scenarios.fail("world_seeds", "every world seed must be an integer of 0 or more");
    spec.world_seeds.push_back(static_cast<std::uint64_t>(*value));
  }
  spec.light = scenarios.text("light", spec.light);
  static const std::set<std::string> kLights{"high-sun", "overexposed", "dark-wet", "low-sun"};
  if (!kLights.contains(spec.light))
    scenarios.fail(
        "light",
        fmt::format("'{}' is no light (high-sun, overexposed, dark-wet, low-sun)", spec.light));
  spec.rock_cover = scenarios.real("rock_cover", 0.0, 0.5).value_or(spec.rock_cover);
  scenarios.reject_unknown_keys();
}

/// Where an upset or a stuck bit is drawn: over the allocated memory (the default) or all of it,
/// or in the buffers whose name contains a text.
void read_memory_target(Table& fault, FaultMix& mix) {
  const std::string over = fault.text("over", "allocated");
  if (over == "memory")
    mix.memory.over = MemoryTarget::Over::memory;
  else if (over != "allocated")
    fault.fail("over", fmt::format("'{}' is neither \"allocated\" nor \"memory\"", over));
  mix.memory.buffer = fault.text("buffer", "");
  if (fault.get("buffer") != nullptr && mix.memory.buffer.empty())
    fault.fail("buffer", "name the buffer, or leave the key out");
  if (mix.kind == Fault::Kind::stuck)
    mix.memory.stuck_value = fault.integer("value", 0, 1, mix.memory.stuck_value ? 1 : 0) == 1;
}

FaultMix read_fault(Table& fault) {
  static const std::map<std::string, Fault::Kind> kKinds{{"hang", Fault::Kind::hang},
                                                         {"power", Fault::Kind::power_loss},
                                                         {"leak", Fault::Kind::leak},
                                                         {"seu", Fault::Kind::upset},
                                                         {"stuck", Fault::Kind::stuck}};
  FaultMix mix;
  mix.line = fault.line();
  const std::string kind = fault.text("kind", "");
  const auto found = kKinds.find(kind);
  if (found == kKinds.end())
    fault.fail("kind", fmt::format("'{}' is no fault kind of a campaign (hang, power, leak, seu, "
                                   "stuck)",
                                   kind));
  mix.kind = found->second;
  if (is_memory_fault(mix.kind))
    read_memory_target(fault, mix);
  mix.weight = fault.real("weight", 1e-9, 1e9).value_or(1.0);
  if (const toml::array* modules = fault.array("modules"))
    for (const toml::node& module : *modules) {
      const std::optional<std::string> name = module.value_exact<std::string>();
      if (!name || name->empty())
        fault.fail("modules", "every module must be a node's name in quotes");
      mix.modules.push_back(*name);
    }
  mix.from_share = fault.real("from_share", 0.0, 1.0).value_or(0.0);
  mix.to_share = fault.real("to_share", 0.0, 1.0).value_or(1.0);
  if (mix.to_share <= mix.from_share)
    fault.fail("to_share", "must be more than from_share: the strike's share of the cycle");
  fault.reject_unknown_keys();
  return mix;
}

void read_protection(Table& protection, CampaignSpec& spec) {
  Protection& p = spec.protection;
  p.edac = protection.flag("edac", false);
  if (const std::optional<double> scrub = protection.real("scrub_period_s", 0.01, 86400.0)) {
    if (!p.edac)
      protection.fail("scrub_period_s", "scrubbing rewrites memory through the EDAC: set edac");
    p.scrub_period = static_cast<emulator::Tick>(*scrub * static_cast<double>(emulator::kSecond));
  }
  p.link_checksums = protection.flag("link_checksums", false);
  p.nav_check = protection.flag("nav_check", false);
  protection.reject_unknown_keys();
}

void read_upsets(Table& upsets, CampaignSpec& spec) {
  const std::string preset = upsets.text("preset", "");
  const std::optional<double> rate = upsets.real("rate_per_bit_day", 1e-15, 1e-3);
  if (!preset.empty() && rate)
    upsets.fail("rate_per_bit_day", "give a preset or a rate, not both");
  if (rate) {
    spec.upset_rate = UpsetRate{"custom", *rate, "the campaign file"};
  } else if (!preset.empty()) {
    const std::optional<UpsetRate> known = upset_preset(preset);
    if (!known)
      upsets.fail("preset", fmt::format("'{}' is no preset ({})", preset, upset_preset_names()));
    spec.upset_rate = known;
  } else {
    upsets.fail("preset", "name a preset or give rate_per_bit_day");
  }
  upsets.reject_unknown_keys();
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

void read_stop(Table& stop, CampaignSpec& spec) {
  spec.runs = static_cast<std::uint64_t>(
      stop.integer("runs", 1, static_cast<std::int64_t>(kMaxCampaignRuns), 1000));
  spec.ci_width = stop.real("ci_width", 1e-6, 1.0);
  stop.reject_unknown_keys();
}

} // namespace

CampaignError::CampaignError(std::string file, int line, std::string key,
                             const std::string& problem)
    : std::runtime_error(line > 0 ? fmt::format("{}:{}: '{}': {}", file, line, key, problem)
                                  : fmt::format("{}: '{}': {}", file, key, problem)),
      file_(std::move(file)), line_(line), key_(std::move(key)) {}

CampaignSpec load_campaign(const std::filesystem::path& file) {
  const toml::table document = io::parse_toml_file(file, "campaign file");
  CampaignSpec spec;
  spec.source = file.string();
  Table top(document, spec, "a campaign file");
  Table campaign(table_named(top, "campaign", true), spec, "[campaign]");
  read_header(campaign, spec);
  Table scenarios(table_named(top, "scenarios", true), spec, "[scenarios]");
  read_scenarios(scenarios, spec);
  const toml::array* faults = top.array("fault");
  if (faults == nullptr || faults->empty())
    top.fail("fault", "the file needs at least one [[fault]] table");
  for (const toml::node& node : *faults) {
    if (!node.is_table())
      top.fail("fault", "every [[fault]] must be a table");
    Table fault(*node.as_table(), spec, "a [[fault]]");
    spec.faults.push_back(read_fault(fault));
  }
  Table protection(table_named(top, "protection", false), spec, "[protection]");
  read_protection(protection, spec);
  if (top.get("upsets") != nullptr) {
    Table upsets(table_named(top, "upsets", true), spec, "[upsets]");
    read_upsets(upsets, spec);
    check_rate_mix(spec);
  }
  Table stop(table_named(top, "stop", false), spec, "[stop]");
  read_stop(stop, spec);
  top.reject_unknown_keys();
  return spec;
}

} // namespace marsokhod::overswitch
