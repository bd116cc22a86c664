// The buffers each process of the navigation program holds at its peak, for the memory plan.
#pragma once

// What an occam programmer sizes as static arrays (private to the layer): the images and maps a
// process receives, keeps and hands on, for one image size.

#include "marsokhod/nav_program/placement/memory_plan.hpp"

#include <cstddef>
#include <vector>

namespace marsokhod::nav_program::detail {

/// The image size and pyramid depth the buffers are planned for.
struct BufferGeometry {
  int width = 0;
  int height = 0;
  int levels = 0;

  std::size_t pixels() const;
  /// The halved layers above the original: floor(w / 2^l) x floor(h / 2^l) each.
  std::size_t pyramid_pixels() const;
};

#define MARSOKHOD_PROCESS(name, priority, code, workspace, group)                                  \
  std::vector<PlannedBuffer> name##_buffers(const BufferGeometry& g, bool terrain_kept);
#include "processes/process_list.def"

} // namespace marsokhod::nav_program::detail
