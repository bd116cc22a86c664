// The error for an output that could not be written (disk full, closed pipe, missing folder).
#pragma once

#include <stdexcept>

namespace marsokhod::io {

/// An output file or stream that could not be written; the message names it and why.
class OutputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace marsokhod::io
