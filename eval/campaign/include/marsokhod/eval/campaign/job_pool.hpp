// Running a campaign's runs in parallel worker processes, their records gathered in run order.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace marsokhod::eval {

/// Runs `record(k)` for k in [first, last) in `jobs` forked worker processes (each takes every
/// jobs-th run; they share the parent's prepared scenes copy-on-write, and no emulator state
/// crosses a thread) and returns the records in run order, so that the result is the same for
/// any number of jobs. `record` returns one line (no newline in it). `progress(done)` (may be
/// empty) is called in the parent as records arrive. A worker that fails ends the whole call
/// with a CampaignRunError carrying its message, or naming the run it died on.
std::vector<std::string> run_in_jobs(std::uint64_t first, std::uint64_t last, int jobs,
                                     const std::function<std::string(std::uint64_t run)>& record,
                                     const std::function<void(std::uint64_t done)>& progress);

} // namespace marsokhod::eval
