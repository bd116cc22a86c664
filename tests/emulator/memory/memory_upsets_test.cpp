// Upsets, stuck bits and SEC-DED EDAC in a node's memory, and the blocks reports name.

#include "marsokhod/emulator/memory/memory_arena.hpp"
#include "marsokhod/emulator/memory/memory_upsets.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace marsokhod::emulator {
namespace {

constexpr Address kUpsetExternal = 0x80001000U;
constexpr Address kOnChip = 0x80000100U;

MemoryConfig upset_node() {
  return MemoryConfig{4096, 4096, 0x70};
}

std::byte byte_at(const MemoryArena& arena, Address address) {
  return *arena.pointer(address);
}

TEST(MemoryUpsets, UnprotectedUpsetInvertsExactlyThatBit) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  *arena.pointer(kUpsetExternal + 5) = std::byte{0x0F};
  EXPECT_EQ(upsets.upset(kUpsetExternal + 5, 7), UpsetEffect::flipped);
  EXPECT_EQ(byte_at(arena, kUpsetExternal + 5), std::byte{0x8F});
  EXPECT_EQ(byte_at(arena, kUpsetExternal + 4), std::byte{0});
  EXPECT_EQ(byte_at(arena, kUpsetExternal + 6), std::byte{0});
}

TEST(MemoryUpsets, EdacCorrectsASingleErrorSoTheProgramReadsTheWordUnchanged) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  upsets.set_edac_on_external(true);
  *arena.pointer(kUpsetExternal + 9) = std::byte{0x42};
  EXPECT_EQ(upsets.upset(kUpsetExternal + 9, 1), UpsetEffect::corrected);
  EXPECT_EQ(byte_at(arena, kUpsetExternal + 9), std::byte{0x42});
  EXPECT_EQ(upsets.latent_words(), 1U);
}

TEST(MemoryUpsets, SecondErrorInOneWordIsUncorrectableAndReachesTheProgram) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  upsets.set_edac_on_external(true);
  // Bytes 8 and 11 share the word at +8; the second error is beyond a SEC-DED code.
  EXPECT_EQ(upsets.upset(kUpsetExternal + 8, 0), UpsetEffect::corrected);
  EXPECT_EQ(upsets.upset(kUpsetExternal + 11, 3), UpsetEffect::uncorrectable);
  EXPECT_EQ(byte_at(arena, kUpsetExternal + 11), std::byte{0x08});
}

TEST(MemoryUpsets, ErrorsInDifferentWordsAreEachCorrected) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  upsets.set_edac_on_external(true);
  EXPECT_EQ(upsets.upset(kUpsetExternal + 3, 0), UpsetEffect::corrected);
  EXPECT_EQ(upsets.upset(kUpsetExternal + 4, 0), UpsetEffect::corrected);
  EXPECT_EQ(upsets.latent_words(), 2U);
}

TEST(MemoryUpsets, ACheckBitErrorCountsAsTheWordsOneError) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  upsets.set_edac_on_external(true);
  EXPECT_EQ(upsets.upset_check_bit(kUpsetExternal + 16, 6), UpsetEffect::corrected);
  EXPECT_EQ(upsets.upset(kUpsetExternal + 17, 2), UpsetEffect::uncorrectable);
  EXPECT_THROW(upsets.upset_check_bit(kUpsetExternal, kEdacCheckBits), std::out_of_range);
}

TEST(MemoryUpsets, OnChipMemoryHasNoEdac) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  upsets.set_edac_on_external(true);
  EXPECT_FALSE(upsets.protects(kOnChip));
  EXPECT_EQ(upsets.upset(kOnChip, 2), UpsetEffect::flipped);
  EXPECT_EQ(byte_at(arena, kOnChip), std::byte{0x04});
  EXPECT_THROW(upsets.upset_check_bit(kOnChip, 0), std::invalid_argument);
}

TEST(MemoryUpsets, ScrubClearsTheSingleErrorsOfItsRangeOnly) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  upsets.set_edac_on_external(true);
  upsets.upset(kUpsetExternal + 0, 0);
  upsets.upset(kUpsetExternal + 2048, 0);
  EXPECT_EQ(upsets.scrub(kUpsetExternal, 1024), 1U);
  EXPECT_EQ(upsets.latent_words(), 1U);
  // The scrubbed word takes a new upset as its only error again.
  EXPECT_EQ(upsets.upset(kUpsetExternal + 1, 0), UpsetEffect::corrected);
  EXPECT_EQ(upsets.scrubbed(), 1U);
}

