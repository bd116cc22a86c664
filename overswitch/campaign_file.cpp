// Reading campaign files, each error naming its file, line and key.

#include "marsokhod/overswitch/campaign_file.hpp"

#include "marsokhod/io/formats/toml_file.hpp"

#include <fmt/format.h>

#include <cmath>
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

FaultMix read_fault(Table& fault) {
  FaultMix mix;
  mix.line = fault.line();
  const std::string kind = fault.text("kind", "");
  if (kind == "hang")
    mix.kind = Fault::Kind::hang;
  else if (kind == "power")
    mix.kind = Fault::Kind::power_loss;
  else if (kind == "leak")
    mix.kind = Fault::Kind::leak;
  else
    fault.fail("kind",
               fmt::format("'{}' is no fault kind of a campaign (hang, power, leak)", kind));
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
  Table stop(table_named(top, "stop", false), spec, "[stop]");
  read_stop(stop, spec);
  top.reject_unknown_keys();
  return spec;
}

} // namespace marsokhod::overswitch
