// Simulated processes: the names of what they wait for, and the process record.

#include "marsokhod/emulator/kernel/process.hpp"

#include "fibers/fiber.hpp"

namespace marsokhod::emulator {

const char* to_string(WaitKind kind) {
  switch (kind) {
  case WaitKind::none:
    return "nothing";
  case WaitKind::channel_input:
    return "channel input";
  case WaitKind::channel_output:
    return "channel output";
  case WaitKind::timer:
    return "timer";
  case WaitKind::alt:
    return "ALT";
  case WaitKind::par_join:
    return "PAR join";
  case WaitKind::link_input:
    return "link input";
  case WaitKind::link_output:
    return "link output";
  case WaitKind::other:
    return "other";
  }
  return "?";
}

Process::Process(Cpu& cpu, std::string&& name, std::uint64_t id, Priority priority)
    : cpu_(&cpu), priority_(priority), id_(id), name_(std::move(name)) {}

Process::~Process() = default;

} // namespace marsokhod::emulator
