// A verdict's keys in a run record, and back.

#include "faults/record_keys.hpp"

#include "marsokhod/eval/faults/fault_verdict.hpp"

namespace marsokhod::eval {
namespace {

using detail::optional_record_value;
using detail::or_null;
using detail::record_value;
using Json = nlohmann::ordered_json;

Json failover_json(const FailoverFigure& f) {
  return {{"failed", f.failed},
          {"spare", f.spare.empty() ? Json(nullptr) : Json(f.spare)},
          {"boot_s", f.boot_s}};
}

FailoverFigure failover_from(const nlohmann::json& j) {
  return {record_value<std::string>(j, "failed"),
          optional_record_value<std::string>(j, "spare").value_or(""),
          record_value<double>(j, "boot_s")};
}

Json halt_json(const HaltFigure& h) {
  return {{"module", h.module},
          {"process", h.process},
          {"what", h.what},
          {"cause", h.cause},
          {"time_s", h.time_s}};
}

HaltFigure halt_from(const nlohmann::json& j) {
  return {record_value<std::string>(j, "module"), record_value<std::string>(j, "process"),
          record_value<std::string>(j, "what"), record_value<std::string>(j, "cause"),
          record_value<double>(j, "time_s")};
}

Json trouble_json(const LinkTroubleFigure& t) {
  return {{"module", t.module},
          {"link", t.link},
          {"peer", t.peer},
          {"trouble", t.trouble},
          {"time_s", t.time_s}};
}

LinkTroubleFigure trouble_from(const nlohmann::json& j) {
  return {record_value<std::string>(j, "module"), record_value<int>(j, "link"),
          record_value<std::string>(j, "peer"), record_value<std::string>(j, "trouble"),
          record_value<double>(j, "time_s")};
}

template <typename T, typename F>
std::vector<T> list_from(const nlohmann::json& json, const char* key, F from, bool may_be_absent) {
  std::vector<T> list;
  if (may_be_absent && !json.contains(key))
    return list;
  const auto items = record_value<nlohmann::json>(json, key);
  if (!items.is_array())
    throw RecordError(std::string("the record's '") + key + "' is no list");
  for (const nlohmann::json& item : items)
    list.push_back(from(item));
  return list;
}

} // namespace

void to_json(Json& j, const FaultVerdict& v) {
  j["outcome"] = to_string(v.outcome);
  if (!v.reason.empty())
    j["reason"] = v.reason;
  j["activated"] = v.activated;
  j["detected"] = v.detected;
  j["detection_latency_s"] = or_null(v.detection_latency_s);
  j["recovery_s"] = or_null(v.recovery_s);
  j["failovers"] = Json::array();
  for (const FailoverFigure& f : v.failovers)
    j["failovers"].push_back(failover_json(f));
  if (!v.halts.empty())
    for (const HaltFigure& h : v.halts)
      j["halts"].push_back(halt_json(h));
  j["restarts"] = v.restarts;
  if (!v.link_troubles.empty())
    for (const LinkTroubleFigure& t : v.link_troubles)
      j["link_troubles"].push_back(trouble_json(t));
  j["path_equals_golden"] = v.path_equals_golden;
  j["unsafe"] = v.unsafe;
  j["golden_unsafe"] = v.golden_unsafe;
  j["telemetry_lost"] = v.telemetry_lost;
  j["wheels_commanded_while_failed"] = v.wheels_commanded_while_failed;
  j["emulated_s"] = v.emulated_s;
  j["delay_s"] = v.delay_s;
}

void from_json(const nlohmann::json& j, FaultVerdict& v) {
  const auto outcome = record_value<std::string>(j, "outcome");
  const std::optional<Outcome> parsed = parse_outcome(outcome);
  if (!parsed)
    throw RecordError("the record's 'outcome' '" + outcome + "' is no outcome class");
  v.outcome = *parsed;
  v.reason = optional_record_value<std::string>(j, "reason", true).value_or("");
  v.activated = record_value<bool>(j, "activated");
  v.detected = record_value<bool>(j, "detected");
  v.detection_latency_s = optional_record_value<double>(j, "detection_latency_s");
  v.recovery_s = optional_record_value<double>(j, "recovery_s");
  v.failovers = list_from<FailoverFigure>(j, "failovers", failover_from, false);
  v.halts = list_from<HaltFigure>(j, "halts", halt_from, true);
  v.restarts = record_value<int>(j, "restarts");
  v.link_troubles = list_from<LinkTroubleFigure>(j, "link_troubles", trouble_from, true);
  v.path_equals_golden = record_value<bool>(j, "path_equals_golden");
  v.unsafe = record_value<bool>(j, "unsafe");
  v.golden_unsafe = record_value<bool>(j, "golden_unsafe");
  v.telemetry_lost = record_value<bool>(j, "telemetry_lost");
  v.wheels_commanded_while_failed = record_value<bool>(j, "wheels_commanded_while_failed");
  v.emulated_s = record_value<double>(j, "emulated_s");
  v.delay_s = record_value<double>(j, "delay_s");
}

} // namespace marsokhod::eval
