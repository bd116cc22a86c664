// A node's memory: the address map, allocation, faults and trace counters.

#include "marsokhod/emulator/memory/memory_arena.hpp"
#include "marsokhod/emulator/memory/memory_arena_hooks.hpp"
#include "marsokhod/emulator/trace/chrome_trace.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory_resource>
#include <sstream>
#include <stdexcept>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace marsokhod::emulator {
namespace {

// T805 address map (T805.md, "Clock and memory"): on-chip RAM #80000000..#80000FFF with
// MemStart #80000070, external memory from #80001000.
constexpr Address kMemStart = 0x80000070U;
constexpr Address kExternal = 0x80001000U;

MemoryConfig small_node(std::size_t external_bytes = 1024) {
  return MemoryConfig{4096, external_bytes, 0x70};
}

TEST(MemoryArena, FirstExternalBlockStartsAtTheExternalBase) {
  MemoryArena arena(small_node());
  EXPECT_EQ(arena.allocate_block(100, 4, Placement::external, "p"), kExternal);
  EXPECT_EQ(arena.allocate_block(8, 4, Placement::external, "p"), kExternal + 100);
}

TEST(MemoryArena, FirstOnChipBlockStartsAtMemStart) {
  MemoryArena arena(small_node());
  EXPECT_EQ(arena.allocate_block(16, 4, Placement::on_chip, "p"), kMemStart);
}

TEST(MemoryArena, SizesAreRoundedUpToWholeWords) {
  MemoryArena arena(small_node());
  arena.allocate_block(1, 1, Placement::external, "p");
  EXPECT_EQ(arena.allocate_block(1, 1, Placement::external, "p"), kExternal + 4);
  EXPECT_EQ(arena.usage().in_use_bytes, 8U);
}

TEST(MemoryArena, AlignmentIsHonouredInAddressesAndHostPointers) {
  MemoryArena arena(small_node());
  arena.allocate_block(4, 4, Placement::external, "p");
  const Address aligned = arena.allocate_block(8, 64, Placement::external, "p");
  EXPECT_EQ(aligned, kExternal + 64);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(arena.pointer(aligned)) % 64, 0U);
  // The 60-byte gap before the aligned block stays free and is reused first.
  EXPECT_EQ(arena.allocate_block(60, 4, Placement::external, "p"), kExternal + 4);
}

TEST(MemoryArena, FreedBlockIsReusedFirstFit) {
  MemoryArena arena(small_node());
  const Address a = arena.allocate_block(64, 4, Placement::external, "p");
  arena.allocate_block(64, 4, Placement::external, "p");
  arena.free_block(a);
  EXPECT_EQ(arena.allocate_block(32, 4, Placement::external, "p"), a);
  EXPECT_EQ(arena.allocate_block(32, 4, Placement::external, "p"), a + 32);
}

TEST(MemoryArena, NeighbouringFreeBlocksCoalesce) {
  MemoryArena arena(small_node(1024));
  const Address a = arena.allocate_block(256, 4, Placement::external, "p");
  const Address b = arena.allocate_block(256, 4, Placement::external, "p");
  const Address c = arena.allocate_block(256, 4, Placement::external, "p");
  arena.allocate_block(256, 4, Placement::external, "p");
  arena.free_block(a);
  arena.free_block(c);
  EXPECT_EQ(arena.largest_free_block(Placement::external), 256U);
  arena.free_block(b); // joins a and c into one 768-byte block
  EXPECT_EQ(arena.largest_free_block(Placement::external), 768U);
  EXPECT_EQ(arena.allocate_block(768, 4, Placement::external, "p"), a);
}

TEST(MemoryArena, EverythingFreedLeavesOneBlockPerRegion) {
  MemoryArena arena(small_node(1024));
  std::vector<Address> blocks;
  for (int i = 0; i < 10; ++i)
    blocks.push_back(arena.allocate_block(40 + 8 * i, 4, Placement::on_chip_then_external, "p"));
  for (std::size_t i = 0; i < blocks.size(); i += 2)
    arena.free_block(blocks[i]);
  for (std::size_t i = 1; i < blocks.size(); i += 2)
    arena.free_block(blocks[i]);
  EXPECT_EQ(arena.largest_free_block(Placement::on_chip), 4096U - 0x70U);
  EXPECT_EQ(arena.largest_free_block(Placement::external), 1024U);
  EXPECT_EQ(arena.usage().in_use_bytes, 0U);
}

