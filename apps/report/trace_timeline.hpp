// The emulated timeline of a cycle: each node's lanes over emulated time, from its trace.json.
#pragma once

#include <filesystem>
#include <string>

namespace marsokhod::apps {

/// Most spans a timeline draws; a trace with more draws its first ones and says so.
inline constexpr std::size_t kMaxTimelineSpans = 20000;

/// A Chart.js chart of the Chrome trace `trace` (what `emulate --trace` writes): one lane per
/// node and track (its CPU's processes, each stage, each link's direction), a bar for every
/// span from its begin to its end event, its name and times on hover, and two sliders that
/// zoom on a stretch of time. Empty when the trace holds no span; CommandError naming the file
/// when it is not a Chrome trace.
std::string timeline_chart(const std::filesystem::path& trace, const std::string& id);

} // namespace marsokhod::apps
