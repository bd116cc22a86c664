// NodeTerrain: the terrain as a node of the program keeps it, whole or as the disparity.
#pragma once

// The terrain as the processes after range hold it (private to the navigation room): the four
// maps when the memory plan keeps them, or only the seeable disparity, whose rows are worked out
// again each time they are read. Both sides of a channel know which: it is the plan's.

#include "navigation/process_bodies.hpp"

#include "marsokhod/nav/terrain/terrain_rows.hpp"

#include <cstdint>
#include <optional>

namespace marsokhod::occam_port::detail {

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
};

/// Range's side: makes the terrain of the seeable disparity (the maps, or only their count of
/// known points) and hands it on; the maps, kept or not, go to the host's products.
void make_and_send_terrain(ProcessContext& c, const FloatImage& seeable, BlockChannel& channel);

} // namespace marsokhod::occam_port::detail
