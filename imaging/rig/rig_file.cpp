// Rig files: reading a TOML rig description into a StereoRig, and writing one back.

#include "rig/rig_fields.hpp"

#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/io/formats/toml_file.hpp"
#include "marsokhod/io/formats/toml_float.hpp"
#include "marsokhod/io/formats/toml_table.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace marsokhod::imaging {
namespace {

constexpr std::string_view kRigTable = "rig";
constexpr std::string_view kMisalignmentKey = "right_misalignment";
constexpr std::string_view kMisalignmentTable = "rig.right_misalignment";

/// A table of a rig file whose errors are RigFileErrors naming its keys in full
/// ('rig.baseline_m'); `name` is the table's ("rig", "rig.right_misalignment"), empty for the
/// whole file.
io::TomlTable rig_table(const toml::table& table, const std::string& file, std::string_view name) {
  return io::TomlTable(table, file, "", io::throw_keyed<RigFileError>, std::string(name));
}

/// Refuses a key that is no field of the table `name` (nor, in [rig], its sub-table), listing
/// the known ones.
void reject_unknown_keys(io::TomlTable& table, std::string_view name) {
  std::string known;
  for (const detail::RigField& field : detail::rig_fields()) {
    if (field.table != name)
      continue;
    table.expect_keys({field.key});
    known += known.empty() ? "" : ", ";
    known += field.key;
  }
  if (name == kRigTable) {
    table.expect_keys({kMisalignmentKey});
    known += fmt::format(", [{}]", kMisalignmentTable);
  }
  table.reject_unknown_keys(fmt::format("unknown key (known keys: {})", known));
}

/// The fields of the table `name` that the file gives, each in the range rig_fields() sets;
/// the others keep their values in `out`. Integers are checked before they are narrowed.
void read_fields(io::TomlTable& table, std::string_view name, RigParameters& out) {
  reject_unknown_keys(table, name);
  for (const detail::RigField& field : detail::rig_fields()) {
    if (field.table != name || !table.table().contains(field.key))
      continue;
    if (field.integer)
      field.set(out, table.integer_in(field.key, static_cast<int>(field.low),
                                      static_cast<int>(field.high)));
    else
      field.set(out, table.number_in(field.key, field.low, field.high));
  }
}

} // namespace

StereoRig StereoRig::load(const std::filesystem::path& path) {
  const std::string file = path.string();
  const toml::table document = io::parse_toml_file(path, "rig file");
  io::TomlTable top = rig_table(document, file, "");
  top.expect_keys({kRigTable});
  top.reject_unknown_keys("unknown key: a rig file holds one [rig] table");
  const toml::table* rig = top.optional_table(kRigTable);
  if (rig == nullptr)
    throw RigFileError(file, 0, std::string(kRigTable), "missing [rig] table");

  RigParameters parameters;
  io::TomlTable table = rig_table(*rig, file, kRigTable);
  read_fields(table, kRigTable, parameters);
  if (const toml::table* misalignment = table.optional_table(kMisalignmentKey)) {
    io::TomlTable sub = rig_table(*misalignment, file, kMisalignmentTable);
    read_fields(sub, kMisalignmentTable, parameters);
  }
  // Each value is in its range; the rig as a whole must still see the ground ahead.
  if (auto problem = detail::rig_geometry_problem(parameters))
    throw RigFileError(file, table.line(), "", *problem);
  return StereoRig(parameters);
}

std::string StereoRig::to_toml() const {
  using io::toml_float;
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
