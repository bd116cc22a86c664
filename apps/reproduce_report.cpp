// The reproduction for scripts and people.

#include "reproduce_report.hpp"

#include "emulate_report.hpp"

#include "marsokhod/imaging/pictures/bar_chart.hpp"

#include <fmt/format.h>

namespace marsokhod::apps {
namespace {

using Json = nlohmann::ordered_json;

std::string seeds_text(const std::vector<std::uint64_t>& seeds) {
  if (seeds.size() == 1)
    return fmt::format("world seed {}", seeds.front());
  return fmt::format("world seeds {}..{}", seeds.front(), seeds.back());
}

Json spread_json(const SceneSpread& s) {
  return Json{{"mean", s.mean}, {"least", s.least}, {"greatest", s.greatest}};
}

std::string signed_percent(double percent) {
  return fmt::format("{:+.1f} %", percent);
}

} // namespace

Json reproduction_json(const Reproduction& r) {
  Json json;
  json["scenes"] = Json{{"seeds", r.seeds}, {"size_px", 128}};
  json["figures"] = Json::array();
  for (const FigureComparison& f : r.figures)
    json["figures"].push_back(Json{{"name", f.name},
                                   {"paper_says", f.paper_says},
                                   {"paper_seconds", f.paper_seconds},
                                   {"model_seconds", f.model.mean},
                                   {"error_percent", f.error_percent()},
                                   {"fitted", f.fitted},
                                   {"over_scenes", spread_json(f.model)}});
  json["fitted_constants"] = Json::array();
  for (const FittedConstant& c : r.fitted)
    json["fitted_constants"].push_back(
        Json{{"name", c.name}, {"value", c.value}, {"fitted_on", c.fitted_on}, {"refit", c.refit}});
  json["sensitivity"] = Json::array();
  for (const SensitivityRow& row : r.sensitivity)
    json["sensitivity"].push_back(Json{{"parameter", row.parameter},
                                       {"value", row.value},
                                       {"shipped", row.shipped},
                                       {"stereo_seconds", row.figures.stereo.mean},
                                       {"card_cycle_seconds", row.figures.card_cycle.mean},
                                       {"onboard_cycle_seconds", row.figures.onboard_cycle.mean}});
  json["sweep"] = Json::array();
  for (const SweepPoint& p : r.sweep)
    json["sweep"].push_back(
        Json{{"external_kb", p.external_kb},
             {"emulated_seconds", p.memory_fault ? Json(nullptr) : Json(p.emulated_seconds)},
             {"memory_fault", memory_fault_json(p.memory_fault)},
             {"terrain_kept", p.terrain_kept},
             {"zone_grid_bytes", p.zone_grid_bytes}});
  return json;
}

std::string reproduction_markdown(const Reproduction& r) {
  std::string md = fmt::format("# The paper's timings from the model\n\n{} at 128x128, the mean "
                               "over the scenes (least..greatest in brackets).\n\n",
                               seeds_text(r.seeds));
  md += "| figure | the paper | paper s | model s | error | fitted |\n|---|---|---|---|---|---|\n";
  for (const FigureComparison& f : r.figures)
    md += fmt::format("| {} | \"{}\" | {:.1f} | {:.2f} ({:.2f}..{:.2f}) | {} | {} |\n", f.name,
                      f.paper_says, f.paper_seconds, f.model.mean, f.model.least, f.model.greatest,
                      signed_percent(f.error_percent()), f.fitted ? "yes" : "no");
  md += "\n## The fitted constant\n\n| name | value | fitted on | fitted again now |\n"
        "|---|---|---|---|\n";
  for (const FittedConstant& c : r.fitted)
    md += fmt::format("| {} | {:.3f} | {} | {:.3f} |\n", c.name, c.value, c.fitted_on, c.refit);
  md += "\n## Sensitivity (the others as shipped, the fitted constant held)\n\n"
        "| parameter | value | stereo s | PC card cycle s | onboard cycle s |\n"
        "|---|---|---|---|---|\n";
  for (const SensitivityRow& row : r.sensitivity)
    md += fmt::format("| {} | {}{} | {:.2f} | {:.2f} | {:.2f} |\n", row.parameter, row.value,
                      row.shipped ? " (shipped)" : "", row.figures.stereo.mean,
                      row.figures.card_cycle.mean, row.figures.onboard_cycle.mean);
  md += "\n## The onboard cycle against each module's external memory\n\n"
        "| external KB | cycle s | terrain | note |\n|---|---|---|---|\n";
  for (const SweepPoint& p : r.sweep)
    md += fmt::format("| {} | {} | {} | {} |\n", p.external_kb,
                      p.memory_fault ? std::string("-") : fmt::format("{:.2f}", p.emulated_seconds),
                      p.terrain_kept ? "four maps" : "disparity",
                      p.memory_fault ? "does not fit: " + memory_fault_message(*p.memory_fault)
                                     : std::string());
  return md;
}

imaging::Image<std::uint8_t> reproduction_chart(const Reproduction& r) {
  imaging::BarChart chart;
  chart.title = fmt::format("paper and model, {}, 128x128", seeds_text(r.seeds));
  chart.y_label = "seconds";
  chart.series = {"paper", "model"};
  for (const FigureComparison& f : r.figures)
    chart.groups.push_back(
        {f.fitted ? f.name + " (fitted)" : f.name, {f.paper_seconds, f.model.mean}});
  return imaging::draw_bar_chart(chart);
}

} // namespace marsokhod::apps
