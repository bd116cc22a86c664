// The ray-casting stereo renderer: shading, supersampling and noise for both eyes.

#include "marsokhod/world/render/renderer.hpp"

#include "render/ground_truth_recorder.hpp"
#include "render/pixel_rays.hpp"
#include "render/surface_sampler.hpp"

#include "marsokhod/world/render/camera_view.hpp"
#include "marsokhod/world/render/sensor_noise.hpp"
#include "marsokhod/world/terrain/seeded_random.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace marsokhod::world {
namespace {

constexpr std::uint64_t kLeftNoise = 0x4c454654; // stream labels
constexpr std::uint64_t kRightNoise = 0x52494748;
constexpr double kNoDepthLimit = std::numeric_limits<double>::infinity();
constexpr float kNoHitDepth = std::numeric_limits<float>::infinity();

void check_options(const RenderOptions& options) {
  if (!std::isfinite(options.noise_sigma) || options.noise_sigma < 0.0)
    throw std::invalid_argument("render options: noise_sigma must be a finite value >= 0");
  if (options.supersampling < 1 || options.supersampling > 8)
    throw std::invalid_argument("render options: supersampling must be within 1..8");
  if (!std::isfinite(options.occlusion_tolerance_m) || options.occlusion_tolerance_m <= 0.0)
    throw std::invalid_argument("render options: occlusion_tolerance_m must be > 0");
}

std::uint8_t to_grey(double value) {
  // Clamped first, the conversion's truncation is floor(value + 0.5).
  return static_cast<std::uint8_t>(std::clamp(value + 0.5, 0.0, 255.0));
}

// Grey level, before noise, of what one ray sees.
class RayShader {
public:
  RayShader(const MaxMipmap& mipmap, const SurfaceSampler& sampler, double sky_grey,
            const Eigen::Vector3d& origin, int first_level)
      : mipmap_(&mipmap), sampler_(&sampler), sky_(sky_grey), origin_(origin),
        first_level_(first_level) {}

  double shade(const Eigen::Vector3d& direction, std::optional<double> hit) const {
    if (!hit)
      return sky_;
    return sampler_->grey(origin_ + *hit * direction, direction, *hit);
  }
  std::optional<double> cast(const Eigen::Vector3d& direction) const {
    return mipmap_->first_hit(origin_, direction, kNoDepthLimit, first_level_);
  }

private:
  const MaxMipmap* mipmap_;
  const SurfaceSampler* sampler_;
  double sky_;
  Eigen::Vector3d origin_;
  int first_level_;
};

// Mean grey over an n x n grid of rays spread evenly over pixel (u, v).
double supersample(const RayShader& shader, const CameraView& camera, int u, int v, int n) {
  double sum = 0.0;
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const Eigen::Vector3d direction =
          camera.ray(u + (a + 0.5) / n - 0.5, v + (b + 0.5) / n - 0.5);
      sum += shader.shade(direction, shader.cast(direction));
    }
  return sum / (n * n);
}

} // namespace

Renderer::Renderer(const Terrain& terrain) : terrain_(&terrain), mipmap_(terrain.height) {}

StereoImages Renderer::render(const imaging::StereoRig& rig, const RoverPlacement& placement,
                              const LitSurface& surface, const RenderOptions& options) const {
  return {render_eye(rig, imaging::Eye::left, placement, surface, options, nullptr),
          render_eye(rig, imaging::Eye::right, placement, surface, options, nullptr)};
}

RenderedFrame Renderer::render_with_ground_truth(const imaging::StereoRig& rig,
                                                 const RoverPlacement& placement,
                                                 const LitSurface& surface,
                                                 const RenderOptions& options) const {
  // The right view goes first: its ray lengths settle most occlusion tests of the left view.
  // Each camera draws its own noise stream, so the order changes no byte.
  RenderedFrame frame;
  imaging::Image<float> right_depth;
  frame.images.right = render_eye(rig, imaging::Eye::right, placement, surface, options, nullptr,
                                  nullptr, &right_depth);
  const imaging::Image<float>* depth_hint =
      options.cast_every_occlusion_ray ? nullptr : &right_depth;
  frame.images.left =
      render_eye(rig, imaging::Eye::left, placement, surface, options, &frame.truth, depth_hint);
  return frame;
}

