// Input errors: the file, the line where there is one, and the problem, in one message.
#include "marsokhod/io/files/input_error.hpp"

#include <fmt/format.h>

#include <utility>

namespace marsokhod::io {
namespace {

std::string message_of(const std::string& file, const std::string& problem, int line) {
  if (line > 0)
    return fmt::format("{}:{}: {}", file, line, problem);
  return fmt::format("{}: {}", file, problem);
}

} // namespace

InputError::InputError(std::string file, std::string problem, int line)
    : std::runtime_error(message_of(file, problem, line)), file_(std::move(file)),
      problem_(std::move(problem)), line_(line) {}

InputError::InputError(const std::string& message)
    : std::runtime_error(message), problem_(message) {}

} // namespace marsokhod::io
