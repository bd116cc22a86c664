// The reproduction for people.

#include "emulation/reproduce_report.hpp"

#include "marsokhod/imaging/pictures/bar_chart.hpp"

#include <fmt/format.h>

namespace marsokhod::apps {
namespace {

using eval::FigureComparison;
using eval::FittedConstant;
using eval::Reproduction;
using eval::SensitivityRow;
using eval::SweepPoint;

std::string seeds_text(const std::vector<std::uint64_t>& seeds) {
  if (seeds.size() == 1)
    return fmt::format("world seed {}", seeds.front());
  return fmt::format("world seeds {}..{}", seeds.front(), seeds.back());
}

std::string signed_percent(double percent) {
  return fmt::format("{:+.1f} %", percent);
}

} // namespace

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
                      p.memory_fault ? "does not fit: " + nav_program::describe(*p.memory_fault)
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
