// Tests: the lighting presets and the lit surface's shading and cast shadows.

#include "support/test_files.hpp"

#include "marsokhod/world/lighting/lighting.hpp"
#include "marsokhod/world/lighting/lit_surface.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace marsokhod::world {
namespace {

using test_support::kDegree;
constexpr double kCell = 0.02;

/// An 8 m x 8 m hand-made site (401 nodes a side, centred on the origin) of uniform albedo.
Terrain site(const std::function<double(double, double)>& z, float albedo = 0.5f) {
  Terrain terrain;
  terrain.height = HeightField(401, 401, kCell, Eigen::Vector2d(-4.0, -4.0));
  for (int j = 0; j < 401; ++j)
    for (int i = 0; i < 401; ++i) {
      const Eigen::Vector2d p = terrain.height.node_position(i, j);
      terrain.height.at(i, j) = static_cast<float>(z(p.x(), p.y()));
    }
  terrain.albedo = imaging::Image<float>(401, 401, 1, albedo);
  return terrain;
}

Lighting sun_at(double elevation_deg, double azimuth_deg) {
  Lighting light;
  light.sun_elevation_deg = elevation_deg;
  light.sun_azimuth_deg = azimuth_deg;
  light.fine_texture = 0.0;
  return light;
}

TEST(Lighting, PresetNamesRoundTrip) {
  for (const char* name : {"high-sun", "overexposed", "dark-wet", "low-sun"}) {
    const LightPreset preset = parse_light_preset(name);
    EXPECT_EQ(to_string(preset), name);
    EXPECT_EQ(lighting_preset(preset).name, name);
  }
}

TEST(Lighting, UnknownPresetNameListsTheValidOnes) {
  try {
    parse_light_preset("midnight");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("midnight"), std::string::npos);
    for (const char* name : {"high-sun", "overexposed", "dark-wet", "low-sun"})
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

/// Grey level of flat ground of the given albedo under a lighting (no shadow).
double flat_grey(const Lighting& light, double albedo) {
  return light.exposure * light.albedo_scale * albedo *
         (light.ambient + light.sun * std::sin(light.sun_elevation_deg * kDegree));
}

TEST(Lighting, PresetsMatchThePapersSites) {
  const Lighting high = lighting_preset(LightPreset::high_sun);
  const Lighting over = lighting_preset(LightPreset::overexposed);
  const Lighting wet = lighting_preset(LightPreset::dark_wet);
  const Lighting low = lighting_preset(LightPreset::low_sun);
  // High sun: mid-grey regolith (albedo about 0.55), bright rocks (0.8) still below 255.
  EXPECT_NEAR(high.sun_elevation_deg, 60.0, 1e-9);
  EXPECT_GT(flat_grey(high, 0.55), 80.0);
  EXPECT_LT(flat_grey(high, 0.80), 255.0);
  // Mojave: the same sun, bright sand clips.
  EXPECT_EQ(over.sun_elevation_deg, high.sun_elevation_deg);
  EXPECT_GE(flat_grey(over, 0.62), 255.0);
  EXPECT_LT(flat_grey(over, 0.35), 255.0); // dark rocks keep detail
  // Kamchatka: overcast (ambient dominates), dark wet dust, low contrast.
  EXPECT_GT(wet.ambient, wet.sun);
  EXPECT_NEAR(wet.albedo_scale, 0.35, 0.05);
  EXPECT_LT(wet.albedo_contrast, 1.0);
  EXPECT_LT(flat_grey(wet, 0.55), 0.5 * flat_grey(high, 0.55));
  // Low sun about 12 degrees, little sky light.
  EXPECT_NEAR(low.sun_elevation_deg, 12.0, 2.0);
  EXPECT_LT(low.ambient, high.ambient);
}

TEST(LitSurface, FlatGroundUnderHighSunIsAlbedoTimesAmbientPlusSunSine) {
  const Terrain flat = site([](double, double) { return 0.0; });
  for (const LightPreset preset : {LightPreset::high_sun, LightPreset::dark_wet}) {
    Lighting light = lighting_preset(preset);
    light.fine_texture = 0.0;
    const LitSurface surface(flat, light);
    const double expected =
        light.albedo_scale * 0.5 *
        (light.ambient + light.sun * std::sin(light.sun_elevation_deg * kDegree));
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {1.234, -2.5}, {-3.99, 3.0}})
      EXPECT_NEAR(surface.radiance(x, y), expected, 1e-6) << to_string(preset);
  }
}

