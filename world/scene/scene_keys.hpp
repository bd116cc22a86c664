// The key names of scene.json (docs/formats.md), shared by its writer and its reader.
#pragma once

#include <string_view>

namespace marsokhod::world::scene_keys {

// The document.
inline constexpr std::string_view kFormat = "format";
inline constexpr std::string_view kFormatName = "marsokhod-scene";
inline constexpr std::string_view kVersion = "version";
inline constexpr std::string_view kTerrain = "terrain";
inline constexpr std::string_view kLighting = "lighting";
inline constexpr std::string_view kRig = "rig";
inline constexpr std::string_view kPlacement = "placement";
inline constexpr std::string_view kRender = "render";
inline constexpr std::string_view kGroundTruth = "ground_truth";
inline constexpr std::string_view kOutputs = "outputs";

// placement.
inline constexpr std::string_view kPose = "pose";
inline constexpr std::string_view kGroundZ = "ground_z_m";
inline constexpr std::string_view kAttitude = "attitude";
inline constexpr std::string_view kLevelToWorld = "level_to_world";

// placement.attitude.
inline constexpr std::string_view kPitch = "pitch_deg";
inline constexpr std::string_view kRoll = "roll_deg";

} // namespace marsokhod::world::scene_keys
