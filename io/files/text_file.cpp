// Whole-file reads of text inputs: regular files only, size bounded, never blocking.
#include "marsokhod/io/files/text_file.hpp"

#include "marsokhod/io/files/input_error.hpp"
#include "marsokhod/io/files/input_file.hpp"

#include <fmt/format.h>

#include <system_error>

namespace marsokhod::io {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& problem) {
  throw InputError(path.string(), problem);
}

} // namespace

std::string byte_count_text(std::size_t bytes) {
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  if (bytes >= kMiB && bytes % kMiB == 0)
    return fmt::format("{} MiB", bytes / kMiB);
  return fmt::format("{} bytes", bytes);
}

std::string read_text_file(const std::filesystem::path& path, std::string_view kind,
                           std::size_t max_bytes) {
  InputFile file(path);
  if (file.error() != 0)
    refuse(path, fmt::format("cannot open the {}: {}", kind, error_text(file.error())));
  if (!file.is_regular())
    refuse(path, fmt::format("is {}; a {} must be a regular file", file.type_name(), kind));
  if (file.size() > max_bytes)
    refuse(path, fmt::format("is {} bytes; a {} is at most {}", file.size(), kind,
                             byte_count_text(max_bytes)));

  std::string text(static_cast<std::size_t>(file.size()), '\0');
  try {
    text.resize(file.read(reinterpret_cast<std::uint8_t*>(text.data()), text.size()));
    // A file that grew after fstat is read only up to its size then; one byte more tells.
    std::uint8_t extra = 0;
    if (file.read(&extra, 1) > 0)
      refuse(path, fmt::format("grew while it was read; a {} is at most {}", kind,
                               byte_count_text(max_bytes)));
  } catch (const std::system_error& error) {
    refuse(path, fmt::format("cannot read the {}: {}", kind, error.code().message()));
  }
  return text;
}

} // namespace marsokhod::io
