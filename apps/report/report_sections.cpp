// The report's section for each kind of folder, from the JSON the command wrote.
#include "report/report_sections.hpp"

#include "cli/command.hpp"
#include "report/html_page.hpp"
#include "report/trace_timeline.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <regex>

namespace marsokhod::apps {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const json kNothing = json::object();

std::string number(const json& value, int digits = 2) {
  if (!value.is_number())
    return value.is_null() ? "-" : html_escape(value.dump());
  return fmt::format("{:.{}f}", value.get<double>(), digits);
}

// A list of numbers, each to `digits` decimals.
std::string numbers(const json& values, int digits = 2) {
  std::vector<std::string> items;
  for (const json& value : values)
    items.push_back(number(value, digits));
  return fmt::format("{}", fmt::join(items, ", "));
}

std::string text(const json& value) {
  return html_escape(value.is_string() ? value.get<std::string>() : value.dump());
}

// The pictures each command always writes: a folder without one has lost it, and the page
// says so rather than leave a hole.
std::vector<std::string_view> expected_pictures(FolderKind kind) {
  switch (kind) {
  case FolderKind::world:
    return {"left.png", "right.png", "gt_obstacles.png"};
  case FolderKind::cycle:
    return {"disparity.png", "elevation.png", "zones.png", "path_overlay.png"};
  case FolderKind::reproduce:
    return {"reproduce.png", "sweep.png"};
  case FolderKind::campaign:
    return {"outcomes.png"};
  case FolderKind::traverse:
    return {"map.png"};
  case FolderKind::traverse_sweep:
    return {"success.png"};
  case FolderKind::terrain:
  case FolderKind::fault:
    break;
  }
  return {};
}

void require_pictures(const ReportFolder& f) {
  for (const std::string_view name : expected_pictures(f.kind))
    if (!fs::is_regular_file(f.dir / name))
      throw CommandError(fmt::format("{}: missing; {} always writes it, so the folder is "
                                     "incomplete",
                                     (f.dir / name).string(), writer_of(f.kind)));
}

// Every PNG of the folder (not of its subfolders), in name order.
std::string pictures(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".png")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::string html;
  for (const fs::path& file : files)
    html += embedded_png(file);
  return html.empty() ? html : "<div class=\"pictures\">\n" + html + "</div>\n";
}

// The timeline of the folder's trace.json, empty without one.
std::string folder_timeline(const fs::path& dir, const std::string& chart_id) {
  const fs::path trace = dir / "trace.json";
  return fs::is_regular_file(trace) ? timeline_chart(trace, chart_id) : std::string();
}

std::string heading(const ReportFolder& f) {
  return fmt::format("<h2>{}: {}</h2>\n", html_escape(std::string(to_string(f.kind))),
                     html_escape(f.dir.string()));
}

ReportSection world_section(const ReportFolder& f) {
  const json& t = f.doc["terrain"];
  const std::string headline = fmt::format(
      "world seed {}: a {} x {} m site, rock cover {} %", text(t["seed"]), number(t["size_m"], 0),
      number(t["width_m"], 0), number(json(100.0 * t.value("rock_cover", 0.0)), 0));
  std::vector<std::vector<std::string>> rows;
  for (const char* key : {"seed", "size_m", "width_m", "rock_cover", "regional_slope_deg",
                          "crater_density_per_m2", "undulation_m", "cell_m"})
    if (t.contains(key))
      rows.push_back({key, text(t[key])});
  return {headline, heading(f) + html_table({"terrain", "value"}, rows) + pictures(f.dir)};
}

