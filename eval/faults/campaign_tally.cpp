// Counting the run records: outcomes by class, fault kind, memory region and buffer.

#include "marsokhod/eval/faults/campaign_tally.hpp"

#include <cctype>

namespace marsokhod::eval {

std::uint64_t OutcomeCounts::total() const {
  std::uint64_t sum = 0;
  for (const std::uint64_t n : runs)
    sum += n;
  return sum;
}

OutcomeCounts& OutcomeCounts::operator+=(const OutcomeCounts& other) {
  for (std::size_t i = 0; i < runs.size(); ++i)
    runs[i] += other.runs[i];
  return *this;
}

std::string buffer_group(const std::string& buffer) {
  for (std::size_t comma = buffer.rfind(", "); comma != std::string::npos && comma > 0;
       comma = buffer.rfind(", ", comma - 1))
    if (comma + 2 < buffer.size() && std::isdigit(static_cast<unsigned char>(buffer[comma + 2])))
      return buffer.substr(0, comma);
  return buffer;
}

void count_run(CampaignTally& t, const RunRecord& record) {
  const FaultVerdict& v = record.verdict;
  const Outcome outcome = v.outcome;
  ++t.runs;
  ++t.outcomes[outcome];
  ++t.by_kind[overswitch::to_string(record.fault.kind)][outcome];
  if (const std::optional<MemoryHitRecord>& hit = record.fault.hit) {
    ++t.by_region[hit->region][outcome];
    ++t.by_buffer[buffer_group(hit->buffer)][outcome];
    t.edac_corrected += hit->edac == emulator::UpsetEffect::corrected ? 1 : 0;
  }
  if (v.golden_unsafe)
    ++t.golden_unsafe_runs;
  else
    ++t.judged;
  t.unsafe += outcome == Outcome::unsafe ? 1 : 0;
  t.activated += v.activated ? 1 : 0;
  if (v.detected) {
    ++t.detected;
    t.detected_activated += v.activated ? 1 : 0;
    if (v.detection_latency_s)
      t.detection_latency_s.push_back(*v.detection_latency_s);
  }
  t.telemetry_lost += v.telemetry_lost ? 1 : 0;
  t.wheels_commanded_while_failed += v.wheels_commanded_while_failed ? 1 : 0;
  t.path_equals_golden += v.path_equals_golden ? 1 : 0;
}

CampaignTally tally(std::span<const RunRecord> records) {
  CampaignTally t;
  for (const RunRecord& record : records)
    count_run(t, record);
  return t;
}

} // namespace marsokhod::eval
