// Rocks of the synthetic site: the Golombek and Rapp abundance model, shapes and placement.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/world/terrain/height_field.hpp"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace marsokhod::world {

/// Smallest and largest rock diameters the generator shapes; smaller rocks are below what a
/// 2 cm grid can represent and are left to the regolith roughness.
inline constexpr double kMinRockDiameterM = 0.05;
inline constexpr double kMaxRockDiameterM = 2.0;

/// The Golombek & Rapp (1997) model of Martian rock abundance: the fraction of the ground
/// covered by rocks of diameter >= D is F_k(D) = k exp(-q(k) D), q(k) = 1.79 + 0.152 / k,
/// with k the total rock cover (J. Geophys. Res. 102(E2), 4117-4129).
class RockAbundanceModel {
public:
  /// Throws std::invalid_argument unless 0 < k < 1.
  explicit RockAbundanceModel(double rock_cover);

  double k() const { return k_; }
  double q() const { return q_; }
  /// F_k(D): cumulative fractional area of rocks with diameter >= D.
  double cumulative_area(double diameter_m) const;
  /// Diameter with the model's number-per-size distribution truncated to
  /// [kMinRockDiameterM, kMaxRockDiameterM], from a uniform u in [0, 1).
  double sample_diameter(double u) const;

private:
  double k_;
  double q_;
  std::vector<double> diameters_;  ///< tabulated inverse of the number distribution
  std::vector<double> cumulative_; ///< normalised cumulative number at diameters_
};

/// One rock: a half-buried ellipsoidal blob whose outline and crown are made irregular.
struct Rock {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double diameter_m = 0.1; ///< the footprint has the area of a disc of this diameter
  double aspect = 1.0;     ///< footprint long / short axis
  double orientation_rad = 0.0;
  double height_m = 0.06; ///< top above the ground, 0.5 .. 0.8 of the diameter
  double bluntness = 0.5; ///< crown exponent: 0.5 is an ellipsoid, smaller is blunter
  std::array<double, 3> lobe_amplitude{}; ///< outline harmonics 2, 3 and 5
  std::array<double, 3> lobe_phase{};
  float albedo = 0.4f;
  std::uint64_t texture_seed = 0;

  /// Largest horizontal distance from the centre that the rock covers.
  double reach_m() const;
  /// Height of the rock above the ground at offset (dx, dy) from its centre; 0 outside it.
  double height_at(double dx, double dy) const;
};

/// Where rocks go: a rectangle of sides extent (east-west, north-south) centred on the origin,
/// minus a clear disc.
struct RockField {
  double rock_cover = 0.10;
  Eigen::Vector2d extent = Eigen::Vector2d::Constant(48.0);
  double clear_radius_m = 1.5;
  Eigen::Vector2d clear_centre = Eigen::Vector2d::Zero();
};

/// Draws rocks with the Golombek-Rapp size distribution at uniform random positions until
/// their footprints add up to -ln(1 - k) of the area, so that, overlaps counted, the expected
/// covered fraction is k. Rocks touching the clear disc are dropped (after being counted).
std::vector<Rock> sample_rocks(const RockField& field, std::uint64_t seed);

/// Sets every node a rock covers to ground + rock height (the highest rock where rocks overlap)
/// and paints the rock's textured albedo there.
void place_rocks(const std::vector<Rock>& rocks, HeightField& height,
                 imaging::Image<float>& albedo);

} // namespace marsokhod::world
