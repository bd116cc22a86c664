// Writing a traverse as JSON: the same keys in the same order every time.
#include "marsokhod/eval/traverse/traverse_json.hpp"

namespace marsokhod::eval {
namespace {

using json = nlohmann::ordered_json;

json pose_json(const world::RoverPose& pose) {
  return {{"x_m", pose.x}, {"y_m", pose.y}, {"heading_deg", pose.heading_deg}};
}

json points_json(const std::vector<Eigen::Vector2d>& points) {
  json list = json::array();
  for (const Eigen::Vector2d& p : points)
    list.push_back({p.x(), p.y()});
  return list;
}

json settings_json(const TraverseSettings& s) {
  return {{"seed", s.seed},
          {"rocks", s.rocks},
          {"slope_deg", s.slope_deg},
          {"light", s.light},
          {"goal_m", s.goal_m},
          {"drive_m", s.drive_m},
          {"hazard_memory_cycles", s.hazard_memory_cycles},
          {"normal_path_m", {s.motion.normal_min_m, s.motion.normal_max_m}},
          {"step_baseline_m", s.step_baseline_m},
          {"unseen_cell_m", s.unseen_cell_m},
          {"slip", s.slip},
          {"image_px", s.image_px},
          {"goal_tolerance_m", s.goal_tolerance_m},
          {"emergency_tilt_deg", s.emergency_tilt_deg},
          {"tilt_limit_deg", s.tilt_limit_deg},
          {"read_every_m", s.read_every_m},
          {"drive_speed_m_s", s.drive_speed_m_s},
          {"turn_rate_deg_s", s.turn_rate_deg_s},
          {"platform", s.platform},
          {"faults_file", s.faults_file}};
}

} // namespace

json cycle_json(const TraverseCycle& c) {
  json line;
  line["cycle"] = c.index;
  line["start"] = pose_json(c.start);
  line["state"] = std::string(nav::to_string(c.state));
  line["turned_deg"] = c.turned_deg;
  line["found"] = c.found;
  line["reason"] = c.found ? "" : c.reason;
  line["planned_m"] = c.planned_m;
  line["driven_m"] = c.driven_m;
  line["emergency_stop"] = c.emergency_stop;
  line["estimate"] = pose_json(c.estimate);
  line["slip"] = c.slip;
  line["compute_seconds"] = c.compute_seconds;
  line["events"] = c.events;
  line["planned"] = points_json(c.planned);
  line["track"] = points_json(c.track);
  line["host"] = {{"seconds", c.host_seconds}};
  return line;
}

json traverse_json(const TraverseResult& r) {
  json doc;
  doc["format"] = "marsokhod-traverse";
  doc["version"] = 1;
  doc["settings"] = settings_json(r.settings);
  doc["outcome"] = std::string(to_string(r.outcome));
  doc["start"] = pose_json(r.start);
  doc["goal"] = {{"x_m", r.goal.x()}, {"y_m", r.goal.y()}};
  doc["end"] = pose_json(r.end);
  doc["goal_left_m"] = r.goal_left_m;
  doc["estimate"] = pose_json(r.estimate);
  doc["odometry_error_m"] = r.odometry_error_m();
  doc["distance_m"] = r.distance_m;
  doc["path_efficiency"] = r.path_efficiency();
  doc["cycles"] = r.cycles.size();
  doc["emergency_stops"] = r.emergency_stops;
  doc["hand_overs"] = r.hand_overs;
  json unsafe = json::array();
  for (const UnsafeEvent& e : r.unsafe_events)
    unsafe.push_back({{"x_m", e.x_m}, {"y_m", e.y_m}, {"why", e.why}});
  doc["unsafe_events"] = unsafe;
  json faults = json::array();
  for (const TraverseFault& f : r.faults)
    faults.push_back({{"cycle", f.cycle},
                      {"fault", f.fault},
                      {"outcome", f.outcome},
                      {"recovered", f.recovered},
                      {"failovers", f.failovers},
                      {"time_lost_s", f.time_lost_s}});
  doc["faults"] = faults;
  doc["mission_seconds"] = r.mission_seconds();
  doc["driving_seconds"] = r.driving_seconds;
  doc["compute_seconds"] = r.compute_seconds;
  doc["host"] = {{"seconds", r.host_seconds}};
  return doc;
}

} // namespace marsokhod::eval
