// The T805 cost model: instruction mnemonics, cycle counts of instruction mixes, and the node
// that charges them.

#include "marsokhod/emulator/node/cost_table.hpp"
#include "marsokhod/emulator/node/node.hpp"
#include "marsokhod/emulator/platform/platform.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string_view>
#include <sys/resource.h>
#include <unistd.h>

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

/// In a child with address space for about one 2 GB node: a second is refused naming it.
[[noreturn]] void build_two_largest_nodes_with_little_address_space() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  statm >> pages;
  const rlim_t room =
      pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)) + (std::size_t{2200} << 20);
  const rlimit limit{room, room};
  if (::setrlimit(RLIMIT_AS, &limit) != 0)
    std::_Exit(2);
  NodeSpec big = card();
  big.memory.external_bytes = 0x7FFFF000U; // the T805 address space, legal in a platform file
  Kernel kernel;
  Node first(kernel, big);
  big.name = "second";
  try {
    Node second(kernel, big);
  } catch (const HostMemoryError& error) {
    std::fputs(error.what(), stderr);
    std::_Exit(0);
  }
  std::_Exit(3);
}

TEST(Node, NodeWhoseMemoryTheHostCannotMapIsAnErrorNamingTheNode) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(build_two_largest_nodes_with_little_address_space(), testing::ExitedWithCode(0),
              "node second \\(2097148 KB of external memory\\): cannot map");
}

} // namespace
} // namespace marsokhod::emulator
