// FaultRecord: a fault as a run record gives it, and RunRecord: one line of runs.jsonl.
#pragma once

#include "marsokhod/emulator/memory/memory_upsets.hpp"
#include "marsokhod/eval/faults/fault_verdict.hpp"
#include "marsokhod/eval/faults/record_error.hpp"
#include "marsokhod/overswitch/faults/fault.hpp"
#include "marsokhod/overswitch/supervision/failover_supervisor.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace marsokhod::eval {

/// The bit a memory fault struck and what that did.
struct MemoryHitRecord {
  std::uint32_t address = 0;
  unsigned bit = 0;
  bool check_bit = false;
  std::string region; ///< "external", "on-chip" or "on-chip reserved"
  std::string buffer; ///< the block's label, or "free", "workspace of matching", ...
  std::optional<std::string> owner;
  emulator::UpsetEffect edac = emulator::UpsetEffect::flipped;
  friend bool operator==(const MemoryHitRecord&, const MemoryHitRecord&) = default;
};

/// A fault as it struck (or, when it never did, as it was drawn): its spec, time, and for a
/// memory fault the bit it hit, the region and buffer, and what it did there.
struct FaultRecord {
  overswitch::Fault::Kind kind = overswitch::Fault::Kind::hang;
  std::string module;
  double at_s = 0.0;
  std::string spec;   ///< in `--inject`'s grammar
  std::string effect; ///< what it did at once; empty when nothing is said
  std::optional<MemoryHitRecord> hit;
  friend bool operator==(const FaultRecord&, const FaultRecord&) = default;
};

/// The record of a fault that struck.
FaultRecord fault_record(const overswitch::InjectedFault& fault);
/// The record of a fault that never struck (the run ended first): its drawn time and spec.
FaultRecord drawn_fault_record(const overswitch::Fault& fault);

void to_json(nlohmann::ordered_json& json, const FaultRecord& record);
void from_json(const nlohmann::json& json, FaultRecord& record);

/// One run of a campaign: which, on which scene, its fault and its verdict.
struct RunRecord {
  std::uint64_t run = 0;
  std::uint64_t world_seed = 0;
  FaultRecord fault;
  FaultVerdict verdict;
  friend bool operator==(const RunRecord&, const RunRecord&) = default;
};

/// `run`, `world_seed`, `fault`, then the verdict's keys (docs/faults.md, "Campaigns").
void to_json(nlohmann::ordered_json& json, const RunRecord& record);
void from_json(const nlohmann::json& json, RunRecord& record);

/// A line of runs.jsonl read back; RecordError when it is not one.
RunRecord parse_run_record(std::string_view line);
/// The line of runs.jsonl for `record` (without its newline).
std::string run_record_line(const RunRecord& record);

} // namespace marsokhod::eval
