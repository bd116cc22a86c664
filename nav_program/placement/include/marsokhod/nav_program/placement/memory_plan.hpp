// MemoryPlan: how the navigation program's code, workspaces and buffers fill each node.
#pragma once

#include "marsokhod/emulator/platform/platform.hpp"
#include "marsokhod/nav_program/placement/placement.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace marsokhod::nav_program {

/// A buffer a process holds, as an occam programmer sizes a static array: what it is and its
/// bytes.
struct PlannedBuffer {
  std::string what; ///< "disparity, 128 rows x 128 px x 4 B"
  std::size_t bytes = 0;
  bool received = false; ///< it arrived from the previous process
  bool handed = false;   ///< still held while handing over to the next process
};

/// One process's share of its node: code, workspace and the buffers it holds at its peak.
struct ProcessPlan {
  std::string process;
  std::size_t code_bytes = 0;
  std::size_t workspace_bytes = 0;
  std::vector<PlannedBuffer> buffers;
  std::size_t buffer_bytes() const;
  std::size_t received_bytes() const; ///< of the buffers received
  std::size_t handed_bytes() const;   ///< of the buffers held at the hand-over
};

/// One node's memory: what the program needs there and what is free for buffers.
struct NodePlan {
  std::string node;
  std::size_t memory_bytes = 0;   ///< on-chip plus external
  std::size_t reserved_bytes = 0; ///< the processor's own words at the bottom of on-chip RAM
  std::size_t code_bytes = 0;
  std::size_t workspace_bytes = 0;
  std::vector<ProcessPlan> processes;
  /// Memory left for buffers after code and workspaces.
  std::size_t free_for_buffers() const;
  /// The node's peak of buffers: the largest process's, or the largest hand-over between two
  /// consecutive processes (what the one still holds and what the other has received).
  std::size_t buffer_bytes() const;
  bool fits() const { return buffer_bytes() <= free_for_buffers(); }
};

/// The whole program's memory plan for one image size: band heights, and per node the code,
/// workspaces and buffers. The stages work on whole images (one band of every row); a node
/// whose buffers do not fit is reported, and the run shows where it fails.
struct MemoryPlan {
  int image_width = 0;
  int image_height = 0;
  int band_rows = 0; ///< rows per band of the original layer's matching and its hand-over
  /// Whether the stages after range keep the terrain's four maps; when they would not fit, only
  /// the disparity is kept and its rows are worked out again where they are read.
  bool terrain_kept = true;
  /// The bytes the zones' ground grid may take: half the zones' node's free memory beside the
  /// zones' own buffers, the other half left to the allocator's fragments and the kernels'
  /// smaller scratch. The zones cut the grid into strips along the forward axis that fit it
  /// (each binned again with its halo), one strip where it holds the whole grid; 0 for the
  /// whole grid at once, as natively.
  std::size_t zone_grid_bytes = 0;
  std::vector<NodePlan> nodes;
  bool fits() const;
};

/// The plan for `width` x `height` images matched over `pyramid_levels` layers, of the placement
/// on the platform (with every node's external memory replaced by `external_bytes` when given).
/// The buffers planned are those the stages hand each other and keep; the kernels' own scratch
/// (cost rows, the ground grid) is not planned but measured by the run. The terrain is kept as
/// four maps when the plan fits with them, else as the disparity (MemoryPlan::terrain_kept).
MemoryPlan plan_memory(const emulator::PlatformSpec& platform, const Placement& placement,
                       int width, int height, int pyramid_levels,
                       std::optional<std::size_t> external_bytes);

/// "disparity, 128 rows x 128 px x 4 B".
std::string buffer_name(std::string_view what, int rows, int columns, int bytes_per_element);

/// The plan as a table a person reads.
std::string describe(const MemoryPlan& plan);

} // namespace marsokhod::nav_program
