// The terrain on the nodes after range: the four maps, or the disparity they come from.

#include "processes/node_terrain.hpp"

#include "channels/word_sum.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace marsokhod::nav_program::detail {
namespace {

bool terrain_checked(const CycleState& s) {
  return s.supervisor != nullptr && s.supervisor->check_terrain();
}

std::span<const std::byte> row_bytes(imaging::ImageView<const float> plane, int y) {
  return std::as_bytes(std::span(plane.row(y), static_cast<std::size_t>(plane.width())));
}

/// The four maps, in the order they go on a channel and their rows are summed.
std::vector<imaging::ImageView<const float>> map_planes(const nav::TerrainPoints& terrain) {
  return {terrain.forward, terrain.left, terrain.elevation, terrain.range};
}

/// What the row sums of `planes` planes of `height` rows hold, for the memory's block names.
std::string sums_what(int height, std::size_t planes) {
  if (planes == 1)
    return fmt::format("terrain row sums, {} rows x 4 B", height);
  return fmt::format("terrain row sums, {} rows x {} planes x 4 B", height, planes);
}

void send_maps(BlockChannel& channel, const nav::TerrainPoints& terrain) {
  for (const imaging::ImageView<const float>& plane : map_planes(terrain))
    send_image<float>(channel, plane);
  send_value(channel, terrain.known_pixels);
}

void send_disparity(BlockChannel& channel, const FloatImage& seeable, std::uint64_t known) {
  send_image<float>(channel, seeable.view());
  send_value(channel, known);
}

} // namespace

CheckedTerrain::CheckedTerrain(const nav::TerrainRows& rows,
                               std::vector<imaging::ImageView<const float>> planes,
                               std::span<const std::uint32_t> sums, emulator::Node& node)
    : nav::TerrainRows(rows.width(), rows.height(), rows.known_pixels()), rows_(&rows),
      planes_(std::move(planes)), sums_(sums), node_(&node) {
  if (sums_.size() != planes_.size() * static_cast<std::size_t>(height()))
    throw std::logic_error(fmt::format("the terrain came with {} row sums for {} rows of {} planes",
                                       sums_.size(), height(), planes_.size()));
}

// Charged first: the sums are compared and the row rebuilt with no time passing between. A row
// asked for again is the one the rows below still hold, rebuilt from the bytes just checked.
nav::TerrainRows::Row CheckedTerrain::row(int y) const {
  if (y == checked_)
    return rows_->row(y);
  const std::size_t bytes = static_cast<std::size_t>(width()) * sizeof(float);
  for (std::size_t p = 0; p < planes_.size(); ++p)
    charge_word_sum(*node_, bytes);
  for (std::size_t p = 0; p < planes_.size(); ++p)
    if (word_sum(row_bytes(planes_[p], y)) !=
        sums_[p * static_cast<std::size_t>(height()) + static_cast<std::size_t>(y)])
      throw std::range_error(
          fmt::format("terrain row {}: its sum no longer checks (the kept terrain was struck)", y));
  checked_ = y;
  return rows_->row(y);
}

std::pmr::vector<std::uint32_t> row_sums(std::span<const imaging::ImageView<const float>> planes,
                                         emulator::Node& node, std::pmr::memory_resource* memory) {
  std::pmr::vector<std::uint32_t> sums(memory);
  for (const imaging::ImageView<const float>& plane : planes)
    for (int y = 0; y < plane.height(); ++y) {
      const std::span<const std::byte> bytes = row_bytes(plane, y);
      charge_word_sum(node, bytes.size());
      sums.push_back(word_sum(bytes));
    }
  return sums;
}

