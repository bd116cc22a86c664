// The model's figures for the paper's table: each one cycle per scene on the shipped platforms.

#include "marsokhod/eval/timing/timing_model.hpp"

#include "marsokhod/eval/timing/paper_figures.hpp"
#include "marsokhod/eval/timing/timing_error.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace marsokhod::eval {
namespace {

namespace emu = emulator;
namespace np = nav_program;

emu::PlatformSpec shipped_platform(const char* file) {
  return emu::load_platform(emu::find_platform_file(file));
}

ReproductionScene render_scene(std::uint64_t seed) {
  world::SceneDescription scene = world::default_scene(seed, kPaperImageSide);
  world::RenderedFrame frame = world::render_site(scene);
  return {seed, std::move(frame.images.left), std::move(frame.images.right),
          std::make_unique<imaging::StereoRig>(scene.rig), scene.placement.attitude};
}

np::CycleEmulation run_cycle(const ReproductionScene& scene, const emu::PlatformSpec& platform,
                             const np::Placement& placement, double occam_style,
                             std::optional<std::size_t> external_bytes = std::nullopt) {
  np::CycleInput input{scene.left, scene.right, scene.rig.get(), {}, {}};
  input.options.attitude = scene.attitude;
  return np::emulate_navigation_cycle(input,
                                      np::CycleSetup{&platform, &placement, external_bytes, nullptr,
                                                     occam_style, nullptr, std::nullopt});
}

// A figure the paper gives must come out of a cycle that ran to its end.
const np::CycleEmulation& ran(const np::CycleEmulation& run, const ReproductionScene& scene,
                              const emu::PlatformSpec& platform) {
  if (run.memory_fault)
    throw TimingError(fmt::format("world seed {} does not fit {}: {}", scene.seed, platform.name,
                                  np::describe(*run.memory_fault)));
  return run;
}

SceneSpread spread(const std::vector<double>& values) {
  SceneSpread s{0.0, values.front(), values.front()};
  for (const double v : values) {
    s.mean += v / static_cast<double>(values.size());
    s.least = std::min(s.least, v);
    s.greatest = std::max(s.greatest, v);
  }
  return s;
}

} // namespace

double stereo_end(const np::CycleEmulation& run) {
  emu::Tick end = 0;
  for (const np::StageFigures& stage : run.stages)
    if (stage.group == np::StageGroup::stereo)
      end = std::max(end, stage.end);
  return emu::to_seconds(end);
}

TimingModel::TimingModel(const std::vector<std::uint64_t>& seeds)
    : card_(shipped_platform("pc-card.toml")), onboard_(shipped_platform("onboard.toml")),
      card_placement_(np::load_program_placement(card_)),
      onboard_placement_(np::load_program_placement(onboard_)) {
  if (seeds.empty())
    throw TimingError("the timing model needs at least one world seed");
  for (const std::uint64_t seed : seeds)
    scenes_.push_back(render_scene(seed));
}

SceneSpread TimingModel::stereo(const emu::PlatformSpec& card, double occam_style) const {
  std::vector<double> seconds;
  for (const ReproductionScene& scene : scenes_)
    seconds.push_back(
        stereo_end(ran(run_cycle(scene, card, card_placement_, occam_style), scene, card)));
  return spread(seconds);
}

ModelFigures TimingModel::figures(const emu::PlatformSpec& card, const emu::PlatformSpec& onboard,
                                  double occam_style) const {
  std::vector<double> stereo;
  std::vector<double> card_cycle;
  std::vector<double> onboard_cycle;
  for (const ReproductionScene& scene : scenes_) {
    const np::CycleEmulation on_card = run_cycle(scene, card, card_placement_, occam_style);
    stereo.push_back(stereo_end(ran(on_card, scene, card)));
    card_cycle.push_back(emu::to_seconds(on_card.emulated));
    const np::CycleEmulation aboard = run_cycle(scene, onboard, onboard_placement_, occam_style);
    onboard_cycle.push_back(emu::to_seconds(ran(aboard, scene, onboard).emulated));
  }
  return {spread(stereo), spread(card_cycle), spread(onboard_cycle)};
}

std::vector<SweepPoint>
TimingModel::onboard_sweep(const std::vector<std::uint64_t>& external_kb, double occam_style,
                           const std::function<void(std::size_t)>& progress) const {
  std::vector<SweepPoint> points;
  for (std::size_t i = 0; i < external_kb.size(); ++i) {
    SweepPoint point{external_kb[i], 0.0, std::nullopt, true, 0, 0};
    for (const ReproductionScene& scene : scenes_) {
      const np::CycleEmulation run = run_cycle(scene, onboard_, onboard_placement_, occam_style,
                                               static_cast<std::size_t>(external_kb[i]) * 1024);
      if (&scene == &scenes_.front()) {
        point.terrain_kept = run.plan.terrain_kept;
        point.zone_grid_bytes = run.plan.zone_grid_bytes;
      }
      point.recomputed_units += run.recomputed_work.total();
      if (run.memory_fault) {
        point.memory_fault = run.memory_fault;
        break;
      }
      point.emulated_seconds += emu::to_seconds(run.emulated) / static_cast<double>(scenes_.size());
    }
    if (point.memory_fault)
      point.emulated_seconds = 0.0;
    points.push_back(std::move(point));
    if (progress)
      progress(i + 1);
  }
  return points;
}

double fit_occam_style(const TimingModel& model, double paper_seconds) {
  double s0 = 1.0;
  double t0 = model.stereo(model.card(), s0).mean;
  double s1 = s0 * paper_seconds / t0;
  for (int step = 0; step < 4; ++step) {
    const double t1 = model.stereo(model.card(), s1).mean;
    if (std::abs(t1 - paper_seconds) < 1e-4 || t1 == t0)
      break;
    const double next = s1 + (paper_seconds - t1) * (s1 - s0) / (t1 - t0);
    s0 = s1;
    t0 = t1;
    s1 = next;
  }
  return std::round(s1 * 1000.0) / 1000.0;
}

} // namespace marsokhod::eval
