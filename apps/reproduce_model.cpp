// The model's figures for the paper's table: each one cycle per scene on the shipped platforms.

#include "reproduce_model.hpp"

#include "command.hpp"

#include "marsokhod/occam_port/navigation/navigation_program.hpp"
#include "marsokhod/world/scene/rendered_site.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace marsokhod::apps {
namespace {

namespace emu = emulator;
namespace op = occam_port;

constexpr int kPaperSide = 128; // "image resolution is 128x128 pixels"

emu::PlatformSpec shipped_platform(const char* file) {
  return emu::load_platform(emu::find_platform_file(file));
}

op::Placement placement_of(const emu::PlatformSpec& platform) {
  return op::load_placement(op::default_placement_file(platform), platform,
                            op::navigation_program_shape());
}

ReproductionScene render_scene(std::uint64_t seed) {
  world::SceneDescription scene = world::default_scene(seed, kPaperSide);
  world::RenderedFrame frame = world::render_site(scene);
  return {seed, std::move(frame.images.left), std::move(frame.images.right),
          std::make_unique<imaging::StereoRig>(scene.rig), scene.placement.attitude};
}

op::CycleEmulation run_cycle(const ReproductionScene& scene, const emu::PlatformSpec& platform,
                             const op::Placement& placement, double occam_style,
                             std::optional<std::size_t> external_bytes = std::nullopt) {
  op::CycleInput input{scene.left, scene.right, scene.rig.get(), {}, {}};
  input.options.attitude = scene.attitude;
  return op::emulate_navigation_cycle(input,
                                      op::CycleSetup{&platform, &placement, external_bytes, nullptr,
                                                     occam_style, nullptr, std::nullopt});
}

// A figure the paper gives must come out of a cycle that ran to its end.
const op::CycleEmulation& ran(const op::CycleEmulation& run, const ReproductionScene& scene,
                              const emu::PlatformSpec& platform) {
  if (run.memory_fault)
    throw CommandError(fmt::format("world seed {} does not fit {}: {}", scene.seed, platform.name,
                                   memory_fault_message(*run.memory_fault)));
  return run;
}

// The stereo reconstruction ends when refine hands the seeable disparity on to range.
double stereo_end(const op::CycleEmulation& run) {
  emu::Tick end = 0;
  for (const op::StageFigures& stage : run.stages)
    if (stage.name == "acquire" || stage.name == "features" || stage.name == "matching" ||
        stage.name == "refine")
      end = std::max(end, stage.end);
  return emu::to_seconds(end);
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

TimingModel::TimingModel(const std::vector<std::uint64_t>& seeds)
    : card_(shipped_platform("pc-card.toml")), onboard_(shipped_platform("onboard.toml")),
      card_placement_(placement_of(card_)), onboard_placement_(placement_of(onboard_)) {
  if (seeds.empty())
    throw UsageError("reproduce needs at least one world seed");
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
    const op::CycleEmulation on_card = run_cycle(scene, card, card_placement_, occam_style);
    stereo.push_back(stereo_end(ran(on_card, scene, card)));
    card_cycle.push_back(emu::to_seconds(on_card.emulated));
    const op::CycleEmulation aboard = run_cycle(scene, onboard, onboard_placement_, occam_style);
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
      const op::CycleEmulation run = run_cycle(scene, onboard_, onboard_placement_, occam_style,
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

namespace {

using Change = std::function<void(emu::PlatformSpec& card, emu::PlatformSpec& onboard)>;

struct Variant {
  std::string parameter;
  std::string value;
  bool shipped = false;
  Change change;
};

void each_node(emu::PlatformSpec& platform, const std::function<void(emu::NodeSpec&)>& f) {
  for (emu::NodeSpec& node : platform.nodes)
    f(node);
}

Change card_grade(const std::string& grade) {
  return [grade](emu::PlatformSpec& card, emu::PlatformSpec&) {
    const auto found = card.speed_grades.find(grade);
    if (found == card.speed_grades.end())
      throw CommandError(fmt::format("{} has no speed grade {}", card.source, grade));
    each_node(
        card,
        [&](emu::NodeSpec& n) {
          n.speed_grade = grade;
          n.cpu.cycle = found->second;
        });
  };
}

Change wait_states(bool on_card, int waits) {
  return [on_card, waits](emu::PlatformSpec& card, emu::PlatformSpec& onboard) {
    each_node(
        on_card ? card : onboard, [waits](emu::NodeSpec& n) { n.cpu.costs.wait_states = waits; });
  };
}

Change external_kb(bool on_card, std::size_t kb) {
  return [on_card, kb](emu::PlatformSpec& card, emu::PlatformSpec& onboard) {
    each_node(
        on_card ? card : onboard, [kb](emu::NodeSpec& n) { n.memory.external_bytes = kb * 1024; });
  };
}

Change link_speed(int mbps) {
  return [mbps](emu::PlatformSpec& card, emu::PlatformSpec& onboard) {
    for (emu::PlatformSpec* p : {&card, &onboard})
      for (emu::WireSpec& wire : p->wires)
        wire.speed_mbps = mbps;
  };
}

// The parameters the paper leaves open, each over the values of its period (docs/timing.md
// gives the sources); the shipped value first.
std::vector<Variant> variants() {
  return {
      {"PC card speed grade", "T805-30", true, card_grade("T805-30")},
      {"PC card speed grade", "T805-25", false, card_grade("T805-25")},
      {"PC card speed grade", "T805-20", false, card_grade("T805-20")},
      {"PC card memory wait states", "0 (3-cycle)", true, wait_states(true, 0)},
      {"PC card memory wait states", "1 (4-cycle DRAM)", false, wait_states(true, 1)},
      {"PC card memory wait states", "2 (5-cycle DRAM)", false, wait_states(true, 2)},
      {"PC card memory", "2 MB", true, external_kb(true, 2048)},
      {"PC card memory", "1 MB", false, external_kb(true, 1024)},
      {"PC card memory", "4 MB", false, external_kb(true, 4096)},
      {"onboard memory wait states", "0 (3-cycle)", true, wait_states(false, 0)},
      {"onboard memory wait states", "1", false, wait_states(false, 1)},
      {"onboard memory wait states", "2", false, wait_states(false, 2)},
      {"link speed", "10 Mbit/s", true, link_speed(10)},
      {"link speed", "20 Mbit/s", false, link_speed(20)},
  };
}

} // namespace

std::vector<SensitivityRow> sensitivity(const TimingModel& model, double occam_style,
                                        const ModelFigures& shipped) {
  std::vector<SensitivityRow> rows;
  for (const Variant& v : variants()) {
    if (v.shipped) {
      rows.push_back({v.parameter, v.value, true, shipped});
      continue;
    }
    emu::PlatformSpec card = model.card();
    emu::PlatformSpec onboard = model.onboard();
    v.change(card, onboard);
    rows.push_back({v.parameter, v.value, v.shipped, model.figures(card, onboard, occam_style)});
  }
  for (const double factor : {0.9, 1.1})
    rows.push_back({"occam style factor (fitted)",
                    fmt::format("{:.3f} (x{:.1f})", occam_style * factor, factor), false,
                    model.figures(model.card(), model.onboard(), occam_style * factor)});
  return rows;
}

} // namespace marsokhod::apps
