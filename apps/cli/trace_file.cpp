// Opening and closing trace files with the reason of any failure in the message.
#include "cli/trace_file.hpp"

#include "cli/command.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>

namespace marsokhod::apps {
namespace {

std::string reason(int error) {
  return error != 0 ? std::string(": ") + std::strerror(error) : std::string();
}

} // namespace

std::ofstream open_trace_file(const std::string& path) {
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out)
    throw CommandError(fmt::format("{}: cannot write the trace file{}", path, reason(errno)));
  return out;
}

void close_trace_file(emulator::ChromeTraceWriter& writer, std::ofstream& out,
                      const std::string& path) {
  writer.close();
  errno = 0;
  out.close();
  if (!out)
    throw CommandError(fmt::format("{}: writing the trace failed{}", path, reason(errno)));
}

} // namespace marsokhod::apps
