// Zone rule: unseen, out-of-range and unreliable pixels marked before the other rules.

#include "zones/zone_bytes.hpp"
#include "zones/zone_rules.hpp"

#include <cmath>
#include <limits>

namespace marsokhod::nav::detail {
namespace {

// The largest float not above `limit`: a float lies beyond `limit` exactly when it lies beyond
// this one, so the range test runs on floats, four to a register, with the same outcome.
float float_at_most(double limit) {
  constexpr float kLargest = std::numeric_limits<float>::max();
  if (limit >= static_cast<double>(kLargest))
    return kLargest;
  const auto nearest = static_cast<float>(limit);
  if (static_cast<double>(nearest) <= limit)
    return nearest;
  return std::nextafter(nearest, -std::numeric_limits<float>::infinity());
}

// Seen (finite elevation; NaN and infinities fail the magnitude test) and within range (a NaN
// range is not beyond it). Branch-free (& rather than &&), so that the loop vectorises.
void mark_seen(const float* elevation, const float* range, float max_range, int width,
               std::uint8_t* out) {
  constexpr float kLargest = std::numeric_limits<float>::max();
  for (int x = 0; x < width; ++x) {
    const bool seen = (std::fabs(elevation[x]) <= kLargest) & !(range[x] > max_range);
    out[x] = seen ? kTraversableZone : kUnknownZone;
  }
}

// Seen pixels the left-right check rejected; returns whether there were any. Bridging judges
// only points within range, which a NaN range is not: such a pixel is unknown outright. The
// mask's channel 0 is read `channels` bytes apart: a mask of one channel gets a loop of its own,
// which vectorises.
bool hold_back_unreliable(const std::uint8_t* reliable, std::ptrdiff_t channels, const float* range,
                          int width, std::uint8_t* out) {
  std::uint8_t any = 0;
  const auto hold = [&](int x, std::uint8_t reliable_byte) {
    const bool rejected = (out[x] == kTraversableZone) & (reliable_byte == 0);
    const bool held = rejected & !std::isnan(range[x]);
    out[x] = held ? kUnreliable : rejected ? kUnknownZone : out[x];
    any |= held ? 1 : 0;
  };
  if (channels == 1)
    for (int x = 0; x < width; ++x)
      hold(x, reliable[x]);
  else
    for (int x = 0; x < width; ++x)
      hold(x, reliable[x * channels]);
  return any != 0;
}

} // namespace

bool mark_unknown(const TerrainRows& terrain, imaging::ImageView<const std::uint8_t> reliable,
                  const ZoneOptions& options, imaging::Image<std::uint8_t>& zone) {
  const bool use_reliable = options.unreliable_is_unknown && !reliable.empty();
  const float max_range = float_at_most(options.max_range_m);
  bool any_unreliable = false;
  for (int y = 0; y < terrain.height(); ++y) {
    std::uint8_t* out = zone.row(y);
    const TerrainRows::Row row = terrain.row(y);
    mark_seen(row.elevation, row.range, max_range, terrain.width(), out);
    if (use_reliable)
      any_unreliable |= hold_back_unreliable(reliable.row(y), reliable.channels(), row.range,
                                             terrain.width(), out);
  }
  return any_unreliable;
}

} // namespace marsokhod::nav::detail
