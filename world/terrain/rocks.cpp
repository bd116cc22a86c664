// Rocks: sizes drawn from the abundance model, shapes, and placement into heights and albedo.

#include "marsokhod/world/terrain/rocks.hpp"

#include "marsokhod/world/terrain/regolith_noise.hpp"
#include "marsokhod/world/terrain/seeded_random.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace marsokhod::world {
namespace {

constexpr int kTableSize = 4096;

/// A rock with its trigonometry done once, for evaluation at many nodes.
class PreparedRock {
public:
  explicit PreparedRock(const Rock& rock) : rock_(rock) {
    cos_ = std::cos(rock.orientation_rad);
    sin_ = std::sin(rock.orientation_rad);
    const double radius = 0.5 * rock.diameter_m;
    inv_long_ = 1.0 / (radius * std::sqrt(rock.aspect));
    inv_short_ = std::sqrt(rock.aspect) / radius;
    double power = 1.0;
    double spread = 1.0;
    for (std::size_t k = 0; k < lobe_.size(); ++k) {
      const double a = rock.lobe_amplitude[k];
      lobe_[k] = std::polar(a, rock.lobe_phase[k]);
      power += 0.5 * a * a;
      spread += a;
    }
    outline_scale_ = 1.0 / std::sqrt(power); // the outline keeps the disc's area
    max_outline_ = spread * outline_scale_;
    crown_pitch_ = std::max(0.25 * rock.diameter_m, 0.03);
  }

  double height(double dx, double dy) const {
    const double along = (cos_ * dx + sin_ * dy) * inv_long_;
    const double across = (-sin_ * dx + cos_ * dy) * inv_short_;
    const double rho2_ellipse = along * along + across * across;
    if (rho2_ellipse >= max_outline_ * max_outline_)
      return 0.0;
    const double outline = outline_at(along, across, rho2_ellipse);
    const double rho2 = rho2_ellipse / (outline * outline);
    if (rho2 >= 1.0)
      return 0.0;
    const double crown = std::pow(1.0 - rho2, rock_.bluntness);
    const double bumps =
        1.0 + 0.08 * lattice_noise(rock_.texture_seed, dx / crown_pitch_, dy / crown_pitch_);
    return rock_.height_m * crown * bumps;
  }

private:
  /// Outline radius towards (along, across): 1 + sum a_k cos(k theta + phase_k), with the
  /// harmonics from powers of the unit complex number e^(i theta) (no trigonometry per node).
  double outline_at(double along, double across, double rho2) const {
    if (rho2 <= 0.0)
      return outline_scale_;
    const std::complex<double> turn = std::complex<double>(along, across) / std::sqrt(rho2);
    const std::complex<double> turn2 = turn * turn;
    const std::complex<double> turn3 = turn2 * turn;
    const std::complex<double> turn5 = turn3 * turn2;
    const double r =
        1.0 + (lobe_[0] * turn2).real() + (lobe_[1] * turn3).real() + (lobe_[2] * turn5).real();
    return r * outline_scale_;
  }

  const Rock& rock_;
  std::array<std::complex<double>, 3> lobe_{};
  double cos_ = 1.0;
  double sin_ = 0.0;
  double inv_long_ = 1.0;
  double inv_short_ = 1.0;
  double outline_scale_ = 1.0;
  double max_outline_ = 1.0;
  double crown_pitch_ = 0.03;
};

/// Number of rocks per unit diameter (up to a constant): area density k q exp(-qD) divided by
/// the area of one rock, pi D^2 / 4.
double number_density(double q, double diameter) {
  return std::exp(-q * diameter) / (diameter * diameter);
}

Rock draw_rock_shape(double diameter, RandomStream& rng) {
  Rock rock;
  rock.diameter_m = diameter;
  rock.aspect = rng.uniform(1.0, 1.5);
  rock.orientation_rad = rng.uniform(0.0, std::numbers::pi);
  rock.height_m = diameter * rng.uniform(0.5, 0.8);
  rock.bluntness = rng.uniform(0.3, 0.6);
  const double lobe_limits[3] = {0.12, 0.08, 0.05};
  for (int k = 0; k < 3; ++k) {
    rock.lobe_amplitude[k] = rng.uniform(0.0, lobe_limits[k]);
    rock.lobe_phase[k] = rng.uniform(0.0, 2.0 * std::numbers::pi);
  }
  // Mostly dark basalt, some lighter rocks: both must stand out from the regolith in stereo.
  const bool dark = rng.uniform() < 0.6;
  rock.albedo = static_cast<float>(dark ? rng.uniform(0.28, 0.42) : rng.uniform(0.62, 0.80));
  rock.texture_seed = rng.bits();
  return rock;
}

float rock_albedo(const Rock& rock, double x, double y, int i, int j) {
  const float mottling = lattice_noise(rock.texture_seed ^ 0x5bd1e995ULL, x / 0.04, y / 0.04);
  const float speckle = lattice_value(rock.texture_seed, i, j);
  return rock.albedo * (1.0f + 0.15f * mottling + 0.08f * speckle);
}

} // namespace

