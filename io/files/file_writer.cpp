// Atomic, checked output files: temporary beside the target, full write, close, rename.
#include "marsokhod/io/files/file_writer.hpp"

#include "marsokhod/io/files/input_file.hpp"
#include "marsokhod/io/files/output_error.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cerrno>
#include <fcntl.h>
#include <unistd.h>

namespace marsokhod::io {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& problem) {
  throw OutputError(fmt::format("{}: {}", path.string(), problem));
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

void write_file_atomically(const fs::path& path, std::span<const std::uint8_t> bytes) {
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code error;
  if (!fs::is_directory(folder, error))
    fail(path, fmt::format("folder {} does not exist", folder.string()));
  if (fs::is_directory(path, error))
    fail(path, "is a directory");

  fs::path temporary;
  const int fd =
      create_temporary(path.parent_path().empty() ? fs::path(".") / path : path, temporary);
  if (fd < 0)
    fail(path, fmt::format("cannot create a file in {}: {}", folder.string(), error_text(errno)));
  const bool written = write_fully(fd, bytes);
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    const int close_errno = errno;
    ::unlink(temporary.c_str());
    fail(path, fmt::format("cannot write: {}", error_text(written ? close_errno : write_errno)));
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_errno = errno;
    ::unlink(temporary.c_str());
    fail(path, fmt::format("cannot write: {}", error_text(rename_errno)));
  }
}

void write_file_atomically(const fs::path& path, std::string_view text) {
  write_file_atomically(path,
                        std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

} // namespace marsokhod::io
