// Test support for the stereo tests: random-dot stereograms with known disparity.
#pragma once

// Synthetic stereo pairs with exactly known disparity for the stereo tests: random-dot
// stereograms of a background plane and an optional foreground square.

#include "marsokhod/imaging/image/image.hpp"
#include "marsokhod/nav/stereo/stereo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace marsokhod::nav::testing {

/// A scene of a background at `background` px and, if square_size > 0, a square at
/// `foreground` px whose top-left corner is (square_x, square_y) in the left image.
struct DotScene {
  int width = 128;
  int height = 96;
  int background = 6;
  int foreground = 14;
  int square_x = 50;
  int square_y = 30;
  int square_size = 36;
  std::uint64_t seed = 7;
};

/// The pair and its truth: disparity of every left pixel, and which left pixels the right
/// camera sees (not occluded by the square, not off the image's left edge).
struct DotPair {
  imaging::Image<std::uint8_t> left;
  imaging::Image<std::uint8_t> right;
  imaging::Image<float> disparity;
  imaging::Image<std::uint8_t> seen;
};

inline bool in_square(const DotScene& scene, int x, int y) {
  return scene.square_size > 0 && x >= scene.square_x && x < scene.square_x + scene.square_size &&
         y >= scene.square_y && y < scene.square_y + scene.square_size;
}

/// Random grey levels in 0..255 from raw generator output (no distribution objects, so the
/// same seed gives the same dots with any standard library).
inline imaging::Image<std::uint8_t> random_dots(int width, int height, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  imaging::Image<std::uint8_t> dots(width, height);
  for (std::size_t i = 0; i < dots.size(); ++i)
    dots.data()[i] = static_cast<std::uint8_t>(generator() >> 56);
  return dots;
}

inline DotPair make_dot_pair(const DotScene& scene) {
  // The texture lives on the surfaces: the background's dots and the square's dots, both in
  // left-image coordinates, wide enough for every right pixel to find its dot.
  const imaging::Image<std::uint8_t> background =
      random_dots(scene.width + 64, scene.height, scene.seed);
  const imaging::Image<std::uint8_t> square =
      random_dots(scene.width, scene.height, scene.seed + 1);
  DotPair pair{imaging::Image<std::uint8_t>(scene.width, scene.height),
               imaging::Image<std::uint8_t>(scene.width, scene.height),
               imaging::Image<float>(scene.width, scene.height),
               imaging::Image<std::uint8_t>(scene.width, scene.height)};
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x) {
      const bool front = in_square(scene, x, y);
      pair.left(x, y) = front ? square(x, y) : background(x, y);
      pair.disparity(x, y) = static_cast<float>(front ? scene.foreground : scene.background);
      // Right pixel x shows the square if the left pixel x + foreground is on it, else the
      // background point of left pixel x + background.
      const int on_square = x + scene.foreground;
      if (on_square < scene.width && in_square(scene, on_square, y))
        pair.right(x, y) = square(on_square, y);
      else
        pair.right(x, y) = background(x + scene.background, y);
    }
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x) {
      const int d = static_cast<int>(pair.disparity(x, y));
      const int right_x = x - d;
      // Seen if the right pixel exists and shows this surface (the square hides background).
      const bool exists = right_x >= 0;
      const bool hidden = !in_square(scene, x, y) && exists &&
                          right_x + scene.foreground < scene.width &&
                          in_square(scene, right_x + scene.foreground, y);
      pair.seen(x, y) = exists && !hidden ? 255 : 0;
    }
  return pair;
}

/// a * image + b, rounded and clamped to 0..255.
inline imaging::Image<std::uint8_t> gain_offset(const imaging::Image<std::uint8_t>& image, double a,
                                                double b) {
  imaging::Image<std::uint8_t> out(image.width(), image.height());
  for (std::size_t i = 0; i < image.size(); ++i)
    out.data()[i] =
        static_cast<std::uint8_t>(std::clamp(std::lround(a * image.data()[i] + b), 0L, 255L));
  return out;
}

/// Share of the pixels with mask != 0 whose estimate lies within `tolerance` of the truth.
inline double share_within(const imaging::Image<float>& estimate,
                           const imaging::Image<float>& truth,
                           const imaging::Image<std::uint8_t>& mask, float tolerance) {
  long scored = 0;
  long good = 0;
  for (int y = 0; y < truth.height(); ++y)
    for (int x = 0; x < truth.width(); ++x) {
      if (mask(x, y) == 0)
        continue;
      ++scored;
      const float e = estimate(x, y);
      good += std::isfinite(e) && std::fabs(e - truth(x, y)) <= tolerance ? 1 : 0;
    }
  return scored == 0 ? 0.0 : static_cast<double>(good) / static_cast<double>(scored);
}

/// Options for the dot scenes: their disparities (6 and 14 px by default) searched up to 24,
/// without the ground prior (a dot scene has no ground).
inline StereoOptions dot_scene_options() {
  StereoOptions options;
  options.max_disparity = 24;
  options.ground_prior = false;
  return options;
}

} // namespace marsokhod::nav::testing
