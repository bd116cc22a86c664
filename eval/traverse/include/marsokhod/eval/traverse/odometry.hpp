// Dead-reckoned odometry: where the rover believes it is, from its wheels, when they slip.
#pragma once

#include "marsokhod/world/scene/rover_placement.hpp"
#include "marsokhod/world/terrain/seeded_random.hpp"

#include <cstdint>

namespace marsokhod::eval {

/// Wheel odometry with slip. Each drive the ground gives only (1 - s) of what the wheels turn,
/// with s drawn per drive uniformly in [0.5, 1.5) x mean_slip; the heading is known (turns are
/// measured, not counted in wheel turns). The estimate adds the true displacement scaled back
/// by 1 / (1 - s): a straight drive overshoots in the estimate, and the error grows with the
/// distance driven.
class Odometry {
public:
  /// Throws std::invalid_argument unless 0 <= mean_slip <= 0.5.
  Odometry(const world::RoverPose& start, double mean_slip, std::uint64_t seed);

  /// The share of each commanded length the ground gives the next drive: 1 - s.
  double next_drive_factor();
  /// Books a drive that took the rover from `from` to `to` on the true ground with `factor`.
  void book(const world::RoverPose& from, const world::RoverPose& to, double factor);

  const world::RoverPose& estimate() const { return estimate_; }

private:
  world::RoverPose estimate_;
  double mean_slip_;
  world::RandomStream rng_;
};

} // namespace marsokhod::eval