RockAbundanceModel::RockAbundanceModel(double rock_cover) : k_(rock_cover) {
  if (!(rock_cover > 0.0 && rock_cover < 1.0))
    throw std::invalid_argument("RockAbundanceModel: rock cover must be in (0, 1)");
  q_ = 1.79 + 0.152 / k_;
  // Tabulate the cumulative number on a geometric grid, dense where small rocks dominate.
  diameters_.resize(kTableSize);
  cumulative_.resize(kTableSize);
  const double ratio = std::log(kMaxRockDiameterM / kMinRockDiameterM) / (kTableSize - 1);
  diameters_[0] = kMinRockDiameterM;
  cumulative_[0] = 0.0;
  for (int n = 1; n < kTableSize; ++n) {
    diameters_[n] = kMinRockDiameterM * std::exp(ratio * n);
    const double width = diameters_[n] - diameters_[n - 1];
    cumulative_[n] =
        cumulative_[n - 1] +
        0.5 * width * (number_density(q_, diameters_[n]) + number_density(q_, diameters_[n - 1]));
  }
  const double total = cumulative_.back();
  for (double& c : cumulative_)
    c /= total;
}

double RockAbundanceModel::cumulative_area(double diameter_m) const {
  return k_ * std::exp(-q_ * diameter_m);
}

double RockAbundanceModel::sample_diameter(double u) const {
  const auto upper = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
  if (upper == cumulative_.begin())
    return diameters_.front();
  if (upper == cumulative_.end())
    return diameters_.back();
  const auto n = static_cast<std::size_t>(upper - cumulative_.begin());
  const double t = (u - cumulative_[n - 1]) / (cumulative_[n] - cumulative_[n - 1]);
  return diameters_[n - 1] + t * (diameters_[n] - diameters_[n - 1]);
}

double Rock::reach_m() const {
  double spread = 1.0;
  for (const double a : lobe_amplitude)
    spread += a;
  return 0.5 * diameter_m * std::sqrt(aspect) * spread;
}

double Rock::height_at(double dx, double dy) const {
  return PreparedRock(*this).height(dx, dy);
}

std::vector<Rock> sample_rocks(const RockField& field, std::uint64_t seed) {
  std::vector<Rock> rocks;
  if (field.rock_cover <= 0.0)
    return rocks;
  const RockAbundanceModel model(field.rock_cover);
  // Centres also fall in a margin around the site so its edges get their share of rocks.
  const Eigen::Vector2d sides = field.extent.array() + kMaxRockDiameterM;
  const double target_area = -std::log(1.0 - field.rock_cover) * sides.prod();
  RandomStream rng(seed);
  double placed_area = 0.0;
  while (placed_area < target_area) {
    const double diameter = model.sample_diameter(rng.uniform());
    Rock rock = draw_rock_shape(diameter, rng);
    rock.centre = uniform_in_rectangle(sides, rng);
    placed_area += 0.25 * std::numbers::pi * diameter * diameter;
    if ((rock.centre - field.clear_centre).norm() < field.clear_radius_m + rock.reach_m())
      continue;
    rocks.push_back(rock);
  }
  return rocks;
}

void place_rocks(const std::vector<Rock>& rocks, HeightField& height,
                 imaging::Image<float>& albedo) {
  if (albedo.width() != height.nx() || albedo.height() != height.ny())
    throw std::invalid_argument("place_rocks: albedo and height grids differ in size");
  imaging::Image<float> rock_height(height.nx(), height.ny(), 1, 0.0f);
  const double cell = height.cell_m();
  const Eigen::Vector2d origin = height.origin();
  for (const Rock& rock : rocks) {
    const PreparedRock shape(rock);
    const double reach = rock.reach_m();
    const NodeRange range = nodes_around(height, rock.centre, reach);
    for (int j = range.j0; j <= range.j1; ++j) {
      const double y = origin.y() + j * cell;
      for (int i = range.i0; i <= range.i1; ++i) {
        const double x = origin.x() + i * cell;
        const auto h = static_cast<float>(shape.height(x - rock.centre.x(), y - rock.centre.y()));
        if (h <= rock_height(i, j))
          continue;
        rock_height(i, j) = h;
        albedo(i, j) = rock_albedo(rock, x, y, i, j);
      }
    }
  }
  for (int j = 0; j < height.ny(); ++j)
    for (int i = 0; i < height.nx(); ++i)
      height.at(i, j) += rock_height(i, j);
}

} // namespace marsokhod::world
