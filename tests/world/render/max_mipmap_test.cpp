// Tests: the maximum mipmap's levels, ray hits and slope bounds against dense marches.

#include "world/hand_scenes.hpp"

#include "marsokhod/world/render/max_mipmap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>

namespace {

using marsokhod::world::HeightField;
using marsokhod::world::MaxMipmap;

double uniform(std::mt19937_64& engine, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

// Bumpy 3 m x 3 m field at 2 cm: a few smooth hills plus per-node roughness.
HeightField bumpy_field() {
  HeightField field(151, 151, 0.02, Eigen::Vector2d(-1.5, -1.5));
  std::mt19937_64 engine(42);
  for (int j = 0; j < field.ny(); ++j)
    for (int i = 0; i < field.nx(); ++i) {
      const double x = -1.5 + 0.02 * i;
      const double y = -1.5 + 0.02 * j;
      field.at(i, j) = static_cast<float>(0.2 * std::sin(2.1 * x) * std::cos(1.7 * y) +
                                          0.1 * std::exp(-((x - 0.4) * (x - 0.4) + y * y) / 0.05) +
                                          uniform(engine, 0.0, 0.01));
    }
  return field;
}

// Reference: march along the ray in 0.1 mm steps with the height field's own bilinear
// evaluation, then bisect the first sign change of (ray z - surface z).
std::optional<double> marched_hit(const HeightField& field, const Eigen::Vector3d& origin,
                                  const Eigen::Vector3d& direction, double t_max) {
  const double step = 1e-4;
  auto above = [&](double t) {
    const Eigen::Vector3d p = origin + t * direction;
    return p.z() - field.height(p.x(), p.y());
  };
  auto inside = [&](double t) {
    const Eigen::Vector3d p = origin + t * direction;
    return field.contains(p.x(), p.y());
  };
  double previous = 0.0;
  for (double t = 0.0; t <= t_max; t += step) {
    if (!inside(t)) {
      if (t > 0.0 && inside(previous))
        return std::nullopt; // left the grid
      previous = t;
      continue;
    }
    if (above(t) <= 0.0) {
      if (t == 0.0 || !inside(previous))
        return t;
      double lo = previous;
      double hi = t;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (above(mid) > 0.0 ? lo : hi) = mid;
      }
      return hi;
    }
    previous = t;
  }
  return std::nullopt;
}

TEST(MaxMipmap, LevelsHoldTheHighestCornerOfEveryCellBelow) {
  const HeightField field = bumpy_field();
  const MaxMipmap mipmap(field);
  ASSERT_EQ(mipmap.blocks_x(0), 150);
  EXPECT_EQ(mipmap.blocks_x(mipmap.levels() - 1), 1);
  EXPECT_EQ(mipmap.blocks_y(mipmap.levels() - 1), 1);
  float highest = -1e9f;
  for (int j = 0; j < field.ny(); ++j)
    for (int i = 0; i < field.nx(); ++i)
      highest = std::max(highest, field.at(i, j));
  EXPECT_EQ(mipmap.max_height(mipmap.levels() - 1, 0, 0), highest);
  // Level 2 block (3, 5) covers cells 12..15 x 20..23, i.e. nodes 12..16 x 20..24.
  float block = -1e9f;
  for (int j = 20; j <= 24; ++j)
    for (int i = 12; i <= 16; ++i)
      block = std::max(block, field.at(i, j));
  EXPECT_EQ(mipmap.max_height(2, 3, 5), block);
}

TEST(MaxMipmap, FirstHitMatchesADenseMarchOnABumpyField) {
  const HeightField field = bumpy_field();
  const MaxMipmap mipmap(field);
  std::mt19937_64 engine(7);
  int hits = 0;
  for (int n = 0; n < 300; ++n) {
    const Eigen::Vector3d origin(uniform(engine, -1.4, 1.4), uniform(engine, -1.4, 1.4),
                                 uniform(engine, 0.35, 1.2));
    const double azimuth = uniform(engine, 0.0, 2.0 * std::numbers::pi);
    const double dip = uniform(engine, 0.03, 0.9); // radians below the horizontal
    const Eigen::Vector3d direction(std::cos(dip) * std::cos(azimuth),
                                    std::cos(dip) * std::sin(azimuth), -std::sin(dip));
    const auto expected = marched_hit(field, origin, direction, 6.0);
    const auto got = mipmap.first_hit(origin, direction);
    ASSERT_EQ(expected.has_value(), got.has_value()) << "ray " << n;
    if (!expected)
      continue;
    ++hits;
    EXPECT_NEAR(*got, *expected, 1e-6) << "ray " << n;
    const Eigen::Vector3d p = origin + *got * direction;
    EXPECT_NEAR(p.z(), field.height(p.x(), p.y()), 1e-6) << "ray " << n;
  }
  EXPECT_GT(hits, 100);
}

TEST(MaxMipmap, VerticalAndAxisParallelRaysHitTheBilinearSurface) {
  const HeightField field = bumpy_field();
  const MaxMipmap mipmap(field);
  const Eigen::Vector3d down(0.0, 0.0, -1.0);
  const Eigen::Vector3d top(0.123, -0.456, 2.0);
  const auto vertical = mipmap.first_hit(top, down);
  ASSERT_TRUE(vertical);
  EXPECT_NEAR(top.z() - *vertical, field.height(top.x(), top.y()), 1e-9);

  // Along a grid line (y on a node row) and dipping in x only.
  const Eigen::Vector3d along_row = Eigen::Vector3d(1.0, 0.0, -0.2).normalized();
  const Eigen::Vector3d start(-1.4, -0.5, 0.6);
  const auto expected = marched_hit(field, start, along_row, 4.0);
  const auto got = mipmap.first_hit(start, along_row);
  ASSERT_EQ(expected.has_value(), got.has_value());
  // Both absent compares 0 with 0.
  EXPECT_NEAR(got.value_or(0.0), expected.value_or(0.0), 1e-6);
}

TEST(MaxMipmap, RaysAboveEverythingOrOutsideTheGridMiss) {
  const HeightField field = bumpy_field();
  const MaxMipmap mipmap(field);
  EXPECT_FALSE(mipmap.first_hit({0.0, 0.0, 2.0}, Eigen::Vector3d(1.0, 0.2, 0.1).normalized()));
  EXPECT_FALSE(mipmap.first_hit({5.0, 5.0, 1.0}, Eigen::Vector3d(0.0, 0.0, -1.0)));
  EXPECT_FALSE(mipmap.first_hit({5.0, 0.0, 1.0}, Eigen::Vector3d(1.0, 0.0, -0.1).normalized()));
}

TEST(MaxMipmap, RayEnteringFromOutsideTheGridFindsTheSurface) {
  HeightField field(101, 101, 0.02, Eigen::Vector2d(0.0, 0.0)); // flat at 0, 2 m x 2 m
  const MaxMipmap mipmap(field);
  // From x = -1 at 0.5 m height, dipping 0.25 m per metre: meets z = 0 at x = 1.
  const Eigen::Vector3d direction = Eigen::Vector3d(1.0, 0.0, -0.25).normalized();
  const auto hit = mipmap.first_hit({-1.0, 1.0, 0.5}, direction);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(*hit, std::hypot(2.0, 0.5), 1e-9);
}

TEST(MaxMipmap, HitsBeyondTheRangeLimitAreIgnored) {
  HeightField field(101, 101, 0.02, Eigen::Vector2d(0.0, 0.0));
  const MaxMipmap mipmap(field);
  const Eigen::Vector3d down(0.0, 0.0, -1.0);
  EXPECT_FALSE(mipmap.first_hit({1.0, 1.0, 0.5}, down, 0.49));
  const auto hit = mipmap.first_hit({1.0, 1.0, 0.5}, down, 0.51);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(*hit, 0.5, 1e-12);
}

} // namespace

