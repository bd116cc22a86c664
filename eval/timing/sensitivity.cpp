// The sensitivity table: each parameter the paper leaves open over its period values.

#include "marsokhod/eval/timing/sensitivity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>

namespace marsokhod::eval {
namespace {

namespace emu = emulator;

/// A parameter: its value in the platforms, its period values (docs/timing.md gives the
/// sources), the label of a value and how a value is set on the platforms.
struct Parameter {
  std::string name;
  std::function<std::string(const emu::PlatformSpec& card, const emu::PlatformSpec& onboard)>
      shipped;
  std::vector<std::string> values;
  std::function<void(const std::string& value, emu::PlatformSpec& card, emu::PlatformSpec& onboard)>
      set;
  std::function<std::string(const std::string& value)> label;
};

void each_node(emu::PlatformSpec& platform, const std::function<void(emu::NodeSpec&)>& f) {
  for (emu::NodeSpec& node : platform.nodes)
    f(node);
}

// The processor file's grades, fastest first.
Parameter card_grade(const emu::PlatformSpec& card) {
  std::vector<std::pair<emu::Tick, std::string>> grades;
  for (const auto& [grade, cycle] : card.speed_grades)
    grades.emplace_back(cycle, grade);
  std::sort(grades.begin(), grades.end());
  std::vector<std::string> values;
  for (const auto& [cycle, grade] : grades)
    values.push_back(grade);
  return {"PC card speed grade",
          [](const emu::PlatformSpec& c, const emu::PlatformSpec&) {
            return c.nodes.front().speed_grade;
          },
          values,
          [](const std::string& grade, emu::PlatformSpec& c, emu::PlatformSpec&) {
            const emu::Tick cycle = c.speed_grades.at(grade);
            each_node(c, [&](emu::NodeSpec& n) {
              n.speed_grade = grade;
              n.cpu.cycle = cycle;
            });
          },
          [](const std::string& grade) { return grade; }};
}

// External memory takes 3 cycles with no wait state (T805 datasheet); each wait state adds one.
// The card's memory is DRAM (docs/timing.md), the onboard modules' of a kind the paper leaves
// open.
Parameter wait_states(bool on_card) {
  return {on_card ? "PC card memory wait states" : "onboard memory wait states",
          [on_card](const emu::PlatformSpec& c, const emu::PlatformSpec& o) {
            return fmt::format("{}", (on_card ? c : o).nodes.front().cpu.costs.wait_states);
          },
          {"0", "1", "2"},
          [on_card](const std::string& value, emu::PlatformSpec& c, emu::PlatformSpec& o) {
            const int waits = std::stoi(value);
            each_node(
                on_card ? c : o, [waits](emu::NodeSpec& n) { n.cpu.costs.wait_states = waits; });
          },
          [on_card](const std::string& value) {
            if (value == "0")
              return std::string("0 (3-cycle)");
            return on_card ? fmt::format("{} ({}-cycle DRAM)", value, 3 + std::stoi(value)) : value;
          }};
}

Parameter card_memory() {
  return {"PC card memory",
          [](const emu::PlatformSpec& c, const emu::PlatformSpec&) {
            return fmt::format("{}", c.nodes.front().memory.external_bytes / 1024);
          },
          {"1024", "2048", "4096"},
          [](const std::string& value, emu::PlatformSpec& c, emu::PlatformSpec&) {
            const std::size_t kb = std::stoul(value);
            each_node(
                c, [kb](emu::NodeSpec& n) { n.memory.external_bytes = kb * 1024; });
          },
          [](const std::string& value) { return fmt::format("{} MB", std::stoul(value) / 1024); }};
}

Parameter link_speed() {
  return {"link speed",
          [](const emu::PlatformSpec& c, const emu::PlatformSpec&) {
            return fmt::format("{}", c.wires.front().speed_mbps);
          },
          {"10", "20"},
          [](const std::string& value, emu::PlatformSpec& c, emu::PlatformSpec& o) {
            const int mbps = std::stoi(value);
            for (emu::PlatformSpec* p : {&c, &o})
              for (emu::WireSpec& wire : p->wires)
                wire.speed_mbps = mbps;
          },
          [](const std::string& value) { return value + " Mbit/s"; }};
}

// The shipped value first, then the period values in their order.
void add_rows(std::vector<SensitivityRow>& rows, const Parameter& p, const TimingModel& model,
              double occam_style, const ModelFigures& shipped) {
  const std::string as_shipped = p.shipped(model.card(), model.onboard());
  rows.push_back({p.name, p.label(as_shipped), true, shipped});
  for (const std::string& value : p.values) {
    if (value == as_shipped)
      continue;
    emu::PlatformSpec card = model.card();
    emu::PlatformSpec onboard = model.onboard();
    p.set(value, card, onboard);
    rows.push_back({p.name, p.label(value), false, model.figures(card, onboard, occam_style)});
  }
}

} // namespace

std::vector<SensitivityRow> sensitivity(const TimingModel& model, double occam_style,
                                        const ModelFigures& shipped) {
  std::vector<SensitivityRow> rows;
  for (const Parameter& p : {card_grade(model.card()), wait_states(true), card_memory(),
                             wait_states(false), link_speed()})
    add_rows(rows, p, model, occam_style, shipped);
  for (const double factor : {0.9, 1.1})
    rows.push_back({"occam style factor (fitted)",
                    fmt::format("{:.3f} (x{:.1f})", occam_style * factor, factor), false,
                    model.figures(model.card(), model.onboard(), occam_style * factor)});
  return rows;
}

} // namespace marsokhod::eval
