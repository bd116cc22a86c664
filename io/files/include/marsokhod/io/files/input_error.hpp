// The one error every project reader throws for a file it cannot accept.
#pragma once

#include <stdexcept>
#include <string>

namespace marsokhod::io {

/// A file that cannot be read or does not hold what its kind needs. what() is
/// "FILE: problem" or "FILE:LINE: problem"; the parts stay available so that a layer can
/// restate the error in its own terms.
class InputError : public std::runtime_error {
public:
  InputError(std::string file, std::string problem, int line = 0);
  /// A problem of no particular file (an option's value, a name taken from a file).
  explicit InputError(const std::string& message);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& problem() const { return problem_; }

private:
  std::string file_;
  std::string problem_;
  int line_ = 0;
};

} // namespace marsokhod::io
