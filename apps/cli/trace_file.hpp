// A Chrome trace written to a file while the emulator runs, with every write failure reported.
#pragma once

#include "marsokhod/emulator/trace/chrome_trace.hpp"

#include <fstream>
#include <string>

namespace marsokhod::apps {

/// Opens `path` for a trace; a CommandError naming the file and why when it cannot be.
std::ofstream open_trace_file(const std::string& path);

/// Closes the trace and its file; a CommandError naming the file when any write failed (a full
/// disk shows at the last flush at the latest).
void close_trace_file(emulator::ChromeTraceWriter& writer, std::ofstream& out,
                      const std::string& path);

/// Runs `run(writer)` with a trace writer streaming into `path`, then closes it checked. A
/// trace can be far larger than memory allows to hold, so it is streamed, not written at once.
template <class Run>
auto with_trace_file(const std::string& path, Run run) {
  std::ofstream out = open_trace_file(path);
  emulator::ChromeTraceWriter writer(out);
  auto result = run(writer);
  close_trace_file(writer, out, path);
  return result;
}

} // namespace marsokhod::apps
