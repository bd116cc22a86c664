// NodeTerrain: the terrain as a node of the program keeps it, whole or as the disparity.
#pragma once

// The terrain as the processes after range hold it (private to the layer): the four
// maps when the memory plan keeps them, or only the seeable disparity, whose rows are worked out
// again each time they are read. Both sides of a channel know which: it is the plan's.

#include "processes/process_bodies.hpp"

#include "marsokhod/nav/terrain/terrain_rows.hpp"

#include <array>
#include <cstdint>
#include <memory_resource>
#include <optional>
#include <span>
#include <vector>

namespace marsokhod::nav_program::detail {

/// Rows of a terrain checked, each time one is asked for, against the word sums range made of
/// the rows they are built from (the seeable disparity, or the four maps): the navigation's
/// check of the buffer it keeps longest (CycleSupervisor::check_terrain).
class CheckedTerrain final : public nav::TerrainRows {
public:
  /// `sums` holds plane p's row y at p * height + y; the node is charged for each sum.
  CheckedTerrain(const nav::TerrainRows& rows, std::vector<imaging::ImageView<const float>> planes,
                 std::span<const std::uint32_t> sums, emulator::Node& node);
  /// Throws std::range_error when a source row's sum no longer checks.
  Row row(int y) const override;

private:
  const nav::TerrainRows* rows_;
  std::vector<imaging::ImageView<const float>> planes_;
  std::span<const std::uint32_t> sums_;
  emulator::Node* node_;
  mutable int checked_ = -1; ///< the row checked last, which the rows below still hold
};

/// The word sums of every row of `planes`, plane after plane, charged to `node`.
std::pmr::vector<std::uint32_t> row_sums(std::span<const imaging::ImageView<const float>> planes,
                                         emulator::Node& node, std::pmr::memory_resource* memory);

/// The terrain received from the previous process, on this process's node.
class NodeTerrain {
public:
  /// Receives it from `channel`, in the form the plan keeps.
  NodeTerrain(ProcessContext& c, BlockChannel& channel);
  NodeTerrain(const NodeTerrain&) = delete;
  NodeTerrain& operator=(const NodeTerrain&) = delete;

  const nav::TerrainRows& rows() const;
  /// Hands it on in the same form.
  void send(BlockChannel& channel) const;

private:
  nav::TerrainPoints maps_;
  FloatImage seeable_;
  std::uint64_t known_pixels_ = 0;
  std::optional<nav::ResidentTerrain> resident_;
  std::optional<nav::RecomputedTerrain> recomputed_;
  std::pmr::vector<std::uint32_t> sums_; ///< range's row sums, when the terrain is checked
  std::optional<CheckedTerrain> checked_;

  std::vector<imaging::ImageView<const float>> planes() const;
};

/// Range's side: makes the terrain of the seeable disparity (the maps, or only their count of
/// known points) and hands it on; the maps, kept or not, go to the host's products.
void make_and_send_terrain(ProcessContext& c, const FloatImage& seeable, BlockChannel& channel);

} // namespace marsokhod::nav_program::detail
