// What `marsokhod fault` prints: the verdict and the run's events, for people and for scripts.
#pragma once

#include "marsokhod/eval/faults/fault_verdict.hpp"
#include "marsokhod/nav_program/run/navigation_program.hpp"
#include "marsokhod/overswitch/supervision/failover_supervisor.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace marsokhod::apps {

/// The outcome, each fault, halt and overswitch event with its time, and the verdict's figures.
void print_verdict(const eval::FaultVerdict& verdict,
                   const overswitch::FailoverSupervisor& supervisor);

/// `platform`, `seed`, `faults`, the verdict's keys, `overswitch_events`, `device_log`
/// (docs/faults.md).
nlohmann::ordered_json fault_run_json(const std::string& platform, std::uint64_t seed,
                                      const eval::FaultVerdict& verdict,
                                      const overswitch::FailoverSupervisor& supervisor,
                                      const nav_program::CycleEmulation& run);

} // namespace marsokhod::apps