TEST(MemoryUpsets, StuckBitIsForcedBackAfterEachWrite) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  upsets.stick(kUpsetExternal + 1, 4, true);
  EXPECT_EQ(byte_at(arena, kUpsetExternal + 1), std::byte{0x10});
  EXPECT_TRUE(upsets.has_stuck());
  *arena.pointer(kUpsetExternal + 1) = std::byte{0x01};
  upsets.reassert_stuck();
  EXPECT_EQ(byte_at(arena, kUpsetExternal + 1), std::byte{0x11});
  upsets.stick(kUpsetExternal + 2, 0, false);
  *arena.pointer(kUpsetExternal + 2) = std::byte{0xFF};
  upsets.reassert_stuck();
  EXPECT_EQ(byte_at(arena, kUpsetExternal + 2), std::byte{0xFE});
}

TEST(MemoryUpsets, UnderEdacAStuckBitIsAPermanentErrorNoScrubClears) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  upsets.set_edac_on_external(true);
  EXPECT_EQ(upsets.stick(kUpsetExternal + 20, 1, true), UpsetEffect::corrected);
  EXPECT_EQ(byte_at(arena, kUpsetExternal + 20), std::byte{0});
  EXPECT_EQ(upsets.scrub(kUpsetExternal, 4096), 0U);
  EXPECT_EQ(upsets.upset(kUpsetExternal + 21, 0), UpsetEffect::uncorrectable);
}

TEST(MemoryUpsets, AddressesOutsideMemoryAndBitsAboveSevenAreRefused) {
  MemoryArena arena(upset_node());
  MemoryUpsets upsets(arena);
  EXPECT_THROW(upsets.upset(kUpsetExternal + 4096, 0), std::out_of_range);
  EXPECT_THROW(upsets.upset(kUpsetExternal, 8), std::out_of_range);
  EXPECT_THROW(upsets.stick(kUpsetExternal + 4096, 0, true), std::out_of_range);
}

TEST(MemoryBlocks, BlockAtNamesOwnerLabelAndKindUntilTheBlockIsFreed) {
  MemoryArena arena(upset_node());
  arena.set_label("matching", "cost rows, 3 rows x 128 px x 2 B");
  const Address data = arena.allocate_block(100, 4, Placement::external, "matching");
  const Address workspace = arena.reserve_workspace("refine", 64);
  const std::optional<BlockInfo> in_data = arena.block_at(data + 99);
  ASSERT_TRUE(in_data.has_value());
  EXPECT_EQ(in_data->start, data);
  EXPECT_EQ(in_data->bytes, 100U);
  EXPECT_EQ(in_data->owner, "matching");
  EXPECT_EQ(in_data->label, "cost rows, 3 rows x 128 px x 2 B");
  EXPECT_EQ(in_data->kind, BlockKind::data);
  EXPECT_FALSE(arena.block_at(data + 100).has_value());
  const std::optional<BlockInfo> in_workspace = arena.block_at(workspace);
  ASSERT_TRUE(in_workspace.has_value());
  EXPECT_EQ(in_workspace->kind, BlockKind::workspace);
  EXPECT_TRUE(in_workspace->label.empty());
  EXPECT_TRUE(in_workspace->on_chip);
  arena.free_block(data);
  EXPECT_FALSE(arena.block_at(data).has_value());
  EXPECT_EQ(arena.blocks().size(), 1U);
}

TEST(MemoryBlocks, BlockListenerSeesEachAllocationAndFree) {
  MemoryArena arena(upset_node());
  std::vector<std::tuple<Address, std::size_t, bool>> seen;
  arena.set_block_listener([&seen](Address start, std::size_t bytes, bool allocated) {
    seen.emplace_back(start, bytes, allocated);
  });
  const Address a = arena.allocate_block(10, 4, Placement::external, "p");
  arena.free_block(a);
  ASSERT_EQ(seen.size(), 2U);
  EXPECT_EQ(seen[0], std::make_tuple(a, std::size_t{12}, true)); // whole words
  EXPECT_EQ(seen[1], std::make_tuple(a, std::size_t{12}, false));
}

} // namespace
} // namespace marsokhod::emulator
