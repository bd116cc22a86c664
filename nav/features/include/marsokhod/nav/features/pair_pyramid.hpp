// PairPyramid: a stereo pair's image pyramid, the caller's images at the bottom.
#pragma once

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/imaging/rig/camera.hpp"
#include "marsokhod/nav/features/image_pyramid.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory_resource>

namespace marsokhod::nav {

/// Most layers an image pyramid may have.
inline constexpr int kMaxPyramidLevels = 6;

/// A stereo pair's image pyramid: the caller's images as layer 0 and `levels - 1` halved
/// layers above them, built from the bottom up with halve_image. The caller's images must
/// outlive it; the halved layers' pixels come from `memory`.
class PairPyramid {
public:
  template <class Meter>
  PairPyramid(imaging::ImageView<const std::uint8_t> left,
              imaging::ImageView<const std::uint8_t> right, int levels, Meter& meter,
              std::pmr::memory_resource* memory)
      : original_{left, right}, levels_(levels) {
    for (int level = 1; level < levels; ++level) {
      left_[static_cast<std::size_t>(level - 1)] =
          halve_image(layer(level - 1, imaging::Eye::left), meter, memory);
      right_[static_cast<std::size_t>(level - 1)] =
          halve_image(layer(level - 1, imaging::Eye::right), meter, memory);
    }
  }

  int levels() const { return levels_; }
  imaging::ImageView<const std::uint8_t> layer(int level, imaging::Eye eye) const {
    if (level == 0)
      return original_[eye == imaging::Eye::left ? 0 : 1];
    const auto& layers = eye == imaging::Eye::left ? left_ : right_;
    return layers[static_cast<std::size_t>(level - 1)].view();
  }

private:
  imaging::ImageView<const std::uint8_t> original_[2];
  int levels_ = 1;
  std::array<imaging::Image<std::uint8_t>, kMaxPyramidLevels> left_;
  std::array<imaging::Image<std::uint8_t>, kMaxPyramidLevels> right_;
};

} // namespace marsokhod::nav
