// The scene.json writer: every setting that fixed a rendered scene, as one JSON document.
#include "scene/scene_keys.hpp"

#include "marsokhod/world/scene/scene.hpp"

namespace marsokhod::world {
namespace {

using nlohmann::json;
namespace keys = scene_keys;

json terrain_json(const TerrainSettings& t, const LocomotionLimits& limits) {
  return {{"seed", t.seed},
          {"size_m", t.size_m},
          {"width_m", north_south_m(t)},
          {"cell_m", t.cell_m},
          {"rock_cover", t.rock_cover},
          {"crater_density_per_m2", t.crater_density},
          {"undulation_m", t.undulation_m},
          {"regional_slope_deg", t.regional_slope_deg},
          {"clear_radius_m", t.clear_radius_m},
          {"clear_centre_m", {t.clear_centre.x(), t.clear_centre.y()}},
          {"obstacle_limits",
           {{"max_step_m", limits.max_step_m},
            {"max_slope_deg", limits.max_slope_deg},
            {"step_baseline_m", limits.step_baseline_m},
            {"slope_baseline_m", limits.slope_baseline_m}}}};
}

json lighting_json(const Lighting& l) {
  return {{"preset", l.name},
          {"sun_elevation_deg", l.sun_elevation_deg},
          {"sun_azimuth_deg", l.sun_azimuth_deg},
          {"sun", l.sun},
          {"ambient", l.ambient},
          {"albedo_scale", l.albedo_scale},
          {"albedo_contrast", l.albedo_contrast},
          {"exposure", l.exposure},
          {"sky_grey", l.sky_grey}};
}

json rig_json(const imaging::RigParameters& r) {
  const imaging::StereoRig rig(r);
  return {{"mast_height_m", r.mast_height_m},
          {"mast_forward_m", r.mast_forward_m},
          {"pitch_down_deg", r.pitch_down_deg},
          {"focal_mm", r.focal_mm},
          {"sensor_mm", r.sensor_mm},
          {"focal_px", rig.focal_px()},
          {"baseline_m", r.baseline_m},
          {"width_px", r.width_px},
          {"height_px", r.height_px},
          {"right_misalignment_arcsec",
           {{"pan", r.right_misalignment.pan_arcsec},
            {"tilt", r.right_misalignment.tilt_arcsec},
            {"roll", r.right_misalignment.roll_arcsec}}}};
}

json placement_json(const RoverPlacement& p) {
  const Eigen::Matrix3d rotation = p.level_to_world.linear();
  const Eigen::Vector3d translation = p.level_to_world.translation();
  json rows = json::array();
  for (int r = 0; r < 3; ++r)
    rows.push_back({rotation(r, 0), rotation(r, 1), rotation(r, 2)});
  return {
      {keys::kPose, {{"x_m", p.pose.x}, {"y_m", p.pose.y}, {"heading_deg", p.pose.heading_deg}}},
      {keys::kGroundZ, p.ground_z},
      {keys::kAttitude, {{keys::kPitch, p.attitude.pitch_deg}, {keys::kRoll, p.attitude.roll_deg}}},
      {keys::kLevelToWorld,
       {{"translation_m", {translation.x(), translation.y(), translation.z()}},
        {"rotation", rows}}}};
}

json render_json(const RenderOptions& r) {
  return {{"noise_sigma_grey", r.noise_sigma},
          {"noise_seed", r.noise_seed},
          {"supersampling", r.supersampling},
          {"filter_texture", r.filter_texture},
          {"occlusion_tolerance_m", r.occlusion_tolerance_m},
          {"method", "one ray per pixel centre through the bilinear height field, exact "
                     "first intersection, maximum-mipmap traversal"}};
}

json stats_json(const GroundTruthStats& s) {
  return {{"pixels", s.pixels},
          {"visible", s.visible},
          {"occluded", s.occluded},
          {"valid", s.valid},
          {"obstacles", s.obstacles},
          {"valid_fraction", s.valid_fraction()},
          {"obstacle_fraction", s.obstacle_fraction()}};
}

} // namespace

nlohmann::json scene_to_json(const SceneDescription& scene) {
  return {{keys::kFormat, keys::kFormatName},
          {keys::kVersion, 1},
          {keys::kTerrain, terrain_json(scene.terrain, scene.limits)},
          {keys::kLighting, lighting_json(scene.lighting)},
          {keys::kRig, rig_json(scene.rig)},
          {keys::kPlacement, placement_json(scene.placement)},
          {keys::kRender, render_json(scene.render)},
          {keys::kGroundTruth, stats_json(scene.stats)},
          {keys::kOutputs, scene.outputs}};
}

} // namespace marsokhod::world
