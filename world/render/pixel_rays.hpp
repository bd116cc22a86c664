// The pixel-centre ray caster of a camera, row by row (private to the renderer).
#pragma once

#include "marsokhod/world/render/camera_view.hpp"
#include "marsokhod/world/render/max_mipmap.hpp"

#include <Eigen/Core>

#include <vector>

namespace marsokhod::world {

/// Casts the rays through a camera's pixel centres row by row, from the bottom row up, and
/// finds each one's first terrain hit: the answers of MaxMipmap::first_hit, found with less
/// work, because a pixel's walk may often start where the ray of the pixel below it ended
/// (pixel_rays.cpp says when). A caller that uses each row's hits right away finds the terrain
/// they touched still in the cache.
class PixelRayCaster {
public:
  PixelRayCaster(const CameraView& camera, const MaxMipmap& mipmap, int first_level);

  /// The next row up (the bottom row first): its rays (CameraView::ray) and the distance
  /// along each to its first hit (+inf for none), valid until the next call.
  int next_row();
  int row() const { return v_; }
  const std::vector<Eigen::Vector3d>& directions() const { return directions_; }
  const std::vector<double>& hits() const { return hits_; }

  /// What the ray of the pixel below proves about a ray (pixel_rays.cpp).
  struct ProvenStart {
    double t_start = 0.0; ///< 0 when nothing is proven
    double gentle = 0.0;
    bool everywhere = false; ///< gentle is at least the whole surface's Lipschitz constant
    bool short_gap = false;  ///< the two rays' ground points stay within a cell of each other
  };

private:
  const CameraView* camera_;
  const MaxMipmap* mipmap_;
  int first_level_;
  int v_;
  std::vector<Eigen::Vector3d> directions_, directions_below_;
  std::vector<double> hits_, hits_below_;
  std::vector<double> clear_,
      clear_below_; // the hit, or where a ray that met nothing left the grid
  std::vector<double> ground_, ground_below_; // lengths of the rays' ground components
  std::vector<ProvenStart> starts_;
};

} // namespace marsokhod::world
