// The error of a key in an input file: "FILE:LINE: 'KEY': problem".
#pragma once

#include <concepts>
#include <stdexcept>
#include <string>
#include <utility>

namespace marsokhod::io {

/// A value of a keyed file (platform, placement, campaign) that the reader cannot accept. what()
/// is "FILE:LINE: 'KEY': problem", "FILE: ..." when the line is 0 and without the key part when
/// the key is empty, so that every such file's errors read alike. Each file kind derives its own
/// type from it, so that a caller can tell whose file was wrong.
class KeyedFileError : public std::runtime_error {
public:
  KeyedFileError(std::string file, int line, std::string key, const std::string& problem);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }
  const std::string& problem() const { return problem_; }

private:
  std::string file_;
  int line_;
  std::string key_;
  std::string problem_;
};

/// Throws a file kind's own KeyedFileError (a PlatformError, a CampaignError) for a key.
using KeyedErrorThrower = void (*)(std::string file, int line, std::string key,
                                   const std::string& problem);

/// The KeyedErrorThrower of Error, which is built as Error(file, line, key, problem).
template <std::derived_from<KeyedFileError> Error>
[[noreturn]] void throw_keyed(std::string file, int line, std::string key,
                              const std::string& problem) {
  throw Error(std::move(file), line, std::move(key), problem);
}

} // namespace marsokhod::io
