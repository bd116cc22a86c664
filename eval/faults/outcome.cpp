// The outcome classes' names and meanings, from outcome_list.def.

#include "marsokhod/eval/faults/outcome.hpp"

namespace marsokhod::eval {
namespace {

struct OutcomeEntry {
  const char* name;
  const char* meaning;
};

constexpr std::array kEntries{
#define MARSOKHOD_OUTCOME(name, meaning) OutcomeEntry{#name, meaning},
#include "marsokhod/eval/faults/outcome_list.def"
};

} // namespace

const char* to_string(Outcome outcome) {
  return kEntries[static_cast<std::size_t>(outcome)].name;
}

const char* meaning(Outcome outcome) {
  return kEntries[static_cast<std::size_t>(outcome)].meaning;
}

std::optional<Outcome> parse_outcome(std::string_view name) {
  for (const Outcome outcome : kOutcomes)
    if (name == to_string(outcome))
      return outcome;
  return std::nullopt;
}

} // namespace marsokhod::eval
