// The T805 cost model: instruction mnemonics, cycle counts of instruction mixes, and the node
// that charges them.

#include "marsokhod/emulator/node/cost_table.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string_view>

namespace marsokhod::emulator {
namespace {

const NodeSpec& card() {
  static const PlatformSpec platform =
      load_platform(std::filesystem::path(MARSOKHOD_SOURCE_DIR) / "platforms" / "pc-card.toml");
  return platform.nodes.front();
}

TEST(CostTable, EveryInstructionHasAMnemonicThatMapsBack) {
  for (std::size_t i = 0; i < kInstructionCount; ++i) {
    const auto instruction = static_cast<Instruction>(i);
    EXPECT_EQ(instruction_from_mnemonic(mnemonic(instruction)), instruction)
        << mnemonic(instruction);
  }
  EXPECT_FALSE(instruction_from_mnemonic("frobnicate").has_value());
}

TEST(CostTable, EveryMnemonicMapsToItsInstructionAndNamesAreUnique) {
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < kInstructionCount; ++i) {
    const std::string_view name = mnemonic(static_cast<Instruction>(i));
    EXPECT_FALSE(name.empty()) << i;
    EXPECT_TRUE(names.insert(name).second) << name << " names two instructions";
    const std::optional<Instruction> back = instruction_from_mnemonic(name);
    ASSERT_TRUE(back.has_value()) << name;
    EXPECT_EQ(mnemonic(*back), name);
  }
  EXPECT_EQ(names.size(), kInstructionCount);
  // The platform file's keys, not the C++ spellings that step around keywords.
  EXPECT_EQ(mnemonic(Instruction::and_), "and");
  EXPECT_EQ(mnemonic(Instruction::not_), "not");
  EXPECT_FALSE(instruction_from_mnemonic("and_").has_value());
  EXPECT_EQ(mnemonic(Instruction::ldl), "ldl");
  EXPECT_EQ(mnemonic(Instruction::fpusqrtstep), "fpusqrtstep");
}

TEST(CostTable, MixCostsTheDataBookCyclesOnChip) {
  const CostTable& costs = card().cpu.costs;
  InstructionMix mix;
  mix.add(Instruction::ldl, 10).add(Instruction::mul, 2).add(Instruction::in, 1, 5);
  mix.add(Instruction::pfix, 3);
  // ldl 2, mul 38, in 2w+19 with w = 5, pfix 1 (data book, T805.md).
  EXPECT_EQ(costs.cycles(mix), 10 * 2 + 2 * 38 + (2 * 5 + 19) + 3 * 1);
}

TEST(CostTable, ExternalAccessesAddTheirExtraCyclesAndWaitStates) {
  CostTable costs = card().cpu.costs;
  InstructionMix mix;
  mix.add(Instruction::ldnl, 7);
  mix.external_accesses = 7;
  // 3-cycle external memory: 2 cycles more than on chip per access.
  EXPECT_EQ(costs.cycles(mix), 7 * 2 + 7 * (3 - 1));
  costs.wait_states = 2;
  EXPECT_EQ(costs.cycles(mix), 7 * 2 + 7 * (3 + 2 - 1));
}

TEST(CostTable, FpuRunsConcurrentlyWithTheIntegerProcessor) {
  const CostTable& costs = card().cpu.costs;
  InstructionMix fpu_bound;
  fpu_bound.add(Instruction::fpmul, 4).add(Instruction::ldl, 5);
  EXPECT_EQ(costs.cycles(fpu_bound), 4 * 11); // FPU 44 cycles hide the 10 integer ones
  InstructionMix integer_bound;
  integer_bound.add(Instruction::fpmul, 4).add(Instruction::ldl, 30);
  EXPECT_EQ(costs.cycles(integer_bound), 30 * 2);
}

TEST(Node, ComputeChargesCyclesAtTheSpeedGrade) {
  Kernel kernel;
  Node node(kernel, card());
  Tick done = -1;
  node.spawn("worker", [&] {
    node.compute(InstructionMix().add(Instruction::mul, 100));
    done = kernel.now();
  });
  kernel.run();
  // T805-30: 33,333 ps per cycle; mul 38 cycles.
  EXPECT_EQ(done, 100 * 38 * 33'333);
}

TEST(Node, PowerOffKillsItsProcessesAndRefusesNewOnes) {
  Kernel kernel;
  Node node(kernel, card());
  bool unwound = false;
  struct Flag {
    bool* set;
    ~Flag() { *set = true; }
  };
  node.spawn("waiter", [&] {
    Flag flag{&unwound};
    kernel.block(WaitInfo{});
  });
  kernel.run();
  node.power_off();
  EXPECT_TRUE(unwound);
  EXPECT_FALSE(node.powered());
  EXPECT_EQ(kernel.live_processes(), 0U);
  EXPECT_THROW(node.spawn("late", [] {}), std::logic_error);
}

TEST(Node, WorkspaceExhaustionIsAMemoryFaultNamingTheProcess) {
  NodeSpec small = card();
  small.memory.external_bytes = 4096;
  Kernel kernel;
  Node node(kernel, small);
  NodeSpawnOptions options;
  options.workspace_bytes = 3000;
  node.spawn(
      "first", [&] { kernel.block(WaitInfo{}); }, options);
  node.spawn(
      "second", [&] { kernel.block(WaitInfo{}); }, options);
  try {
    node.spawn(
        "third", [] {}, options);
    FAIL() << "a third 3000-byte workspace cannot fit in 4 KB on chip + 4 KB external";
  } catch (const MemoryFault& fault) {
    EXPECT_EQ(fault.process(), "third");
  }
}

} // namespace
} // namespace marsokhod::emulator
