// The memory plan: each process's buffers from the image size, each node's code, workspaces,
// free memory and peak, worked out by hand.

#include "support/test_files.hpp"

#include "marsokhod/nav_program/placement/memory_plan.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace marsokhod::nav_program {
namespace {

using test_support::kPlatforms;

struct Shipped {
  emulator::PlatformSpec platform;
  Placement placement;
};

Shipped shipped(const std::string& name) {
  emulator::PlatformSpec platform = emulator::load_platform(kPlatforms / (name + ".toml"));
  Placement placement =
      load_placement(default_placement_file(platform), platform, navigation_program_shape());
  return {std::move(platform), std::move(placement)};
}

const ProcessPlan& process(const NodePlan& node, const std::string& name) {
  for (const ProcessPlan& p : node.processes)
    if (p.process == name)
      return p;
  throw std::out_of_range(name);
}

TEST(MemoryPlan, BuffersFollowTheImageSizeAndThePyramid) {
  const Shipped card = shipped("pc-card");
  const MemoryPlan plan = plan_memory(card.platform, card.placement, 128, 128, 3, std::nullopt);
  ASSERT_EQ(plan.nodes.size(), 1U);
  const NodePlan& node = plan.nodes[0];
  // Both images (2 x 16384), layers 1 and 2 of both pyramids (2 x (64x64 + 32x32)), and the
  // original layer's census features of both eyes (2 x 16384).
  EXPECT_EQ(process(node, "features").buffer_bytes(),
            2 * 16384U + 2 * (4096U + 1024U) + 2 * 16384U);
  // The seeable disparity (4 B), the validity (1 B) and the four REAL32 terrain maps, which
  // the card's 2 MB keep.
  EXPECT_TRUE(plan.terrain_kept);
  EXPECT_EQ(process(node, "range").buffer_bytes(), 128U * 128U * (4 + 1 + 16));
  EXPECT_EQ(process(node, "acquire").buffer_bytes(), 16384U);
  // Matching keeps its inputs, the coarser layer's result (64x64, 4 B + 1 B) and one band of
  // 8 matched rows (4 B + 1 B); refine the whole original layer on its way to range.
  EXPECT_EQ(process(node, "matching").buffer_bytes(), 3 * 16384U + 4096U * 5 + 8U * 128U * 5);
  EXPECT_EQ(process(node, "refine").buffer_bytes(), 128U * 128U * (1 + 4 + 1 + 1 + 4));
  EXPECT_EQ(plan.band_rows, 8);
}

TEST(MemoryPlan, NodeFiguresAddCodeWorkspacesAndThePeakHandOver) {
  const Shipped card = shipped("pc-card");
  const MemoryPlan plan = plan_memory(card.platform, card.placement, 128, 128, 3, std::nullopt);
  const NodePlan& node = plan.nodes[0];
  // 4 KB on chip + 2 MB external; 0x70 reserved by the processor.
  EXPECT_EQ(node.memory_bytes, 4096U + 2048U * 1024U);
  EXPECT_EQ(node.reserved_bytes, 0x70U);
  std::size_t code = 0;
  std::size_t workspace = 0;
  for (const ProcessPlan& p : node.processes) {
    code += p.code_bytes;
    workspace += p.workspace_bytes;
  }
  EXPECT_EQ(node.code_bytes, code);
  EXPECT_EQ(node.free_for_buffers(), node.memory_bytes - 0x70U - code - workspace);
  // The largest hand-over is range's to zones: range still holds the seeable disparity (4 B),
  // the validity (1 B) and the terrain maps (16 B) when zones has received the maps and the
  // validity.
  EXPECT_EQ(node.buffer_bytes(), 128U * 128U * ((4 + 1 + 16) + (16 + 1)));
  EXPECT_TRUE(node.fits());
}

TEST(MemoryPlan, OnboardModulesHoldTheProgramWithBandsTheDisparityAndStrips) {
  const Shipped onboard = shipped("onboard");
  const MemoryPlan plan =
      plan_memory(onboard.platform, onboard.placement, 128, 128, 3, std::nullopt);
  ASSERT_EQ(plan.nodes.size(), 2U); // the cold spares run nothing
  EXPECT_EQ(plan.nodes[0].node, "module0");
  EXPECT_EQ(plan.nodes[1].node, "module1");
  // module0: features, holding everything, hands over to matching, which has received the
  // left layer and both eyes' features (3 x 1 B).
  EXPECT_EQ(plan.nodes[0].buffer_bytes(), 75776U + 3 * 16384U);
  // module1: the four terrain maps alone are 256 KB, so the terrain is kept as the disparity;
  // then refine's own buffers are the largest (left image, filled disparity 4 B, validity,
  // texture mask, seeable disparity 4 B), above every hand-over (80 KB + 80 KB).
  EXPECT_FALSE(plan.terrain_kept);
  EXPECT_EQ(plan.nodes[1].buffer_bytes(), 128U * 128U * (1 + 4 + 1 + 1 + 4));
  EXPECT_TRUE(plan.fits());
  // The zones' grid gets half of what module1 has beside the zones' own buffers (the
  // disparity, a terrain row, the validity and the zone map).
  const std::size_t zones = 128U * 128U * (4 + 1 + 1) + 128U * 16;
  EXPECT_EQ(plan.zone_grid_bytes, (plan.nodes[1].free_for_buffers() - zones) / 2);
  // With 1 MB per module (a what-if) the terrain's maps are kept, and the grid's budget is
  // what is left beside them.
  const MemoryPlan roomy =
      plan_memory(onboard.platform, onboard.placement, 128, 128, 3, 1024 * 1024);
  EXPECT_TRUE(roomy.fits());
  EXPECT_TRUE(roomy.terrain_kept);
  const std::size_t zones_with_maps = 128U * 128U * (16 + 1 + 1);
  EXPECT_EQ(roomy.zone_grid_bytes, (roomy.nodes[1].free_for_buffers() - zones_with_maps) / 2);
}

TEST(MemoryPlan, TheTerrainIsKeptWhereTheMapsFitAndWorkedOutAgainWhereNot) {
  const Shipped card = shipped("pc-card");
  // At 256 x 256 the four maps are 1 MB: zones handing over to path would hold 2.3 MB, more
  // than the card's 2 MB, so only the disparity is kept; with 8 MB the maps are.
  const MemoryPlan small = plan_memory(card.platform, card.placement, 256, 256, 4, std::nullopt);
  EXPECT_FALSE(small.terrain_kept);
  EXPECT_TRUE(small.fits());
  EXPECT_EQ(process(small.nodes[0], "zones").buffer_bytes(), 256U * 256U * (4 + 1 + 1) + 256U * 16);
  EXPECT_TRUE(plan_memory(card.platform, card.placement, 256, 256, 4, 8U << 20).terrain_kept);
}

} // namespace
} // namespace marsokhod::nav_program
