// Every live process, oldest first, and the memory of deleted ones kept for reuse.

#include "kernel/process_registry.hpp"

#include <new>
#include <utility>

namespace marsokhod::emulator::detail {

ProcessRegistry::~ProcessRegistry() {
  while (oldest_ != nullptr)
    remove_and_delete(oldest_);
  for (void* memory : spare_)
    ::operator delete(memory);
}

Process* ProcessRegistry::create(Cpu& cpu, std::string&& name, std::uint64_t id,
                                 Priority priority) {
  void* memory = nullptr;
  if (spare_.empty()) {
    memory = ::operator new(sizeof(Process));
  } else {
    memory = spare_.back();
    spare_.pop_back();
  }
  // The constructor only moves a string and stores scalars: it does not throw.
  return new (memory) Process(cpu, std::move(name), id, priority);
}

void ProcessRegistry::destroy(Process* p) {
  p->~Process();
  if (spare_.size() >= kMaxSpare) {
    ::operator delete(p);
    return;
  }
  spare_.push_back(p);
}

void ProcessRegistry::add(Process* p) {
  p->older_ = newest_;
  p->newer_ = nullptr;
  (newest_ != nullptr ? newest_->newer_ : oldest_) = p;
  newest_ = p;
}

void ProcessRegistry::remove_and_delete(Process* p) {
  (p->older_ != nullptr ? p->older_->newer_ : oldest_) = p->newer_;
  (p->newer_ != nullptr ? p->newer_->older_ : newest_) = p->older_;
  destroy(p);
}

} // namespace marsokhod::emulator::detail
