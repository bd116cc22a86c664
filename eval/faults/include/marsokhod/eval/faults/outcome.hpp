// The outcome classes of a fault run (docs/faults.md, "Outcome classes").
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace marsokhod::eval {

/// The class of a fault run's outcome, in the order reports list them (outcome_list.def).
enum class Outcome : std::uint8_t {
#define MARSOKHOD_OUTCOME(name, meaning) name,
#include "marsokhod/eval/faults/outcome_list.def"
};

/// Every class, in outcome_list.def's order.
inline constexpr std::array kOutcomes{
#define MARSOKHOD_OUTCOME(name, meaning) Outcome::name,
#include "marsokhod/eval/faults/outcome_list.def"
};

/// The class's name in records and reports ("masked", "sdc_safe", ...).
const char* to_string(Outcome outcome);
/// What the class means, in a sentence.
const char* meaning(Outcome outcome);
/// The class named `name`; nothing when no class has that name.
std::optional<Outcome> parse_outcome(std::string_view name);

} // namespace marsokhod::eval
