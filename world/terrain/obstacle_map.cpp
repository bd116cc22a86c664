// The obstacle map: steps and slopes over the locomotion limits' baselines, by sliding extremes.

#include "marsokhod/world/terrain/obstacle_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::world {
namespace {

void require_positive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("LocomotionLimits: ") + name +
                                " must be positive and finite");
}

/// out[i] = pick over in[i - s .. i + s] (clipped to the array), by van Herk / Gil-Werman:
/// prefix and suffix extremes within blocks of 2s+1, three operations per element whatever s.
template <class Pick>
void sliding_extreme(const float* in, float* out, int n, int s, float identity, Pick pick,
                     std::vector<float>& g, std::vector<float>& h) {
  const int w = 2 * s + 1;
  const int padded = (n + 2 * s + w - 1) / w * w;
  g.assign(static_cast<std::size_t>(padded), identity);
  std::copy(in, in + n, g.begin() + s);
  h = g;
  for (int block = 0; block < padded; block += w)
    for (int k = block + 1; k < block + w; ++k)
      g[static_cast<std::size_t>(k)] =
          pick(g[static_cast<std::size_t>(k) - 1], g[static_cast<std::size_t>(k)]);
  for (int block = padded - w; block >= 0; block -= w)
    for (int k = block + w - 2; k >= block; --k)
      h[static_cast<std::size_t>(k)] =
          pick(h[static_cast<std::size_t>(k) + 1], h[static_cast<std::size_t>(k)]);
  for (int i = 0; i < n; ++i)
    out[i] = pick(h[static_cast<std::size_t>(i)], g[static_cast<std::size_t>(i + 2 * s)]);
}

/// The same van Herk / Gil-Werman extreme down the columns, done on strips of whole rows so
/// that every operation runs along contiguous memory.
template <class Pick>
void column_extreme(const imaging::Image<float>& in, imaging::Image<float>& out, int s,
                    float identity, Pick pick) {
  constexpr int kStrip = 256;
  const int nx = in.width();
  const int ny = in.height();
  const int w = 2 * s + 1;
  const int padded = (ny + 2 * s + w - 1) / w * w;
  std::vector<float> g(static_cast<std::size_t>(padded) * kStrip);
  std::vector<float> h(g.size());
  const auto line = [](std::vector<float>& buffer, int r) {
    return buffer.data() + static_cast<std::ptrdiff_t>(r) * kStrip;
  };
  for (int x0 = 0; x0 < nx; x0 += kStrip) {
    const int width = std::min(kStrip, nx - x0);
    for (int r = 0; r < padded; ++r) {
      const int j = r - s;
      if (j >= 0 && j < ny)
        std::copy(in.row(j) + x0, in.row(j) + x0 + width, line(g, r));
      else
        std::fill(line(g, r), line(g, r) + width, identity);
    }
    std::copy(g.begin(), g.end(), h.begin());
    for (int block = 0; block < padded; block += w)
      for (int r = block + 1; r < block + w; ++r) {
        float* current = line(g, r);
        const float* previous = line(g, r - 1);
        for (int c = 0; c < width; ++c)
          current[c] = pick(previous[c], current[c]);
      }
    for (int block = padded - w; block >= 0; block -= w)
      for (int r = block + w - 2; r >= block; --r) {
        float* current = line(h, r);
        const float* next = line(h, r + 1);
        for (int c = 0; c < width; ++c)
          current[c] = pick(next[c], current[c]);
      }
    for (int j = 0; j < ny; ++j) {
      const float* upper = line(h, j);
      const float* lower = line(g, j + 2 * s);
      float* target = out.row(j) + x0;
      for (int c = 0; c < width; ++c)
        target[c] = pick(upper[c], lower[c]);
    }
  }
}

