// Craters and pits of the synthetic site: their size distribution, shape and carving.
#pragma once

#include "marsokhod/world/terrain/height_field.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace marsokhod::world {

/// Diameter range of impact craters; pits are drawn separately.
inline constexpr double kMinCraterDiameterM = 0.5;
inline constexpr double kMaxCraterDiameterM = 6.0;
/// Exponent b of the cumulative size distribution N(>= D) ~ D^-b of small fresh craters.
inline constexpr double kCraterSizeExponent = 2.0;
/// Share of the depressions that are steep-walled deep pits (the paper's fig. 4) rather than
/// bowl-shaped craters.
inline constexpr double kPitFraction = 0.15;

/// A bowl-shaped impact crater with a raised rim and ejecta blanket, or a steep-walled pit.
struct Crater {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double diameter_m = 1.0;    ///< rim crest to rim crest
  double depth_m = 0.2;       ///< floor below the rim crest
  double rim_height_m = 0.04; ///< rim crest above the surrounding ground
  bool pit = false;

  /// Largest distance from the centre the crater changes the ground (ejecta included).
  double reach_m() const;
  /// Change of ground height at distance r from the centre.
  double relief_at(double r) const;
};

/// Where craters go: a rectangle of sides extent (east-west, north-south) centred on the origin,
/// minus a clear disc.
struct CraterField {
  double density_per_m2 = 0.004;
  Eigen::Vector2d extent = Eigen::Vector2d::Constant(48.0);
  double clear_radius_m = 1.5;
  Eigen::Vector2d clear_centre = Eigen::Vector2d::Zero();
};

/// Draws round(density * area) depressions (random rounding): diameters from the power law on
/// [kMinCraterDiameterM, kMaxCraterDiameterM], depth ~0.2 D and rim ~0.04 D; a kPitFraction of
/// them are deep pits 1-3 m across and 0.35-0.5 D deep. None reaches into the clear disc.
std::vector<Crater> sample_craters(const CraterField& field, std::uint64_t seed);

/// Adds every crater's relief to the heights (overlapping craters superpose).
void carve_craters(const std::vector<Crater>& craters, HeightField& height);

} // namespace marsokhod::world