namespace {

TEST(MaxMipmap, SteepestGradientOfAPlaneIsItsSlope) {
  // z = 0.3 x - 0.4 y: gradient (0.3, -0.4), magnitude 0.5 by hand.
  HeightField field(21, 21, 0.05);
  for (int j = 0; j < field.ny(); ++j)
    for (int i = 0; i < field.nx(); ++i)
      field.at(i, j) = static_cast<float>(0.3 * 0.05 * i - 0.4 * 0.05 * j);
  EXPECT_NEAR(MaxMipmap(field).steepest_gradient(), 0.5, 1e-5);
}

TEST(MaxMipmap, NoTwoSurfacePointsDifferMoreThanTheSteepestGradientAllows) {
  const HeightField field = bumpy_field();
  const double lipschitz = MaxMipmap(field).steepest_gradient();
  std::mt19937_64 engine(11);
  double steepest_seen = 0.0;
  for (int n = 0; n < 20000; ++n) {
    const Eigen::Vector2d p(uniform(engine, -1.5, 1.5), uniform(engine, -1.5, 1.5));
    const Eigen::Vector2d q =
        p + Eigen::Vector2d(uniform(engine, -0.05, 0.05), uniform(engine, -0.05, 0.05));
    if (!field.contains(q.x(), q.y()))
      continue;
    const double slope =
        std::abs(field.height(p.x(), p.y()) - field.height(q.x(), q.y())) / (p - q).norm();
    EXPECT_LE(slope, lipschitz * (1.0 + 1e-9)) << n;
    steepest_seen = std::max(steepest_seen, slope);
  }
  // The bound is at most sqrt(2) times the true constant (bilinear cells, see slope_levels.cpp).
  EXPECT_GT(steepest_seen, lipschitz / std::sqrt(2.0) * 0.8);
}

TEST(MaxMipmap, FirstHitBeyondAStartBeforeTheHitFindsTheSameHit) {
  const HeightField field = bumpy_field();
  const MaxMipmap mipmap(field);
  std::mt19937_64 engine(5);
  int compared = 0;
  for (int n = 0; n < 300; ++n) {
    const Eigen::Vector3d origin(uniform(engine, -1.4, 1.4), uniform(engine, -1.4, 1.4),
                                 uniform(engine, 0.35, 1.2));
    const double azimuth = uniform(engine, 0.0, 2.0 * std::numbers::pi);
    const double dip = uniform(engine, 0.03, 0.9);
    const Eigen::Vector3d direction(std::cos(dip) * std::cos(azimuth),
                                    std::cos(dip) * std::sin(azimuth), -std::sin(dip));
    const auto full = mipmap.first_hit(origin, direction);
    if (!full)
      continue;
    const auto beyond = mipmap.first_hit_beyond(origin, direction, *full * uniform(engine, 0, 1));
    ASSERT_TRUE(beyond.has_value()) << n;
    EXPECT_NEAR(*beyond, *full, 1e-9) << n;
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

// The bumpy field with a 0.3 m block on it: steep at the block's sides, gentle elsewhere.
HeightField field_with_a_block() {
  HeightField field = bumpy_field();
  for (int j = 90; j <= 100; ++j)
    for (int i = 30; i <= 45; ++i)
      field.at(i, j) += 0.3F;
  return field;
}

TEST(MaxMipmap, BlockSlopeBoundsHoldForSegmentsUpToACellFromTheBlock) {
  const HeightField field = field_with_a_block();
  const MaxMipmap mipmap(field);
  std::mt19937_64 engine(13);
  const double cell = field.cell_m();
  int gentler = 0;
  for (int n = 0; n < 20000; ++n) {
    const int level = MaxMipmap::kSlopeLevel + static_cast<int>(engine() % 3);
    const int bx = static_cast<int>(engine() % mipmap.blocks_x(level));
    const int by = static_cast<int>(engine() % mipmap.blocks_y(level));
    const double side = cell * (1 << level);
    const Eigen::Vector2d p =
        field.origin() +
        Eigen::Vector2d(bx + uniform(engine, 0, 1), by + uniform(engine, 0, 1)) * side;
    const double angle = uniform(engine, 0.0, 2.0 * std::numbers::pi);
    const Eigen::Vector2d q =
        p + uniform(engine, 0.0, cell) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    if (!field.contains(p.x(), p.y()) || !field.contains(q.x(), q.y()) || (p - q).norm() == 0.0)
      continue;
    const double slope =
        std::abs(field.height(p.x(), p.y()) - field.height(q.x(), q.y())) / (p - q).norm();
    const double bound = mipmap.steepest_gradient_near(level, bx, by);
    EXPECT_LE(slope, bound * (1.0 + 1e-9)) << n;
    EXPECT_LE(bound, static_cast<float>(mipmap.steepest_gradient()));
    if (bound < mipmap.steepest_gradient() / 4.0)
      ++gentler;
  }
  // Away from the block the local bounds are far below the whole surface's.
  EXPECT_GT(gentler, 10000);
}

// Any `gentle` is a true premise for a start short of the hit (the ray meets nothing before
// it at all), so the walk must find the same hit whichever blocks it skips unseen.
TEST(MaxMipmap, FirstHitBeyondGentleFindsTheSameHit) {
  const HeightField field = field_with_a_block();
  const MaxMipmap mipmap(field);
  std::mt19937_64 engine(17);
  int compared = 0;
  for (int n = 0; n < 600; ++n) {
    const Eigen::Vector3d origin(uniform(engine, -1.4, 1.4), uniform(engine, -1.4, 1.4),
                                 uniform(engine, 0.5, 1.2));
    const double azimuth = uniform(engine, 0.0, 2.0 * std::numbers::pi);
    const double dip = uniform(engine, 0.03, 0.9);
    const Eigen::Vector3d direction(std::cos(dip) * std::cos(azimuth),
                                    std::cos(dip) * std::sin(azimuth), -std::sin(dip));
    const auto full = mipmap.first_hit(origin, direction);
    if (!full)
      continue;
    const double gentle = n % 4 == 0 ? std::numeric_limits<double>::infinity()
                                     : uniform(engine, 0.0, mipmap.steepest_gradient());
    const auto got = mipmap.first_hit_beyond_gentle(
        origin, direction, *full * uniform(engine, 0, 1), gentle, mipmap.start_level(origin));
    ASSERT_TRUE(got.has_value()) << n;
    EXPECT_NEAR(*got, *full, 1e-9) << n;
    ++compared;
  }
  EXPECT_GT(compared, 200);
}

} // namespace
