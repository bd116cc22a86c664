// A fault and a run as their records give them, and back.

#include "marsokhod/eval/faults/fault_record.hpp"

#include "faults/record_keys.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>

namespace marsokhod::eval {
namespace {

namespace emu = emulator;
using detail::optional_record_value;
using detail::record_value;
using Json = nlohmann::ordered_json;

emu::UpsetEffect upset_effect(const std::string& name) {
  for (const emu::UpsetEffect effect :
       {emu::UpsetEffect::flipped, emu::UpsetEffect::corrected, emu::UpsetEffect::uncorrectable})
    if (name == emu::to_string(effect))
      return effect;
  throw RecordError("the record's 'edac' '" + name +
                    "' is none of flipped, corrected, "
                    "uncorrectable");
}

// "#8000A010", as the T805's data book writes addresses.
std::uint32_t address_of(const std::string& text) {
  std::uint32_t address = 0;
  const char* end = text.data() + text.size();
  if (text.size() == 9 && text.front() == '#') {
    const auto [stop, error] = std::from_chars(text.data() + 1, end, address, 16);
    if (error == std::errc() && stop == end)
      return address;
  }
  throw RecordError("the record's 'address' '" + text + "' is no #XXXXXXXX address");
}

overswitch::Fault::Kind kind_of(const nlohmann::json& j) {
  const auto name = record_value<std::string>(j, "kind");
  if (const std::optional<overswitch::Fault::Kind> kind = overswitch::parse_fault_kind(name))
    return *kind;
  throw RecordError("the record's 'kind' '" + name + "' is no fault kind (" +
                    overswitch::fault_kind_names() + ")");
}

} // namespace

FaultRecord fault_record(const overswitch::InjectedFault& f) {
  FaultRecord r{f.fault.kind, f.fault.module, emu::to_seconds(f.at), overswitch::describe(f.fault),
                f.effect,     std::nullopt};
  if (!f.hit)
    return r;
  const overswitch::MemoryHit& hit = *f.hit;
  r.hit = MemoryHitRecord{static_cast<std::uint32_t>(hit.address),
                          hit.bit,
                          hit.check_bit,
                          hit.region(),
                          hit.buffer(),
                          hit.block ? std::optional(hit.block->owner) : std::nullopt,
                          hit.effect};
  return r;
}

FaultRecord drawn_fault_record(const overswitch::Fault& fault) {
  return {fault.kind, fault.module, emu::to_seconds(fault.offset), overswitch::describe(fault),
          {},         std::nullopt};
}

void to_json(Json& j, const FaultRecord& r) {
  j["kind"] = overswitch::to_string(r.kind);
  j["module"] = r.module;
  j["at_s"] = r.at_s;
  j["spec"] = r.spec;
  if (!r.effect.empty())
    j["effect"] = r.effect;
  if (!r.hit)
    return;
  j["address"] = fmt::format("#{:08X}", r.hit->address);
  j["bit"] = r.hit->bit;
  j["check_bit"] = r.hit->check_bit;
  j["region"] = r.hit->region;
  j["buffer"] = r.hit->buffer;
  j["owner"] = detail::or_null(r.hit->owner);
  j["edac"] = emu::to_string(r.hit->edac);
}

void from_json(const nlohmann::json& j, FaultRecord& r) {
  r.kind = kind_of(j);
  r.module = record_value<std::string>(j, "module");
  r.at_s = record_value<double>(j, "at_s");
  r.spec = record_value<std::string>(j, "spec");
  r.effect = optional_record_value<std::string>(j, "effect", true).value_or("");
  r.hit.reset();
  if (!j.contains("address"))
    return;
  r.hit = MemoryHitRecord{address_of(record_value<std::string>(j, "address")),
                          record_value<unsigned>(j, "bit"),
                          record_value<bool>(j, "check_bit"),
                          record_value<std::string>(j, "region"),
                          record_value<std::string>(j, "buffer"),
                          optional_record_value<std::string>(j, "owner"),
                          upset_effect(record_value<std::string>(j, "edac"))};
}

void to_json(Json& j, const RunRecord& r) {
  j["run"] = r.run;
  j["world_seed"] = r.world_seed;
  to_json(j["fault"], r.fault);
  to_json(j, r.verdict);
}

void from_json(const nlohmann::json& j, RunRecord& r) {
  r.run = record_value<std::uint64_t>(j, "run");
  r.world_seed = record_value<std::uint64_t>(j, "world_seed");
  from_json(record_value<nlohmann::json>(j, "fault"), r.fault);
  from_json(j, r.verdict);
}

RunRecord parse_run_record(std::string_view line) {
  const nlohmann::json json = nlohmann::json::parse(line, nullptr, false);
  if (json.is_discarded() || !json.is_object())
    throw RecordError("a run record is one JSON object on a line");
  RunRecord record;
  from_json(json, record);
  return record;
}

std::string run_record_line(const RunRecord& record) {
  Json json;
  to_json(json, record);
  return json.dump();
}

} // namespace marsokhod::eval
