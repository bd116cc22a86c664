// What `marsokhod fault` prints: the verdict with its events for people, JSON for scripts.

#include "faults/fault_report.hpp"

#include "marsokhod/eval/faults/fault_record.hpp"

#include <fmt/format.h>

namespace marsokhod::apps {

namespace emu = emulator;

void print_verdict(const eval::FaultVerdict& v, const overswitch::FailoverSupervisor& supervisor) {
  fmt::print("outcome: {}{}\n", eval::to_string(v.outcome),
             v.reason.empty() ? "" : " (" + v.reason + ")");
  for (const overswitch::InjectedFault& f : supervisor.injected()) {
    fmt::print("  {:9.6f} s  fault {}", emu::to_seconds(f.at), overswitch::describe(f.fault));
    if (f.hit)
      fmt::print(": bit {}{} of #{:08X}, {} memory, {}", f.hit->bit,
                 f.hit->check_bit ? " (a check bit)" : "", f.hit->address, f.hit->region(),
                 f.hit->buffer());
    fmt::print("{}\n", f.effect.empty() ? "" : ": " + f.effect);
  }
  for (const eval::HaltFigure& h : v.halts)
    fmt::print("  {:9.6f} s  {} halted: {} ({}{})\n", h.time_s, h.module, h.cause,
               h.process.empty() ? "" : h.process + ", ", h.what);
  for (const overswitch::OverswitchEvent& e : supervisor.overswitch().events())
    fmt::print("  {:9.6f} s  overswitch: {} {}{}\n", emu::to_seconds(e.time),
               overswitch::to_string(e.kind), e.module, e.detail.empty() ? "" : ": " + e.detail);
  if (v.detection_latency_s)
    fmt::print("detected after {:.6f} s", *v.detection_latency_s);
  if (v.recovery_s)
    fmt::print(", pair whole again {:.6f} s later", *v.recovery_s);
  if (v.detection_latency_s)
    fmt::print("\n");
  fmt::print("cycle {:.3f} s emulated ({:+.3f} s on the fault-free run); path {} the fault-free "
             "one; {}; telemetry {}; wheels {}commanded by a failed module\n",
             v.emulated_s, v.delay_s, v.path_equals_golden ? "equals" : "differs from",
             v.unsafe ? "UNSAFE: the path crosses an obstacle" : "safe",
             v.telemetry_lost ? "lost" : "delivered",
             v.wheels_commanded_while_failed ? "" : "never ");
}

nlohmann::ordered_json fault_run_json(const std::string& platform, std::uint64_t seed,
                                      const eval::FaultVerdict& verdict,
                                      const overswitch::FailoverSupervisor& supervisor,
                                      const nav_program::CycleEmulation& run) {
  nlohmann::ordered_json j;
  j["platform"] = platform;
  j["seed"] = seed;
  j["faults"] = nlohmann::ordered_json::array();
  for (const overswitch::InjectedFault& f : supervisor.injected()) {
    nlohmann::ordered_json fault;
    eval::to_json(fault, eval::fault_record(f));
    j["faults"].push_back(fault);
  }
  eval::to_json(j, verdict);
  j["overswitch_events"] = nlohmann::ordered_json::array();
  for (const overswitch::OverswitchEvent& e : supervisor.overswitch().events())
    j["overswitch_events"].push_back({{"time_s", emu::to_seconds(e.time)},
                                      {"event", overswitch::to_string(e.kind)},
                                      {"module", e.module},
                                      {"detail", e.detail}});
  j["device_log"] = nlohmann::ordered_json::array();
  for (const nav_program::DeviceUpload& u : run.uploads)
    j["device_log"].push_back(
        {{"time_s", emu::to_seconds(u.time)}, {"from", u.node}, {"bytes", u.bytes}});
  return j;
}

} // namespace marsokhod::apps
