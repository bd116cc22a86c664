// The files `marsokhod nav` writes: disparity, range, elevation, zones, path overlay, path.json.

#include "navigation/nav_outputs.hpp"

#include "cli/command.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/pictures/colormap.hpp"
#include "marsokhod/io/files/file_writer.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;
using Rgb = std::array<std::uint8_t, 3>;

constexpr Rgb kPathRed{230, 30, 30};
constexpr Rgb kFractureYellow{255, 220, 0};
constexpr Rgb kStartGreen{40, 220, 60};
constexpr Rgb kTargetBlue{40, 120, 255};

void paint(imaging::Image<std::uint8_t>& picture, int x, int y, int radius, const Rgb& colour) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      if (picture.contains(x + dx, y + dy))
        for (int c = 0; c < 3; ++c)
          picture(x + dx, y + dy, c) = colour[static_cast<std::size_t>(c)];
}

nlohmann::ordered_json ground_point(const nav::GroundPoint& p) {
  return nlohmann::ordered_json::array({p.x, p.y});
}

template <class T>
void write_or_fail(const fs::path& path, const imaging::Image<T>& image) {
  try {
    imaging::write_image(path, image.view());
  } catch (const std::exception& error) {
    throw CommandError(error.what());
  }
}

imaging::ColormapOptions colour_options(const char* unit, const char* title) {
  imaging::ColormapOptions options;
  options.unit = unit;
  options.title = title;
  return options;
}

} // namespace

imaging::Image<std::uint8_t> zone_picture(const nav::ZoneMap& zones) {
  imaging::Image<std::uint8_t> picture(zones.width(), zones.height());
  for (int y = 0; y < zones.height(); ++y)
    for (int x = 0; x < zones.width(); ++x) {
      const nav::Zone zone = zones.at(x, y);
      picture(x, y) = zone == nav::Zone::traversable ? kZoneBlack
                      : zone == nav::Zone::margin    ? kZoneMarginGrey
                                                     : kZoneWhite;
    }
  return picture;
}

imaging::Image<std::uint8_t> path_overlay(const imaging::Image<std::uint8_t>& left,
                                          const nav::NavigationResult& result) {
  imaging::Image<std::uint8_t> picture(left.width(), left.height(), 3);
  for (int y = 0; y < left.height(); ++y)
    for (int x = 0; x < left.width(); ++x)
      for (int c = 0; c < 3; ++c)
        picture(x, y, c) = left(x, y);
  if (!result.found())
    return picture;
  const auto& pixels = result.plan.pixels;
  for (const nav::PixelPoint& p : pixels)
    paint(picture, p.x, p.y, 1, kPathRed);
  // Fracture points are path points the simplification kept; find their pixels.
  const auto& ground = result.drive.ground_path;
  for (std::size_t v = 1; v + 1 < result.drive.polyline.size(); ++v)
    for (std::size_t i = 0; i < ground.size() && i < pixels.size(); ++i)
      if (ground[i] == result.drive.polyline[v])
        paint(picture, pixels[i].x, pixels[i].y, 2, kFractureYellow);
  paint(picture, result.plan.start.x, result.plan.start.y, 2, kStartGreen);
  paint(picture, result.plan.target.x, result.plan.target.y, 2, kTargetBlue);
  return picture;
}

nlohmann::ordered_json path_json(const nav::NavigationResult& result) {
  nlohmann::ordered_json json;
  json["found"] = result.found();
  if (!result.found()) {
    json["reason"] = result.reason();
    return json;
  }
  json["pixel_path"] = nlohmann::ordered_json::array();
  for (const nav::PixelPoint& p : result.plan.pixels)
    json["pixel_path"].push_back({p.x, p.y});
  json["ground_polyline"] = nlohmann::ordered_json::array();
  for (const nav::GroundPoint& p : result.drive.polyline)
    json["ground_polyline"].push_back(ground_point(p));
  json["start_m"] = result.drive.start_m;
  json["fracture_m"] = result.drive.fracture_m;
  json["target_m"] = result.drive.target_m;
  json["commands"] = nlohmann::ordered_json::array();
  for (const nav::DriveCommand& c : result.drive.commands)
    json["commands"].push_back({{"turn_deg", c.turn_deg}, {"distance_m", c.distance_m}});
  json["cost"] = result.plan.cost;
  return json;
}

std::map<std::string, fs::path> write_navigation_outputs(const fs::path& folder,
                                                         const imaging::Image<std::uint8_t>& left,
                                                         const imaging::Image<float>& disparity,
                                                         const nav::NavigationResult& result) {
  std::map<std::string, fs::path> written;
  auto put = [&](const std::string& key, const std::string& name, const auto& image) {
    write_or_fail(folder / name, image);
    written[key] = folder / name;
  };
  put("disparity", "disparity.pfm", disparity);
  put("disparity_png", "disparity.png",
      imaging::false_colour(disparity, colour_options("px", "disparity")));
  put("range", "range.pfm", result.terrain.range);
  put("elevation", "elevation.pfm", result.terrain.elevation);
  put("elevation_png", "elevation.png",
      imaging::false_colour(result.terrain.elevation, colour_options("m", "elevation")));
  put("zones", "zones.png", zone_picture(result.zones));
  put("path_overlay", "path_overlay.png", path_overlay(left, result));
  const fs::path json_path = folder / "path.json";
  io::write_file_atomically(json_path, path_json(result).dump(2) + '\n');
  written["path"] = json_path;
  return written;
}

} // namespace marsokhod::apps
