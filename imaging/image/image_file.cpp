// File access shared by the image readers and writers: reads bounded by what the header needs.

#include "image/image_codec.hpp"

#include "marsokhod/io/files/file_writer.hpp"
#include "marsokhod/io/files/output_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace marsokhod::imaging::detail {
namespace {

namespace fs = std::filesystem;

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

ImageFileReader::ImageFileReader(const fs::path& path) : name_(path.string()) {
  // O_NONBLOCK: opening a FIFO without a writer must not wait; the type check refuses it.
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    const int error = errno;
    if (error == ENOENT)
      fail(name_, "no such file");
    fail(name_, fmt::format("cannot open: {}", errno_text(error)));
  }
  struct stat status {};
  if (::fstat(fd_, &status) != 0) {
    const int error = errno;
    ::close(fd_);
    fail(name_, fmt::format("cannot read: {}", errno_text(error)));
  }
  const char* problem = nullptr;
  if (S_ISDIR(status.st_mode))
    problem = "is a directory, not an image file";
  else if (!S_ISREG(status.st_mode))
    problem = "not a regular file";
  else if (status.st_size == 0)
    problem = "empty file";
  if (problem != nullptr) {
    ::close(fd_);
    fail(name_, problem);
  }
  size_ = static_cast<std::uint64_t>(status.st_size);
}

ImageFileReader::~ImageFileReader() {
  ::close(fd_);
}

std::size_t ImageFileReader::read_next(std::uint8_t* out, std::size_t length) {
  std::size_t done = 0;
  while (done < length) {
    const ssize_t got = ::read(fd_, out + done, length - done);
    if (got < 0 && errno == EINTR)
      continue;
    if (got < 0)
      fail(name_, fmt::format("cannot read: {}", errno_text(errno)));
    if (got == 0)
      break;
    done += static_cast<std::size_t>(got);
  }
  position_ += done;
  return done;
}

void ImageFileReader::read_up_to(std::vector<std::uint8_t>& bytes, std::size_t count) {
  if (bytes.size() != position_ || count <= bytes.size())
    return;
  // Never more than the file held when it was opened: a header's promise is not an allocation.
  const std::size_t wanted =
      static_cast<std::size_t>(std::min<std::uint64_t>(count, std::max(size_, position_)));
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
