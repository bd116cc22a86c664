// TimingError: a timing figure the model cannot give.
#pragma once

#include <stdexcept>

namespace marsokhod::eval {

/// A figure the timing model cannot give: a scene that does not fit a platform's memory, a
/// variant the platform files do not have, no scenes. The message names the seed or the file.
class TimingError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace marsokhod::eval
