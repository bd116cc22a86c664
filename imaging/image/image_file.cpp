// File access shared by the image readers and writers: reads bounded by what the header needs.

#include "image/image_codec.hpp"

#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/io/files/output_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <system_error>

namespace marsokhod::imaging::detail {
namespace {

namespace fs = std::filesystem;

} // namespace

bool starts_with(std::span<const std::uint8_t> bytes, std::string_view prefix) {
  return bytes.size() >= prefix.size() &&
         std::equal(
             prefix.begin(), prefix.end(), bytes.begin(),
             [](char a, std::uint8_t b) { return static_cast<std::uint8_t>(a) == b; });
}

void fail(std::string_view name, std::string_view problem) {
  throw ImageError(fmt::format("{}: {}", name, problem));
}

void check_image_size(std::string_view name, long long width, long long height) {
  if (width < 1 || width > kMaxImageSide)
    fail(name, fmt::format("width {} is out of range 1..{}", width, kMaxImageSide));
  if (height < 1 || height > kMaxImageSide)
    fail(name, fmt::format("height {} is out of range 1..{}", height, kMaxImageSide));
}

ImageFileReader::ImageFileReader(const fs::path& path) : name_(path.string()), file_(path) {
  if (file_.error() == ENOENT)
    fail(name_, "no such file");
  if (file_.error() != 0)
    fail(name_, fmt::format("cannot open: {}", io::error_text(file_.error())));
  if (file_.is_directory())
    fail(name_, "is a directory, not an image file");
  if (!file_.is_regular())
    fail(name_, "not a regular file");
  if (file_.size() == 0)
    fail(name_, "empty file");
}

std::size_t ImageFileReader::read_next(std::uint8_t* out, std::size_t length) {
  try {
    const std::size_t done = file_.read(out, length);
    position_ += done;
    return done;
  } catch (const std::system_error& error) {
    fail(name_, fmt::format("cannot read: {}", error.code().message()));
  }
}

void ImageFileReader::read_up_to(std::vector<std::uint8_t>& bytes, std::size_t count) {
  if (bytes.size() != position_ || count <= bytes.size())
    return;
  // Never more than the file held when it was opened: a header's promise is not an allocation.
  const std::size_t wanted =
      static_cast<std::size_t>(std::min<std::uint64_t>(count, std::max(file_.size(), position_)));
  const std::size_t old_size = bytes.size();
  bytes.resize(wanted);
  bytes.resize(old_size + read_next(bytes.data() + old_size, wanted - old_size));
}

void write_file_atomically(const fs::path& path, std::span<const std::uint8_t> bytes) {
  try {
    io::write_file_atomically(path, bytes);
  } catch (const io::OutputError& error) {
    throw ImageError(error.what());
  }
}

} // namespace marsokhod::imaging::detail