imaging::Image<std::uint8_t> Renderer::render_view(const imaging::StereoRig& rig, imaging::Eye eye,
                                                   const RoverPlacement& placement,
                                                   const LitSurface& surface,
                                                   const RenderOptions& options) const {
  return render_eye(rig, eye, placement, surface, options, nullptr);
}

imaging::Image<std::uint8_t> Renderer::render_eye(const imaging::StereoRig& rig, imaging::Eye eye,
                                                  const RoverPlacement& placement,
                                                  const LitSurface& surface,
                                                  const RenderOptions& options, GroundTruth* truth,
                                                  const imaging::Image<float>* right_depth,
                                                  imaging::Image<float>* depth) const {
  check_options(options);
  const CameraView camera(rig, eye, placement);
  const CameraView right(rig, imaging::Eye::right, placement);
  std::optional<GroundTruthRecorder> recorder;
  if (truth) {
    *truth = GroundTruth::unknown(rig.width(), rig.height());
    recorder.emplace(*truth, *terrain_, mipmap_, right, placement.level_to_world,
                     options.occlusion_tolerance_m, right_depth);
  }
  if (depth)
    *depth = imaging::Image<float>(rig.width(), rig.height(), 1, kNoHitDepth);
  const int n = options.supersampling;
  const SurfaceSampler sampler(surface, terrain_->height, 1.0 / (rig.focal_px() * n),
                               options.filter_texture);
  // Every ray of this camera starts at its centre: find once where the walk may begin.
  const RayShader shader(mipmap_, sampler, surface.lighting().sky_grey, camera.centre(),
                         mipmap_.start_level(camera.centre()));
  // The two cameras draw independent noise streams from one seed.
  GaussianNoise noise(
      substream_seed(options.noise_seed, eye == imaging::Eye::left ? kLeftNoise : kRightNoise));

  // Rows are cast bottom-up and each is shaded and recorded while the terrain its rays met is
  // still in the cache; the noise is then added in row-major order, as the stream runs.
  PixelRayCaster caster(camera, mipmap_, mipmap_.start_level(camera.centre()));
  const int width = rig.width();
  std::vector<double> values(static_cast<std::size_t>(width) * rig.height());
  const double sky_grey = surface.lighting().sky_grey;
  std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(width));
  std::vector<double> weights(static_cast<std::size_t>(width));
  for (int r = 0; r < rig.height(); ++r) {
    const int v = caster.next_row();
    double* row_values = values.data() + static_cast<std::size_t>(v) * width;
    for (int u = 0; u < width; ++u) {
      const double t = caster.hits()[u];
      if (!std::isfinite(t))
        continue;
      if (depth)
        (*depth)(u, v) = static_cast<float>(t);
      if (recorder)
        recorder->record(u, v, camera.centre() + t * caster.directions()[u]);
    }
    if (n > 1) {
      for (int u = 0; u < width; ++u)
        row_values[u] = supersample(shader, camera, u, v, n);
      continue;
    }
    // Shading in loops of their own, the texture weights first: with no occlusion ray or
    // texture lookup between two pixels, the square roots and divisions of one overlap those of
    // the next.
    for (int u = 0; u < width; ++u) {
      const double t = caster.hits()[u];
      if (!std::isfinite(t))
        continue;
      points[u] = camera.centre() + t * caster.directions()[u];
      weights[u] = sampler.texture_weight(points[u], caster.directions()[u], t);
    }
    for (int u = 0; u < width; ++u)
      row_values[u] =
          std::isfinite(caster.hits()[u]) ? sampler.grey_with(points[u], weights[u]) : sky_grey;
  }
  imaging::Image<std::uint8_t> image(rig.width(), rig.height());
  for (int v = 0; v < image.height(); ++v) {
    std::uint8_t* row = image.row(v);
    const double* row_values = values.data() + static_cast<std::size_t>(v) * width;
    for (int u = 0; u < image.width(); ++u) {
      double value = row_values[u];
      if (options.noise_sigma > 0.0)
        value += options.noise_sigma * noise.next();
      row[u] = to_grey(value);
    }
  }
  return image;
}

} // namespace marsokhod::world
