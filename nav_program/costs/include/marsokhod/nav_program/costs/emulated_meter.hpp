// EmulatedMeter: the nav kernels' work reports turned into CPU time on an emulated node.
#pragma once

#include "marsokhod/emulator/kernel/time.hpp"
#include "marsokhod/nav/work/work.hpp"

#include <array>
#include <cstdint>

namespace marsokhod::emulator {
class Node;
} // namespace marsokhod::emulator

namespace marsokhod::nav_program {

/// The meter a nav kernel reports to when it runs inside an emulated process (contract 1 of the
/// design): every report of n units of a Work kind charges the current process n times that
/// kind's cycles from the cost table (work_costs.hpp) on its node, with the buffer accesses in
/// external memory when the process's buffers were placed there. It also counts the reports
/// per kind, so that the work done inside the emulation can be compared with a native run's.
class EmulatedMeter final : public nav::DynamicMeter {
public:
  /// `occam_style`: the cycles of the program's occam per unit over the cost table's
  /// (work_costs.hpp, kOccamStyleFactor).
  EmulatedMeter(emulator::Node& node, bool buffers_external, double occam_style);

  void operator()(nav::Work kind, std::uint64_t count) override;

  const nav::CountingMeter& counts() const { return counts_; }
  /// Simulated CPU time charged so far.
  emulator::Tick charged() const { return charged_; }
  /// Cycles one unit of a kind costs on this node.
  std::uint64_t cycles_per_unit(nav::Work kind) const {
    return cycles_per_unit_[static_cast<std::size_t>(kind)];
  }

private:
  emulator::Node* node_;
  std::array<std::uint64_t, nav::kWorkKinds> cycles_per_unit_{};
  nav::CountingMeter counts_;
  emulator::Tick charged_ = 0;
};

} // namespace marsokhod::nav_program
