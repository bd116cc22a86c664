// What `marsokhod world` prints of the scene it rendered.
#pragma once

#include "marsokhod/world/scene/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <string>

namespace marsokhod::apps {

/// The scene, its ground truth's shares, the files written and the step timings, for people.
void print_world_summary(const world::SceneDescription& scene, std::uint64_t seed,
                         const std::filesystem::path& out, const std::string& timings);

/// The outputs and the scene's figures as JSON on stdout.
void print_world_json(const world::SceneDescription& scene, std::uint64_t seed,
                      const std::filesystem::path& out);

} // namespace marsokhod::apps
