// The calibration file: a vertical parallax map as TOML (docs/formats.md, "Calibration files").

#include "marsokhod/imaging/rig/toml_document.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"
#include "marsokhod/nav/calibration/vertical_parallax.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string_view>

namespace marsokhod::nav {
namespace {

constexpr std::string_view kTable = "vertical_parallax";
constexpr std::array<std::string_view, 6> kCoefficientKeys = {"c0",  "cx",  "cy",
                                                              "cxx", "cxy", "cyy"};
constexpr int kMinSide = 16;
// Largest |coefficient| (rows, rows per pixel, rows per pixel squared). A quadratic within
// kMaxVerticalShift rows over an image of at least 16 x 16 pixels has coefficients below about
// 64 * 4, so this refuses no usable map; it keeps every term (at most 1e6 * 8192^2 rows over
// the largest image) finite, so that no two terms can cancel to NaN.
constexpr double kMaxCoefficient = 1e6;

/// Reads a calibration file and reports every problem naming the file and, where the problem
/// has one, the line and column.
class CalibrationFileReader {
public:
  explicit CalibrationFileReader(const std::filesystem::path& path)
      : document_(path, "calibration") {}

  VerticalParallaxMap read() const {
    const toml::table document = document_.parse();
    const toml::table* table = nullptr;
    for (auto&& [key, node] : document) {
      if (key.str() != kTable)
        fail(key.source(), fmt::format("unknown key '{}' (a calibration file has one [{}] table)",
                                       key.str(), kTable));
      if (!node.is_table())
        fail(key.source(), fmt::format("key '{}' must be a table", kTable));
      table = node.as_table();
    }
    if (table == nullptr)
      document_.fail(fmt::format("no [{}] table", kTable));
    return read_map(*table);
  }

private:
  [[noreturn]] void fail(const toml::source_region& where, const std::string& problem) const {
    document_.fail(where, problem);
  }

  VerticalParallaxMap read_map(const toml::table& table) const {
    for (auto&& [key, node] : table)
      if (key.str() != "width_px" && key.str() != "height_px" && !is_coefficient(key.str()))
        fail(key.source(), fmt::format("unknown key '{}.{}' (known keys: width_px, height_px, c0, "
                                       "cx, cy, cxx, cxy, cyy)",
                                       kTable, key.str()));
    VerticalParallaxMap map;
    map.width = read_side(table, "width_px");
    map.height = read_side(table, "height_px");
    for (std::size_t i = 0; i < kCoefficientKeys.size(); ++i)
      map.coefficients[i] = read_number(table, kCoefficientKeys[i]);
    const double largest = map.largest_shift();
    if (!(largest <= kMaxVerticalShift))
      document_.fail(fmt::format("the map shifts rows by up to {:.1f}, more than the {} rows a "
                                 "calibration may correct",
                                 largest, kMaxVerticalShift));
    return map;
  }

  static bool is_coefficient(std::string_view key) {
    for (std::string_view known : kCoefficientKeys)
      if (key == known)
        return true;
    return false;
  }

  const toml::node& require(const toml::table& table, std::string_view key) const {
    const toml::node* node = table.get(key);
    if (node == nullptr)
      document_.fail(fmt::format("key '{}.{}' is missing", kTable, key));
    return *node;
  }

  int read_side(const toml::table& table, std::string_view key) const {
    const toml::node& node = require(table, key);
    if (!node.is_integer())
      fail(node.source(), fmt::format("key '{}.{}' must be an integer", kTable, key));
    const std::int64_t value = node.as_integer()->get();
    const std::optional<int> side = io::narrow<int>(value);
    if (!side || *side < kMinSide || *side > imaging::kMaxImageSide)
      fail(node.source(), fmt::format("key '{}.{}' must lie within {}..{} (got {})", kTable, key,
                                      kMinSide, imaging::kMaxImageSide, value));
    return *side;
  }

  double read_number(const toml::table& table, std::string_view key) const {
    const toml::node& node = require(table, key);
    if (!node.is_integer() && !node.is_floating_point())
      fail(node.source(), fmt::format("key '{}.{}' must be a number", kTable, key));
    const double value = node.is_integer() ? static_cast<double>(node.as_integer()->get())
                                           : node.as_floating_point()->get();
    if (!std::isfinite(value))
      fail(node.source(), fmt::format("key '{}.{}' must be finite (got {})", kTable, key, value));
    if (std::fabs(value) > kMaxCoefficient)
      fail(node.source(), fmt::format("key '{}.{}' must be {} (got {})", kTable, key,
                                      io::range_text(-kMaxCoefficient, kMaxCoefficient), value));
    return value;
  }

  imaging::detail::TomlDocument<CalibrationError> document_;
};

} // namespace

using imaging::detail::toml_float;

VerticalParallaxMap load_vertical_parallax(const std::filesystem::path& path) {
  return CalibrationFileReader(path).read();
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
    text += fmt::format("{} = {}\n", kCoefficientKeys[i], toml_float(map.coefficients[i]));
  return text;
}

} // namespace marsokhod::nav
