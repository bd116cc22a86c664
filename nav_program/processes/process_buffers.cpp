// The buffers each process holds at its peak: the images and maps it receives, keeps and hands
// on.

#include "processes/planned_buffers.hpp"

#include "marsokhod/nav/stereo/layered_matching.hpp"

#include <fmt/format.h>

#include <string_view>

namespace marsokhod::nav_program::detail {
namespace {

PlannedBuffer image(std::string_view what, const BufferGeometry& g, int bytes_per_pixel) {
  return {buffer_name(what, g.height, g.width, bytes_per_pixel),
          g.pixels() * static_cast<std::size_t>(bytes_per_pixel)};
}

// The terrain no process keeps: one row of level points at a time, worked out again from the
// disparity.
PlannedBuffer terrain_row(const BufferGeometry& g) {
  return {buffer_name("terrain row (forward, left, elevation, range)", 1, g.width, 16),
          static_cast<std::size_t>(g.width) * 16};
}

// A buffer that arrived from the previous process, one still held when handing over to the
// next, or both.
PlannedBuffer in(PlannedBuffer b) {
  b.received = true;
  return b;
}
PlannedBuffer out(PlannedBuffer b) {
  b.handed = true;
  return b;
}
PlannedBuffer through(PlannedBuffer b) {
  return in(out(std::move(b)));
}

PlannedBuffer terrain_maps(const BufferGeometry& g) {
  return image("terrain points (forward, left, elevation, range)", g, 16);
}

PlannedBuffer kept_disparity(const BufferGeometry& g) {
  return image("seeable disparity (the terrain, kept)", g, 4);
}

} // namespace

std::size_t BufferGeometry::pixels() const {
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

std::size_t BufferGeometry::pyramid_pixels() const {
  std::size_t total = 0;
  for (int level = 1; level < levels; ++level)
    total += static_cast<std::size_t>(width >> level) * static_cast<std::size_t>(height >> level);
  return total;
}

std::vector<PlannedBuffer> acquire_buffers(const BufferGeometry& g, bool) {
  return {out(image("camera image", g, 1))};
}

// Features and matching hold everything until their last hand-over.
std::vector<PlannedBuffer> features_buffers(const BufferGeometry& g, bool) {
  return {
      through(image("left image", g, 1)), through(image("right image", g, 1)),
      out({fmt::format("pyramid layers 1..{}, both eyes", g.levels - 1), 2 * g.pyramid_pixels()}),
      out(image("census features, left", g, 1)), out(image("census features, right", g, 1))};
}

std::vector<PlannedBuffer> matching_buffers(const BufferGeometry& g, bool) {
  return {through(image("left layer", g, 1)), through(image("census features, left", g, 1)),
          through(image("census features, right", g, 1)),
          out({"coarser layer's disparity and validity", g.pixels() / 4 * 5}),
          out({buffer_name("a band of disparity and validity", nav::kMatchedBandRows, g.width, 5),
               static_cast<std::size_t>(nav::kMatchedBandRows * g.width) * 5})};
}

// Refine lets go of the image, the filled disparity and the mask before its hand-over.
std::vector<PlannedBuffer> refine_buffers(const BufferGeometry& g, bool) {
  return {in(image("left image", g, 1)), in(image("disparity, filled and smoothed", g, 4)),
          through(image("validity", g, 1)), image("texture mask", g, 1),
          out(image("seeable disparity", g, 4))};
}

// The stages reading the terrain hold it whole (four REAL32 maps) or as the disparity plus one
// row worked out again; range makes it, zones passes it on, path reads it. Range holds what it
// received until it has handed the terrain on.
std::vector<PlannedBuffer> range_buffers(const BufferGeometry& g, bool terrain_kept) {
  return {through(image("seeable disparity", g, 4)), through(image("validity", g, 1)),
          terrain_kept ? out(terrain_maps(g)) : terrain_row(g)};
}

// The validity is let go of before the hand-over.
std::vector<PlannedBuffer> zones_buffers(const BufferGeometry& g, bool terrain_kept) {
  std::vector<PlannedBuffer> buffers;
  if (terrain_kept)
    buffers.push_back(through(terrain_maps(g)));
  else
    buffers.insert(buffers.end(), {through(kept_disparity(g)), terrain_row(g)});
  buffers.push_back(in(image("validity", g, 1)));
  buffers.push_back(out(image("zone map", g, 1)));
  return buffers;
}

std::vector<PlannedBuffer> path_buffers(const BufferGeometry& g, bool terrain_kept) {
  std::vector<PlannedBuffer> buffers;
  if (terrain_kept)
    buffers.push_back(in(terrain_maps(g)));
  else
    buffers.insert(buffers.end(), {in(kept_disparity(g)), terrain_row(g)});
  buffers.push_back(in(image("zone map", g, 1)));
  buffers.push_back(image("row sweep costs", g, 4));
  buffers.push_back(image("row sweep steps", g, 1));
  return buffers;
}

std::vector<PlannedBuffer> drive_buffers(const BufferGeometry& g, bool) {
  return {
      in({buffer_name("ground path", g.height, 1, 16), static_cast<std::size_t>(g.height) * 16})};
}

// The motion scheme and telemetry hold only a few words and the lists they pass on.
std::vector<PlannedBuffer> motion_buffers(const BufferGeometry&, bool) {
  return {};
}

std::vector<PlannedBuffer> telemetry_buffers(const BufferGeometry&, bool) {
  return {};
}

} // namespace marsokhod::nav_program::detail
