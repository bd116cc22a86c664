// What `marsokhod world` prints: the scene for people, the outputs and figures for scripts.

#include "navigation/world_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace marsokhod::apps {

void print_world_summary(const world::SceneDescription& scene, std::uint64_t seed,
                         const std::filesystem::path& out, const std::string& timings) {
  const auto& p = scene.placement;
  fmt::print("marsokhod world: seed {}, {}x{} pair, light {}, rover at ({:.2f}, {:.2f}) m heading "
             "{:.1f} deg, pitch {:.2f} deg, roll {:.2f} deg\n",
             seed, scene.rig.width_px, scene.rig.height_px, scene.lighting.name, p.pose.x, p.pose.y,
             p.pose.heading_deg, p.attitude.pitch_deg, p.attitude.roll_deg);
  fmt::print("ground truth: {:.1f} % of pixels valid in both views, {:.1f} % of visible pixels "
             "on obstacles\n",
             100.0 * scene.stats.valid_fraction(), 100.0 * scene.stats.obstacle_fraction());
  fmt::print("wrote {} files to {}:", scene.outputs.size(), out.string());
  for (const auto& [key, name] : scene.outputs)
    fmt::print(" {}", name);
  fmt::print("\ntimings: {}\n", timings);
}

void print_world_json(const world::SceneDescription& scene, std::uint64_t seed,
                      const std::filesystem::path& out) {
  nlohmann::json outputs = nlohmann::json::object();
  for (const auto& [key, name] : scene.outputs)
    outputs[key] = (out / name).string();
  const nlohmann::json summary = {{"outputs", outputs},
                                  {"seed", seed},
                                  {"size", scene.rig.width_px},
                                  {"light", scene.lighting.name},
                                  {"attitude",
                                   {{"pitch_deg", scene.placement.attitude.pitch_deg},
                                    {"roll_deg", scene.placement.attitude.roll_deg}}},
                                  {"ground_z_m", scene.placement.ground_z},
                                  {"valid_fraction", scene.stats.valid_fraction()},
                                  {"obstacle_fraction", scene.stats.obstacle_fraction()}};
  fmt::print("{}\n", summary.dump(2));
}

} // namespace marsokhod::apps
