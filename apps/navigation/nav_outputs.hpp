// The files `marsokhod nav` writes, and the pictures of zones and of the path.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/cycle/navigation.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace marsokhod::apps {

/// Grey levels of zones.png: the paper's fig. 4b draws prohibited ground white and traversable
/// ground black; the rover's margin around the hazards is drawn light grey.
inline constexpr std::uint8_t kZoneWhite = 255;
inline constexpr std::uint8_t kZoneMarginGrey = 160;
inline constexpr std::uint8_t kZoneBlack = 0;

/// zones.png's pixels for a zone map.
imaging::Image<std::uint8_t> zone_picture(const nav::ZoneMap& zones);

/// The left image in colour with the path drawn over it (fig. 4c): the path red, the fracture
/// points yellow, the start green and the target blue.
imaging::Image<std::uint8_t> path_overlay(const imaging::Image<std::uint8_t>& left,
                                          const nav::NavigationResult& result);

/// The path.json document: found, reason (when not found), the pixel path, the ground
/// polyline, start_m, fracture_m, target_m and the drive commands (docs/formats.md).
nlohmann::ordered_json path_json(const nav::NavigationResult& result);

/// Writes every output of `marsokhod nav` into `folder` (which must exist) and returns output
/// name -> file path. Throws CommandError naming a file that cannot be written.
std::map<std::string, std::filesystem::path> write_navigation_outputs(
    const std::filesystem::path& folder, const imaging::Image<std::uint8_t>& left,
    const imaging::Image<float>& disparity, const nav::NavigationResult& result);

} // namespace marsokhod::apps
