// The PAIRS.tsv reader: header columns, one entry a line, errors naming the file and line; the
// file through io's bounded reader, its numbers through io's checked conversions.
#include "marsokhod/eval/stereo/stereo_pairs.hpp"

#include "marsokhod/eval/common/errors.hpp"
#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/files/text_file.hpp"
#include "marsokhod/io/numbers/checked_number.hpp"
#include "marsokhod/io/paths/contained_path.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <string_view>
#include <system_error>

namespace marsokhod::eval {
namespace {

namespace fs = std::filesystem;

// Ground truth is stored value / gt_scale: within these bounds a 16-bit value stays a finite,
// representable disparity and no real encoding (1, 3, 4, 8, 16, 256) is refused.
constexpr double kMinTruthScale = 0.001;
constexpr double kMaxTruthScale = 65536.0;

constexpr std::array<std::string_view, 9> kRequired = {
    "name", "left", "right", "gt", "gt_scale", "gt_bits", "width", "height", "max_gt_disp_px"};

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t tab = line.find('\t', start);
    fields.push_back(
        line.substr(start, tab == std::string::npos ? std::string::npos : tab - start));
    if (tab == std::string::npos)
      return fields;
    start = tab + 1;
  }
}

// Where each required column is, from the header (a note in parentheses is not part of the name).
std::map<std::string, std::size_t, std::less<>> column_positions(const std::string& header,
                                                                 const fs::path& index) {
  std::map<std::string, std::size_t, std::less<>> positions;
  const std::vector<std::string> names = split_tabs(header);
  for (std::size_t i = 0; i < names.size(); ++i)
    positions.emplace(names[i].substr(0, names[i].find('(')), i);
  for (std::string_view column : kRequired)
    if (positions.find(column) == positions.end())
      throw EvaluationError(
          fmt::format("{}:1: the header lacks the column '{}'", index.string(), column));
  return positions;
}

class LineReader {
public:
  LineReader(const fs::path& index, int line, std::vector<std::string> fields,
             const std::map<std::string, std::size_t, std::less<>>& positions)
      : index_(index), line_(line), fields_(std::move(fields)), positions_(positions) {}

  const std::string& text(std::string_view column) const {
    const std::size_t at = positions_.find(column)->second;
    if (at >= fields_.size())
      fail(fmt::format("has {} fields, the column '{}' is missing", fields_.size(), column));
    return fields_[at];
  }
  int integer(std::string_view column) const {
    const std::string& field = text(column);
    const std::optional<int> value = io::parse_integer<int>(field);
    if (!value)
      fail(fmt::format("column '{}' is not a whole number: '{}'", column, field));
    return *value;
  }
  double real(std::string_view column) const {
    const std::string& field = text(column);
    const std::optional<double> value = io::parse_finite(field);
    if (!value)
      fail(fmt::format("column '{}' is not a finite number: '{}'", column, field));
    return *value;
  }
  // An input beside the index (or anywhere, given an absolute path); only a regular file will
  // do, so that a FIFO or a device cannot stall or flood the image readers.
  fs::path existing_file(std::string_view column) const {
    const std::string& field = text(column);
    if (field.empty())
      fail(fmt::format("column '{}' is empty; it names a file", column));
    const fs::path path = index_.parent_path() / field;
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (!fs::exists(status))
      fail(fmt::format("{} file {} does not exist", column, path.string()));
    if (!fs::is_regular_file(status))
      fail(fmt::format("{} file {} is not a regular file", column, path.string()));
    return path;
  }
  [[noreturn]] void fail(const std::string& problem) const {
    throw EvaluationError(fmt::format("{}:{}: {}", index_.string(), line_, problem));
  }

private:
  const fs::path& index_;
  int line_;
  std::vector<std::string> fields_;
  const std::map<std::string, std::size_t, std::less<>>& positions_;
};

// The name becomes <name>_disparity.pfm in the --out folder: one file name, nothing that
// could lead out of it.
void check_pair_name(const LineReader& reader, const std::string& name) {
  if (name.empty())
    reader.fail("the pair has no name");
  if (const auto problem = io::contained_name_problem(name))
    reader.fail(fmt::format("pair name '{}' {}", name, *problem));
  if (name.find('/') != std::string::npos)
    reader.fail(fmt::format("pair name '{}' holds a '/'; it names files in one folder", name));
}

StereoPairEntry read_entry(const LineReader& reader, int line) {
  StereoPairEntry entry;
  entry.line = line;
  entry.name = reader.text("name");
  check_pair_name(reader, entry.name);
  entry.left = reader.existing_file("left");
  entry.right = reader.existing_file("right");
  entry.width = reader.integer("width");
  entry.height = reader.integer("height");
  if (entry.width <= 0 || entry.height <= 0)
    reader.fail(fmt::format("size {}x{} is not positive", entry.width, entry.height));
  if (entry.width > imaging::kMaxImageSide || entry.height > imaging::kMaxImageSide)
    reader.fail(fmt::format("size {}x{} exceeds the largest image side, {} px", entry.width,
                            entry.height, imaging::kMaxImageSide));
  if (reader.text("max_gt_disp_px") != "-") {
    const double largest = reader.real("max_gt_disp_px");
    if (!(largest > 0.0 && largest <= imaging::kMaxImageSide))
      reader.fail(fmt::format("max_gt_disp_px {} is not above 0 and at most {} px", largest,
                              imaging::kMaxImageSide));
    entry.max_truth_disparity = largest;
  }
  if (reader.text("gt") == "-")
    return entry;
  entry.truth = reader.existing_file("gt");
  entry.truth_scale = reader.real("gt_scale");
  entry.truth_bits = reader.integer("gt_bits");
  if (!(entry.truth_scale > 0.0))
    reader.fail(fmt::format("gt_scale {} is not positive", entry.truth_scale));
  if (entry.truth_scale < kMinTruthScale || entry.truth_scale > kMaxTruthScale)
    reader.fail(fmt::format("gt_scale {} is not {}", entry.truth_scale,
                            io::range_text(kMinTruthScale, kMaxTruthScale)));
  if (entry.truth_bits != 8 && entry.truth_bits != 16)
    reader.fail(fmt::format("gt_bits {} is neither 8 nor 16", entry.truth_bits));
  return entry;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

std::string index_text(const fs::path& index) {
  try {
    return io::read_text_file(index, "pair index");
  } catch (const io::InputError& error) {
    throw EvaluationError(error.what());
  }
}

} // namespace

std::vector<StereoPairEntry> read_stereo_pairs(const fs::path& index) {
  const std::vector<std::string> lines = split_lines(index_text(index));
  if (lines.empty())
    throw EvaluationError(fmt::format("{}: the pair index is empty", index.string()));
  const auto positions = column_positions(lines.front(), index);
  std::vector<StereoPairEntry> entries;
  std::map<std::string, int, std::less<>> first_line_of;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::string& text = lines[i];
    if (text.empty() || text.front() == '#')
      continue;
    const int line = static_cast<int>(i) + 1;
    const LineReader reader(index, line, split_tabs(text), positions);
    StereoPairEntry entry = read_entry(reader, line);
    // Two pairs of one name would overwrite each other's outputs.
    const auto [previous, fresh] = first_line_of.emplace(entry.name, line);
    if (!fresh)
      reader.fail(
          fmt::format("pair name '{}' is already used on line {}", entry.name, previous->second));
    entries.push_back(std::move(entry));
  }
  if (entries.empty())
    throw EvaluationError(fmt::format("{}: the pair index lists no pair", index.string()));
  return entries;
}

} // namespace marsokhod::eval
