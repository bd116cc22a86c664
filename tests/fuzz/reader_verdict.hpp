// Running one reader on one input and judging the outcome: accepted, rejected, or a finding.
#pragma once

#include "fuzz/reader_targets.hpp"

#include <chrono>
#include <filesystem>
#include <string>

namespace marsokhod::fuzz {

/// How a reader met an input.
enum class Outcome : std::uint8_t {
  accepted, ///< returned, and what it returned passed the target's checks
  rejected, ///< threw a std::runtime_error naming the file, with no internal message
  finding,  ///< anything else: a logic_error, bad_alloc, a foreign exception, garbage, ...
};

/// The outcome and, for a rejection or a finding, what was thrown.
struct Verdict {
  Outcome outcome = Outcome::accepted;
  std::string detail;
};

/// The reader's work folder under `root` (root/<name>), created with its companion files;
/// returns the path its input goes to.
std::filesystem::path prepare_input(const ReaderTarget& target, const std::filesystem::path& root);

/// Runs the reader on `input` (inside a folder made by prepare_input) and judges the outcome.
Verdict judge(const ReaderTarget& target, const std::filesystem::path& input);

/// Writes `bytes` to `input` and judges them.
Verdict judge_bytes(const ReaderTarget& target, const std::filesystem::path& input,
                    const Bytes& bytes);

/// Saves a finding's input as root/<reader>/<hash>-<file name> with a .txt note beside it
/// saying what happened; returns the saved input's path.
std::filesystem::path save_finding(const ReaderTarget& target, const Bytes& bytes,
                                   const Verdict& verdict, const std::filesystem::path& root);

/// The command line that replays a saved input.
std::string replay_command(const ReaderTarget& target, const std::filesystem::path& saved);

/// Aborts the process when one input runs longer than `limit` (a hang is a finding too), after
/// printing which reader and input hung. One per process; arm() before each input.
class HangWatchdog {
public:
  explicit HangWatchdog(std::chrono::seconds limit);
  ~HangWatchdog();
  HangWatchdog(const HangWatchdog&) = delete;
  HangWatchdog& operator=(const HangWatchdog&) = delete;

  void arm(const ReaderTarget& target, const std::filesystem::path& input);
  void disarm();

private:
  struct State;
  State* state_;
};

} // namespace marsokhod::fuzz
