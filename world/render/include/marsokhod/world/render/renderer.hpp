// The ray-casting stereo renderer: options, rendered pairs and their ground truth.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/world/render/ground_truth.hpp"
#include "marsokhod/world/render/max_mipmap.hpp"
#include "marsokhod/world/terrain/terrain.hpp"

#include <cstdint>

namespace marsokhod::world {

/// How images are made from the exact geometry.
struct RenderOptions {
  /// Standard deviation of the Gaussian sensor noise, grey levels (0 = noiseless).
  double noise_sigma = 2.0;
  /// Seed of the sensor noise; the left and right cameras draw independent streams from it.
  std::uint64_t noise_seed = 1;
  /// n x n rays per pixel for the images (1 = one ray through the pixel centre). Ground truth
  /// always comes from the pixel-centre ray.
  int supersampling = 1;
  /// Fades the lit surface's sub-grid texture where a pixel's footprint is wider than its pitch
  /// (texture level of detail), as a real sensor's pixel averages it; off, one ray per pixel
  /// aliases it into noise that differs between the two cameras.
  bool filter_texture = true;
  /// A point counts as seen by the right camera when the right camera's ray towards it first
  /// meets the terrain no more than this short of it, metres.
  double occlusion_tolerance_m = 0.01;
  /// Decides every pixel's occlusion with its own ray from the right camera, instead of first
  /// comparing against the right view's depths (which casts rays only near depth edges and
  /// the image border). The masks agree; this is the slower reference.
  bool cast_every_occlusion_ray = false;
};

/// The two 8-bit grey images of a stereo pair.
struct StereoImages {
  imaging::Image<std::uint8_t> left;
  imaging::Image<std::uint8_t> right;
};

/// A rendered pair with the ground truth of its left image.
struct RenderedFrame {
  StereoImages images;
  GroundTruth truth;
};

/// Ray-casting stereo renderer over one terrain. Construction builds the terrain's maximum
/// mipmap once; every frame then casts one ray per pixel centre (or n x n with supersampling)
/// through the bilinear height field to its exact first intersection. Grey level =
/// clamp(round(exposure * radiance + noise)); rays that leave the terrain see the sky_grey.
/// Keeps a reference to the terrain, which must outlive the renderer.
class Renderer {
public:
  explicit Renderer(const Terrain& terrain);

  const Terrain& terrain() const { return *terrain_; }
  const MaxMipmap& acceleration() const { return mipmap_; }

  /// Both images seen by the rig from the placed rover under a lit surface of this terrain.
  StereoImages render(const imaging::StereoRig& rig, const RoverPlacement& placement,
                      const LitSurface& surface, const RenderOptions& options = {}) const;
  /// The images and the ground truth of the left image, sharing the left camera's rays.
  RenderedFrame render_with_ground_truth(const imaging::StereoRig& rig,
                                         const RoverPlacement& placement, const LitSurface& surface,
                                         const RenderOptions& options = {}) const;
  /// One image: the given camera's view.
  imaging::Image<std::uint8_t> render_view(const imaging::StereoRig& rig, imaging::Eye eye,
                                           const RoverPlacement& placement,
                                           const LitSurface& surface,
                                           const RenderOptions& options = {}) const;

private:
  imaging::Image<std::uint8_t> render_eye(const imaging::StereoRig& rig, imaging::Eye eye,
                                          const RoverPlacement& placement,
                                          const LitSurface& surface, const RenderOptions& options,
                                          GroundTruth* truth,
                                          const imaging::Image<float>* right_depth = nullptr,
                                          imaging::Image<float>* depth = nullptr) const;

  const Terrain* terrain_;
  MaxMipmap mipmap_;
};

} // namespace marsokhod::world
