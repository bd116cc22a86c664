// The course options of `traverse` and `eval traverse`.
#include "traverse/course_options.hpp"

#include "cli/command.hpp"
#include "cli/option_checks.hpp"

#include <fmt/format.h>

#include <optional>
#include <string>
#include <utility>

namespace marsokhod::apps {

namespace {

// Normal paths end beyond the escapes' 3-4 m and within the zones' 20 m.
constexpr double kShortestNormalPath = 4.0;
constexpr double kLongestNormalPath = 20.0;

std::optional<std::pair<double, double>> normal_path_band(const std::string& text) {
  return real_band(text, kShortestNormalPath, kLongestNormalPath);
}

} // namespace

void add_course_options(CLI::App* app, eval::TraverseSettings& course) {
  app->add_option("--slope", course.slope_deg, "Regional slope of the site, degrees")
      ->check(real_between(0.0, 15.0))
      ->capture_default_str();
  app->add_option("--light", course.light, "Lighting preset")
      ->check(CLI::IsMember({"high-sun", "overexposed", "dark-wet", "low-sun"}))
      ->capture_default_str();
  app->add_option("--platform", course.platform,
                  "Where each cycle's navigation runs: native, or emulated on pc-card or onboard "
                  "(the emulated cycle time counts as mission time; onboard images are 128 x 128, "
                  "what its two 256 KB modules hold)")
      ->check(CLI::IsMember({"native", "pc-card", "onboard"}))
      ->capture_default_str();
  app->add_option("--drive-m", course.drive_m,
                  "How far along each planned path the rover drives before it looks again, m; "
                  "0 drives every path to its end (the paper's scheme)")
      ->check(real_between(0.0, 20.0))
      ->capture_default_str();
  app->add_option("--hazard-memory", course.hazard_memory_cycles,
                  "Cycles whose steps and slopes the rover remembers to check the ground below "
                  "its cameras' view that its next drives begin on; 0 keeps nothing between "
                  "cycles, as the paper's navigation")
      ->transform(integer_between(0, 10))
      ->capture_default_str();
  app->add_option_function<std::string>(
         "--normal-path",
         [&course](const std::string& text) {
           const auto band = normal_path_band(text);
           course.motion.normal_min_m = band->first;
           course.motion.normal_max_m = band->second;
         },
         "Band of the motion scheme's normal paths, A..B m (the paper's 10..12; escapes are 3..4)")
      ->check(CLI::Validator(
          [](std::string& text) {
            return normal_path_band(text)
                       ? std::string()
                       : fmt::format("'{}': write A..B in metres, {} <= A <= "
                                     "B <= {}",
                                     text, kShortestNormalPath, kLongestNormalPath);
          },
          "A..B"));
  app->add_option("--step-baseline", course.step_baseline_m,
                  "The zones' step window, m (the world judges steps over 0.30)")
      ->check(real_between(0.05, 1.0))
      ->capture_default_str();
  app->add_option("--unseen-cell", course.unseen_cell_m,
                  "Keep each drive's footprint on ground the pair saw, judged on a grid of this "
                  "cell, m (0: the footprint may cross unseen ground)")
      ->check(real_between(0.0, 2.0))
      ->capture_default_str();
  app->add_option("--slip", course.slip,
                  "Mean wheel slip, 0..0.5: the ground gives each drive (1 - s) of what the "
                  "wheels turn, s drawn per drive around this mean, and the rover steers by its "
                  "dead-reckoned odometry")
      ->check(real_between(0.0, 0.5))
      ->capture_default_str();
  app->add_option("--faults", course.faults_file,
                  "A campaign file (docs/faults.md) whose fault mix strikes the emulated computer "
                  "once a course, in one of its first 8 cycles, the overswitch failing over; its "
                  "platform must be --platform's");
  app->add_option("--goal-m", course.goal_m, "Straight-line distance from the start to the goal, m")
      ->check(real_between(5.0, 180.0))
      ->capture_default_str();
}

void check_course_faults(const eval::TraverseSettings& course) {
  if (course.faults_file.empty())
    return;
  if (course.platform == "native")
    throw UsageError("--faults strike the emulated computer: give --platform onboard or pc-card");
  const eval::TraverseFaults faults(course.faults_file, course.seed);
  if (faults.platform_name() != course.platform)
    throw UsageError(
        fmt::format("--faults: the campaign file {} runs on '{}', not on --platform '{}'",
                    course.faults_file, faults.platform_name(), course.platform));
}

} // namespace marsokhod::apps