TEST(MemoryArena, OnChipThenExternalSpillsWhenOnChipIsFull) {
  MemoryArena arena(small_node());
  EXPECT_EQ(arena.allocate_block(3900, 4, Placement::on_chip_then_external, "p"), kMemStart);
  EXPECT_EQ(arena.allocate_block(100, 4, Placement::on_chip_then_external, "p"), kExternal);
}

TEST(MemoryArena, ExhaustionRaisesMemoryFaultNamingTheProcessAndRequest) {
  MemoryArena arena(small_node(1024));
  arena.allocate_block(1000, 4, Placement::external, "stereo.match");
  try {
    arena.allocate_block(512, 8, Placement::external, "stereo.match");
    FAIL() << "expected a memory fault";
  } catch (const MemoryFault& fault) {
    EXPECT_EQ(fault.process(), "stereo.match");
    EXPECT_EQ(fault.requested_bytes(), 512U);
    EXPECT_EQ(fault.alignment(), 8U);
    EXPECT_EQ(fault.free_bytes(), 24U);
    const std::string message = fault.what();
    EXPECT_NE(message.find("'stereo.match'"), std::string::npos) << message;
    EXPECT_NE(message.find("512 bytes"), std::string::npos) << message;
  }
}

TEST(MemoryArena, PmrInterfaceChargesTheScopedOwner) {
  MemoryArena arena(small_node(4096));
  {
    MemoryArena::OwnerScope scope(arena, "elevation");
    std::pmr::vector<int> values(100, 7, &arena);
    EXPECT_EQ(arena.address_of(values.data()), kExternal);
    EXPECT_EQ(arena.owners().at(0).owner, "elevation");
    EXPECT_EQ(arena.owners().at(0).data_bytes, 400U);
  }
  EXPECT_EQ(arena.owners().at(0).data_bytes, 0U);
  EXPECT_EQ(arena.owners().at(0).peak_bytes, 400U);
}

TEST(MemoryArena, PmrExhaustionNamesTheProviderProcess) {
  MemoryArena arena(small_node(256));
  arena.set_owner_provider([] { return std::string("planner"); });
  std::pmr::vector<char> bytes(&arena);
  EXPECT_THROW(
      {
        try {
          bytes.resize(1000);
        } catch (const MemoryFault& fault) {
          EXPECT_EQ(fault.process(), "planner");
          throw;
        }
      },
      MemoryFault);
}

TEST(MemoryArena, WorkspacesAreChargedApartFromData) {
  MemoryArena arena(small_node());
  const Address workspace = arena.reserve_workspace("consumer", 200);
  arena.allocate_block(100, 4, Placement::external, "consumer");
  EXPECT_TRUE(arena.is_on_chip(workspace));
  const OwnerUsage usage = arena.owners().at(0);
  EXPECT_EQ(usage.workspace_bytes, 200U);
  EXPECT_EQ(usage.data_bytes, 100U);
  EXPECT_EQ(arena.usage().workspace_bytes, 200U);
}

TEST(MemoryArena, HighWaterMarksSurviveFrees) {
  MemoryArena arena(small_node());
  const Address a = arena.allocate_block(300, 4, Placement::external, "a");
  const Address b = arena.allocate_block(200, 4, Placement::on_chip, "b");
  arena.free_block(a);
  arena.free_block(b);
  EXPECT_EQ(arena.usage().in_use_bytes, 0U);
  EXPECT_EQ(arena.usage().peak_bytes, 500U);
  EXPECT_EQ(arena.usage().external_peak_bytes, 300U);
  EXPECT_EQ(arena.usage().on_chip_peak_bytes, 200U);
  EXPECT_EQ(arena.usage().allocations, 2U);
  EXPECT_EQ(arena.usage().frees, 2U);
}

