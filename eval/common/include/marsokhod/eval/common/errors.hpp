// The exceptions of the evaluation layer: bad files or data, and bad options.
#pragma once

#include <stdexcept>

namespace marsokhod::eval {

/// A file or its data cannot be evaluated (missing, malformed, of the wrong size); the message
/// names the file.
class EvaluationError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// An option value the evaluation cannot take (a malformed seed range); the message quotes the
/// value, and the caller names the option it came from.
class OptionError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

} // namespace marsokhod::eval
