// Non-blocking input files: open, fstat and full reads, with EINTR retried.
#include "marsokhod/io/files/input_file.hpp"

#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace marsokhod::io {

InputFile::InputFile(const std::filesystem::path& path)
    : fd_(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)) {
  if (fd_ < 0) {
    error_ = errno;
    return;
  }
  struct stat status {};
  if (::fstat(fd_, &status) != 0) {
    error_ = errno;
    return;
  }
  mode_ = status.st_mode;
  size_ = static_cast<std::uint64_t>(status.st_size);
}

InputFile::~InputFile() {
  if (fd_ >= 0)
    ::close(fd_);
}

bool InputFile::is_regular() const {
  return error_ == 0 && S_ISREG(mode_);
}

bool InputFile::is_directory() const {
  return error_ == 0 && S_ISDIR(mode_);
}

std::string_view InputFile::type_name() const {
  if (S_ISDIR(mode_))
    return "a directory";
  if (S_ISFIFO(mode_))
    return "a FIFO";
  if (S_ISCHR(mode_) || S_ISBLK(mode_))
    return "a device";
  if (S_ISSOCK(mode_))
    return "a socket";
  return "not a regular file";
}

std::size_t InputFile::read(std::uint8_t* out, std::size_t length) {
  std::size_t done = 0;
  while (done < length) {
    const ssize_t got = ::read(fd_, out + done, length - done);
    if (got < 0 && errno == EINTR)
      continue;
    if (got < 0)
      throw std::system_error(errno, std::generic_category());
    if (got == 0)
      break;
    done += static_cast<std::size_t>(got);
  }
  return done;
}

std::string error_text(int error) {
  return std::generic_category().message(error);
}

} // namespace marsokhod::io