TEST(MemoryArena, AddressMapDistinguishesOnChipFromExternal) {
  MemoryArena arena(small_node(1024));
  EXPECT_TRUE(arena.is_on_chip(0x80000000U));
  EXPECT_TRUE(arena.is_on_chip(0x80000FFFU));
  EXPECT_FALSE(arena.is_on_chip(0x80001000U));
  EXPECT_TRUE(arena.contains(0x800013FFU));
  EXPECT_FALSE(arena.contains(0x80001400U));
  EXPECT_FALSE(arena.contains(0x7FFFFFFFU));
  EXPECT_EQ(arena.end_address(), 0x80001400U);
  EXPECT_EQ(arena.address_of(arena.pointer(0x80001234U)), 0x80001234U);
  EXPECT_THROW(arena.pointer(0x80001400U), std::out_of_range);
}

TEST(MemoryArena, BitFlipChangesExactlyOneBitOfTheRealBytes) {
  MemoryArena arena(small_node(1024));
  const Address block = arena.allocate_block(64, 4, Placement::external, "p");
  std::memset(arena.pointer(block), 0x5A, 64);
  std::vector<std::byte> before(arena.pointer(block), arena.pointer(block) + 64);
  arena.flip_bit(block + 10, 3);
  int changed_bits = 0;
  for (std::size_t i = 0; i < 64; ++i)
    changed_bits +=
        __builtin_popcount(std::to_integer<unsigned>(before[i] ^ arena.pointer(block)[i]));
  EXPECT_EQ(changed_bits, 1);
  EXPECT_EQ(std::to_integer<unsigned>(arena.pointer(block)[10]), 0x5AU ^ 0x08U);
}

TEST(MemoryArena, BitFlipOutsideMemoryIsRefused) {
  MemoryArena arena(small_node(1024));
  EXPECT_THROW(arena.flip_bit(0x80001400U, 0), std::out_of_range);
  EXPECT_THROW(arena.flip_bit(0x80001000U, 8), std::out_of_range);
}

TEST(MemoryArena, SameRequestsGiveSameAddresses) {
  auto run = [] {
    MemoryArena arena(small_node(8192));
    std::vector<Address> seen;
    std::vector<Address> live;
    for (unsigned i = 0; i < 200; ++i) {
      const std::size_t bytes = 4 + (i * 37U) % 120;
      live.push_back(
          arena.allocate_block(bytes, 4U << (i % 3), Placement::on_chip_then_external, "p"));
      seen.push_back(live.back());
      if (i % 3 == 2) {
        arena.free_block(live[live.size() / 2]);
        live.erase(live.begin() + static_cast<std::ptrdiff_t>(live.size() / 2));
      }
    }
    return seen;
  };
  EXPECT_EQ(run(), run());
}

TEST(MemoryArena, FreeingAnUnknownAddressIsRefused) {
  MemoryArena arena(small_node());
  const Address a = arena.allocate_block(16, 4, Placement::external, "p");
  EXPECT_THROW(arena.free_block(a + 4), std::invalid_argument);
  arena.free_block(a);
  EXPECT_THROW(arena.free_block(a), std::invalid_argument);
}

TEST(MemoryArena, OversizedOnChipMemoryIsRefused) {
  EXPECT_THROW(MemoryArena(MemoryConfig{8192, 1024, 0x70}), std::invalid_argument);
}

TEST(MemoryArenaInKernel, AllocationsAreChargedToTheRunningProcess) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  MemoryArena arena(small_node(4096));
  attach_memory(arena, kernel, "node0");
  kernel.spawn(
      cpu, "stereo", [&] { std::pmr::vector<int> row(64, 0, &arena); });
  kernel.spawn(cpu, "planner", [&] { std::pmr::vector<int> path(16, 0, &arena); });
  kernel.run();
  const auto owners = arena.owners();
  ASSERT_EQ(owners.size(), 2U);
  EXPECT_EQ(owners[0].owner, "stereo");
  EXPECT_EQ(owners[0].peak_bytes, 256U);
  EXPECT_EQ(owners[1].owner, "planner");
  EXPECT_EQ(owners[1].peak_bytes, 64U);
}

