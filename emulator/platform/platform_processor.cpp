// Reading a processor file: scheduling, timers, memory and the cost table.

#include "platform/platform_processor.hpp"

#include "platform/platform_toml.hpp"

#include "marsokhod/emulator/platform/platform_limits.hpp"

#include <fmt/format.h>

namespace marsokhod::emulator::detail {
namespace {

namespace limits = platform_limits;
using io::TomlTable;

void read_scheduling(TomlTable& processor, ProcessorSpec& spec) {
  spec.type = processor.string("type");
  spec.links = processor.integer_in("links", 1, limits::kMaxLinks, "links, as on a T805");
  spec.cpu.on_chip_bytes =
      processor.integer_in<std::size_t>("on_chip_bytes", 1, limits::kMaxOnChipBytes,
                                        "bytes, the room the T805 address map leaves on chip");
  spec.reserved_on_chip_bytes =
      processor.integer_in<std::size_t>("reserved_on_chip_bytes", 0, spec.cpu.on_chip_bytes - 1,
                                        "bytes, leaving on-chip memory to allocate");
  spec.cpu.timeslice = processor.integer_in("timeslice_ns", limits::kMinTimesliceNs,
                                            limits::kMaxTimesliceNs, "ns, 1 us to 1 s") *
                       kNanosecond;
  spec.cpu.slices_before_deschedule = processor.integer_in<std::int32_t>(
      "slices_before_deschedule", 1, limits::kMaxSlicesBeforeDeschedule, "timeslices");
  const auto timer_tick = [&](std::string_view key) {
    return processor.integer_in(key, limits::kMinTimerTickNs, limits::kMaxTimerTickNs,
                                "ns, 1 ns to 1 ms, so that a timer wait 2^32 ticks ahead "
                                "fits the emulator's clock") *
           kNanosecond;
  };
  spec.cpu.high_timer_tick = timer_tick("high_timer_tick_ns");
  spec.cpu.low_timer_tick = timer_tick("low_timer_tick_ns");
  CostTable& costs = spec.cpu.costs;
  costs.external_access_cycles = processor.integer_in(
      "external_access_cycles", limits::kMinExternalAccessCycles, limits::kMaxExternalAccessCycles,
      "cycles, six EMI T-states of one to four half-cycles");
  costs.event_latency_cycles = processor.integer_in<std::int32_t>(
      "event_latency_cycles", 0, limits::kMaxInstructionCycles, "cycles");
  costs.event_latency_max_cycles =
      processor.integer_in("event_latency_max_cycles", costs.event_latency_cycles,
                           limits::kMaxInstructionCycles, "cycles, at least event_latency_cycles");
}

void read_link_speeds(TomlTable& processor, ProcessorSpec& spec) {
  if (processor.optional_array("link_speeds_mbps") == nullptr)
    processor.fail("link_speeds_mbps", "must list the link speeds in Mbit/s");
  spec.link_speeds_mbps = processor.integers_in("link_speeds_mbps", limits::kMinLinkMbps,
                                                limits::kMaxLinkMbps, "Mbit/s");
  if (spec.link_speeds_mbps.empty())
    processor.fail("link_speeds_mbps", "must list the link speeds in Mbit/s");
}

void read_speed_grades(const toml::table& table, const std::string& file, ProcessorSpec& spec) {
  TomlTable grades = platform_table(table, file, "[speed_grades]");
  for (const auto& [key, node] : table) {
    const Tick cycle_ps = grades.integer_in(key.str(), limits::kMinCyclePs, limits::kMaxCyclePs,
                                            "ps per cycle, 1 GHz to 1 MHz");
    spec.speed_grades.emplace(std::string(key.str()), cycle_ps * kPicosecond);
  }
  if (spec.speed_grades.empty())
    throw PlatformError(file, static_cast<int>(table.source().begin.line), "speed_grades",
                        "names no speed grade");
}

void read_link_timing(const toml::table& table, const std::string& file, LinkTimingSpec& timing) {
  TomlTable reader = platform_table(table, file, "[link_timing]");
  const auto bits = [&](std::string_view key, double minimum) {
    return reader.number_in(key, minimum, limits::kMaxLinkBits);
  };
  timing.data_packet_bits = bits("data_packet_bits", 1);
  timing.ack_packet_bits = bits("ack_packet_bits", 1);
  timing.ack_delay_bits = bits("ack_delay_bits", 0);
  timing.ack_turnaround_bits = bits("ack_turnaround_bits", 0);
  timing.ack_turnaround_fixed = reader.integer_in("ack_turnaround_ps", Tick{0},
                                                  limits::kMaxAckTurnaroundPs, "ps, 0 to 10 us") *
                                kPicosecond;
  timing.inter_packet_gap_bits = bits("inter_packet_gap_bits", 0);
  reader.reject_unknown_keys();
}

InstructionCost read_cost(const toml::node& node, std::string_view name, TomlTable& costs) {
  if (node.is_integer())
    return InstructionCost{costs.integer_in(name, 0, limits::kMaxInstructionCycles, "cycles"), 0,
                           false};
  if (!node.is_table())
    costs.fail(name, "must be a cycle count or { base = N, per_unit = N, fpu = BOOL }");
  TomlTable entry =
      platform_table(*node.as_table(), costs.file(), fmt::format("[cost_table] entry '{}'", name));
  InstructionCost cost;
  cost.base = entry.integer_in("base", 0, limits::kMaxInstructionCycles, "cycles");
  cost.per_unit =
      entry.optional_integer_in("per_unit", 0, limits::kMaxInstructionCycles, 0, "cycles per unit");
  cost.fpu = entry.boolean("fpu", false);
  entry.reject_unknown_keys();
  return cost;
}

void read_cost_table(const toml::table& table, const std::string& file, CostTable& table_out) {
  TomlTable costs = platform_table(table, file, "[cost_table]");
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

const toml::table& require_table(TomlTable& top, std::string_view key) {
  const toml::table* table = top.optional_table(key);
  if (table == nullptr)
    throw PlatformError(top.file(), 1, std::string(key), "missing table");
  return *table;
}

} // namespace

ProcessorSpec load_processor(const std::string& file) {
  const toml::table root = parse_toml_file(file, "processor file");
  TomlTable top = platform_table(root, file, "the processor file");
  ProcessorSpec spec;
  TomlTable processor = platform_table(require_table(top, "processor"), file, "[processor]");
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
