// The kinds of fault, their names and what each strikes, from fault_kinds.def.

#include "marsokhod/overswitch/faults/fault.hpp"

#include <array>

namespace marsokhod::overswitch {
namespace {

struct KindEntry {
  Fault::Kind kind;
  const char* name;
  FaultClass fault_class;
};

constexpr std::array kKinds{
#define MARSOKHOD_FAULT_KIND(enumerator, name, fault_class)                                        \
  KindEntry{Fault::Kind::enumerator, name, FaultClass::fault_class},
#include "marsokhod/overswitch/faults/fault_kinds.def"
};

constexpr std::array kAllKinds{
#define MARSOKHOD_FAULT_KIND(enumerator, name, fault_class) Fault::Kind::enumerator,
#include "marsokhod/overswitch/faults/fault_kinds.def"
};

const KindEntry& entry(Fault::Kind kind) {
  return kKinds[static_cast<std::size_t>(kind)];
}

} // namespace

std::span<const Fault::Kind> fault_kinds() {
  return kAllKinds;
}

const char* to_string(Fault::Kind kind) {
  return entry(kind).name;
}

std::optional<Fault::Kind> parse_fault_kind(std::string_view name) {
  for (const KindEntry& e : kKinds)
    if (name == e.name)
      return e.kind;
  return std::nullopt;
}

std::string fault_kind_names() {
  std::string names;
  for (const KindEntry& e : kKinds)
    names.append(names.empty() ? "" : ", ").append(e.name);
  return names;
}

FaultClass fault_class(Fault::Kind kind) {
  return entry(kind).fault_class;
}

bool is_memory_fault(Fault::Kind kind) {
  return fault_class(kind) == FaultClass::memory;
}

bool is_link_fault(Fault::Kind kind) {
  return fault_class(kind) == FaultClass::link;
}

bool stops_module(Fault::Kind kind) {
  return fault_class(kind) == FaultClass::module;
}

} // namespace marsokhod::overswitch
