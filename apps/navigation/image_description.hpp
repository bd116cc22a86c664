// What `marsokhod image info` says of an image.
#pragma once

#include "marsokhod/imaging/image/image.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace marsokhod::apps {

/// An image file's container, size, sample type and the range of its finite samples.
struct ImageDescription {
  std::string file;
  std::string format; ///< the container its magic bytes name: pgm, ppm, pfm, png
  int width = 0;
  int height = 0;
  int channels = 0;
  std::size_t bit_depth = 0;
  std::string sample_type; ///< uint8, uint16, float32
  std::uint64_t finite = 0;
  std::uint64_t non_finite = 0;
  /// Of the finite samples; nothing without one.
  std::optional<double> min;
  std::optional<double> max;
  std::optional<double> mean;
};

/// Reads the file strip by strip (imaging::scan_image): memory stays small however large the
/// image. Throws imaging::ImageError for a file read_image would refuse.
ImageDescription describe_image_file(const std::string& file);

/// {file, format, width, height, channels, bit_depth, sample_type, finite, non_finite, min,
/// max, mean (null without a finite sample)}.
void to_json(nlohmann::json& json, const ImageDescription& description);

} // namespace marsokhod::apps
