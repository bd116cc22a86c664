// Tests: the terrain generator's determinism, grid, rock cover, craters, slope and albedo.

#include "marsokhod/world/terrain/terrain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace marsokhod::world {
namespace {

TerrainSettings small_site(std::uint64_t seed = 7) {
  TerrainSettings settings;
  settings.seed = seed;
  settings.size_m = 10.0;
  return settings;
}

template <class T>
bool same_bytes(const imaging::Image<T>& a, const imaging::Image<T>& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(TerrainGenerator, SameSettingsGiveByteIdenticalSites) {
  const Terrain a = Terrain::generate(small_site());
  const Terrain b = Terrain::generate(small_site());
  EXPECT_TRUE(same_bytes(a.height.nodes(), b.height.nodes()));
  EXPECT_TRUE(same_bytes(a.albedo, b.albedo));
  EXPECT_TRUE(same_bytes(a.obstacles, b.obstacles));
}

TEST(TerrainGenerator, DifferentSeedsGiveDifferentSites) {
  const Terrain a = Terrain::generate(small_site(1));
  const Terrain b = Terrain::generate(small_site(2));
  std::size_t differing = 0;
  for (std::size_t k = 0; k < a.height.nodes().size(); ++k)
    differing += a.height.nodes().data()[k] != b.height.nodes().data()[k];
  EXPECT_GT(differing, a.height.nodes().size() * 9 / 10);
  EXPECT_FALSE(same_bytes(a.albedo, b.albedo));
}

TEST(TerrainGenerator, GridIsCentredOnTheOriginWithSizeOverCellNodes) {
  const Terrain site = Terrain::generate(small_site());
  ASSERT_EQ(site.height.nx(), 500); // 10 m / 2 cm
  ASSERT_EQ(site.height.ny(), 500);
  EXPECT_NEAR(site.height.origin().x(), -0.5 * 499 * 0.02, 1e-12);
  EXPECT_NEAR(site.height.node_position(499, 499).x(), 0.5 * 499 * 0.02, 1e-9);
  EXPECT_EQ(site.albedo.width(), 500);
  EXPECT_EQ(site.obstacles.height(), 500);
}

TEST(TerrainGenerator, StripHasItsTwoSidesCentredOnTheOrigin) {
  TerrainSettings settings = small_site();
  settings.size_m = 20.0;
  settings.width_m = 6.0;
  const Terrain strip = Terrain::generate(settings);
  ASSERT_EQ(strip.height.nx(), 1000); // 20 m / 2 cm east-west
  ASSERT_EQ(strip.height.ny(), 300);  // 6 m / 2 cm north-south
  EXPECT_NEAR(strip.height.origin().x(), -0.5 * 999 * 0.02, 1e-12);
  EXPECT_NEAR(strip.height.origin().y(), -0.5 * 299 * 0.02, 1e-12);
  EXPECT_EQ(strip.albedo.width(), 1000);
  EXPECT_EQ(strip.obstacles.height(), 300);
}

/// Fraction of the nodes farther than `radius` from the origin where the two sites differ in
/// height by more than a millimetre, i.e. where rocks stand.
double covered_fraction(const Terrain& with_rocks, const Terrain& bare, double radius) {
  std::size_t covered = 0;
  std::size_t counted = 0;
  for (int j = 0; j < bare.height.ny(); ++j)
    for (int i = 0; i < bare.height.nx(); ++i) {
      if (bare.height.node_position(i, j).norm() <= radius)
        continue;
      ++counted;
      covered += with_rocks.height.at(i, j) - bare.height.at(i, j) > 0.001f;
    }
  return static_cast<double>(covered) / static_cast<double>(counted);
}

TEST(TerrainGenerator, RealisedRockCoverMatchesTheSetting) {
  for (const double cover : {0.05, 0.10, 0.20}) {
    TerrainSettings settings;
    settings.seed = 11;
    settings.size_m = 24.0;
    settings.rock_cover = cover;
    const Terrain rocky = Terrain::generate(settings);
    settings.rock_cover = 0.0;
    const Terrain bare = Terrain::generate(settings);
    const double measured = covered_fraction(rocky, bare, settings.clear_radius_m + 1.0);
    EXPECT_NEAR(measured, cover, 0.1 * cover) << "rock_cover " << cover;
  }
}

TEST(TerrainGenerator, RockCoverOfAStripMatchesTheSetting) {
  TerrainSettings settings;
  settings.seed = 12;
  settings.size_m = 60.0;
  settings.width_m = 10.0;
  settings.rock_cover = 0.10;
  const Terrain rocky = Terrain::generate(settings);
  settings.rock_cover = 0.0;
  const Terrain bare = Terrain::generate(settings);
  EXPECT_NEAR(covered_fraction(rocky, bare, settings.clear_radius_m + 1.0), 0.10, 0.01);
}

// The disc around `centre` (radius 2 m) is left bare; rocks and craters land outside it.
void expect_clear_disc_around(const Eigen::Vector2d& centre) {
  TerrainSettings settings = small_site(5);
  settings.rock_cover = 0.3;
  settings.crater_density = 0.2;
  settings.clear_radius_m = 2.0;
  settings.clear_centre = centre;
  const Terrain busy = Terrain::generate(settings);
  settings.rock_cover = 0.0;
  settings.crater_density = 0.0;
  const Terrain bare = Terrain::generate(settings);
  std::size_t inside = 0;
  std::size_t changed_outside = 0;
  for (int j = 0; j < bare.height.ny(); ++j)
    for (int i = 0; i < bare.height.nx(); ++i) {
      const bool differs = busy.height.at(i, j) != bare.height.at(i, j);
      if ((bare.height.node_position(i, j) - centre).norm() < settings.clear_radius_m) {
        ++inside;
        EXPECT_FALSE(differs) << "node " << i << ", " << j;
        if (differs)
          return;
      } else {
        changed_outside += differs;
      }
    }
  EXPECT_GT(inside, 30000u);
  EXPECT_GT(changed_outside, 10000u); // rocks and craters did land outside the disc
}

TEST(TerrainGenerator, ClearDiscHasNeitherRocksNorCraters) {
  expect_clear_disc_around(Eigen::Vector2d::Zero());
}

TEST(TerrainGenerator, ClearDiscFollowsItsCentre) {
  expect_clear_disc_around(Eigen::Vector2d(3.0, -2.5));
}

/// Number of 4-connected regions of nodes below `level`.
int depressions_below(const HeightField& height, float level) {
  const int nx = height.nx();
  const int ny = height.ny();
  std::vector<char> seen(static_cast<std::size_t>(nx) * ny, 0);
  std::vector<int> stack;
  int regions = 0;
  for (int start = 0; start < nx * ny; ++start) {
    if (seen[start] || height.at(start % nx, start / nx) >= level)
      continue;
    ++regions;
    stack.push_back(start);
    seen[start] = 1;
    while (!stack.empty()) {
      const int node = stack.back();
      stack.pop_back();
      const int i = node % nx;
      const int j = node / nx;
      for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int a = i + di;
        const int b = j + dj;
        if (a < 0 || b < 0 || a >= nx || b >= ny)
          continue;
        const int next = b * nx + a;
        if (!seen[next] && height.at(a, b) < level) {
          seen[next] = 1;
          stack.push_back(next);
        }
      }
    }
  }
  return regions;
}

TEST(TerrainGenerator, CratersArePresentAtTheRequestedDensity) {
  TerrainSettings settings;
  settings.seed = 3;
  settings.size_m = 20.0;
  settings.rock_cover = 0.0;
  settings.undulation_m = 0.0;
  settings.regional_slope_deg = 0.0;
  settings.crater_density = 0.05; // 20 expected on 400 m^2
  const Terrain cratered = Terrain::generate(settings);
  const int regions = depressions_below(cratered.height, -0.05f);
  EXPECT_GE(regions, 8);
  EXPECT_LE(regions, 32);

  settings.crater_density = 0.0;
  const Terrain smooth = Terrain::generate(settings);
  EXPECT_EQ(depressions_below(smooth.height, -0.05f), 0); // roughness alone stays above
}

TEST(TerrainGenerator, RegionalSlopeTiltsTheSite) {
  TerrainSettings settings = small_site(21);
  settings.rock_cover = 0.0;
  settings.crater_density = 0.0;
  settings.undulation_m = 0.0;
  settings.regional_slope_deg = 10.0;
  const Terrain site = Terrain::generate(settings);
  // Least-squares gradient over the whole grid (symmetric about the origin).
  double sxz = 0.0;
  double syz = 0.0;
  double sxx = 0.0;
  for (int j = 0; j < site.height.ny(); ++j)
    for (int i = 0; i < site.height.nx(); ++i) {
      const Eigen::Vector2d p = site.height.node_position(i, j);
      sxz += p.x() * site.height.at(i, j);
      syz += p.y() * site.height.at(i, j);
      sxx += p.x() * p.x();
    }
  const double gradient = std::hypot(sxz / sxx, syz / sxx);
  EXPECT_NEAR(gradient, std::tan(10.0 * std::numbers::pi / 180.0), 0.003);
}

TEST(TerrainGenerator, AlbedoIsBoundedAndTexturedDownToTheGridSpacing) {
  const Terrain site = Terrain::generate(small_site());
  double sum = 0.0;
  double neighbour_difference = 0.0;
  for (int j = 0; j < site.albedo.height(); ++j)
    for (int i = 0; i < site.albedo.width(); ++i) {
      const float a = site.albedo(i, j);
      ASSERT_GE(a, 0.0f);
      ASSERT_LE(a, 1.0f);
      sum += a;
      if (i > 0)
        neighbour_difference += std::abs(a - site.albedo(i - 1, j));
    }
  const double n = static_cast<double>(site.albedo.size());
  EXPECT_NEAR(sum / n, 0.55, 0.08);
  EXPECT_GT(neighbour_difference / n, 0.005); // adjacent nodes differ: matchable texture
}

TEST(TerrainGenerator, BadSettingsAreRejectedWithTheirName) {
  const auto message_of = [](TerrainSettings settings) {
    try {
      Terrain::generate(settings);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  TerrainSettings bad = small_site();
  bad.rock_cover = 0.7;
  EXPECT_NE(message_of(bad).find("rock_cover"), std::string::npos);
  bad = small_site();
  bad.cell_m = 0.0;
  EXPECT_NE(message_of(bad).find("cell_m"), std::string::npos);
  bad = small_site();
  bad.size_m = -1.0;
  EXPECT_NE(message_of(bad).find("size_m"), std::string::npos);
  bad = small_site();
  bad.width_m = -2.0;
  EXPECT_NE(message_of(bad).find("width_m"), std::string::npos);
  bad = small_site();
  bad.width_m = 400.0; // 20000 nodes north-south
  EXPECT_NE(message_of(bad).find("width_m / cell_m"), std::string::npos);
  bad = small_site();
  bad.size_m = 1000.0; // 50000 nodes a side
  EXPECT_NE(message_of(bad).find("nodes a side"), std::string::npos);
  bad = small_site();
  bad.crater_density = -0.1;
  EXPECT_NE(message_of(bad).find("crater_density"), std::string::npos);
  bad = small_site();
  bad.undulation_m = std::nan("");
  EXPECT_NE(message_of(bad).find("undulation_m"), std::string::npos);
  bad = small_site();
  bad.regional_slope_deg = 60.0;
  EXPECT_NE(message_of(bad).find("regional_slope_deg"), std::string::npos);
  bad = small_site();
  bad.clear_radius_m = -2.0;
  EXPECT_NE(message_of(bad).find("clear_radius_m"), std::string::npos);
  LocomotionLimits limits;
  limits.max_step_m = 0.0;
  EXPECT_THROW(Terrain::generate(small_site(), limits), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::world