ReportSection cycle_section(const ReportFolder& f, const std::string& chart_id) {
  const json& p = f.doc;
  const bool traced = fs::is_regular_file(f.dir / "trace.json");
  const std::string headline =
      p.value("found", false)
          ? fmt::format("{}: path found, start {} m, target {} m{}", html_escape(f.dir.string()),
                        number(p["start_m"]), number(p["target_m"]),
                        traced ? " (emulated, with its trace)" : "")
          : fmt::format("{}: no path", html_escape(f.dir.string()));
  std::vector<std::vector<std::string>> rows = {
      {"found", text(p["found"])},
      {"start, m", number(p.value("start_m", json()))},
      {"target, m", number(p.value("target_m", json()))},
      {"fractures, m", numbers(p.value("fracture_m", json::array()))},
      {"drive commands", std::to_string(p.value("commands", json::array()).size())},
      {"cost", number(p.value("cost", json()), 4)}};
  if (traced)
    rows.push_back({"trace", "trace.json beside it (Chrome trace: open in ui.perfetto.dev)"});
  const std::string timeline = folder_timeline(f.dir, chart_id);
  return {headline, heading(f) + html_table({"path", "value"}, rows) + timeline + pictures(f.dir),
          !timeline.empty()};
}

ReportSection reproduce_section(const ReportFolder& f, const std::string& chart_id) {
  std::vector<std::vector<std::string>> rows;
  int passed = 0;
  int checked = 0;
  json labels = json::array();
  json paper = json::array();
  json model_seconds = json::array();
  for (const json& figure : f.doc["figures"]) {
    const double model = figure.value("model_seconds", 0.0);
    labels.push_back(figure.value("name", ""));
    paper.push_back(figure.value("paper_seconds", 0.0));
    model_seconds.push_back(model);
    const auto check = check_against_paper(figure.value("paper_says", ""), model);
    std::string verdict = "-";
    if (check) {
      ++checked;
      passed += check->pass ? 1 : 0;
      verdict = fmt::format("<span class=\"{}\">{}</span> ({:.1f}..{:.1f} s)",
                            check->pass ? "pass" : "fail", check->pass ? "matches" : "misses",
                            check->low_s, check->high_s);
    }
    rows.push_back({text(figure["name"]), "&ldquo;" + text(figure["paper_says"]) + "&rdquo;",
                    number(figure["paper_seconds"], 1), number(figure["model_seconds"]),
                    fmt::format("{:+.1f} %", figure.value("error_percent", 0.0)),
                    figure.value("fitted", false) ? "yes" : "no", verdict});
  }
  const std::string headline =
      fmt::format("the paper's timings from the model: {} of {} match the paper's stated precision",
                  passed, checked);
  const std::string note =
      "<p>A figure matches when the model lies within half a unit of the paper's last digit "
      "(8 sec: 7.5 to 8.5 s; 1.3 min: 75 to 81 s). A fitted figure matches by construction.</p>\n";
  const json chart = {
      {"type", "bar"},
      {"data",
       {{"labels", labels},
        {"datasets",
         {{{"label", "the paper, s"}, {"data", paper}, {"backgroundColor", "#888"}},
          {{"label", "the model, s"}, {"data", model_seconds}, {"backgroundColor", "#2a6"}}}}}}};
  return {headline,
          heading(f) +
              html_table({"figure", "the paper", "paper s", "model s", "error", "fitted",
                          "against the paper"},
                         rows) +
              note + chart_canvas(chart_id, chart) + pictures(f.dir),
          true};
}

ReportSection campaign_section(const ReportFolder& f, const std::string& chart_id) {
  const json& s = f.doc;
  std::vector<std::vector<std::string>> rows;
  const json& outcomes = s.contains("outcomes") ? s["outcomes"] : kNothing;
  json labels = json::array();
  json counts = json::array();
  for (const auto& [outcome, count] : outcomes.items()) {
    rows.push_back({html_escape(outcome), text(count)});
    labels.push_back(outcome);
    counts.push_back(count);
  }
  const json ci = s.value("unsafe_ci95", json::array({0.0, 0.0}));
  const std::string headline = fmt::format(
      "campaign {}: {} runs, unsafe rate {} (95 % interval {} to {})", text(s["campaign"]),
      text(s["runs"]), number(s["unsafe_rate"], 4), number(ci[0], 4), number(ci[1], 4));
  const json chart = {
      {"type", "bar"},
      {"data",
       {{"labels", labels},
        {"datasets", {{{"label", "runs"}, {"data", counts}, {"backgroundColor", "#36a"}}}}}}};
  return {headline,
          heading(f) + html_table({"outcome", "runs"}, rows) + chart_canvas(chart_id, chart) +
              pictures(f.dir),
          true};
}