TEST(MemoryArenaInKernel, FaultInsideAProcessNamesItAndIsTraced) {
  std::ostringstream out;
  std::string faulted;
  {
    ChromeTraceWriter writer(out);
    Kernel kernel;
    kernel.set_trace(&writer);
    Cpu& cpu = kernel.add_cpu("module1");
    MemoryArena arena(small_node(1024));
    attach_memory(arena, kernel, "module1");
    kernel.spawn(cpu, "elevation", [&] {
      try {
        std::pmr::vector<double> map(1000, 0.0, &arena);
      } catch (const MemoryFault& fault) {
        faulted = fault.process();
      }
    });
    kernel.run();
  }
  EXPECT_EQ(faulted, "elevation");
  EXPECT_NE(out.str().find("\"memory fault\""), std::string::npos);
  EXPECT_NE(out.str().find("'elevation'"), std::string::npos);
}

TEST(MemoryArenaInKernel, ScheduledBitFlipLandsAtItsTime) {
  Kernel kernel;
  Cpu& cpu = kernel.add_cpu("node0");
  MemoryArena arena(small_node(1024));
  const Address word = arena.allocate_block(4, 4, Placement::external, "p");
  schedule_bit_flip(kernel, arena, "node0", microseconds(5), word + 1, 7);
  unsigned before = 0;
  unsigned after = 0;
  kernel.spawn(cpu, "reader", [&] {
    kernel.consume(microseconds(4));
    before = std::to_integer<unsigned>(arena.pointer(word + 1)[0]);
    kernel.consume(microseconds(2));
    after = std::to_integer<unsigned>(arena.pointer(word + 1)[0]);
  });
  kernel.run();
  EXPECT_EQ(before, 0x00U);
  EXPECT_EQ(after, 0x80U);
  EXPECT_THROW(schedule_bit_flip(kernel, arena, "node0", microseconds(9), 0x80002000U, 0),
               std::out_of_range);
}

/// Host memory of this process, in bytes: resident (touched) and virtual (mapped).
std::size_t statm_bytes(int field) {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages[2] = {0, 0};
  statm >> pages[0] >> pages[1];
  return pages[field] * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

// The largest T805 memory is legal in a platform file; it must cost the host only what is used.
constexpr std::size_t kLargestExternal = 0x7FFFF000U;

TEST(MemoryArena, TheLargestExternalMemoryTakesHostMemoryOnlyWhereTouched) {
  const std::size_t resident_before = statm_bytes(1);
  MemoryArena arena(small_node(kLargestExternal));
  EXPECT_LT(statm_bytes(1), resident_before + (std::size_t{64} << 20));
  // Zero where never written, at both ends, and usable.
  const Address last = arena.end_address() - 1;
  EXPECT_EQ(std::to_integer<int>(*arena.pointer(last)), 0);
  EXPECT_EQ(std::to_integer<int>(*arena.pointer(kExternal)), 0);
  *arena.pointer(last) = std::byte{0x5A};
  EXPECT_EQ(std::to_integer<int>(*arena.pointer(last)), 0x5A);
  const Address block = arena.allocate_block(std::size_t{1} << 30, 4, Placement::external, "big");
  EXPECT_EQ(block, kExternal);
  EXPECT_LT(statm_bytes(1), resident_before + (std::size_t{64} << 20));
}

/// In a child: address space for a little more than one 2 GB node (as under `ulimit -v`), then
/// two such nodes. Exits 0 when the second is a HostMemoryError stating the size.
[[noreturn]] void map_two_largest_nodes_with_little_address_space() {
  const rlim_t room = statm_bytes(0) + (std::size_t{2200} << 20);
  const rlimit limit{room, room};
  if (::setrlimit(RLIMIT_AS, &limit) != 0)
    std::_Exit(2);
  MemoryArena first(small_node(kLargestExternal));
  try {
    MemoryArena second(small_node(kLargestExternal));
  } catch (const HostMemoryError& error) {
    std::fputs(error.what(), stderr);
    std::_Exit(std::strstr(error.what(), "2147483648 bytes") != nullptr ? 0 : 3);
  } catch (...) {
    std::_Exit(4);
  }
  std::_Exit(5);
}

TEST(MemoryArena, AHostThatCannotMapTheMemoryIsAHostMemoryErrorNotABadAlloc) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(map_two_largest_nodes_with_little_address_space(), testing::ExitedWithCode(0),
              "cannot map 2147483648 bytes of host memory");
}

} // namespace
} // namespace marsokhod::emulator
