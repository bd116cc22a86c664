// `marsokhod rig`: the stereo rig's geometry (blind zone, ground disparity, stone parallax).

#include "cli/command.hpp"
#include "cli/option_checks.hpp"

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/imaging/rig/rig_geometry.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marsokhod::apps {
namespace {

// The paper's obstacle example (section 2): a 30 cm stone 14 m from the rover centre.
constexpr double kStoneDistanceM = 14.0;
constexpr double kStoneHeightM = 0.3;
constexpr int kRowStep = 16;

struct RigOptions {
  std::string rig_file;
  std::optional<int> size;
  bool json = false;
};

imaging::StereoRig make_rig(const RigOptions& options) {
  imaging::RigParameters parameters;
  if (!options.rig_file.empty())
    parameters = imaging::StereoRig::load(options.rig_file).parameters();
  if (options.size) {
    parameters.width_px = *options.size;
    parameters.height_px = *options.size;
  }
  return imaging::StereoRig(parameters);
}

// Every 16th row and the bottom row, where the blind zone ends.
std::vector<int> table_rows(const imaging::StereoRig& rig) {
  std::vector<int> rows;
  for (int v = 0; v < rig.height(); v += kRowStep)
    rows.push_back(v);
  if (rows.back() != rig.height() - 1)
    rows.push_back(rig.height() - 1);
  return rows;
}

// JSON has no infinity: ground never reached is null.
nlohmann::ordered_json finite_or_null(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json rig_json(const imaging::StereoRig& rig) {
  const imaging::RigParameters& p = rig.parameters();
  nlohmann::ordered_json json;
  json["rig"] = {{"mast_height_m", p.mast_height_m},
                 {"mast_forward_m", p.mast_forward_m},
                 {"pitch_down_deg", p.pitch_down_deg},
                 {"focal_mm", p.focal_mm},
                 {"sensor_mm", p.sensor_mm},
                 {"baseline_m", p.baseline_m},
                 {"width_px", p.width_px},
                 {"height_px", p.height_px}};
  json["focal_px"] = rig.focal_px();
  json["vertical_fov_deg"] = rig.vertical_fov_deg();
  json["ground_visible_from_m"] = finite_or_null(rig.ground_visible_from_m());
  json["horizon_row"] = finite_or_null(imaging::horizon_row(rig));
  json["rows"] = nlohmann::ordered_json::array();
  for (int v : table_rows(rig))
    json["rows"].push_back(
        {{"row", v},
         {"ground_distance_m", finite_or_null(imaging::ground_distance_at_row(rig, v))},
         {"ground_disparity_px", rig.ground_disparity(rig.cx(), v)}});
  const imaging::ObstacleParallax stone =
      imaging::obstacle_parallax(rig, kStoneDistanceM, kStoneHeightM);
  json["stone_14m"] = {{"distance_m", stone.distance_m},
                       {"height_m", stone.height_m},
                       {"top_row", stone.top_row},
                       {"bottom_row", stone.bottom_row},
                       {"top_disparity_px", stone.top_disparity_px},
                       {"bottom_disparity_px", stone.bottom_disparity_px},
                       {"top_minus_bottom_px", stone.top_minus_bottom_px},
                       {"ground_behind_distance_m", finite_or_null(stone.ground_behind_distance_m)},
                       {"ground_behind_disparity_px", stone.ground_behind_disparity_px},
                       {"top_minus_ground_px", stone.top_minus_ground_px}};
  return json;
}

std::string metres_or_dash(double value) {
  return std::isfinite(value) ? fmt::format("{:8.2f}", value) : fmt::format("{:>8}", "-");
}

void print_text(const imaging::StereoRig& rig) {
  const imaging::RigParameters& p = rig.parameters();
  fmt::print("stereo rig: {} x {} px, f = {} mm on a {} mm CCD, baseline {} m, mast {} m, "
             "pitched {} deg down\n",
             p.width_px, p.height_px, p.focal_mm, p.sensor_mm, p.baseline_m, p.mast_height_m,
             p.pitch_down_deg);
  fmt::print("  focal length            {:.3f} px\n", rig.focal_px());
  fmt::print("  vertical field of view  {:.2f} deg\n", rig.vertical_fov_deg());
  // A rig pitched up sees no ground at all (JSON: null); say so rather than print "inf".
  const double ground_from = rig.ground_visible_from_m();
  if (std::isfinite(ground_from))
    fmt::print("  ground visible from     {:.3f} m ahead of the rover centre\n", ground_from);
  else
    fmt::print("  ground visible from     nowhere: every row looks above the horizon\n");
  fmt::print("  horizon row             {:.2f}\n\n", imaging::horizon_row(rig));
  fmt::print("   row  ground (m)  disparity (px)\n");
  for (int v : table_rows(rig))
    fmt::print("  {:4d}  {}  {:14.3f}\n", v,
               metres_or_dash(imaging::ground_distance_at_row(rig, v)),
               rig.ground_disparity(rig.cx(), v));
  const imaging::ObstacleParallax stone =
      imaging::obstacle_parallax(rig, kStoneDistanceM, kStoneHeightM);
  fmt::print("\n{:.0f} cm stone {:.0f} m ahead (paper section 2: \"3 pixels\"):\n",
             stone.height_m * 100.0, stone.distance_m);
  // The figures hold for the geometry either way; a rig that cannot see the stone must say so.
  const auto in_image = [&](double row) { return row >= 0.0 && row <= rig.height() - 1.0; };
  if (!in_image(stone.top_row) || !in_image(stone.bottom_row))
    fmt::print("  outside the image: top in row {:.1f}, foot in row {:.1f} of 0..{}\n",
               stone.top_row, stone.bottom_row, rig.height() - 1);
  fmt::print("  top {:.3f} px, foot {:.3f} px: top - foot = {:.3f} px\n", stone.top_disparity_px,
             stone.bottom_disparity_px, stone.top_minus_bottom_px);
  fmt::print("  ground in the top's row {:.2f} m ahead, {:.3f} px: top - ground = {:.3f} px\n",
             stone.ground_behind_distance_m, stone.ground_behind_disparity_px,
             stone.top_minus_ground_px);
}

} // namespace

Command make_rig_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "rig", "Print the stereo rig's derived geometry: focal length in pixels, field of view, "
             "blind zone, ground disparity per row, the paper's 30 cm stone at 14 m.");
  auto options = std::make_shared<RigOptions>();
  app->add_option("--rig", options->rig_file, "rig TOML file (default: the paper's rig)");
  app->add_option("--size", options->size, "image side in pixels, overriding the rig's size")
      ->transform(integer_one_of({128, 256}));
  app->add_flag("--json", options->json, "print one JSON object instead of text");
  return {app, [options] {
            const imaging::StereoRig rig = make_rig(*options);
            if (options->json)
              fmt::print("{}\n", rig_json(rig).dump(2));
            else
              print_text(rig);
            return kSuccess;
          }};
}

} // namespace marsokhod::apps
