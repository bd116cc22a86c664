// Craters and pits: sampling their sizes and places, and carving them into the heights.

#include "marsokhod/world/terrain/craters.hpp"

#include "marsokhod/world/terrain/seeded_random.hpp"

#include <algorithm>
#include <cmath>

namespace marsokhod::world {
namespace {

constexpr double kCraterEjectaReach = 2.0; ///< ejecta blanket ends at this many radii
constexpr double kPitRimReach = 1.5;
constexpr double kPitWallStart = 0.45; ///< pit floor is flat inside this fraction of the radius
constexpr int kPlacementAttempts = 1000;

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

/// Inverse transform of the truncated power law N(>= D) ~ D^-b.
double power_law_diameter(double u) {
  const double ratio = std::pow(kMinCraterDiameterM / kMaxCraterDiameterM, kCraterSizeExponent);
  return kMinCraterDiameterM * std::pow(1.0 - u * (1.0 - ratio), -1.0 / kCraterSizeExponent);
}

Crater draw_crater(RandomStream& rng) {
  Crater crater;
  crater.pit = rng.uniform() < kPitFraction;
  if (crater.pit) {
    crater.diameter_m = rng.uniform(1.0, 3.0);
    crater.depth_m = crater.diameter_m * rng.uniform(0.35, 0.5);
    crater.rim_height_m = crater.diameter_m * rng.uniform(0.0, 0.02);
    return crater;
  }
  crater.diameter_m = power_law_diameter(rng.uniform());
  crater.depth_m = crater.diameter_m * rng.uniform(0.16, 0.22);
  crater.rim_height_m = crater.diameter_m * rng.uniform(0.025, 0.045);
  return crater;
}

} // namespace

double Crater::reach_m() const {
  return 0.5 * diameter_m * (pit ? kPitRimReach : kCraterEjectaReach);
}

double Crater::relief_at(double r) const {
  const double rho = r / (0.5 * diameter_m);
  if (pit) {
    if (rho < 1.0) {
      const double wall = smoothstep(kPitWallStart, 1.0, rho);
      return (rim_height_m - depth_m) * (1.0 - wall) + rim_height_m * wall;
    }
    const double t = std::min(1.0, (rho - 1.0) / (kPitRimReach - 1.0));
    return rim_height_m * (1.0 - t) * (1.0 - t);
  }
  if (rho < 1.0) // parabolic bowl from the floor up to the rim crest
    return rim_height_m - depth_m * (1.0 - rho * rho);
  if (rho >= kCraterEjectaReach)
    return 0.0;
  // Ejecta thickness falls as rho^-3, shifted to reach zero at the blanket's edge.
  const double edge = 1.0 / (kCraterEjectaReach * kCraterEjectaReach * kCraterEjectaReach);
  return rim_height_m * (1.0 / (rho * rho * rho) - edge) / (1.0 - edge);
}

std::vector<Crater> sample_craters(const CraterField& field, std::uint64_t seed) {
  std::vector<Crater> craters;
  RandomStream rng(seed);
  const double expected = field.density_per_m2 * field.extent.prod();
  const auto count = static_cast<long>(std::floor(expected + rng.uniform()));
  for (long n = 0; n < count; ++n) {
    Crater crater = draw_crater(rng);
    for (int attempt = 0; attempt < kPlacementAttempts; ++attempt) {
      crater.centre = uniform_in_rectangle(field.extent, rng);
      if ((crater.centre - field.clear_centre).norm() >= field.clear_radius_m + crater.reach_m()) {
        craters.push_back(crater);
        break;
      }
    }
  }
  return craters;
}

void carve_craters(const std::vector<Crater>& craters, HeightField& height) {
  const double cell = height.cell_m();
  const Eigen::Vector2d origin = height.origin();
  for (const Crater& crater : craters) {
    const double reach = crater.reach_m();
    const NodeRange range = nodes_around(height, crater.centre, reach);
    for (int j = range.j0; j <= range.j1; ++j) {
      const double dy = origin.y() + j * cell - crater.centre.y();
      for (int i = range.i0; i <= range.i1; ++i) {
        const double dx = origin.x() + i * cell - crater.centre.x();
        const double r = std::sqrt(dx * dx + dy * dy);
        if (r < reach)
          height.at(i, j) += static_cast<float>(crater.relief_at(r));
      }
    }
  }
}

} // namespace marsokhod::world
