// Tests: rock sizes follow the Golombek-Rapp model, and rock footprints fit their diameters.

#include "marsokhod/world/terrain/rocks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace marsokhod::world {
namespace {

TEST(Rocks, RockSizesFollowTheGolombekRappModel) {
  // Share of the rock area in rocks >= D: [F(D) - F(Dmax)] / [F(Dmin) - F(Dmax)] with
  // F(D) = k exp(-q D), q = 1.79 + 0.152 / k (Golombek & Rapp 1997).
  const double k = 0.10;
  const double q = 1.79 + 0.152 / k;
  const auto share_above = [&](double d) {
    return (std::exp(-q * d) - std::exp(-q * 2.0)) / (std::exp(-q * 0.05) - std::exp(-q * 2.0));
  };
  const std::vector<Rock> rocks = sample_rocks({k, Eigen::Vector2d(150.0, 150.0), 0.0}, 99);
  double total = 0.0;
  double above_02 = 0.0;
  double above_05 = 0.0;
  for (const Rock& rock : rocks) {
    ASSERT_GE(rock.diameter_m, 0.05);
    ASSERT_LE(rock.diameter_m, 2.0);
    const double area = rock.diameter_m * rock.diameter_m;
    total += area;
    above_02 += rock.diameter_m >= 0.2 ? area : 0.0;
    above_05 += rock.diameter_m >= 0.5 ? area : 0.0;
  }
  EXPECT_NEAR(above_02 / total, share_above(0.2), 0.05 * share_above(0.2));
  EXPECT_NEAR(above_05 / total, share_above(0.5), 0.10 * share_above(0.5));
}

TEST(Rocks, RockFootprintHasTheAreaOfItsDiameterAndHeightInRange) {
  Rock rock;
  rock.diameter_m = 1.0;
  rock.aspect = 1.4;
  rock.orientation_rad = 0.7;
  rock.height_m = 0.65;
  rock.lobe_amplitude = {0.12, 0.08, 0.05};
  rock.lobe_phase = {0.3, 1.9, 4.0};
  const double step = 0.005;
  double area = 0.0;
  double highest = 0.0;
  for (double y = -1.0; y <= 1.0; y += step)
    for (double x = -1.0; x <= 1.0; x += step) {
      const double h = rock.height_at(x, y);
      area += h > 0.0 ? step * step : 0.0;
      highest = std::max(highest, h);
    }
  EXPECT_NEAR(area, std::numbers::pi / 4.0, 0.02 * std::numbers::pi / 4.0);
  EXPECT_NEAR(highest, rock.height_m, 0.08 * rock.height_m); // crown bumps are +-8 %
  EXPECT_EQ(rock.height_at(rock.reach_m() + 0.01, 0.0), 0.0);
}

} // namespace
} // namespace marsokhod::world