ReportSection traverse_section(const ReportFolder& f) {
  const json& t = f.doc;
  const std::string headline =
      fmt::format("traverse: {} after {} m in {} cycles, path efficiency {}", text(t["outcome"]),
                  number(t["distance_m"], 1), text(t["cycles"]), number(t["path_efficiency"]));
  std::vector<std::vector<std::string>> rows;
  for (const char* key :
       {"outcome", "distance_m", "goal_left_m", "path_efficiency", "cycles", "emergency_stops",
        "hand_overs", "mission_seconds", "driving_seconds", "compute_seconds"})
    if (t.contains(key))
      rows.push_back({key, t[key].is_number_float() ? number(t[key]) : text(t[key])});
  rows.push_back({"unsafe events", std::to_string(t.value("unsafe_events", json::array()).size())});
  return {headline, heading(f) + html_table({"traverse", "value"}, rows) + pictures(f.dir)};
}

ReportSection sweep_section(const ReportFolder& f, const std::string& chart_id) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> successes;
  json ks = json::array();
  json rates = json::array();
  for (const json& k : f.doc["by_rocks"]) {
    ks.push_back(k.value("rocks", 0.0));
    rates.push_back(100.0 * k.value("success_rate", 0.0));
    const json ci = k.value("success_ci95", json::array({0.0, 0.0}));
    rows.push_back({number(k["rocks"]), text(k["trials"]),
                    fmt::format("{:.0f} %", 100.0 * k.value("success_rate", 0.0)),
                    fmt::format("{:.0f} to {:.0f} %", 100.0 * ci[0].get<double>(),
                                100.0 * ci[1].get<double>()),
                    text(k["unsafe_trials"]), number(k["spl"])});
    successes.push_back(
        fmt::format("k = {}: {:.0f} %", number(k["rocks"]), 100.0 * k.value("success_rate", 0.0)));
  }
  const std::string headline =
      fmt::format("traverse sweep, {} trials: success {}", text(f.doc["trials"]),
                  fmt::format("{}", fmt::join(successes, ", ")));
  const json chart = {
      {"type", "line"},
      {"data",
       {{"labels", ks},
        {"datasets",
         {{{"label", "success, % of trials"}, {"data", rates}, {"borderColor", "#2a6"}}}}}},
      {"options", {{"scales", {{"y", {{"min", 0}, {"max", 100}}}}}}}};
  return {
      headline,
      heading(f) +
          html_table({"rock cover k", "trials", "success", "95 % interval", "unsafe trials", "SPL"},
                     rows) +
          chart_canvas(chart_id, chart) + pictures(f.dir),
      true};
}