/// Extreme of the heights over the (2s+1)^2 square window around every node (separable).
template <class Pick>
imaging::Image<float> window_extreme(const imaging::Image<float>& heights, int s, float identity,
                                     Pick pick) {
  const int nx = heights.width();
  const int ny = heights.height();
  imaging::Image<float> along_rows(nx, ny);
  std::vector<float> g;
  std::vector<float> h;
  for (int j = 0; j < ny; ++j)
    sliding_extreme(heights.row(j), along_rows.row(j), nx, s, identity, pick, g, h);
  imaging::Image<float> result(nx, ny);
  column_extreme(along_rows, result, s, identity, pick);
  return result;
}

void flag_steps(const HeightField& height, const LocomotionLimits& limits,
                imaging::Image<std::uint8_t>& flags) {
  const int s =
      std::max(1, static_cast<int>(std::lround(limits.step_baseline_m / height.cell_m())));
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  const imaging::Image<float> highest = window_extreme(
      height.nodes(), s, -kInfinity, [](float a, float b) { return a > b ? a : b; });
  const imaging::Image<float> lowest =
      window_extreme(height.nodes(), s, kInfinity, [](float a, float b) { return a < b ? a : b; });
  const auto step = static_cast<float>(limits.max_step_m);
  for (int j = 0; j < height.ny(); ++j)
    for (int i = 0; i < height.nx(); ++i) {
      const float z = height.at(i, j);
      if (highest(i, j) - z > step || z - lowest(i, j) > step)
        flags(i, j) = kObstacle;
    }
}

void flag_slopes(const HeightField& height, const LocomotionLimits& limits,
                 imaging::Image<std::uint8_t>& flags) {
  const double cell = height.cell_m();
  const int d = std::max(1, static_cast<int>(std::lround(0.5 * limits.slope_baseline_m / cell)));
  const double tan_limit = std::tan(limits.max_slope_deg * std::numbers::pi / 180.0);
  const auto limit2 = static_cast<float>(tan_limit * tan_limit);
  const imaging::Image<float>& z = height.nodes();
  const int nx = height.nx();
  const int ny = height.ny();
  for (int j = 0; j < ny; ++j) {
    const int j0 = std::max(0, j - d);
    const int j1 = std::min(ny - 1, j + d);
    const float* low = z.row(j0);
    const float* mid = z.row(j);
    const float* high = z.row(j1);
    const auto inv_dy = static_cast<float>(1.0 / (3.0 * (j1 - j0) * cell));
    std::uint8_t* out = flags.row(j);
    for (int i = 0; i < nx; ++i) {
      const int i0 = std::max(0, i - d);
      const int i1 = std::min(nx - 1, i + d);
      const float column_low = low[i0] + mid[i0] + high[i0];
      const float column_high = low[i1] + mid[i1] + high[i1];
      const float row_low = low[i0] + low[i] + low[i1];
      const float row_high = high[i0] + high[i] + high[i1];
      const float gx = (column_high - column_low) / (3.0f * static_cast<float>((i1 - i0) * cell));
      const float gy = (row_high - row_low) * inv_dy;
      if (gx * gx + gy * gy > limit2)
        out[i] = kObstacle;
    }
  }
}

} // namespace

void validate(const LocomotionLimits& limits) {
  require_positive(limits.max_step_m, "max_step_m");
  require_positive(limits.step_baseline_m, "step_baseline_m");
  require_positive(limits.slope_baseline_m, "slope_baseline_m");
  if (!(limits.max_slope_deg > 0.0 && limits.max_slope_deg < 90.0))
    throw std::invalid_argument("LocomotionLimits: max_slope_deg must be in (0, 90)");
}

imaging::Image<std::uint8_t> obstacle_map(const HeightField& height,
                                          const LocomotionLimits& limits) {
  validate(limits);
  imaging::Image<std::uint8_t> flags(height.nx(), height.ny(), 1, 0);
  if (height.nx() < 2 || height.ny() < 2)
    return flags;
  flag_steps(height, limits, flags);
  flag_slopes(height, limits, flags);
  return flags;
}

} // namespace marsokhod::world
