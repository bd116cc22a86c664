// RecordError: a run record or summary that cannot be read back.
#pragma once

#include <stdexcept>

namespace marsokhod::eval {

/// A record (a line of runs.jsonl) that is no record of ours: not JSON, a key missing, or a
/// value of the wrong kind. The message names the key.
class RecordError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace marsokhod::eval
