// ProgressBar: runs done, speed and time left on a terminal.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace marsokhod::apps {

/// Progress of a long run on stderr when it is a terminal: "[####    ] 120/1000 runs, 980
/// runs/min, ETA 0:54", redrawn at most 5 times a second, ended with a newline at the last.
class ProgressBar {
public:
  /// `shown` false (e.g. with --json) draws nothing; so does a stderr that is no terminal.
  ProgressBar(std::uint64_t total, bool shown, std::string unit = "runs");

  void update(std::uint64_t done);

private:
  using Clock = std::chrono::steady_clock;
  std::uint64_t total_;
  bool shown_;
  std::string unit_;
  Clock::time_point start_;
  Clock::time_point last_{};
};

} // namespace marsokhod::apps
