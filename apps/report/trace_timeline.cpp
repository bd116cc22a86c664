// Reading a Chrome trace's begin and end events into lanes and drawing them with Chart.js.
#include "report/trace_timeline.hpp"

#include "cli/command.hpp"
#include "report/html_page.hpp"

#include "marsokhod/io/formats/json_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace marsokhod::apps {
namespace {

using nlohmann::json;
using Track = std::pair<long long, long long>; // pid, tid

struct Open {
  double begin_s;
  std::string name;
};

struct Timeline {
  std::vector<std::string> lanes;
  json spans = json::array(); ///< [lane, begin s, end s, name]
  double end_s = 0.0;
  std::size_t dropped = 0;
};

// "module0 / link1 out" for every track the metadata names, in the trace's sort order.
std::map<Track, std::string> track_names(const json& events) {
  std::map<long long, std::string> processes;
  std::map<Track, std::string> tracks;
  for (const json& e : events)
    if (e.value("ph", "") == "M" && e.value("name", "") == "process_name")
      processes[e.value("pid", 0LL)] = e["args"].value("name", "");
  for (const json& e : events)
    if (e.value("ph", "") == "M" && e.value("name", "") == "thread_name") {
      const long long pid = e.value("pid", 0LL);
      tracks[{pid, e.value("tid", 0LL)}] = processes[pid] + " / " + e["args"].value("name", "");
    }
  return tracks;
}

// Lanes in the trace's own order (node, then track); spans in the order they ended.
Timeline read_timeline(const json& events) {
  const std::map<Track, std::string> names = track_names(events);
  std::map<Track, std::vector<Open>> open;
  std::vector<std::pair<Track, json>> ended;
  Timeline t;
  for (const json& e : events) {
    const std::string ph = e.value("ph", "");
    if (ph != "B" && ph != "E")
      continue;
    const Track track{e.value("pid", 0LL), e.value("tid", 0LL)};
    const double at_s = e.value("ts", 0.0) * 1e-6; // Chrome traces count microseconds
    t.end_s = std::max(t.end_s, at_s);
    if (ph == "B") {
      open[track].push_back({at_s, e.value("name", "")});
      continue;
    }
    std::vector<Open>& stack = open[track];
    if (stack.empty())
      continue;
    if (ended.size() >= kMaxTimelineSpans) {
      ++t.dropped;
      stack.pop_back();
      continue;
    }
    ended.emplace_back(track, json::array({stack.back().begin_s, at_s, stack.back().name}));
    stack.pop_back();
  }
  std::map<Track, std::size_t> lane_of;
  for (const auto& [track, span] : ended)
    lane_of.emplace(track, 0);
  for (auto& [track, lane] : lane_of) {
    lane = t.lanes.size();
    const auto name = names.find(track);
    t.lanes.push_back(name != names.end() ? name->second
                                          : fmt::format("{} / {}", track.first, track.second));
  }
  for (const auto& [track, span] : ended)
    t.spans.push_back({lane_of[track], span[0], span[1], span[2]});
  return t;
}

} // namespace

std::string timeline_chart(const std::filesystem::path& trace, const std::string& id) {
  json doc;
  try {
    doc = io::parse_json_file(trace, "trace file");
  } catch (const std::exception& error) {
    throw CommandError(error.what());
  }
  if (!doc.is_object() || !doc.contains("traceEvents") || !doc["traceEvents"].is_array())
    throw CommandError(fmt::format("{}: not a Chrome trace (no traceEvents list)", trace.string()));
  const Timeline t = read_timeline(doc["traceEvents"]);
  if (t.spans.empty())
    return {};
  const std::string note =
      t.dropped == 0 ? std::string()
                     : fmt::format("<p>The first {} spans are drawn; {} more are in {}.</p>\n",
                                   kMaxTimelineSpans, t.dropped, html_escape(trace.string()));
  return fmt::format(
      R"(<h3>Emulated timeline</h3>
<div class="timeline" style="height: {height}px"><canvas id="{id}"></canvas></div>
<p>Zoom: from <input type="range" id="{id}-from" min="0" max="1000" value="0"> to
<input type="range" id="{id}-to" min="0" max="1000" value="1000"> of the cycle's {end:.3f} s.</p>
{note}<script>
(function() {{
  const lanes = {lanes};
  const spans = {spans};
  const end = {end};
  const data = spans.map(s => ({{x: [s[1], s[2]], y: lanes[s[0]], name: s[3]}}));
  const chart = new Chart(document.getElementById("{id}"), {{
    type: "bar",
    data: {{labels: lanes, datasets: [{{label: "busy", data: data, backgroundColor: "#36a",
      barPercentage: 0.8, categoryPercentage: 1.0, minBarLength: 1}}]}},
    options: {{indexAxis: "y", animation: false, maintainAspectRatio: false,
      scales: {{x: {{type: "linear", min: 0, max: end,
                   title: {{display: true, text: "emulated seconds"}}}},
                y: {{type: "category", ticks: {{autoSkip: false}}}}}},
      plugins: {{legend: {{display: false}},
        tooltip: {{callbacks: {{label: c => c.raw.name + ": " + c.raw.x[0].toFixed(6) +
          " to " + c.raw.x[1].toFixed(6) + " s"}}}}}}}}
  }});
  const from = document.getElementById("{id}-from");
  const to = document.getElementById("{id}-to");
  function zoom() {{
    const a = Math.min(from.value, to.value) / 1000 * end;
    const b = Math.max(from.value, to.value) / 1000 * end;
    chart.options.scales.x.min = a;
    chart.options.scales.x.max = Math.max(b, a + end / 1000);
    chart.update();
  }}
  from.oninput = zoom;
  to.oninput = zoom;
  marsokhodMarkDrawn(chart);
}})();
</script>
)",
      fmt::arg("id", html_escape(id)), fmt::arg("height", 60 + 18 * t.lanes.size()),
      fmt::arg("end", t.end_s), fmt::arg("note", note), fmt::arg("lanes", script_json(t.lanes)),
      fmt::arg("spans", script_json(t.spans)));
}

} // namespace marsokhod::apps
