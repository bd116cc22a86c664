// The PAIRS.tsv reader: header columns, one entry a line, errors naming the file and line.
#include "marsokhod/eval/stereo/stereo_pairs.hpp"

#include "marsokhod/eval/common/errors.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <fstream>
#include <map>
#include <string_view>

namespace marsokhod::eval {
namespace {

namespace fs = std::filesystem;

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
  template <class Number>
  Number number(std::string_view column) const {
    const std::string& field = text(column);
    Number value{};
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc() || end != field.data() + field.size())
      fail(fmt::format("column '{}' is not a number: '{}'", column, field));
    return value;
  }
  fs::path existing_file(std::string_view column) const {
    const fs::path path = index_.parent_path() / text(column);
    if (!fs::is_regular_file(path))
      fail(fmt::format("{} file {} does not exist", column, path.string()));
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

StereoPairEntry read_entry(const LineReader& reader, int line) {
  StereoPairEntry entry;
  entry.line = line;
  entry.name = reader.text("name");
  if (entry.name.empty())
    reader.fail("the pair has no name");
  entry.left = reader.existing_file("left");
  entry.right = reader.existing_file("right");
  entry.width = reader.number<int>("width");
  entry.height = reader.number<int>("height");
  if (entry.width <= 0 || entry.height <= 0)
    reader.fail(fmt::format("size {}x{} is not positive", entry.width, entry.height));
  if (reader.text("max_gt_disp_px") != "-")
    entry.max_truth_disparity = reader.number<double>("max_gt_disp_px");
  if (reader.text("gt") == "-")
    return entry;
  entry.truth = reader.existing_file("gt");
  entry.truth_scale = reader.number<double>("gt_scale");
  entry.truth_bits = reader.number<int>("gt_bits");
  if (!(entry.truth_scale > 0.0))
    reader.fail(fmt::format("gt_scale {} is not positive", entry.truth_scale));
  if (entry.truth_bits != 8 && entry.truth_bits != 16)
    reader.fail(fmt::format("gt_bits {} is neither 8 nor 16", entry.truth_bits));
  return entry;
}

} // namespace

std::vector<StereoPairEntry> read_stereo_pairs(const fs::path& index) {
  std::ifstream stream(index);
  if (!stream)
    throw EvaluationError(fmt::format("{}: cannot open the pair index", index.string()));
  std::string header;
  if (!std::getline(stream, header))
    throw EvaluationError(fmt::format("{}: the pair index is empty", index.string()));
  if (!header.empty() && header.back() == '\r')
    header.pop_back();
  const auto positions = column_positions(header, index);
  std::vector<StereoPairEntry> entries;
  std::string text;
  for (int line = 2; std::getline(stream, text); ++line) {
    if (!text.empty() && text.back() == '\r')
      text.pop_back();
    if (text.empty() || text.front() == '#')
      continue;
    entries.push_back(read_entry(LineReader(index, line, split_tabs(text), positions), line));
  }
  if (entries.empty())
    throw EvaluationError(fmt::format("{}: the pair index lists no pair", index.string()));
  return entries;
}

} // namespace marsokhod::eval
