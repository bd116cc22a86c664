// File access shared by the image readers and writers.

#include "image/image_codec.hpp"

#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/io/files/output_error.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <fstream>
#include <system_error>

namespace marsokhod::imaging::detail {
namespace {

namespace fs = std::filesystem;

// The largest file any supported image can need: an RGB PFM at the size limit plus a header.
constexpr std::uintmax_t kMaxImageFileBytes =
    std::uintmax_t{kMaxImageSide} * kMaxImageSide * 3 * sizeof(float) + 4096;

std::string errno_text(int error) {
  return std::generic_category().message(error);
}

} // namespace

void fail(std::string_view name, std::string_view problem) {
  throw ImageError(fmt::format("{}: {}", name, problem));
}

void check_image_size(std::string_view name, long long width, long long height) {
  if (width < 1 || width > kMaxImageSide)
    fail(name, fmt::format("width {} is out of range 1..{}", width, kMaxImageSide));
  if (height < 1 || height > kMaxImageSide)
    fail(name, fmt::format("height {} is out of range 1..{}", height, kMaxImageSide));
}

std::vector<std::uint8_t> read_file_bytes(const fs::path& path) {
  const std::string name = path.string();
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status))
    fail(name, "no such file");
  if (fs::is_directory(status))
    fail(name, "is a directory, not an image file");
  if (!fs::is_regular_file(status))
    fail(name, "not a regular file");
  const std::uintmax_t size = fs::file_size(path, error);
  if (error)
    fail(name, fmt::format("cannot read: {}", error.message()));
  if (size == 0)
    fail(name, "empty file");
  if (size > kMaxImageFileBytes)
    fail(name, fmt::format("{} bytes is more than any supported image can hold", size));

  std::ifstream stream(path, std::ios::binary);
  if (!stream)
    fail(name, fmt::format("cannot open: {}", errno_text(errno)));
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  stream.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
  if (static_cast<std::uintmax_t>(stream.gcount()) != size)
    fail(name, "cannot read: the file shrank while it was read");
  return bytes;
}

void write_file_atomically(const fs::path& path, std::span<const std::uint8_t> bytes) {
  try {
    io::write_file_atomically(path, bytes);
  } catch (const io::OutputError& error) {
    throw ImageError(error.what());
  }
}

} // namespace marsokhod::imaging::detail
