// The traverse's records: traverse.json and one cycles.jsonl line per cycle.
#pragma once

#include "marsokhod/eval/traverse/traverse.hpp"

#include <nlohmann/json.hpp>

namespace marsokhod::eval {

/// One cycle (docs/traverse.md): pose, state, plan, drive, events. No host-dependent value
/// except host_seconds, kept under "host".
nlohmann::ordered_json cycle_json(const TraverseCycle& cycle);

/// The whole traverse: settings, outcome, distances, times, events; host-dependent values
/// only under "host".
nlohmann::ordered_json traverse_json(const TraverseResult& result);

} // namespace marsokhod::eval