// Built on the node's memory: moving a buffer into an image of another memory would copy it
// there.
NodeTerrain::NodeTerrain(ProcessContext& c, BlockChannel& channel)
    : maps_{FloatImage(c.memory()), FloatImage(c.memory()), FloatImage(c.memory()),
            FloatImage(c.memory()), 0},
      seeable_(c.memory()), sums_(c.memory()) {
  const CycleState& s = c.cycle();
  if (s.plan->terrain_kept) {
    maps_.forward = receive_floats(c, channel, "terrain forward");
    maps_.left = receive_floats(c, channel, "terrain left");
    maps_.elevation = receive_floats(c, channel, "terrain elevation");
    maps_.range = receive_floats(c, channel, "terrain range");
    maps_.known_pixels = receive_value<std::uint64_t>(channel);
    resident_.emplace(maps_);
  } else {
    seeable_ = receive_floats(c, channel, "seeable disparity (the terrain, kept)");
    known_pixels_ = receive_value<std::uint64_t>(channel);
  }
  if (terrain_checked(s)) {
    c.doing(sums_what(s.height, planes().size()));
    sums_ = receive_list<std::uint32_t>(channel, c.memory());
  }
  if (!resident_) {
    c.doing(image_what("terrain row (forward, left, elevation, range)", s.width, 1, 16));
    recomputed_.emplace(seeable_, *s.rig, s.options.attitude, known_pixels_, c.recompute_meter(),
                        c.memory());
  }
  if (terrain_checked(s))
    checked_.emplace(resident_ ? static_cast<const nav::TerrainRows&>(*resident_) : *recomputed_,
                     planes(), sums_, c.node());
}

std::vector<imaging::ImageView<const float>> NodeTerrain::planes() const {
  if (resident_)
    return map_planes(maps_);
  return {seeable_};
}

const nav::TerrainRows& NodeTerrain::rows() const {
  if (checked_)
    return *checked_;
  if (resident_)
    return *resident_;
  return *recomputed_;
}

// The sums go on as they came: made again here, they would vouch for a row struck here.
void NodeTerrain::send(BlockChannel& channel) const {
  if (resident_)
    send_maps(channel, maps_);
  else
    send_disparity(channel, seeable_, known_pixels_);
  if (checked_)
    send_list<std::uint32_t>(channel, sums_);
}

namespace {

/// With the check, range's sums of the planes it is about to send, made before they go, of what
/// range made; nothing without it.
std::pmr::vector<std::uint32_t>
sums_to_send(ProcessContext& c, const std::vector<imaging::ImageView<const float>>& planes) {
  std::pmr::vector<std::uint32_t> sums(c.memory());
  if (!terrain_checked(c.cycle()))
    return sums;
  c.doing(sums_what(c.cycle().height, planes.size()));
  return row_sums(planes, c.node(), c.memory());
}

void send_sums(ProcessContext& c, BlockChannel& channel,
               const std::pmr::vector<std::uint32_t>& sums) {
  if (terrain_checked(c.cycle()))
    send_list<std::uint32_t>(channel, sums);
}

} // namespace

void make_and_send_terrain(ProcessContext& c, const FloatImage& seeable, BlockChannel& channel) {
  CycleState& s = c.cycle();
  if (s.plan->terrain_kept) {
    c.doing(image_what("terrain points (forward, left, elevation, range)", s.width, s.height, 16));
    const nav::TerrainPoints terrain =
        nav::reconstruct_terrain(seeable, *s.rig, s.options.attitude, c.meter(), c.memory());
    s.products.terrain = terrain;
    const std::pmr::vector<std::uint32_t> sums = sums_to_send(c, map_planes(terrain));
    send_maps(channel, terrain);
    send_sums(c, channel, sums);
    return;
  }
  c.doing(image_what("terrain row (forward, left, elevation, range)", s.width, 1, 16));
  const std::uint64_t known =
      nav::count_terrain_points(seeable, *s.rig, s.options.attitude, c.meter(), c.memory());
  // The maps no node keeps, worked out on the host for the files (as read out of a node).
  s.products.terrain = nav::reconstruct_terrain(seeable, *s.rig, s.options.attitude);
  const std::pmr::vector<std::uint32_t> sums = sums_to_send(c, {seeable});
  send_disparity(channel, seeable, known);
  send_sums(c, channel, sums);
}

} // namespace marsokhod::nav_program::detail
