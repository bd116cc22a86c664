// Reading a processor file: scheduling, timers, memory and the cost table.

#include "platform/platform_processor.hpp"

#include "platform/platform_table_reader.hpp"

#include <fmt/format.h>

#include <limits>

namespace marsokhod::emulator::detail {
namespace {

constexpr std::int64_t kMaxCycles = std::numeric_limits<std::int32_t>::max();

void read_scheduling(TableReader& processor, ProcessorSpec& spec) {
  spec.type = processor.string("type");
  spec.links = static_cast<int>(processor.integer_at_least("links", 1));
  spec.cpu.on_chip_bytes = static_cast<std::size_t>(processor.integer_at_least("on_chip_bytes", 1));
  if (spec.cpu.on_chip_bytes > 4096)
    processor.fail("on_chip_bytes", "the T805 address map has room for at most 4096 bytes on chip");
  spec.reserved_on_chip_bytes =
      static_cast<std::size_t>(processor.integer_at_least("reserved_on_chip_bytes", 0));
  if (spec.reserved_on_chip_bytes >= spec.cpu.on_chip_bytes)
    processor.fail("reserved_on_chip_bytes", "leaves no on-chip memory to allocate");
  spec.cpu.timeslice = processor.integer_at_least("timeslice_ns", 1) * kNanosecond;
  spec.cpu.slices_before_deschedule =
      static_cast<int>(processor.integer_at_least("slices_before_deschedule", 1));
  spec.cpu.high_timer_tick = processor.integer_at_least("high_timer_tick_ns", 1) * kNanosecond;
  spec.cpu.low_timer_tick = processor.integer_at_least("low_timer_tick_ns", 1) * kNanosecond;
  CostTable& costs = spec.cpu.costs;
  costs.external_access_cycles =
      static_cast<std::int32_t>(processor.integer_at_least("external_access_cycles", 1));
  costs.event_latency_cycles =
      static_cast<std::int32_t>(processor.integer_at_least("event_latency_cycles", 0));
  costs.event_latency_max_cycles = static_cast<std::int32_t>(
      processor.integer_at_least("event_latency_max_cycles", costs.event_latency_cycles));
}

void read_link_speeds(TableReader& processor, ProcessorSpec& spec) {
  const toml::array* speeds = processor.optional_array("link_speeds_mbps");
  if (speeds == nullptr || speeds->empty())
    processor.fail("link_speeds_mbps", "must list the link speeds in Mbit/s");
  for (const toml::node& speed : *speeds) {
    const auto value = speed.value_exact<std::int64_t>();
    if (!value || *value <= 0 || *value > 1000)
      processor.fail("link_speeds_mbps", "must hold positive integers (Mbit/s)");
    spec.link_speeds_mbps.push_back(static_cast<int>(*value));
  }
}

void read_speed_grades(const toml::table& table, const std::string& file, ProcessorSpec& spec) {
  TableReader grades(table, file, "[speed_grades]");
  for (const auto& [key, node] : table) {
    const std::int64_t cycle_ps = grades.integer_at_least(key.str(), 1);
    spec.speed_grades.emplace(std::string(key.str()), cycle_ps * kPicosecond);
  }
  if (spec.speed_grades.empty())
    throw PlatformError(file, static_cast<int>(table.source().begin.line), "speed_grades",
                        "names no speed grade");
}

void read_link_timing(const toml::table& table, const std::string& file, LinkTimingSpec& timing) {
  TableReader reader(table, file, "[link_timing]");
  auto bits = [&](std::string_view key, double minimum) {
    const double value = reader.number(key);
    if (value < minimum || value > 1000)
      reader.fail(key, fmt::format("{} bit times is impossible (at least {})", value, minimum));
    return value;
  };
  timing.data_packet_bits = bits("data_packet_bits", 1);
  timing.ack_packet_bits = bits("ack_packet_bits", 1);
  timing.ack_delay_bits = bits("ack_delay_bits", 0);
  timing.ack_turnaround_bits = bits("ack_turnaround_bits", 0);
  timing.ack_turnaround_fixed = reader.integer_at_least("ack_turnaround_ps", 0) * kPicosecond;
  timing.inter_packet_gap_bits = bits("inter_packet_gap_bits", 0);
  reader.reject_unknown_keys();
}

InstructionCost read_cost(const toml::node& node, std::string_view name, TableReader& costs) {
  if (const auto cycles = node.value_exact<std::int64_t>()) {
    if (*cycles < 0 || *cycles > kMaxCycles)
      costs.fail(name, "cycles must be a non-negative integer");
    return InstructionCost{static_cast<std::int32_t>(*cycles), 0, false};
  }
  if (!node.is_table())
    costs.fail(name, "must be a cycle count or { base = N, per_unit = N, fpu = BOOL }");
  TableReader entry(*node.as_table(), costs.file(), fmt::format("[cost_table] entry '{}'", name));
  InstructionCost cost;
  cost.base = static_cast<std::int32_t>(entry.integer_at_least("base", 0));
  cost.per_unit = static_cast<std::int32_t>(entry.optional_integer("per_unit").value_or(0));
  if (cost.per_unit < 0)
    entry.fail("per_unit", "must not be negative");
  cost.fpu = entry.boolean("fpu", false);
  entry.reject_unknown_keys();
  return cost;
}

void read_cost_table(const toml::table& table, const std::string& file, CostTable& table_out) {
  TableReader costs(table, file, "[cost_table]");
  std::array<bool, kInstructionCount> seen{};
  for (const auto& [key, node] : table) {
    const auto instruction = instruction_from_mnemonic(key.str());
    if (!instruction)
      throw PlatformError(file, static_cast<int>(key.source().begin.line), std::string(key.str()),
                          "not a T805 instruction the cost model knows ([cost_table])");
    table_out[*instruction] = read_cost(node, key.str(), costs);
    seen[static_cast<std::size_t>(*instruction)] = true;
  }
  for (std::size_t i = 0; i < kInstructionCount; ++i)
    if (!seen[i])
      throw PlatformError(
          file, static_cast<int>(table.source().begin.line),
          std::string(mnemonic(static_cast<Instruction>(i))),
          "missing from [cost_table]: every instruction needs its data-book cycles");
}

const toml::table& require_table(TableReader& top, std::string_view key) {
  const toml::table* table = top.optional_table(key);
  if (table == nullptr)
    throw PlatformError(top.file(), 1, std::string(key), "missing table");
  return *table;
}

} // namespace

ProcessorSpec load_processor(const std::string& file) {
  const toml::table root = parse_toml_file(file);
  TableReader top(root, file, "the processor file");
  ProcessorSpec spec;
  TableReader processor(require_table(top, "processor"), file, "[processor]");
  read_scheduling(processor, spec);
  read_link_speeds(processor, spec);
  processor.reject_unknown_keys();
  read_speed_grades(require_table(top, "speed_grades"), file, spec);
  read_link_timing(require_table(top, "link_timing"), file, spec.link_timing);
  read_cost_table(require_table(top, "cost_table"), file, spec.cpu.costs);
  top.reject_unknown_keys();
  return spec;
}

} // namespace marsokhod::emulator::detail
