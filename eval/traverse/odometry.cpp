// Dead-reckoned odometry with per-drive wheel slip.
#include "marsokhod/eval/traverse/odometry.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace marsokhod::eval {
namespace {

// The slip stream's label, apart from the site's and the render noise's seeds.
constexpr std::uint64_t kSlipStream = 0x5117;

} // namespace

Odometry::Odometry(const world::RoverPose& start, double mean_slip, std::uint64_t seed)
    : estimate_(start), mean_slip_(mean_slip), rng_(world::substream_seed(seed, kSlipStream)) {
  if (!(mean_slip >= 0.0 && mean_slip <= 0.5))
    throw std::invalid_argument(
        fmt::format("odometry: slip = {} must be within 0..0.5", mean_slip));
}

double Odometry::next_drive_factor() {
  if (mean_slip_ == 0.0)
    return 1.0;
  return 1.0 - mean_slip_ * rng_.uniform(0.5, 1.5);
}

void Odometry::book(const world::RoverPose& from, const world::RoverPose& to, double factor) {
  estimate_.x += (to.x - from.x) / factor;
  estimate_.y += (to.y - from.y) / factor;
  estimate_.heading_deg += to.heading_deg - from.heading_deg;
}

} // namespace marsokhod::eval
