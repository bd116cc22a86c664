// The progress bar of campaigns and other long runs.

#include "cli/progress_bar.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <unistd.h>

namespace marsokhod::apps {

ProgressBar::ProgressBar(std::uint64_t total, bool shown, std::string unit)
    : total_(total), shown_(shown && ::isatty(STDERR_FILENO) != 0), unit_(std::move(unit)),
      start_(Clock::now()) {}

void ProgressBar::update(std::uint64_t done) {
  if (!shown_)
    return;
  const Clock::time_point now = Clock::now();
  if (done < total_ && now - last_ < std::chrono::milliseconds(200))
    return;
  last_ = now;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0.0;
  const double left = rate > 0 ? static_cast<double>(total_ - done) / rate : 0.0;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(kWidth * done / std::max<std::uint64_t>(total_, 1));
  fmt::print(stderr, "\r[{:<{}}] {}/{} {}, {:.0f} {}/min, ETA {}:{:02}   ",
             std::string(static_cast<std::size_t>(filled), '#'), kWidth, done, total_, unit_,
             rate * 60.0, unit_, static_cast<int>(left) / 60, static_cast<int>(left) % 60);
  if (done == total_)
    fmt::print(stderr, "\n");
}

} // namespace marsokhod::apps
