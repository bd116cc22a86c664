// An input file opened without ever blocking, with what it is known before a byte is read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace marsokhod::io {

/// An input file opened read-only and non-blocking (a FIFO without a writer opens at once),
/// with its fstat type and size. It reports problems as facts rather than messages, so that
/// every reader can word its refusal for its own kind of file.
class InputFile {
public:
  /// Opens `path`; a failure is left in error(), never thrown.
  explicit InputFile(const std::filesystem::path& path);
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  ~InputFile();

  /// errno of the open or fstat that failed, 0 when the file is open.
  int error() const { return error_; }
  bool is_regular() const;
  bool is_directory() const;
  /// "a directory", "a FIFO", "a device", "a socket" or "not a regular file".
  std::string_view type_name() const;
  /// The size fstat gave when the file was opened.
  std::uint64_t size() const { return size_; }

  /// Reads up to `length` bytes, fewer only at the end of the file; a read error throws
  /// std::system_error with its errno.
  std::size_t read(std::uint8_t* out, std::size_t length);

private:
  int fd_ = -1;
  int error_ = 0;
  unsigned mode_ = 0;
  std::uint64_t size_ = 0;
};

/// The text of an errno value ("No such file or directory").
std::string error_text(int error);

} // namespace marsokhod::io
