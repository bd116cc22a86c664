// PAR, replicated PAR and PRI PAR: startp/endp and the join of started branches.

#include "marsokhod/occam_port/par.hpp"

#include "marsokhod/emulator/node/node.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::occam_port {

namespace {

using emulator::Instruction;
using emulator::Kernel;
using emulator::Node;
using emulator::Priority;
using emulator::Process;

/// The started branches of a PAR that are still running, oldest first. A PAR knows how many
/// it starts; up to a few the list lives on the parent's stack, so that a PAR in a loop costs
/// no trip to the heap.
class RunningBranches {
public:
  explicit RunningBranches(std::size_t capacity) {
    if (capacity > inline_.size()) {
      heap_ = std::make_unique<Process*[]>(capacity);
      data_ = heap_.get();
    }
    capacity_ = capacity;
  }
  RunningBranches(const RunningBranches&) = delete;
  RunningBranches& operator=(const RunningBranches&) = delete;

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  void push_back(Process* p) {
    if (size_ == capacity_)
      throw std::logic_error("PAR started more branches than it announced");
    data_[size_++] = p;
  }
  Process* pop_back() { return data_[--size_]; }
  void erase(const Process* p) {
    Process** end = data_ + size_;
    Process** at = std::find(data_, end, p);
    if (at != end) {
      std::copy(at + 1, end, at);
      --size_;
    }
  }

private:
  std::array<Process*, 8> inline_{};
  std::unique_ptr<Process*[]> heap_;
  Process** data_ = inline_.data();
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

/// The parent's end of a PAR: counts running branches, wakes the parent after the last one.
class Join : public emulator::ExitHook, public emulator::WaitTarget {
public:
  Join(Kernel& kernel, Process& parent, std::size_t branches)
      : kernel_(kernel), parent_(parent), children_(branches) {}
  Join(const Join&) = delete;
  Join& operator=(const Join&) = delete;
  ~Join() override {
    // The parent is being killed: its branches go with it (they refer to its stack).
    while (!children_.empty())
      kernel_.kill(*children_.pop_back());
  }

  void started(Process& child) { children_.push_back(&child); }
  void on_exit(Process& child) override {
    children_.erase(&child);
    // Only a parent waiting at the join may be woken: before that it is running its own
    // branch and may be blocked on something else entirely.
    if (children_.empty() && waiting_)
      kernel_.wake(parent_);
  }
  std::string describe() const override {
    return fmt::format("PAR join of {} ({} branch{} running)", parent_.name(), children_.size(),
                       children_.size() == 1 ? "" : "es");
  }
  void wait() {
    if (!children_.empty()) {
      waiting_ = true;
      kernel_.block(emulator::WaitInfo{emulator::WaitKind::par_join, this});
      waiting_ = false;
    }
  }

private:
  Kernel& kernel_;
  Process& parent_;
  RunningBranches children_;
  bool waiting_ = false;
};

Process& current_process(const char* construct) {
  Kernel* kernel = Kernel::active();
  Process* p = kernel != nullptr ? kernel->current() : nullptr;
  if (p == nullptr)
    throw std::logic_error(std::string(construct) + " used outside a simulated process");
  return *p;
}

/// Starts branch `index` of `parent`'s PAR as a process of `priority`.
void start_branch(Node& node, Join& join, const Process& parent, std::size_t index,
                  const std::function<void()>& branch, Priority priority,
                  const ParOptions& options) {
  emulator::NodeSpawnOptions spawn;
  spawn.priority = priority;
  spawn.stack_bytes = options.stack_bytes;
  spawn.workspace_bytes = options.workspace_bytes;
  spawn.exit_hook = &join;
  // "parent.index", written in place into a string made at its final length: a PAR in a
  // loop names its branches every time round.
  std::array<char, 24> digits{};
  const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), index).ptr;
  const std::string& base = parent.name();
  std::string name(base.size() + 1 + static_cast<std::size_t>(end - digits.data()), '.');
  std::copy(base.begin(), base.end(), name.begin());
  std::copy(digits.data(), end, name.begin() + static_cast<std::ptrdiff_t>(base.size()) + 1);
  Process& child = node.spawn(
      std::move(name),
      [&node, &branch] {
        branch();
        node.execute(Instruction::endp);
      },
      spawn);
  join.started(child);
}

} // namespace

void par(std::span<const std::function<void()>> branches, const ParOptions& options) {
  if (branches.empty())
    return;
  Process& parent = current_process("PAR");
  Node& node = Node::current();
  const std::size_t started = branches.size() - 1;
  Join join(node.kernel(), parent, started);
  node.execute(Instruction::startp, started);
  for (std::size_t i = 0; i < started; ++i)
    start_branch(node, join, parent, i, branches[i], parent.priority(), options);
  branches.back()();
  node.execute(Instruction::endp);
  join.wait();
}

void par_for(std::size_t count, const std::function<void(std::size_t)>& body,
             const ParOptions& options) {
  std::vector<std::function<void()>> branches;
  branches.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
    branches.emplace_back([&body, i] { body(i); });
  par(std::span<const std::function<void()>>(branches), options);
}

void pri_par(const std::function<void()>& high, const std::function<void()>& low,
             const ParOptions& options) {
  Process& parent = current_process("PRI PAR");
  Node& node = Node::current();
  Join join(node.kernel(), parent, 1);
  node.execute(Instruction::startp);
  start_branch(node, join, parent, 0, high, Priority::high, options);
  low();
  node.execute(Instruction::endp);
  join.wait();
}

} // namespace marsokhod::occam_port
