// SceneDescription and writing a rendered scene's files (images, ground truth, scene.json).
#pragma once

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/world/render/ground_truth.hpp"
#include "marsokhod/world/render/renderer.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>

namespace marsokhod::world {

/// Everything that fixed a rendered synthetic scene; written next to its images as scene.json
/// (format in docs/formats.md) so that a pair can be traced back to its settings and rebuilt.
struct SceneDescription {
  TerrainSettings terrain;
  LocomotionLimits limits;
  Lighting lighting;
  imaging::RigParameters rig;
  RoverPlacement placement;
  RenderOptions render;
  GroundTruthStats stats;
  /// Output name ("left", "gt_disparity", ...) -> file name inside the scene folder.
  std::map<std::string, std::string> outputs;
};

/// The scene.json document (keys in a fixed order, no host-dependent values).
nlohmann::json scene_to_json(const SceneDescription& scene);

/// Creates the scene folder and its parents if missing; throws std::runtime_error naming the
/// folder when it cannot be created (a file in the way, no permission).
void create_scene_folder(const std::filesystem::path& folder);

/// Writes a rendered frame into a folder (created if missing): left.pgm, right.pgm,
/// gt_disparity.pfm, gt_range.pfm, gt_elevation.pfm, gt_obstacles.pgm, gt_valid.pgm, PNG
/// previews for people and scene.json. Fills scene.outputs and scene.stats. Throws
/// std::runtime_error naming the path that could not be written.
void write_scene(const std::filesystem::path& folder, const RenderedFrame& frame,
                 SceneDescription& scene);

} // namespace marsokhod::world
