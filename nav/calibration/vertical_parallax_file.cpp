// The calibration file: a vertical parallax map as TOML (docs/formats.md, "Calibration files").

#include "marsokhod/io/formats/toml_file.hpp"
#include "marsokhod/io/formats/toml_float.hpp"
#include "marsokhod/io/formats/toml_table.hpp"
#include "marsokhod/nav/calibration/vertical_parallax.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <array>
#include <sstream>
#include <string_view>

namespace marsokhod::nav {
namespace {

constexpr std::string_view kTable = "vertical_parallax";
constexpr std::array<std::string_view, 6> kCoefficientKeys = {"c0",  "cx",  "cy",
                                                              "cxx", "cxy", "cyy"};
/// A table of a calibration file whose errors are CalibrationFileErrors naming its keys in full
/// ('vertical_parallax.c0'); `name` is the table's, empty for the whole file.
io::TomlTable calibration_table(const toml::table& table, const std::string& file,
                                std::string_view name) {
  return io::TomlTable(table, file, "", io::throw_keyed<CalibrationFileError>, std::string(name));
}

VerticalParallaxMap read_map(io::TomlTable& table) {
  table.expect_keys({"width_px", "height_px"});
  for (const std::string_view key : kCoefficientKeys)
    table.expect_keys({key});
  table.reject_unknown_keys("unknown key (known keys: width_px, height_px, c0, cx, cy, cxx, cxy, "
                            "cyy)");
  VerticalParallaxMap map;
  map.width = table.integer_in("width_px", kMinCalibrationSide, imaging::kMaxImageSide);
  map.height = table.integer_in("height_px", kMinCalibrationSide, imaging::kMaxImageSide);
  for (std::size_t i = 0; i < kCoefficientKeys.size(); ++i)
    map.coefficients[i] = table.number_in(kCoefficientKeys[i], -kMaxCalibrationCoefficient,
                                          kMaxCalibrationCoefficient);
  // Each key is in range; the map as a whole must still keep rows corresponding.
  const std::string problem = calibration_map_problem(map);
  if (!problem.empty())
    throw CalibrationFileError(table.file(), table.line(), "", problem);
  return map;
}

} // namespace

VerticalParallaxMap load_vertical_parallax(const std::filesystem::path& path) {
  const std::string file = path.string();
  const toml::table document = io::parse_toml_file(path, "calibration file");
  io::TomlTable top = calibration_table(document, file, "");
  top.expect_keys({kTable});
  top.reject_unknown_keys(
      fmt::format("unknown key: a calibration file holds one [{}] table", kTable));
  const toml::table* table = top.optional_table(kTable);
  if (table == nullptr)
    throw CalibrationFileError(file, 0, std::string(kTable),
                               fmt::format("missing [{}] table", kTable));
  io::TomlTable reader = calibration_table(*table, file, kTable);
  return read_map(reader);
}

std::string vertical_parallax_to_toml(const VerticalParallaxMap& map, const std::string& comment) {
  std::string text = "# Vertical parallax calibration (format: docs/navigation.md, \"Calibration "
                     "file\").\n";
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);)
    text += "# " + line + "\n";
  text += fmt::format("[{}]\nwidth_px = {}\nheight_px = {}\n", kTable, map.width, map.height);
  text += "# shift(x, y) = c0 + cx u + cy v + cxx u^2 + cxy u v + cyy v^2 rows (right image "
          "content lower),\n# u = x - (width_px - 1) / 2, v = y - (height_px - 1) / 2\n";
  for (std::size_t i = 0; i < kCoefficientKeys.size(); ++i)
    text += fmt::format("{} = {}\n", kCoefficientKeys[i], io::toml_float(map.coefficients[i]));
  return text;
}

} // namespace marsokhod::nav
