// Rig files: reading a TOML rig description into a StereoRig, and writing one back.

#include "rig/rig_fields.hpp"

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/imaging/rig/toml_document.hpp"
#include "marsokhod/io/formats/toml_file.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <string_view>

namespace marsokhod::imaging {
namespace {

constexpr std::string_view kRigTable = "rig";
constexpr std::string_view kMisalignmentKey = "right_misalignment";
constexpr std::string_view kMisalignmentTable = "rig.right_misalignment";

/// Reads a rig file and reports every problem as a RigError naming the file and the line.
class RigFileReader {
public:
  explicit RigFileReader(const std::filesystem::path& path) : document_(path, "rig") {}

  RigParameters read() const {
    const toml::table document = document_.parse();
    const toml::node* rig = nullptr;
    for (auto&& [key, node] : document) {
      if (key.str() != kRigTable)
        fail(key.source(),
             fmt::format("unknown key '{}' (a rig file has one [rig] table)", key.str()));
      rig = &node;
    }
    if (rig == nullptr)
      document_.fail("no [rig] table");
    RigParameters parameters;
    read_table(*rig, kRigTable, parameters);
    return parameters;
  }

private:
  [[noreturn]] void fail(const toml::source_region& where, const std::string& problem) const {
    document_.fail(where, problem);
  }

  const toml::table& as_table(const toml::node& node, std::string_view name) const {
    if (!node.is_table())
      fail(node.source(),
           fmt::format("key '{}' must be a table (got {})", name, io::toml_type_name(node.type())));
    return *node.as_table();
  }

  void read_table(const toml::node& node, std::string_view name, RigParameters& out) const {
    for (auto&& [key, value] : as_table(node, name)) {
      if (name == kRigTable && key.str() == kMisalignmentKey) {
        read_table(value, kMisalignmentTable, out);
        continue;
      }
      read_value(find_field(name, key), value, out);
    }
  }

  const detail::RigField& find_field(std::string_view table, const toml::key& key) const {
    std::string known;
    for (const detail::RigField& field : detail::rig_fields()) {
      if (field.table != table)
        continue;
      if (field.key == key.str())
        return field;
      known += known.empty() ? "" : ", ";
      known += field.key;
    }
    if (table == kRigTable)
      known += fmt::format(", [{}]", kMisalignmentTable);
    fail(key.source(),
         fmt::format("unknown key '{}.{}' (known keys: {})", table, key.str(), known));
  }

  void read_value(const detail::RigField& field, const toml::node& node, RigParameters& out) const {
    const std::string name = fmt::format("{}.{}", field.table, field.key);
    const bool number_ok = node.is_integer() || (!field.integer && node.is_floating_point());
    if (!number_ok)
      fail(node.source(),
           fmt::format("key '{}' must be {} (got {})", name,
                       field.integer ? "an integer" : "a number", io::toml_type_name(node.type())));
    const double value = node.is_integer() ? static_cast<double>(node.as_integer()->get())
                                           : node.as_floating_point()->get();
    if (auto problem = detail::rig_value_problem(field, value))
      fail(node.source(), fmt::format("key '{}' {}", name, *problem));
    field.set(out, value);
  }

  detail::TomlDocument<RigError> document_;
};

} // namespace

using detail::toml_float;

StereoRig StereoRig::load(const std::filesystem::path& path) {
  const RigParameters parameters = RigFileReader(path).read();
  try {
    return StereoRig(parameters);
  } catch (const RigError& error) {
    throw RigError(fmt::format("{}: {}", path.string(), error.what()));
  }
}

std::string StereoRig::to_toml() const {
  const RigParameters& p = parameters_;
  const Misalignment& m = p.right_misalignment;
  return fmt::format("# Stereo rig (format: docs/formats.md, \"Rig files\").\n"
                     "[rig]\n"
                     "mast_height_m = {}\n"
                     "mast_forward_m = {}\n"
                     "pitch_down_deg = {}\n"
                     "focal_mm = {}\n"
                     "sensor_mm = {}\n"
                     "baseline_m = {}\n"
                     "width_px = {}\n"
                     "height_px = {}\n"
                     "\n"
                     "[rig.right_misalignment]\n"
                     "pan_arcsec = {}\n"
                     "tilt_arcsec = {}\n"
                     "roll_arcsec = {}\n",
                     toml_float(p.mast_height_m), toml_float(p.mast_forward_m),
                     toml_float(p.pitch_down_deg), toml_float(p.focal_mm), toml_float(p.sensor_mm),
                     toml_float(p.baseline_m), p.width_px, p.height_px, toml_float(m.pan_arcsec),
                     toml_float(m.tilt_arcsec), toml_float(m.roll_arcsec));
}

} // namespace marsokhod::imaging
