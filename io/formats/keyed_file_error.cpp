// The shape every keyed file's error message has.
#include "marsokhod/io/formats/keyed_file_error.hpp"

#include <fmt/format.h>

#include <utility>

namespace marsokhod::io {
namespace {

std::string describe(const std::string& file, int line, const std::string& key,
                     const std::string& problem) {
  const std::string where = line > 0 ? fmt::format("{}:{}", file, line) : file;
  if (key.empty())
    return fmt::format("{}: {}", where, problem);
  return fmt::format("{}: '{}': {}", where, key, problem);
}

} // namespace

KeyedFileError::KeyedFileError(std::string file, int line, std::string key,
                               const std::string& problem)
    : std::runtime_error(describe(file, line, key, problem)), file_(std::move(file)), line_(line),
      key_(std::move(key)), problem_(problem) {}

} // namespace marsokhod::io
