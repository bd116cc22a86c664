#include "marsokhod/occam_port/par.hpp"

#include "marsokhod/emulator/node.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
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

/// The parent's end of a PAR: counts running branches, wakes the parent after the last one.
class Join : public emulator::ExitHook, public emulator::WaitTarget {
public:
  Join(Kernel& kernel, Process& parent) : kernel_(kernel), parent_(parent) {}
  Join(const Join&) = delete;
  Join& operator=(const Join&) = delete;
  ~Join() override {
    // The parent is being killed: its branches go with it (they refer to its stack).
    while (!children_.empty()) {
      Process* child = children_.back();
      children_.pop_back();
      kernel_.kill(*child);
    }
  }

  void started(Process& child) { children_.push_back(&child); }
  void on_exit(Process& child) override {
    children_.erase(std::find(children_.begin(), children_.end(), &child));
    // Only a parent waiting at the join may be woken: before that it is running its own
    // branch and may be blocked on something else entirely.
    if (children_.empty() && waiting_) {
      kernel_.wake(parent_);
    }
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
  std::vector<Process*> children_;
  bool waiting_ = false;
};

Process& current_process(const char* construct) {
  Kernel* kernel = Kernel::active();
  Process* p = kernel != nullptr ? kernel->current() : nullptr;
  if (p == nullptr) {
    throw std::logic_error(std::string(construct) + " used outside a simulated process");
  }
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
  // "parent.index", without a formatting library on this path: a PAR in a loop names its
  // branches every time round.
  std::string name;
  name.reserve(parent.name().size() + 4);
  name.append(parent.name());
  name.push_back('.');
  std::array<char, 24> digits{};
  const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), index).ptr;
  name.append(digits.data(), end);
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
  if (branches.empty()) {
    return;
  }
  Process& parent = current_process("PAR");
  Node& node = Node::current();
  Join join(node.kernel(), parent);
  const std::size_t started = branches.size() - 1;
  node.execute(Instruction::startp, started);
  for (std::size_t i = 0; i < started; ++i) {
    start_branch(node, join, parent, i, branches[i], parent.priority(), options);
  }
  branches.back()();
  node.execute(Instruction::endp);
  join.wait();
}

void par_for(std::size_t count, const std::function<void(std::size_t)>& body,
             const ParOptions& options) {
  std::vector<std::function<void()>> branches;
  branches.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    branches.emplace_back([&body, i] { body(i); });
  }
  par(std::span<const std::function<void()>>(branches), options);
}

void pri_par(const std::function<void()>& high, const std::function<void()>& low,
             const ParOptions& options) {
  Process& parent = current_process("PRI PAR");
  Node& node = Node::current();
  Join join(node.kernel(), parent);
  node.execute(Instruction::startp);
  start_branch(node, join, parent, 0, high, Priority::high, options);
  low();
  node.execute(Instruction::endp);
  join.wait();
}

} // namespace marsokhod::occam_port