ReportSection terrain_section(const ReportFolder& f) {
  const json& t = f.doc;
  const std::string headline = fmt::format(
      "terrain evaluation, {} seeds in {}: obstacle recall {} %, false prohibition {} %, paths "
      "found on {} of {} sites where the truth has one, {} unsafe",
      text(t["seeds"]), text(t["light"]), number(t["obstacle_recall"], 1),
      number(t["false_prohibited"], 1), text(t["paths_found_where_ground_truth_has_one"]),
      text(t["ground_truth_paths"]), text(t["unsafe_paths"]));
  std::vector<std::vector<std::string>> rows;
  for (const char* key :
       {"seeds", "size", "light", "rocks", "stereo", "obstacle_recall", "false_prohibited",
        "paths_found", "ground_truth_paths", "paths_found_where_ground_truth_has_one",
        "unsafe_paths", "unsafe_paths_pixel_rule"})
    if (t.contains(key))
      rows.push_back({key, t[key].is_number_float() ? number(t[key]) : text(t[key])});
  std::vector<std::vector<std::string>> unsafe;
  for (const json& seed : t.value("per_seed", json::array()))
    if (seed.contains("unsafe_because"))
      unsafe.push_back({text(seed["seed"]), text(seed["unsafe_because"])});
  std::string body = heading(f) + html_table({"evaluation", "value"}, rows);
  if (!unsafe.empty())
    body += html_table({"unsafe seed", "why"}, unsafe);
  return {headline, body + pictures(f.dir)};
}

ReportSection fault_section(const ReportFolder& f, const std::string& chart_id) {
  const json& v = f.doc;
  std::vector<std::string> specs;
  for (const json& fault : v.value("faults", json::array()))
    specs.push_back(fault.value("spec", ""));
  const std::string faults = fmt::format("{}", fmt::join(specs, ", "));
  const std::string headline =
      fmt::format("fault run ({}): {}, {} failover{}, {}", html_escape(faults), text(v["outcome"]),
                  v.value("failovers", json::array()).size(),
                  v.value("failovers", json::array()).size() == 1 ? "" : "s",
                  v.value("unsafe", false) ? "unsafe" : "safe");
  std::vector<std::vector<std::string>> rows = {{"faults", html_escape(faults)}};
  rows.push_back({"failovers", std::to_string(v.value("failovers", json::array()).size())});
  for (const char* key : {"outcome", "activated", "detected", "detection_latency_s", "recovery_s",
                          "restarts", "path_equals_golden", "unsafe", "telemetry_lost",
                          "wheels_commanded_while_failed", "emulated_s", "delay_s"})
    if (v.contains(key))
      rows.push_back({key, v[key].is_number_float() ? number(v[key], 3) : text(v[key])});
  const std::string timeline = folder_timeline(f.dir, chart_id);
  return {headline, heading(f) + html_table({"verdict", "value"}, rows) + timeline,
          !timeline.empty()};
}

} // namespace

std::optional<PaperCheck> check_against_paper(const std::string& paper_says, double model_s) {
  static const std::regex kFigure(R"(([0-9]+)(?:\.([0-9]+))?\s*(sec|s|min)\b)");
  std::smatch match;
  if (!std::regex_search(paper_says, match, kFigure))
    return std::nullopt;
  const std::string decimals = match[2].str();
  const double scale = match[3].str() == "min" ? 60.0 : 1.0;
  const double value = std::stod(match[1].str() + (decimals.empty() ? "" : "." + decimals));
  const double half_unit = 0.5 * std::pow(10.0, -static_cast<double>(decimals.size())) * scale;
  PaperCheck check{value * scale - half_unit, value * scale + half_unit, false};
  check.pass = model_s >= check.low_s && model_s <= check.high_s;
  return check;
}

ReportSection report_section(const ReportFolder& folder, int index) {
  require_pictures(folder);
  const std::string chart_id = fmt::format("chart-{}", index);
  switch (folder.kind) {
  case FolderKind::world:
    return world_section(folder);
  case FolderKind::cycle:
    return cycle_section(folder, chart_id);
  case FolderKind::reproduce:
    return reproduce_section(folder, chart_id);
  case FolderKind::campaign:
    return campaign_section(folder, chart_id);
  case FolderKind::traverse:
    return traverse_section(folder);
  case FolderKind::traverse_sweep:
    return sweep_section(folder, chart_id);
  case FolderKind::fault:
    return fault_section(folder, chart_id);
  case FolderKind::terrain:
    break;
  }
  return terrain_section(folder);
}

} // namespace marsokhod::apps
