// Tests: the two-lane terrain conversion against the plain per-pixel expression, bit for bit.

#include "support/test_files.hpp"
#include "terrain/terrain_rounding.hpp"

#include "marsokhod/nav/terrain/elevation.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

// reconstruct_terrain converts two pixels at a time; every field must be, bit for bit, what the
// plain per-pixel expression below gives, whatever the disparity (tiny, huge, negative, NaN).

namespace marsokhod::nav {
namespace {

using test_support::kInf;

void expect_same_bits(float got, float want, int u, int v) {
  ASSERT_EQ(std::bit_cast<std::uint32_t>(got), std::bit_cast<std::uint32_t>(want))
      << u << "," << v << ": " << got << " vs " << want;
}

float random_disparity(std::mt19937_64& random) {
  const std::uint64_t kind = random() % 16;
  if (kind == 0)
    return std::numeric_limits<float>::quiet_NaN();
  if (kind == 1)
    return kInf;
  if (kind == 2)
    return -1.0F;
  if (kind == 3)
    return std::bit_cast<float>(static_cast<std::uint32_t>(random() % 0x7f800000U));
  return static_cast<float>(random() % 4000) / 64.0F;
}

TEST(ReconstructTerrain, MatchesThePlainExpressionBitForBit) {
  std::mt19937_64 random(5511);
  for (const int side : {16, 17, 64, 65}) {
    imaging::RigParameters p;
    p.width_px = side;
    p.height_px = side + 3;
    const imaging::StereoRig rig(p);
    const imaging::Attitude attitude{3.0, -2.0};
    imaging::Image<float> disparity(rig.width(), rig.height(), 1, kInf);
    for (int v = 0; v < rig.height(); ++v)
      for (int u = 0; u < rig.width(); ++u)
        disparity(u, v) = random_disparity(random);
    const TerrainPoints terrain = reconstruct_terrain(disparity, rig, attitude);
    const Eigen::Isometry3d pose = rig.camera_to_level(imaging::Eye::left, attitude);
    std::uint64_t known = 0;
    for (int v = 0; v < rig.height(); ++v) {
      const Eigen::Vector3d row =
          pose.linear() * Eigen::Vector3d(-rig.cx(), v - rig.cy(), rig.focal_px());
      for (int u = 0; u < rig.width(); ++u) {
        const float d = disparity(u, v);
        float want[4] = {kInf, kInf, kInf, kInf};
        if (d > 0.0F && std::isfinite(d)) {
          const Eigen::Vector3d point =
              pose.translation() +
              (rig.baseline_m() / d) * (row + u * Eigen::Vector3d(pose.linear().col(0)));
          want[0] = static_cast<float>(point.x());
          want[1] = static_cast<float>(point.y());
          want[2] = static_cast<float>(point.z());
          want[3] = static_cast<float>(std::hypot(point.x(), point.y()));
          ++known;
        }
        expect_same_bits(terrain.forward(u, v), want[0], u, v);
        expect_same_bits(terrain.left(u, v), want[1], u, v);
        expect_same_bits(terrain.elevation(u, v), want[2], u, v);
        expect_same_bits(terrain.range(u, v), want[3], u, v);
      }
    }
    EXPECT_EQ(terrain.known_pixels, known);
  }
}

// The plain test ground_distance() makes of a root in range.
bool rounding_settled(double estimate) {
  const auto rounded = static_cast<float>(estimate);
  return static_cast<float>(estimate * (1.0 - 1e-15)) == rounded &&
         static_cast<float>(estimate * (1.0 + 1e-15)) == rounded;
}

// Roots near the float rounding midpoints, powers of two and the ends of the float range.
TEST(SettledRoundings, ImpliesThePlainTest) {
  std::mt19937_64 random(8093);
  int settled_near_midpoints = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const int exponent = static_cast<int>(random() % 300) - 150;
    const double base =
        std::ldexp(1.0 + static_cast<double>(random() % (1U << 23)) * 0x1p-23, exponent);
    const std::int64_t offset = static_cast<std::int64_t>(random() % 81) - 40;
    const std::uint64_t midpoint =
        std::bit_cast<std::uint64_t>(base) + (trial % 3 == 0 ? 0 : (1ULL << 28));
    const double a = std::bit_cast<double>(midpoint + static_cast<std::uint64_t>(offset));
    const double b = std::bit_cast<double>(random() >> 1);
    const int bits = detail::settled_roundings(detail::Doubles2{a, b});
    if ((bits & 1) != 0) {
      ASSERT_TRUE(rounding_settled(a)) << a;
      settled_near_midpoints += 1;
    }
    ASSERT_TRUE((bits & 2) == 0 || rounding_settled(b)) << b;
  }
  EXPECT_GT(settled_near_midpoints, 10000);
}

} // namespace
} // namespace marsokhod::nav
