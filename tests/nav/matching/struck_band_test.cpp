// A band of the matcher whose memory an upset struck stops with a range error (what occam's
// range checks do) rather than index outside its buffers; an intact band passes.

#include "matching/band_dp.hpp"
#include "matching/band_layout.hpp"
#include "matching/band_output.hpp"
#include "stereo/stereo_layer.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory_resource>
#include <stdexcept>
#include <utility>
#include <vector>

namespace marsokhod::nav::detail {
namespace {

constexpr int kWidth = 40;

/// Hands out memory as usual and remembers each block, so a test can strike a bit in it as an
/// upset would strike the module's memory.
class RecordingMemory : public std::pmr::memory_resource {
public:
  std::vector<std::pair<void*, std::size_t>> blocks;

private:
  void* do_allocate(std::size_t bytes, std::size_t alignment) override {
    void* block = std::pmr::new_delete_resource()->allocate(bytes, alignment);
    blocks.emplace_back(block, bytes);
    return block;
  }
  void do_deallocate(void* block, std::size_t bytes, std::size_t alignment) override {
    std::pmr::new_delete_resource()->deallocate(block, bytes, alignment);
  }
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
    return this == &other;
  }
};

/// Every tile wants disparities 2 .. 9 of the limits 0 .. 12.
BandLayout laid_out(std::pmr::memory_resource* memory) {
  BandLayout layout(memory);
  const std::vector<int> low(static_cast<std::size_t>(tile_count(kWidth)), 2);
  const std::vector<int> high(low.size(), 9);
  layout.lay_out(kWidth, DisparityLimits{0, 12}, low, high);
  return layout;
}

TEST(StruckBand, IntactLayoutPassesItsCheck) {
  RecordingMemory memory;
  const BandLayout layout = laid_out(&memory);
  EXPECT_NO_THROW(layout.check());
  EXPECT_EQ(layout.first(16), 2);
  EXPECT_EQ(layout.cells(16), 8);
}

// The first block the layout takes holds each tile's first disparity: bit 20 of tile 0's is
// struck, far outside the limits (1 << 20 columns back).
TEST(StruckBand, LayoutWithAStruckFirstDisparityIsARangeError) {
  RecordingMemory memory;
  const BandLayout layout = laid_out(&memory);
  ASSERT_FALSE(memory.blocks.empty());
  int first = 0;
  std::memcpy(&first, memory.blocks.front().first, sizeof first);
  ASSERT_EQ(first, 2) << "the first block is not the tiles' first disparities";
  first ^= 1 << 20;
  std::memcpy(memory.blocks.front().first, &first, sizeof first);
  EXPECT_THROW(layout.check(), std::range_error);
}

// A low bit struck keeps the disparity inside the limits but breaks the tile's offsets: the
// pixels would read other pixels' cells.
TEST(StruckBand, LayoutWithAStruckCellCountIsARangeError) {
  RecordingMemory memory;
  const BandLayout layout = laid_out(&memory);
  ASSERT_GE(memory.blocks.size(), 2U);
  int cells = 0;
  std::byte* block = static_cast<std::byte*>(memory.blocks[1].first);
  std::memcpy(&cells, block + sizeof(int), sizeof cells); // tile 1's cells
  ASSERT_EQ(cells, 8) << "the second block is not the tiles' cell counts";
  cells ^= 1;
  std::memcpy(block + sizeof(int), &cells, sizeof cells);
  EXPECT_THROW(layout.check(), std::range_error);
}

// A chosen disparity beyond the right lines' reach would read before their first entry.
TEST(StruckBand, ChosenDisparityBeyondTheLinesIsARangeError) {
  std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
  const int max_disparity = 12;
  RightLines right(kWidth, max_disparity, memory);
  const std::vector<std::int16_t> right_view(static_cast<std::size_t>(kWidth * kBandRows), 3);
  right.load(right_view.data());
  BandChoice choice(memory);
  choice.disparity.assign(static_cast<std::size_t>(kWidth * kBandRows), 3);
  choice.subpixel.assign(choice.disparity.size(), 3.0F);
  LayerOutput output{imaging::Image<float>(kWidth, kBandRows, 1, 0.0F, memory),
                     imaging::Image<std::uint8_t>(kWidth, kBandRows, 1, 0, memory), 0, 0, 0};
  // Intact: every pixel from x = 3 on finds its right pixel agreeing.
  EXPECT_EQ(check_band(choice, right, 0, kBandRows, 0, output), 3);
  EXPECT_EQ(output.valid_pixels, static_cast<std::uint64_t>((kWidth - 3) * kBandRows));
  choice.disparity[17] = static_cast<std::int16_t>(3 | (1 << 12));
  EXPECT_THROW(check_band(choice, right, 0, kBandRows, 0, output), std::range_error);
  choice.disparity[17] = -200;
  EXPECT_THROW(check_band(choice, right, 0, kBandRows, 0, output), std::range_error);
}

} // namespace
} // namespace marsokhod::nav::detail
