// render_site: a synthetic site rendered from its scene description, as `marsokhod world` does.
#pragma once

#include "marsokhod/world/render/renderer.hpp"
#include "marsokhod/world/scene/scene.hpp"

#include <cstdint>

namespace marsokhod::world {

/// The scene `marsokhod world --seed SEED --size SIZE` renders with every other option at its
/// default: the seed's terrain, the high sun, the rover at the centre, sensor noise drawn from
/// the seed, the paper's rig at SIZE x SIZE pixels. Its placement is filled by render_site.
SceneDescription default_scene(std::uint64_t seed, int size_px);

/// Generates the scene's terrain, lights it, places the rover on it (scene.placement is set
/// from scene.placement.pose) and renders the pair with its ground truth.
RenderedFrame render_site(SceneDescription& scene);

} // namespace marsokhod::world
