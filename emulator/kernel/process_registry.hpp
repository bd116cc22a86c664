// Every live process, oldest first, and the memory of deleted ones kept for reuse.
#pragma once

#include "marsokhod/emulator/kernel/process.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace marsokhod::emulator::detail {

/// Every process not yet deleted, oldest first (intrusive, so that listing them costs no
/// allocation), and the memory of deleted ones kept for the next: a PAR in a loop creates and
/// deletes a process every time round, which then costs no trip to the heap.
class ProcessRegistry {
public:
  ProcessRegistry() = default;
  ProcessRegistry(const ProcessRegistry&) = delete;
  ProcessRegistry& operator=(const ProcessRegistry&) = delete;
  ~ProcessRegistry();

  /// A new process, not yet listed.
  Process* create(Cpu& cpu, std::string&& name, std::uint64_t id, Priority priority);
  /// Deletes a process that create() made and add() did not list.
  void destroy(Process* p);
  void add(Process* p);
  void remove_and_delete(Process* p);

  Process* oldest() const { return oldest_; }
  static Process* newer(const Process* p) { return p->newer_; }
  Process* newest() const { return newest_; }
  static Process* older(const Process* p) { return p->older_; }

private:
  static constexpr std::size_t kMaxSpare = 256;

  Process* oldest_ = nullptr;
  Process* newest_ = nullptr;
  std::vector<void*> spare_; // memory for a Process, not constructed
};

} // namespace marsokhod::emulator::detail
