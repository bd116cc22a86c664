// The cost table against the occam-probe kit: each nav::Work kind's entry beside the kit's
// figure for its reference kernel (nav_program/costs/reference/*.occ, compiled by the real INMOS oc
// 2.01.01 and run instruction by instruction; measured.toml is the kit's output, written by
// nav_program/costs/reference/price-kernels.sh). docs/cost-table.md, "Checked against the
// compiler".

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav_program/costs/work_costs.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace marsokhod::nav_program {
namespace {

using emulator::Instruction;

const std::filesystem::path kReference =
    std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "nav_program" / "costs" / "reference";

const emulator::CostTable& probe_t805() {
  static const emulator::PlatformSpec platform = emulator::load_platform(
      std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "platforms" / "pc-card.toml");
  return platform.nodes.front().cpu.costs;
}

// The entry's cycles as the kit's model prices them: every instruction in sequence (the FPU
// not overlapped) and bitcnt at 2 cycles (the kit has no b term).
double kit_model_cycles(const emulator::InstructionMix& mix) {
  const emulator::CostTable& costs = probe_t805();
  double cycles = 0.0;
  for (std::size_t i = 0; i < emulator::kInstructionCount; ++i) {
    const emulator::InstructionCost& c = costs[static_cast<Instruction>(i)];
    const double per_unit = static_cast<Instruction>(i) == Instruction::bitcnt ? 0.0 : c.per_unit;
    cycles +=
        static_cast<double>(mix.count[i]) * c.base + static_cast<double>(mix.units[i]) * per_unit;
  }
  return cycles;
}

struct KitFigure {
  double instructions = 0.0;
  double cycles = 0.0;
};

std::map<std::string, KitFigure> kit_figures() {
  const toml::table file = toml::parse_file((kReference / "measured.toml").string());
  std::map<std::string, KitFigure> figures;
  for (const auto& [kind, node] : file) {
    const toml::table& t = *node.as_table();
    figures[std::string(kind.str())] = {t["instructions_per_unit"].value_or(0.0),
                                        t["cycles_per_unit"].value_or(0.0)};
  }
  return figures;
}

// The one kind whose reference kernel does more than its unit, by design: nav reports the
// pixels the fill writes, and the kernel's loop also scans the reliable pixels between runs
// (18 instructions, 46 cycles each) and ends each run (35, 79), work nav does not report.
bool scans_more_than_its_unit(nav::Work kind) {
  return kind == nav::Work::fill_pixel;
}

TEST(WorkCostsProbe, EveryKindHasAReferenceKernelPricedByTheKit) {
  const std::map<std::string, KitFigure> kit = kit_figures();
  for (const WorkCost& cost : work_costs()) {
    const std::string kind(nav::to_string(cost.kind));
    EXPECT_TRUE(std::filesystem::exists(kReference / (kind + ".occ"))) << kind;
    ASSERT_TRUE(kit.contains(kind)) << kind << " is missing from measured.toml";
    EXPECT_GT(kit.at(kind).cycles, 0.0) << kind;
  }
}

TEST(WorkCostsProbe, EveryEntryIsWithinATenthOfItsReferenceKernel) {
  const std::map<std::string, KitFigure> kit = kit_figures();
  for (const WorkCost& cost : work_costs()) {
    if (scans_more_than_its_unit(cost.kind))
      continue;
    const std::string kind(nav::to_string(cost.kind));
    const double table = kit_model_cycles(cost.per_unit);
    EXPECT_NEAR(table, kit.at(kind).cycles, 0.10 * kit.at(kind).cycles) << kind;
  }
}

// The fill's unit is the scan step of an unreliable pixel and its fill step (36 + 28 cycles in
// the kernel's trace); the kernel's figure per written pixel adds the reliable pixels' scan.
TEST(WorkCostsProbe, TheFillsUnitIsItsKernelsWrittenPixelWithoutTheScanOfReliableOnes) {
  const WorkCost& fill = work_cost(nav::Work::fill_pixel);
  EXPECT_NEAR(kit_model_cycles(fill.per_unit), 36.0 + 28.0, 1.0);
  EXPECT_GT(kit_figures().at("fill_pixel").cycles, 4.0 * kit_model_cycles(fill.per_unit));
}

} // namespace
} // namespace marsokhod::nav_program
