// The cycle's time against the nodes' external memory: each size one emulated cycle.

#include "emulation/sweep_report.hpp"

#include "cli/command.hpp"

#include "marsokhod/imaging/image/image_io.hpp"
#include "marsokhod/imaging/pictures/line_chart.hpp"
#include "marsokhod/io/files/file_writer.hpp"

#include <fmt/format.h>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;

std::string fault_text(const eval::SweepPoint& p) {
  return p.memory_fault ? nav_program::describe(*p.memory_fault) : std::string();
}

// CSV fields are quoted, with quotes doubled.
std::string csv_quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text)
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + '"';
}

imaging::LineChart chart_of(const std::vector<eval::SweepPoint>& points,
                            const EmulationSubject& subject,
                            const std::vector<imaging::LineChart::Mark>& marks) {
  imaging::LineChart chart;
  chart.title = fmt::format("one cycle on {}, {}", subject.platform, subject.pair);
  chart.x_label = "external memory per node, kb (log scale). x: the cycle does not fit";
  chart.y_label = "emulated s";
  for (const eval::SweepPoint& p : points) {
    const auto kb = static_cast<double>(std::max<std::uint64_t>(p.external_kb, 1));
    if (p.memory_fault)
      chart.missing.push_back(kb);
    else
      chart.points.push_back({kb, p.emulated_seconds});
  }
  chart.marks = marks;
  return chart;
}

} // namespace

std::string sweep_table(const std::vector<eval::SweepPoint>& points) {
  std::string text = "external KB  emulated s  terrain     zones grid  recomputed units\n";
  for (const eval::SweepPoint& p : points) {
    const std::string grid =
        p.zone_grid_bytes > 0 ? fmt::format("{} B", p.zone_grid_bytes) : std::string("whole");
    text +=
        fmt::format("{:>11}  {:>10}  {:<10}  {:>10}  {:>16}{}\n", p.external_kb,
                    p.memory_fault ? std::string("-") : fmt::format("{:.3f}", p.emulated_seconds),
                    p.terrain_kept ? "four maps" : "disparity", grid, p.recomputed_units,
                    p.memory_fault ? "  does not fit: " + fault_text(p) : std::string());
  }
  return text;
}

nlohmann::ordered_json sweep_json(const std::vector<eval::SweepPoint>& points,
                                  const EmulationSubject& subject) {
  nlohmann::ordered_json json;
  json["platform"] = subject.platform;
  json["platform_file"] = subject.platform_file;
  json["placement_file"] = subject.placement_file;
  json["pair"] = subject.pair;
  json["sweep"] = nlohmann::ordered_json::array();
  for (const eval::SweepPoint& p : points) {
    nlohmann::ordered_json point;
    eval::to_json(point, p);
    json["sweep"].push_back(point);
  }
  return json;
}

std::string sweep_csv(const std::vector<eval::SweepPoint>& points) {
  std::string csv = "external_kb,emulated_seconds,memory_fault,terrain_kept,zone_grid_bytes,"
                    "recomputed_units\n";
  for (const eval::SweepPoint& p : points)
    csv += fmt::format("{},{},{},{},{},{}\n", p.external_kb,
                       p.memory_fault ? std::string() : fmt::format("{:.9f}", p.emulated_seconds),
                       csv_quoted(fault_text(p)), p.terrain_kept ? 1 : 0, p.zone_grid_bytes,
                       p.recomputed_units);
  return csv;
}

std::map<std::string, fs::path> write_sweep(const fs::path& folder,
                                            const std::vector<eval::SweepPoint>& points,
                                            const EmulationSubject& subject,
                                            const std::vector<imaging::LineChart::Mark>& marks) {
  std::map<std::string, fs::path> written{{"sweep_csv", folder / "sweep.csv"},
                                          {"sweep_json", folder / "sweep.json"},
                                          {"sweep_png", folder / "sweep.png"}};
  try {
    io::write_file_atomically(written["sweep_csv"], sweep_csv(points));
    io::write_file_atomically(written["sweep_json"], sweep_json(points, subject).dump(2) + '\n');
    imaging::write_image(written["sweep_png"],
                         imaging::draw_line_chart(chart_of(points, subject, marks)));
  } catch (const std::exception& error) {
    throw CommandError(error.what());
  }
  return written;
}

} // namespace marsokhod::apps
