// The reproduction: the three figures, the constant fitted again, sensitivity and sweep.

#include "marsokhod/eval/timing/reproduction.hpp"

#include "marsokhod/eval/timing/paper_figures.hpp"
#include "marsokhod/nav_program/costs/work_costs.hpp"

#include <fmt/format.h>

namespace marsokhod::eval {
namespace {

using Json = nlohmann::ordered_json;

void tell(const std::function<void(const std::string&)>& note, const std::string& text) {
  if (note)
    note(text);
}

FigureComparison compared(const PaperFigure& paper, const SceneSpread& model, bool fitted) {
  return {paper.name, paper.paper_says, paper.seconds, model, fitted};
}

Json spread_json(const SceneSpread& s) {
  return Json{{"mean", s.mean}, {"least", s.least}, {"greatest", s.greatest}};
}

Json figure_json(const FigureComparison& f) {
  return {{"name", f.name},
          {"paper_says", f.paper_says},
          {"paper_seconds", f.paper_seconds},
          {"model_seconds", f.model.mean},
          {"error_percent", f.error_percent()},
          {"fitted", f.fitted},
          {"over_scenes", spread_json(f.model)}};
}

Json sensitivity_json(const SensitivityRow& row) {
  return {{"parameter", row.parameter},
          {"value", row.value},
          {"shipped", row.shipped},
          {"stereo_seconds", row.figures.stereo.mean},
          {"card_cycle_seconds", row.figures.card_cycle.mean},
          {"onboard_cycle_seconds", row.figures.onboard_cycle.mean}};
}

Json sweep_point_json(const SweepPoint& p) {
  return {{"external_kb", p.external_kb},
          {"emulated_seconds", p.memory_fault ? Json(nullptr) : Json(p.emulated_seconds)},
          {"memory_fault", memory_fault_json(p.memory_fault)},
          {"terrain_kept", p.terrain_kept},
          {"zone_grid_bytes", p.zone_grid_bytes}};
}

} // namespace

Reproduction reproduce(const std::vector<std::uint64_t>& seeds,
                       const std::vector<std::uint64_t>& sweep_kb,
                       const std::function<void(const std::string&)>& note) {
  Reproduction r;
  r.seeds = seeds;
  tell(note, fmt::format("rendering {} world scenes at 128x128...", seeds.size()));
  const TimingModel model(seeds);
  r.card_external_kb = model.card().nodes.front().memory.external_bytes / 1024;
  r.onboard_external_kb = model.onboard().nodes.front().memory.external_bytes / 1024;
  const double style = nav_program::kOccamStyleFactor;
  tell(note, "fitting the occam style factor on the stereo figure...");
  r.fitted.push_back({"occam_style_factor", style, fit_occam_style(model, kPaperStereo.seconds),
                      "stereo 128x128 on one T805 (the PC card), 8 s"});
  tell(note, "the three figures...");
  const ModelFigures f = model.figures(model.card(), model.onboard(), style);
  r.figures = {compared(kPaperStereo, f.stereo, true),
               compared(kPaperCardCycle, f.card_cycle, false),
               compared(kPaperOnboardCycle, f.onboard_cycle, false)};
  tell(note, "sensitivity to the parameters the paper does not give...");
  r.sensitivity = sensitivity(model, style, f);
  r.sweep = model.onboard_sweep(sweep_kb, style, [&](std::size_t done) {
    tell(note, fmt::format("sweep {}/{}: {} KB", done, sweep_kb.size(), sweep_kb[done - 1]));
  });
  return r;
}

void to_json(Json& json, const Reproduction& r) {
  json["scenes"] = Json{{"seeds", r.seeds}, {"size_px", kPaperImageSide}};
  json["figures"] = Json::array();
  for (const FigureComparison& f : r.figures)
    json["figures"].push_back(figure_json(f));
  json["fitted_constants"] = Json::array();
  for (const FittedConstant& c : r.fitted)
    json["fitted_constants"].push_back(
        Json{{"name", c.name}, {"value", c.value}, {"fitted_on", c.fitted_on}, {"refit", c.refit}});
  json["sensitivity"] = Json::array();
  for (const SensitivityRow& row : r.sensitivity)
    json["sensitivity"].push_back(sensitivity_json(row));
  json["sweep"] = Json::array();
  for (const SweepPoint& p : r.sweep)
    json["sweep"].push_back(sweep_point_json(p));
}

} // namespace marsokhod::eval
