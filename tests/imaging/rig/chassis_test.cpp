// Tests: the chassis footprint's size, corners and coverage, by hand geometry.

#include "marsokhod/imaging/rig/chassis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace marsokhod::imaging {
namespace {

TEST(Chassis, FootprintSpansTheWheelsOuterFacesAndEnds) {
  const Chassis chassis;
  EXPECT_DOUBLE_EQ(chassis.length_m(), 1.5 + 0.35);
  EXPECT_DOUBLE_EQ(chassis.width_m(), 1.0 + 0.20);
  EXPECT_DOUBLE_EQ(footprint_reach_m(chassis), 0.5 * std::sqrt(1.85 * 1.85 + 1.2 * 1.2));
}

TEST(Chassis, CornersTurnWithTheHeading) {
  const Chassis chassis;
  // Facing +y, the front left corner lies ahead (+y) and to the left (-x).
  const auto corners = footprint_corners(chassis, {2.0, 3.0, std::numbers::pi / 2.0});
  EXPECT_NEAR(corners[0].x(), 2.0 - 0.6, 1e-12);
  EXPECT_NEAR(corners[0].y(), 3.0 + 0.925, 1e-12);
  EXPECT_NEAR(corners[2].x(), 2.0 + 0.6, 1e-12);
  EXPECT_NEAR(corners[2].y(), 3.0 - 0.925, 1e-12);
}

TEST(Chassis, CoversPointsInsideItsRectangleOnly) {
  const Chassis chassis;
  const PlanarPose east{0.0, 0.0, 0.0};
  EXPECT_TRUE(under_footprint(chassis, east, 0.92, 0.59));
  EXPECT_FALSE(under_footprint(chassis, east, 0.93, 0.0));
  EXPECT_FALSE(under_footprint(chassis, east, 0.0, -0.61));
  const PlanarPose north{0.0, 0.0, std::numbers::pi / 2.0};
  EXPECT_TRUE(under_footprint(chassis, north, 0.0, 0.92));
  EXPECT_FALSE(under_footprint(chassis, north, 0.92, 0.0));
}

TEST(Chassis, ValidateNamesTheFirstBadDimension) {
  Chassis chassis;
  chassis.wheel_width_m = std::numeric_limits<double>::quiet_NaN();
  try {
    validate(chassis);
    FAIL() << "a NaN wheel width was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("wheel_width_m"), std::string::npos);
  }
  EXPECT_NO_THROW(validate(Chassis{}));
}

} // namespace
} // namespace marsokhod::imaging
