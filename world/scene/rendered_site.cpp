// A synthetic site from its description: terrain, light, rover placement, rendered pair.

#include "marsokhod/world/scene/rendered_site.hpp"

#include "marsokhod/world/lighting/lighting.hpp"
#include "marsokhod/world/lighting/lit_surface.hpp"
#include "marsokhod/world/scene/rover_placement.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

namespace marsokhod::world {

SceneDescription default_scene(std::uint64_t seed, int size_px) {
  SceneDescription scene;
  scene.rig.width_px = size_px;
  scene.rig.height_px = size_px;
  scene.lighting = lighting_preset(LightPreset::high_sun);
  scene.terrain.seed = seed;
  scene.render.noise_seed = seed;
  return scene;
}

RenderedFrame render_site(SceneDescription& scene) {
  const Terrain terrain = Terrain::generate(scene.terrain, scene.limits);
  const LitSurface surface(terrain, scene.lighting);
  const Renderer renderer(terrain);
  scene.placement = place_rover(terrain.height, scene.placement.pose);
  return renderer.render_with_ground_truth(imaging::StereoRig(scene.rig), scene.placement, surface,
                                           scene.render);
}

} // namespace marsokhod::world
