// Whole-file reads of text inputs: regular files only, size bounded, never blocking.
#include "marsokhod/io/files/text_file.hpp"

#include "marsokhod/io/files/input_error.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace marsokhod::io {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& problem) {
  throw InputError(path.string(), problem);
}

std::string errno_text(int error) {
  return std::generic_category().message(error);
}

// Closes the descriptor on every exit path, exceptions included.
class FileDescriptor {
public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0)
      ::close(fd_);
  }
  int get() const { return fd_; }

private:
  int fd_;
};

std::string_view file_type_name(mode_t mode) {
  if (S_ISDIR(mode))
    return "a directory";
  if (S_ISFIFO(mode))
    return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode))
    return "a device";
  if (S_ISSOCK(mode))
    return "a socket";
  return "not a regular file";
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
  // O_NONBLOCK: opening a FIFO without a writer must not wait; the type check below refuses it.
  const FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (fd.get() < 0)
    fail(path, fmt::format("cannot open the {}: {}", kind, errno_text(errno)));
  struct stat status {};
  if (::fstat(fd.get(), &status) != 0)
    fail(path, fmt::format("cannot read the {}: {}", kind, errno_text(errno)));
  if (!S_ISREG(status.st_mode))
    fail(path,
         fmt::format("is {}; a {} must be a regular file", file_type_name(status.st_mode), kind));
  const auto size = static_cast<std::uintmax_t>(status.st_size);
  if (size > max_bytes)
    fail(path,
         fmt::format("is {} bytes; a {} is at most {}", size, kind, byte_count_text(max_bytes)));

  std::string text(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t got = ::read(fd.get(), text.data() + done, text.size() - done);
    if (got < 0 && errno == EINTR)
      continue;
    if (got < 0)
      fail(path, fmt::format("cannot read the {}: {}", kind, errno_text(errno)));
    if (got == 0)
      break;
    done += static_cast<std::size_t>(got);
  }
  text.resize(done);
  // A file that grew after fstat is read only up to its size then; one byte more tells.
  char extra = 0;
  if (::read(fd.get(), &extra, 1) > 0)
    fail(path, fmt::format("grew while it was read; a {} is at most {}", kind,
                           byte_count_text(max_bytes)));
  return text;
}

} // namespace marsokhod::io
