// File access shared by the image readers and writers.

#include "image/image_codec.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cerrno>
#include <fcntl.h>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace marsokhod::imaging::detail {
namespace {

namespace fs = std::filesystem;

// The largest file any supported image can need: an RGB PFM at the size limit plus a header.
constexpr std::uintmax_t kMaxImageFileBytes =
    std::uintmax_t{kMaxImageSide} * kMaxImageSide * 3 * sizeof(float) + 4096;

std::string errno_text(int error) {
  return std::generic_category().message(error);
}

bool write_fully(int fd, std::span<const std::uint8_t> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t written = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (written < 0 && errno == EINTR)
      continue;
    if (written <= 0)
      return false;
    done += static_cast<std::size_t>(written);
  }
  return true;
}

// A fresh name beside the target; the process id and a counter keep concurrent writers apart.
int create_temporary(const fs::path& target, fs::path& temporary) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    temporary = target.parent_path() /
                fmt::format(".{}.tmp{}-{}", target.filename().string(), ::getpid(), counter++);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST)
      return fd;
  }
  errno = EEXIST;
  return -1;
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
  const std::string name = path.string();
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code error;
  if (!fs::is_directory(folder, error))
    fail(name, fmt::format("folder {} does not exist", folder.string()));
  if (fs::is_directory(path, error))
    fail(name, "is a directory");

  fs::path temporary;
  const int fd =
      create_temporary(path.parent_path().empty() ? fs::path(".") / path : path, temporary);
  if (fd < 0)
    fail(name, fmt::format("cannot create a file in {}: {}", folder.string(), errno_text(errno)));
  const bool written = write_fully(fd, bytes);
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    ::unlink(temporary.c_str());
    fail(name, fmt::format("cannot write: {}", errno_text(written ? errno : write_errno)));
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_errno = errno;
    ::unlink(temporary.c_str());
    fail(name, fmt::format("cannot write: {}", errno_text(rename_errno)));
  }
}

} // namespace marsokhod::imaging::detail
