#pragma once

#include "marsokhod/world/camera_view.hpp"
#include "marsokhod/world/max_mipmap.hpp"

#include <vector>

namespace marsokhod::world {

/// Distance along the ray through every pixel centre of a camera to its first terrain hit
/// (+inf where the ray meets nothing), row-major: the answers of MaxMipmap::first_hit, found
/// with less work, because a pixel's walk may often start where the ray of the pixel below it
/// ended (pixel_rays.cpp says when).
std::vector<double> cast_pixel_rays(const CameraView& camera, const MaxMipmap& mipmap,
                                    int first_level);

} // namespace marsokhod::world
