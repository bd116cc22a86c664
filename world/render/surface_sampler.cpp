// The exposed radiance a camera ray samples, with the fine texture filtered by footprint.

#include "render/surface_sampler.hpp"

#include <algorithm>
#include <cmath>

namespace marsokhod::world {
namespace {

// Grazing rays stretch the footprint without bound; this caps the stretch at 20 x.
constexpr double kMinCosine = 0.05;
// Below this weight the texture's remaining contrast (under 0.2 % of the radiance) is dropped
// and its evaluation skipped.
constexpr double kNegligibleWeight = 1.0 / 32.0;

} // namespace

SurfaceSampler::SurfaceSampler(const LitSurface& surface, const HeightField& height,
                               double pixel_angle, bool filter_texture)
    : surface_(&surface), height_(&height), pixel_angle_(pixel_angle), filter_(filter_texture),
      exposure_(surface.lighting().exposure),
      texture_pitch_m_(height.cell_m() / kFineTexturePerCell) {}

double SurfaceSampler::grid_radiance(double x, double y) const {
  // Bilinear radiance of the nodes, with the border clamping of LitSurface::radiance().
  const imaging::Image<float>& nodes = surface_->nodes();
  const double u =
      clamp_grid_coordinate((x - height_->origin().x()) / height_->cell_m(), nodes.width() - 1);
  const double v =
      clamp_grid_coordinate((y - height_->origin().y()) / height_->cell_m(), nodes.height() - 1);
  const int i = std::min(static_cast<int>(u), nodes.width() - 2);
  const int j = std::min(static_cast<int>(v), nodes.height() - 2);
  const double fx = u - i;
  const double fy = v - j;
  const double lower = nodes(i, j) + fx * (nodes(i + 1, j) - nodes(i, j));
  const double upper = nodes(i, j + 1) + fx * (nodes(i + 1, j + 1) - nodes(i, j + 1));
  return lower + fy * (upper - lower);
}

double SurfaceSampler::texture_weight(const Eigen::Vector3d& point,
                                      const Eigen::Vector3d& direction, double distance) const {
  if (!filter_)
    return 1.0;
  // The footprint is pixel_angle * distance across the ray and longer by 1 / cos(incidence)
  // along it; the texture averages over its area.
  const double across = pixel_angle_ * distance;
  const double cosine =
      std::max(kMinCosine, std::abs(direction.dot(height_->normal(point.x(), point.y()))));
  return texture_pitch_m_ * std::sqrt(cosine) / across;
}

double SurfaceSampler::grey_with(const Eigen::Vector3d& point, double weight) const {
  if (weight >= 1.0)
    return exposure_ * surface_->radiance(point.x(), point.y());
  const double base = grid_radiance(point.x(), point.y());
  if (weight < kNegligibleWeight)
    return exposure_ * base;
  const double full = surface_->radiance(point.x(), point.y());
  return exposure_ * (base + (full - base) * weight);
}

} // namespace marsokhod::world
