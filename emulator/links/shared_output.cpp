// Turns at a shared link output: first come, first served, released even by a killed process.

#include "marsokhod/emulator/links/shared_output.hpp"

#include <algorithm>
#include <stdexcept>

namespace marsokhod::emulator {

/// A process's place at the output, from asking to having sent; its destructor (also when
/// the process is killed) gives the place up and hands the output to the next in line.
class SharedOutput::Turn {
public:
  Turn(SharedOutput& shared, Process& self) : shared_(shared), self_(self) {}
  Turn(const Turn&) = delete;
  Turn& operator=(const Turn&) = delete;
  ~Turn() {
    auto& waiting = shared_.waiting_;
    waiting.erase(std::remove(waiting.begin(), waiting.end(), &self_), waiting.end());
    if (shared_.holder_ != &self_)
      return;
    shared_.holder_ = nullptr;
    if (waiting.empty())
      return;
    shared_.holder_ = waiting.front();
    waiting.pop_front();
    shared_.port_->link().kernel().wake(*shared_.holder_);
  }

private:
  SharedOutput& shared_;
  Process& self_;
};

void SharedOutput::output(std::initializer_list<std::span<const std::byte>> parts,
                          const std::function<void()>& before_each) {
  Kernel& kernel = port_->link().kernel();
  Process* self = kernel.current();
  if (self == nullptr)
    throw std::logic_error(port_->name() + ": a shared output is only used from a process");
  Turn turn(*this, *self);
  if (holder_ == nullptr)
    holder_ = self;
  else
    waiting_.push_back(self);
  // The process giving its turn up hands it on directly, so no late asker jumps the line.
  while (holder_ != self)
    kernel.block(WaitInfo{WaitKind::link_output, this});
  for (const std::span<const std::byte> part : parts) {
    if (before_each)
      before_each();
    port_->output(part);
  }
}

std::string SharedOutput::describe() const {
  return "turn at " + port_->name() + "'s output";
}

} // namespace marsokhod::emulator
