// The terrain on the nodes after range: the four maps, or the disparity they come from.

#include "navigation/node_terrain.hpp"

namespace marsokhod::occam_port::detail {
namespace {

void send_maps(BlockChannel& channel, const nav::TerrainPoints& terrain) {
  for (const FloatImage* plane :
       {&terrain.forward, &terrain.left, &terrain.elevation, &terrain.range})
    send_image<float>(channel, plane->view());
  send_value(channel, terrain.known_pixels);
}

void send_disparity(BlockChannel& channel, const FloatImage& seeable, std::uint64_t known) {
  send_image<float>(channel, seeable.view());
  send_value(channel, known);
}

} // namespace

// Built on the node's memory: moving a buffer into an image of another memory would copy it
// there.
NodeTerrain::NodeTerrain(ProcessContext& c, BlockChannel& channel)
    : maps_{FloatImage(c.memory()), FloatImage(c.memory()), FloatImage(c.memory()),
            FloatImage(c.memory()), 0},
      seeable_(c.memory()) {
  const CycleState& s = c.cycle();
  if (s.plan->terrain_kept) {
    maps_.forward = receive_floats(c, channel, "terrain forward");
    maps_.left = receive_floats(c, channel, "terrain left");
    maps_.elevation = receive_floats(c, channel, "terrain elevation");
    maps_.range = receive_floats(c, channel, "terrain range");
    maps_.known_pixels = receive_value<std::uint64_t>(channel);
    resident_.emplace(maps_);
    return;
  }
  seeable_ = receive_floats(c, channel, "seeable disparity (the terrain, kept)");
  known_pixels_ = receive_value<std::uint64_t>(channel);
  c.doing(image_what("terrain row (forward, left, elevation, range)", s.width, 1, 16));
  recomputed_.emplace(seeable_, *s.rig, s.options.attitude, known_pixels_, c.recompute_meter(),
                      c.memory());
}

const nav::TerrainRows& NodeTerrain::rows() const {
  if (resident_)
    return *resident_;
  return *recomputed_;
}

void NodeTerrain::send(BlockChannel& channel) const {
  if (resident_) {
    send_maps(channel, maps_);
    return;
  }
  send_disparity(channel, seeable_, known_pixels_);
}

void make_and_send_terrain(ProcessContext& c, const FloatImage& seeable, BlockChannel& channel) {
  CycleState& s = c.cycle();
  if (s.plan->terrain_kept) {
    c.doing(image_what("terrain points (forward, left, elevation, range)", s.width, s.height, 16));
    const nav::TerrainPoints terrain =
        nav::reconstruct_terrain(seeable, *s.rig, s.options.attitude, c.meter(), c.memory());
    s.products.terrain = terrain;
    send_maps(channel, terrain);
    return;
  }
  c.doing(image_what("terrain row (forward, left, elevation, range)", s.width, 1, 16));
  const std::uint64_t known =
      nav::count_terrain_points(seeable, *s.rig, s.options.attitude, c.meter(), c.memory());
  // The maps no node keeps, worked out on the host for the files (as read out of a node).
  s.products.terrain = nav::reconstruct_terrain(seeable, *s.rig, s.options.attitude);
  send_disparity(channel, seeable, known);
}

} // namespace marsokhod::occam_port::detail