TEST(LitSurface, TiltedGroundFollowsLambertsCosine) {
  // A 20 degree slope rising towards the east: its normal leans 20 degrees to the west.
  const double g = std::tan(20.0 * kDegree);
  const Terrain slope = site([=](double x, double) { return g * x; });
  // Sun in the west 40 degrees up, i.e. 50 degrees from the zenith: 30 degrees from the normal.
  const Lighting light = sun_at(40.0, 180.0);
  const LitSurface facing(slope, light);
  EXPECT_NEAR(facing.radiance(0.3, 0.1), 0.5 * (light.ambient + std::cos(30.0 * kDegree)), 1e-5);
  // Sun in the east at 15 degrees: it grazes behind the slope, ambient only.
  const LitSurface behind(slope, sun_at(15.0, 0.0));
  EXPECT_NEAR(behind.radiance(0.3, 0.1), 0.5 * 0.25, 1e-6);
}

TEST(LitSurface, AlbedoContrastScalesVariationAboutTheMean) {
  Terrain halves = site([](double, double) { return 0.0; });
  for (int j = 0; j < 401; ++j)
    for (int i = 0; i < 401; ++i)
      halves.albedo(i, j) = (i + j) % 2 == 0 ? 0.6f : 0.4f;
  // Mean albedo: 0.6 on 80401 nodes, 0.4 on 80400.
  const double mean = (0.6 * 80401 + 0.4 * 80400) / (401.0 * 401.0);
  Lighting light = sun_at(90.0, 0.0);
  light.ambient = 0.0;
  light.albedo_contrast = 0.5;
  light.albedo_scale = 0.8;
  const LitSurface surface(halves, light);
  EXPECT_NEAR(surface.nodes()(0, 0), 0.8 * (mean + 0.5 * (0.6 - mean)), 1e-6);
  EXPECT_NEAR(surface.nodes()(1, 0), 0.8 * (mean + 0.5 * (0.4 - mean)), 1e-6);
}

/// Distance from `start` along `direction` (unit) to the first point whose radiance exceeds
/// `level`, in steps of 5 mm.
double shadow_end(const LitSurface& surface, Eigen::Vector2d start, Eigen::Vector2d direction,
                  double level) {
  for (double s = 0.0; s < 4.0; s += 0.005) {
    const Eigen::Vector2d p = start + s * direction;
    if (surface.radiance(p.x(), p.y()) > level)
      return s;
  }
  return 4.0;
}

TEST(LitSurface, WallCastsAShadowOfHeightOverTanElevation) {
  // A 0.5 m wall, 4 cm thick, along y at x = 0 (nodes 199..201); sun from the east.
  const double h = 0.5;
  const Terrain wall = site([=](double x, double) { return std::abs(x) <= 0.02 + 1e-9 ? h : 0.0; });
  for (const double elevation : {20.0, 30.0, 45.0}) {
    const LitSurface surface(wall, sun_at(elevation, 0.0));
    // Walk west from the wall's west face (node 199, x = -0.02) to the first sunlit node.
    const int row = 200;
    int first_lit = 198;
    while (first_lit > 0 && !surface.sunlit()(first_lit, row))
      --first_lit;
    const double length = (199 - first_lit) * kCell;
    const double expected = h / std::tan(elevation * kDegree);
    EXPECT_NEAR(length, expected, 2.0 * kCell) << "elevation " << elevation;
    const double expected_cells = expected / kCell;
    // The shadow holds only sky light; the sunlit ground beyond has the full sun.
    EXPECT_NEAR(surface.radiance(-0.05, 0.0), 0.5 * 0.25, 1e-6);
    EXPECT_NEAR(surface.radiance(-0.03 - 2.0 * expected_cells * kCell, 0.0),
                0.5 * (0.25 + std::sin(elevation * kDegree)), 1e-6);
  }
}

TEST(LitSurface, PillarShadowPointsAwayFromTheSunForAnyAzimuth) {
  // A 0.4 m square pillar 0.6 m tall at the origin.
  const double h = 0.6;
  const Terrain pillar = site([=](double x, double y) {
    return std::abs(x) <= 0.2 + 1e-9 && std::abs(y) <= 0.2 + 1e-9 ? h : 0.0;
  });
  for (const auto& [azimuth, elevation] :
       {std::pair{30.0, 35.0}, {135.0, 60.0}, {200.0, 25.0}, {290.0, 45.0}}) {
    const LitSurface surface(pillar, sun_at(elevation, azimuth));
    const Eigen::Vector2d away(-std::cos(azimuth * kDegree), -std::sin(azimuth * kDegree));
    // Where the line from the centre leaves the pillar's square footprint.
    const double exit = 0.2 / std::max(std::abs(away.x()), std::abs(away.y()));
    const double lit_level = 0.5 * (0.25 + 0.5 * std::sin(elevation * kDegree));
    const double length = shadow_end(surface, exit * away, away, lit_level);
    EXPECT_NEAR(length, h / std::tan(elevation * kDegree), 2.0 * kCell)
        << "azimuth " << azimuth << " elevation " << elevation;
    // Towards the sun the ground next to the pillar is lit.
    const Eigen::Vector2d sunward = -(exit + 0.1) * away;
    EXPECT_GT(surface.radiance(sunward.x(), sunward.y()), lit_level);
  }
}

TEST(LitSurface, LowSunCastsLongShadows) {
  const Terrain rock = site([](double x, double y) { return x * x + y * y < 0.01 ? 0.2 : 0.0; });
  Lighting low = lighting_preset(LightPreset::low_sun);
  const LitSurface surface(rock, low);
  const Eigen::Vector2d away(-std::cos(low.sun_azimuth_deg * kDegree),
                             -std::sin(low.sun_azimuth_deg * kDegree));
  const Eigen::Vector2d behind = (0.1 + 0.8) * away; // 0.8 m behind the 0.2 m rock
  EXPECT_NEAR(surface.nodes()(static_cast<int>(std::lround((behind.x() + 4.0) / kCell)),
                              static_cast<int>(std::lround((behind.y() + 4.0) / kCell))),
              0.5 * low.ambient, 1e-6);
}

TEST(LitSurface, FineTextureIsDeterministicBoundedAndVariesInsideACell) {
  const Terrain flat = site([](double, double) { return 0.0; });
  const Lighting light = lighting_preset(LightPreset::high_sun);
  const LitSurface a(flat, light);
  const LitSurface b(flat, light);
  const double base = 0.5 * (light.ambient + std::sin(light.sun_elevation_deg * kDegree));
  double lowest = 1e9;
  double highest = -1e9;
  for (int k = 0; k < 20; ++k) {
    const double x = 1.0 + 0.001 * k; // 20 samples inside one 2 cm cell
    const float r = a.radiance(x, 0.505);
    EXPECT_EQ(r, b.radiance(x, 0.505));
    EXPECT_LE(std::abs(r / base - 1.0), light.fine_texture + 1e-6);
    lowest = std::min<double>(lowest, r);
    highest = std::max<double>(highest, r);
  }
  EXPECT_GT(highest - lowest, 0.005 * base);
}

TEST(LitSurface, RejectsMeaninglessLighting) {
  const Terrain flat = site([](double, double) { return 0.0; });
  Lighting bad = sun_at(45.0, 0.0);
  bad.ambient = -0.1;
  EXPECT_THROW(LitSurface(flat, bad), std::invalid_argument);
  bad = sun_at(45.0, 0.0);
  bad.exposure = 0.0;
  EXPECT_THROW(LitSurface(flat, bad), std::invalid_argument);
  bad = sun_at(120.0, 0.0);
  EXPECT_THROW(LitSurface(flat, bad), std::invalid_argument);
  EXPECT_THROW(LitSurface(Terrain{}, sun_at(45.0, 0.0)), std::invalid_argument);
}

} // namespace
} // namespace marsokhod::world
